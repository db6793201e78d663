// derived_cache.cc - see derived_cache.h.
#include "passes/mesh/derived_cache.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>
#include <xxhash.h>

#include <cerrno>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace mdlc::mesh {
namespace {
namespace fs = std::filesystem;

// Bump when the layout of an entry or the meaning of its values changes.
constexpr std::string_view kMagic = "mdlc-derived-mesh/1\n";

// FNV-1a, 64 bits: an entry's checksum against a torn or damaged file.
struct Fnv {
  uint64_t h;
  void Add(std::string_view bytes) {
    for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ULL;
  }
};

std::string Checksum(std::string_view bytes) {
  Fnv f{0xcbf29ce484222325ULL};
  f.Add(bytes);
  return fmt::format("{:016x}", f.h);
}

}  // namespace

std::string DerivedMeshCache::DefaultDirectory() {
  if (const char* dir = std::getenv("MDLC_CACHE_DIR"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
    return (fs::path(xdg) / "mdlc").string();
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return (fs::path(home) / ".cache" / "mdlc").string();
  }
  return "";
}

std::optional<ContentDigest> DerivedMeshCache::Digest(const std::string& path) {
  // XXH3 at memory speed: a warm compile hashes every mesh it would have
  // read, and this is then most of its time
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  XXH3_state_t* state = XXH3_createState();
  XXH3_128bits_reset(state);
  uint64_t size = 0;
  std::vector<char> buffer(size_t{1} << 20);
  bool failed = false;
  for (;;) {
    const ssize_t n = ::read(fd, buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) failed = true;
    if (n <= 0) break;
    XXH3_128bits_update(state, buffer.data(), static_cast<size_t>(n));
    size += static_cast<uint64_t>(n);
  }
  const XXH128_hash_t h = XXH3_128bits_digest(state);
  XXH3_freeState(state);
  ::close(fd);
  if (failed) return std::nullopt;
  return ContentDigest{h.high64, h.low64, size};
}

std::string DerivedMeshCache::Key(const ContentDigest& content, std::string_view options) {
  // the options and the format version are part of what the key names
  const std::string text = fmt::format("{:016x}{:016x}|{}|{}|{}", content.a, content.b,
                                       content.size, options, kMagic);
  const XXH128_hash_t h = XXH3_128bits(text.data(), text.size());
  return fmt::format("{:016x}{:016x}", h.high64, h.low64);
}

std::optional<std::string> DerivedMeshCache::Key(const std::string& path,
                                                 std::string_view options) {
  const std::optional<ContentDigest> content = Digest(path);
  if (!content) return std::nullopt;
  return Key(*content, options);
}

std::optional<std::vector<double>> DerivedMeshCache::Load(const std::string& key) {
  // layout: magic, key, count, the values' bytes, checksum of all before it
  std::ifstream in(fs::path(dir_) / key, std::ios::binary);
  std::stringstream ss;
  if (in) ss << in.rdbuf();
  const std::string entry = ss.str();
  const std::string head = fmt::format("{}{}\n", kMagic, key);
  auto miss = [&]() -> std::optional<std::vector<double>> {
    ++misses_;
    return std::nullopt;
  };
  if (!entry.starts_with(head) || entry.size() < head.size() + 8 + 16) return miss();
  uint64_t count = 0;
  std::memcpy(&count, entry.data() + head.size(), 8);
  const size_t body = head.size() + 8 + count * sizeof(double);
  if (count > (1u << 20) || entry.size() != body + 16 ||
      entry.compare(body, 16, Checksum(std::string_view(entry).substr(0, body))) != 0) {
    return miss();
  }
  std::vector<double> values(count);
  std::memcpy(values.data(), entry.data() + head.size() + 8, count * sizeof(double));
  ++hits_;
  return values;
}

void DerivedMeshCache::Store(const std::string& key, const std::vector<double>& values) {
  std::string entry = fmt::format("{}{}\n", kMagic, key);
  const uint64_t count = values.size();
  entry.append(reinterpret_cast<const char*>(&count), 8);
  entry.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
  entry += Checksum(entry);
  std::error_code ec;
  fs::create_directories(dir_, ec);
  // a name no other writer uses, then an atomic rename over the entry
  const fs::path temporary =
      fs::path(dir_) / fmt::format(".{}.{}.{}.tmp", key, ::getpid(),
                                   std::hash<std::thread::id>()(std::this_thread::get_id()));
  {
    std::ofstream out(temporary, std::ios::binary);
    out.write(entry.data(), static_cast<std::streamsize>(entry.size()));
    if (!out.flush()) {
      out.close();
      fs::remove(temporary, ec);
      return;
    }
  }
  fs::rename(temporary, fs::path(dir_) / key, ec);
  if (ec) fs::remove(temporary, ec);
}

}  // namespace mdlc::mesh
