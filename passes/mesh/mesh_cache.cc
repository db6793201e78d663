// mesh_cache.cc - see mesh_cache.h.
#include "passes/mesh/mesh_cache.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <thread>

#include "passes/mesh/in_process_reader.h"
#include "passes/mesh/point_cloud.h"
#include "passes/mesh/io/mesh_wire.h"
#include "passes/mesh/reader_location.h"
#include "passes/mesh/reader_pool.h"

namespace mdlc::mesh {
namespace {

// MeshFacts as the derived cache keeps them: up axis, turned, vertex and
// triangle counts (below 2^53, so exact as doubles)
constexpr size_t kFactValues = 4;

std::vector<double> FactValues(const MeshFacts& f) {
  return {static_cast<double>(f.declared_up), f.turned_to_z_up ? 1.0 : 0.0,
          static_cast<double>(f.vertices), static_cast<double>(f.triangles)};
}

std::optional<MeshFacts> FactsFromValues(const std::vector<double>& v) {
  if (v.size() != kFactValues || v[0] < 0 || v[0] > static_cast<double>(UpAxis::kZ) ||
      (v[1] != 0 && v[1] != 1) || v[2] < 0 || v[3] < 1) {
    return std::nullopt;  // not what this build writes: recompute
  }
  return MeshFacts{static_cast<UpAxis>(v[0]), v[1] == 1, static_cast<uint64_t>(v[2]),
                   static_cast<uint64_t>(v[3])};
}

MeshFacts FactsOf(const TriangleMesh& m) {
  return {m.declared_up, m.turned_to_z_up, m.vertices.size(), m.triangles.size()};
}

}  // namespace

MeshCache::MeshCache(const Limits& limits, MeshReading reading, const MeshAxes& axes,
                     std::shared_ptr<DerivedMeshCache> derived)
    : derived_(std::move(derived)) {
  settings_ = fmt::format("{}", fmt::join(EncodeMeshSettings(limits, axes), " "));
  if (reading == MeshReading::kChildProcess) {
    MeshReaderLocation found = FindMeshReader();
    reader_ = std::move(found.path);
    reader_missing_ = std::move(found.why_none);
  }
  if (reader_.empty()) {
    loader_ = [limits, axes](const std::string& path) {
      return LoadMeshInProcess(path, limits, axes);
    };
  } else {
    pool_ = SharedMeshReaderPool(reader_);
    workers_before_ = pool_->workers_started();
    loader_ = [limits, axes, pool = pool_](const std::string& path) {
      return pool->Read(path, limits, axes);
    };
  }
}

MeshCache::MeshCache(Loader loader, std::shared_ptr<DerivedMeshCache> derived,
                     std::string settings)
    : loader_(std::move(loader)), settings_(std::move(settings)), derived_(std::move(derived)) {}

MeshCache::~MeshCache() = default;

size_t MeshCache::workers_started() const {
  return pool_ ? pool_->workers_started() - workers_before_ : 0;
}

std::shared_ptr<MeshCache::Entry> MeshCache::EntryFor(const std::string& path) {
  std::lock_guard lock(mutex_);
  auto& entry = entries_[path];
  if (!entry) entry = std::make_shared<Entry>();
  return entry;
}

MeshOrError MeshCache::Get(const std::string& path) {
  std::shared_ptr<Entry> entry = EntryFor(path);
  // other threads asking for the same file wait here for the one reader
  std::call_once(entry->read_once, [&] {
    entry->mesh = HullOfPointCloud(loader_(path), fmt::format("mesh file '{}'", path));
    ++files_read_;
  });
  return entry->mesh;
}

void MeshCache::Provide(const std::string& key, MeshOrError mesh) {
  std::shared_ptr<Entry> entry = EntryFor(key);
  std::call_once(entry->read_once, [&] { entry->mesh = std::move(mesh); });
  // no file: nothing to hash, nothing the derived cache can key
  std::call_once(entry->digest_once, [] {});
  std::call_once(entry->lookup_once, [] {});
}

std::optional<ContentDigest> MeshCache::Digest(const std::string& path) {
  std::shared_ptr<Entry> entry = EntryFor(path);
  std::call_once(entry->digest_once, [&] {
    entry->digest = DerivedMeshCache::Digest(path);
    ++files_hashed_;
  });
  return entry->digest;
}

MeshCache::Entry& MeshCache::LookUp(const std::string& path) {
  std::shared_ptr<Entry> entry = EntryFor(path);
  std::call_once(entry->lookup_once, [&] {
    if (!derived_) return;
    const std::optional<ContentDigest> digest = Digest(path);
    if (!digest) return;
    entry->facts_key = DerivedMeshCache::Key(*digest, "facts|" + settings_);
    if (auto values = derived_->Load(*entry->facts_key)) entry->cached_facts = FactsFromValues(*values);
  });
  return *entry;  // entries live as long as the cache
}

MeshStatus MeshCache::FindStatus(const std::string& path) {
  const Entry& entry = LookUp(path);
  if (entry.cached_facts) {
    ++facts_from_cache_;
    return {entry.cached_facts, {}, false};
  }
  const MeshOrError m = Get(path);
  if (!m.ok()) return {std::nullopt, m.error, m.over_limit};
  const MeshFacts facts = FactsOf(*m.mesh);
  // only a mesh is kept: an error may be the machine's (a worker that ran
  // out of time), and the next compile should try again
  if (entry.facts_key) derived_->Store(*entry.facts_key, FactValues(facts));
  return {facts, {}, false};
}

MeshStatus MeshCache::Status(const std::string& path) {
  std::shared_ptr<Entry> entry = EntryFor(path);
  std::call_once(entry->status_once, [&] { entry->status = FindStatus(path); });
  return entry->status;
}

void MeshCache::ForEachInParallel(const std::vector<std::string>& todo, size_t threads,
                                  const std::function<void(const std::string&)>& work) {
  threads = std::min(threads, todo.size());
  if (threads <= 1) {
    for (const std::string& p : todo) work(p);
    return;
  }
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i = next++; i < todo.size(); i = next++) work(todo[i]);
  };
  std::vector<std::thread> pool;
  for (size_t t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
}

