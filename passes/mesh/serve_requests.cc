// serve_requests.cc - see serve_requests.h.
#include "passes/mesh/serve_requests.h"

#include <fmt/format.h>

#include <cstdio>
#include <string_view>
#include <vector>

#include "passes/mesh/mesh_wire.h"
#include "passes/mesh/worker_frames.h"

namespace mdlc::mesh {

int ServeMeshRequests(int in, int out, const ReadMeshFunction& read) {
  RequestFrameReader requests(in);
  std::vector<std::string> args;
  std::string problem;
  for (;;) {
    switch (requests.Next(&args, &problem)) {
      case RequestFrameReader::Status::kEnd: return 0;
      case RequestFrameReader::Status::kMalformed:
        fmt::print(stderr, "mdlc-mesh-reader: error: {}\n", problem);
        std::fflush(stderr);
        return 2;
      case RequestFrameReader::Status::kRequest: break;
    }
    const std::vector<std::string_view> request(args.begin(), args.end());
    // a fresh set of limits for each request: none carries over
    Limits limits;
    MeshAxes axes;
    std::string path;
    MeshOrError result;
    if (auto bad = DecodeMeshRequest(request, &path, &limits, &axes)) {
      fmt::print(stderr, "mdlc-mesh-reader: error: {}\n", *bad);
      std::fflush(stderr);
      return 2;
    }
    result = read(path, limits, axes);
    if (!WriteAll(out, EncodeReplyFrame(EncodeMeshReply(result)))) return 3;
  }
}

}  // namespace mdlc::mesh
