// worker_frames.cc - see worker_frames.h.
#include "passes/mesh/io/worker_frames.h"

#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "passes/mesh/io/mesh_wire.h"

namespace mdlc::mesh {
namespace {

template <typename T>
void Put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

}  // namespace

std::string EncodeRequestFrame(const std::vector<std::string>& args) {
  std::string out;
  Put(out, kRequestFrameMagic);
  Put(out, kMeshWireVersion);
  Put(out, static_cast<uint32_t>(args.size()));
  for (const std::string& a : args) {
    Put(out, static_cast<uint32_t>(a.size()));
    out += a;
  }
  return out;
}

std::string ReplyFrameHeader(uint64_t length) {
  std::string out;
  Put(out, length);
  return out;
}

std::optional<uint64_t> ReplyFrameLength(std::string_view bytes) {
  if (bytes.size() < kReplyFrameHeader) return std::nullopt;
  uint64_t length = 0;
  std::memcpy(&length, bytes.data(), sizeof length);
  return length;
}

bool WriteAll(int fd, std::string_view bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

bool RequestFrameReader::ReadExactly(void* out, size_t n, bool* nothing_read) {
  auto* bytes = static_cast<char*>(out);
  size_t done = 0;
  while (done < n) {
    if (taken_ == buffer_.size()) {
      buffer_.resize(size_t{1} << 16);
      taken_ = 0;
      ssize_t got;
      do {
        got = ::read(fd_, buffer_.data(), buffer_.size());
      } while (got < 0 && errno == EINTR);
      buffer_.resize(static_cast<size_t>(std::max<ssize_t>(got, 0)));
      if (got <= 0) break;
    }
    const size_t step = std::min(n - done, buffer_.size() - taken_);
    std::memcpy(bytes + done, buffer_.data() + taken_, step);
    taken_ += step;
    done += step;
  }
  if (nothing_read) *nothing_read = done == 0;
  return done == n;
}

RequestFrameReader::Status RequestFrameReader::Next(std::vector<std::string>* args,
                                                    std::string* problem) {
  uint32_t header[3];
  bool nothing = false;
  if (!ReadExactly(header, sizeof header, &nothing)) {
    if (nothing) return Status::kEnd;
    *problem = "the request frame's header is truncated";
    return Status::kMalformed;
  }
  if (header[0] != kRequestFrameMagic || header[1] != kMeshWireVersion) {
    *problem = fmt::format("not a request frame of version {}", kMeshWireVersion);
    return Status::kMalformed;
  }
  if (header[2] > kMaxRequestArguments) {
    *problem = fmt::format("a request of {} arguments", header[2]);
    return Status::kMalformed;
  }
  args->assign(header[2], std::string());
  for (std::string& a : *args) {
    uint32_t length = 0;
    if (!ReadExactly(&length, sizeof length, nullptr) || length > kMaxRequestArgumentBytes) {
      *problem = "a request argument is truncated or too long";
      return Status::kMalformed;
    }
    a.resize(length);
    if (!ReadExactly(a.data(), length, nullptr)) {
      *problem = "a request argument is truncated";
      return Status::kMalformed;
    }
  }
  return Status::kRequest;
}

}  // namespace mdlc::mesh
