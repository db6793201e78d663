// reader_location.h - finds the two forms of the mesh reader (mesh_loader.h,
// issue 16): the program mdlc-mesh-reader, run in a child process, and the
// module mdlc-mesh-import.so, opened in this process when meshes are read
// here (in_process_reader.h).
#pragma once

#include <string>

namespace mdlc::mesh {

/// The environment variables that name the reader program and the import
/// module, overriding the search (tests point them at stand-ins; packagers
/// at their own layout).
inline constexpr const char* kMeshReaderVariable = "MDLC_MESH_READER";
inline constexpr const char* kMeshModuleVariable = "MDLC_MESH_MODULE";

struct MeshReaderLocation {
  std::string path;  // empty: none found
  std::string why_none;  // when none: why, for the user
};

/// The reader program: $MDLC_MESH_READER when set; else
/// <prefix>/libexec/mdlc/mdlc-mesh-reader of the installed prefix holding
/// the library, module or program this code is linked into; else the one
/// this source tree built. Only the variable is read anew at each call;
/// the folders are searched once per process.
MeshReaderLocation FindMeshReader();

/// The import module: $MDLC_MESH_MODULE when set; else
/// <prefix>/lib/mdlc/mdlc-mesh-import.so (the library folder the build was
/// installed with) of the installed prefix holding this code; else the one
/// this source tree built. Searched the same way as the program, with the
/// variable read anew at each call.
MeshReaderLocation FindMeshImportModule();

}  // namespace mdlc::mesh
