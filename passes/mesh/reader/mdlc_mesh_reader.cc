// mdlc-mesh-reader - reads mesh files with assimp for mdlc, in a worker
// process of its own, so that assimp's memory errors, hangs and leaks on
// malformed files stay out of mdlc (issues 16 and 57). Its in-process twin
// is the import module (mdlc_mesh_import.cc).
//
// mdlc keeps a few of these running while it compiles (reader_pool.h) and
// sends each a request frame per file; the worker answers each with a reply
// frame (worker_frames.h) and exits when its standard input ends. Not meant
// to be run by hand:
//
//   mdlc-mesh-reader --serve
//
// Exit status 0 at the end of the input, 2 on bad usage or a malformed
// request, 3 when a reply cannot be written.
#include <malloc.h>
#include <unistd.h>

#include <fmt/format.h>

#include <climits>
#include <cstdio>
#include <string_view>

#include "passes/mesh/import/assimp_loader.h"
#include "passes/mesh/io/serve_requests.h"

int main(int argc, char** argv) {
  if (argc != 2 || std::string_view(argv[1]) != "--serve") {
    fmt::print(stderr,
               "mdlc-mesh-reader: error: mdlc runs this program itself\n"
               "usage: mdlc-mesh-reader --serve   (request frames on standard input)\n");
    std::fflush(stderr);
    ::_exit(2);
  }
  // a worker reads file after file, each allocating and freeing much the
  // same: keep freed memory for the next file instead of giving it back to
  // the system and faulting it in again (most of a small file's time
  // otherwise). The worker is replaced after a bounded number of files.
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, INT_MAX);
  const int status = mdlc::mesh::ServeMeshRequests(STDIN_FILENO, STDOUT_FILENO,
                                                   &mdlc::mesh::ImportMesh);
  // _exit: no destructors, no exit handlers. Whatever assimp leaked or
  // damaged goes with the process, and a leak checker built into the
  // program does not report assimp's leaks as ours.
  ::_exit(status);
}
