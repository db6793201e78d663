// serve_requests.cc - see serve_requests.h.
#include "passes/mesh/io/serve_requests.h"

#include <fmt/format.h>

#include <cstdio>
#include <string_view>
#include <vector>

#include "passes/mesh/io/mesh_wire.h"
#include "passes/mesh/io/worker_frames.h"

namespace mdlc::mesh {
namespace {

/// Says why a request is refused; the exit status for it.
int Refuse(const std::string& problem) {
  fmt::print(stderr, "mdlc-mesh-reader: error: {}\n", problem);
  std::fflush(stderr);
  return 2;
}

}  // namespace

int ServeMeshRequests(int in, int out, const ReadMeshFunction& read) {
  RequestFrameReader requests(in);
  std::vector<std::string> args;
  std::string problem;
  for (;;) {
    switch (requests.Next(&args, &problem)) {
      case RequestFrameReader::Status::kEnd: return 0;
      case RequestFrameReader::Status::kMalformed: return Refuse(problem);
      case RequestFrameReader::Status::kRequest: break;
    }
    const std::vector<std::string_view> request(args.begin(), args.end());
    // a fresh set of limits for each request: none carries over
    Limits limits;
    MeshAxes axes;
    std::string path;
    if (auto bad = DecodeMeshRequest(request, &path, &limits, &axes)) return Refuse(*bad);
    const std::string reply = EncodeMeshReply(read(path, limits, axes));
    if (!WriteAll(out, ReplyFrameHeader(reply.size())) || !WriteAll(out, reply)) return 3;
  }
}

}  // namespace mdlc::mesh
