// mdlc_faulty_mesh_reader - a mesh reader worker for tests (issue 57) that
// serves requests as mdlc-mesh-reader does, except for files whose names
// ask it to misbehave:
//
//   ...crash...    dies of SIGSEGV while reading the file
//   ...hang...     never answers
//   ...garbage...  answers with a frame that holds no reply, then exits
//   ...vanish...   exits without a word
//
// Any other file is read with assimp, as the real reader does.
#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <string_view>

#include "passes/mesh/import/assimp_loader.h"
#include "passes/mesh/io/serve_requests.h"
#include "passes/mesh/io/worker_frames.h"

namespace {

mdlc::mesh::MeshOrError ReadOrMisbehave(const std::string& path, const mdlc::Limits& limits,
                                        const mdlc::mesh::MeshAxes& axes) {
  const std::string name = std::filesystem::path(path).filename().string();
  if (name.find("crash") != std::string::npos) {
    // past any handler a sanitizer installed: a plain crash, as assimp's
    ::signal(SIGSEGV, SIG_DFL);
    ::raise(SIGSEGV);
  }
  if (name.find("hang") != std::string::npos) {
    for (;;) ::pause();
  }
  if (name.find("garbage") != std::string::npos) {
    const std::string_view garbage = "no reply, honestly";
    mdlc::mesh::WriteAll(STDOUT_FILENO, mdlc::mesh::ReplyFrameHeader(garbage.size()));
    mdlc::mesh::WriteAll(STDOUT_FILENO, garbage);
    ::_exit(0);
  }
  if (name.find("vanish") != std::string::npos) ::_exit(0);
  return mdlc::mesh::ImportMesh(path, limits, axes);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 || std::string_view(argv[1]) != "--serve") ::_exit(2);
  ::_exit(mdlc::mesh::ServeMeshRequests(STDIN_FILENO, STDOUT_FILENO, &ReadOrMisbehave));
}