namespace {

/// `paths` without repeats.
std::vector<std::string> Distinct(const std::vector<std::string>& paths) {
  const std::set<std::string> unique(paths.begin(), paths.end());
  return {unique.begin(), unique.end()};
}

size_t HardwareThreads() { return std::max(1u, std::thread::hardware_concurrency()); }

/// Threads worth reading files of `bytes` in all: each further thread has
/// a reader worker (or the import module) to start, about 10 ms of a core,
/// which a few MB of mesh repay and a few small files do not.
size_t ReadingThreadsFor(uint64_t bytes) {
  constexpr uint64_t kBytesPerThread = uint64_t{2} << 20;
  return std::clamp<size_t>(static_cast<size_t>(bytes / kBytesPerThread), 1, HardwareThreads());
}

}  // namespace

void MeshCache::Survey(const std::vector<std::string>& paths) {
  // first what the derived cache knows (hashing is cheap: a thread each),
  // then the files it does not, read on as many threads as they are worth
  const std::vector<std::string> files = Distinct(paths);
  if (derived_) {
    ForEachInParallel(files, HardwareThreads(), [this](const std::string& p) { LookUp(p); });
  }
  std::vector<std::string> unknown;
  uint64_t bytes = 0;
  for (const std::string& p : files) {
    if (LookUp(p).cached_facts) continue;
    unknown.push_back(p);
    std::error_code ec;
    const uint64_t size = std::filesystem::file_size(p, ec);
    if (!ec) bytes += size;
  }
  ForEachInParallel(unknown, ReadingThreadsFor(bytes),
                    [this](const std::string& p) { Status(p); });
  for (const std::string& p : files) Status(p);  // the known ones: no reading
}

void MeshCache::Prefetch(const std::vector<std::string>& paths) {
  ForEachInParallel(Distinct(paths), HardwareThreads(), [this](const std::string& p) { Get(p); });
}

}  // namespace mdlc::mesh
