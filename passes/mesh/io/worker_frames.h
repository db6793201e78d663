// worker_frames.h - how requests and replies (mesh_wire.h) travel between
// mdlc and a mesh reader worker that reads many files, one after another
// (issue 57; reader_pool.h).
//
// A worker reads request frames from its standard input and writes one
// reply frame to its standard output for each, in order:
//
//   request frame: u32 kRequestFrameMagic, u32 kMeshWireVersion,
//                  u32 argument count N, then N times (u32 length, bytes),
//                  the arguments being a request (EncodeMeshRequest)
//   reply frame:   u64 length, then that many bytes: a reply
//                  (EncodeMeshReply)
//
// The end of its standard input, at a frame boundary, tells the worker to
// exit. Numbers are in the machine's own byte order, as in mesh_wire.h.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mdlc::mesh {

inline constexpr uint32_t kRequestFrameMagic = 0x51524c4d;  // "MLRQ"
/// Bounds a worker holds a request frame to (mdlc's own requests are a few
/// dozen short arguments and a path): a damaged stream is refused, not
/// allocated.
inline constexpr uint32_t kMaxRequestArguments = 1024;
inline constexpr uint32_t kMaxRequestArgumentBytes = 1 << 20;

/// `args` as a request frame.
std::string EncodeRequestFrame(const std::vector<std::string>& args);

/// The header of a reply frame whose reply is `length` bytes; the reply
/// follows it as it is (a mesh's reply can be hundreds of MB: not copied).
std::string ReplyFrameHeader(uint64_t length);

/// Reads whole request frames from a file descriptor (a worker's standard
/// input), buffered: a request of a few dozen arguments is one read, not
/// two per argument.
class RequestFrameReader {
 public:
  explicit RequestFrameReader(int fd) : fd_(fd) {}
  enum class Status { kRequest, kEnd, kMalformed };
  /// The next request's arguments (kRequest); kEnd at the end of the input
  /// between frames; kMalformed, with `*problem` set, for anything else.
  Status Next(std::vector<std::string>* args, std::string* problem);

 private:
  bool ReadExactly(void* out, size_t n, bool* nothing_read);
  int fd_;
  std::string buffer_;  // read from fd_, not yet taken
  size_t taken_ = 0;
};

/// Writes all of `bytes` to `fd`; false when it cannot.
bool WriteAll(int fd, std::string_view bytes);

/// The length a reply frame announces once its first 8 bytes are in
/// `bytes`; nullopt before that.
std::optional<uint64_t> ReplyFrameLength(std::string_view bytes);
inline constexpr size_t kReplyFrameHeader = sizeof(uint64_t);

}  // namespace mdlc::mesh
