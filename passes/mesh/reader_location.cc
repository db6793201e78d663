#include "passes/mesh/reader_location.h"

#include <dlfcn.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <optional>

// Set by the build: the reader's and the module's paths below an install
// prefix, and where this build tree puts them.
#ifndef MDLC_MESH_READER_INSTALL_PATH
#define MDLC_MESH_READER_INSTALL_PATH "libexec/mdlc/mdlc-mesh-reader"
#endif
#ifndef MDLC_MESH_READER_BUILD_PATH
#define MDLC_MESH_READER_BUILD_PATH ""
#endif
#ifndef MDLC_MESH_MODULE_INSTALL_PATH
#define MDLC_MESH_MODULE_INSTALL_PATH "lib/mdlc/mdlc-mesh-import.so"
#endif
#ifndef MDLC_MESH_MODULE_BUILD_PATH
#define MDLC_MESH_MODULE_BUILD_PATH ""
#endif

namespace mdlc::mesh {
namespace {

namespace fs = std::filesystem;

/// One form of the reader: how to recognise it and where it lies.
struct ReaderForm {
  const char* variable;
  const char* install_path;  // below an install prefix
  const char* build_path;    // in this build tree
  const char* what;          // for the user
  bool executable;           // a program, or a module to open
};

constexpr ReaderForm kProgram{kMeshReaderVariable, MDLC_MESH_READER_INSTALL_PATH,
                              MDLC_MESH_READER_BUILD_PATH, "the mdlc-mesh-reader program", true};
constexpr ReaderForm kModule{kMeshModuleVariable, MDLC_MESH_MODULE_INSTALL_PATH,
                             MDLC_MESH_MODULE_BUILD_PATH, "the mdlc-mesh-import.so module", false};

bool IsUsable(const fs::path& file, const ReaderForm& form) {
  std::error_code ec;
  const int mode = form.executable ? X_OK : R_OK;
  return fs::is_regular_file(file, ec) && ::access(file.c_str(), mode) == 0;
}

/// The reader of the install prefix above `binary`: the binary may sit in
/// <prefix>/bin, <prefix>/lib, <prefix>/lib/<multiarch>, or (the Python
/// module) <prefix>/lib/python3/dist-packages/mdlc, so a few folders up are
/// tried.
std::string InstalledNextTo(const fs::path& binary, const ReaderForm& form) {
  std::error_code ec;
  fs::path dir = fs::weakly_canonical(binary, ec).parent_path();
  if (ec) return {};
  for (int up = 0; up < 5 && !dir.empty(); ++up, dir = dir.parent_path()) {
    const fs::path candidate = dir / form.install_path;
    if (IsUsable(candidate, form)) return candidate.string();
    if (dir == dir.root_path()) break;
  }
  return {};
}

MeshReaderLocation SearchNextToThisCode(const ReaderForm& form) {
  // the shared object this code is in (a shared library, the Python
  // module), then the program (mdlc, or a program linking mdlc statically)
  Dl_info info;
  if (::dladdr(reinterpret_cast<void*>(&FindMeshReader), &info) != 0 && info.dli_fname &&
      std::string_view(info.dli_fname).find('/') != std::string_view::npos) {
    if (std::string found = InstalledNextTo(info.dli_fname, form); !found.empty()) {
      return {found, {}};
    }
  }
  if (std::string found = InstalledNextTo("/proc/self/exe", form); !found.empty()) {
    return {found, {}};
  }
  if (const fs::path built = form.build_path; !built.empty() && IsUsable(built, form)) {
    return {built.string(), {}};
  }
  return {{}, fmt::format("{} was not found (set {} to its path)", form.what, form.variable)};
}

/// What $variable names, when it is set.
std::optional<MeshReaderLocation> Named(const ReaderForm& form) {
  const char* named = std::getenv(form.variable);
  if (!named || !*named) return std::nullopt;
  if (IsUsable(named, form)) return MeshReaderLocation{named, {}};
  const char* kind = form.executable ? "an executable" : "a readable";
  return MeshReaderLocation{
      {}, fmt::format("{} names '{}', which is not {} file", form.variable, named, kind)};
}

}  // namespace

MeshReaderLocation FindMeshReader() {
  if (auto named = Named(kProgram)) return *named;
  // where this code and the program are does not change while they run:
  // the folders are searched once per process (a score of system calls),
  // not once per compile
  static const MeshReaderLocation found = SearchNextToThisCode(kProgram);
  return found;
}

MeshReaderLocation FindMeshImportModule() {
  if (auto named = Named(kModule)) return *named;
  static const MeshReaderLocation found = SearchNextToThisCode(kModule);
  return found;
}

}  // namespace mdlc::mesh
