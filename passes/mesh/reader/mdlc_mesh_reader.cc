// mdlc-mesh-reader - reads one mesh file with assimp and writes the result
// to standard output as a mesh reply (passes/mesh/mesh_wire.h). Its
// in-process twin is the import module (mdlc_mesh_import.cc).
//
// mdlc runs it in a child process for each mesh file (child_reader.h), so
// that assimp's memory errors, hangs and leaks on malformed files stay in
// this short-lived process (issue 16). Not meant to be run by hand:
//
//   mdlc-mesh-reader [LIMIT=VALUE]... [collada-up-axis=MODE] -- PATH
//
// LIMIT=VALUE as `mdlc --limit` takes them, MODE as `mdlc
// --collada-up-axis` does. Exit status 0 with a reply
// (also when the file is unreadable: the reply says why), 2 on bad usage, 3
// when the reply cannot be written.
#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "ir/limits.h"
#include "passes/mesh/assimp_loader.h"
#include "passes/mesh/mesh_wire.h"

namespace {

bool WriteAll(int fd, const std::string& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

[[noreturn]] void Usage(const std::string& problem) {
  fmt::print(stderr,
             "mdlc-mesh-reader: error: {}\n"
             "usage: mdlc-mesh-reader [LIMIT=VALUE]... [collada-up-axis=MODE] -- PATH\n",
             problem);
  std::fflush(stderr);
  ::_exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string_view> request(argv + 1, argv + argc);
  mdlc::Limits limits;
  mdlc::mesh::MeshAxes axes;
  std::string path;
  if (auto problem = mdlc::mesh::DecodeMeshRequest(request, &path, &limits, &axes)) Usage(*problem);
  const std::string reply = mdlc::mesh::EncodeMeshReply(mdlc::mesh::ImportMesh(path, limits, axes));
  // _exit: no destructors, no exit handlers. Whatever assimp leaked or
  // damaged goes with the process, and a leak checker built into the
  // program does not report assimp's leaks as ours.
  ::_exit(WriteAll(STDOUT_FILENO, reply) ? 0 : 3);
}
