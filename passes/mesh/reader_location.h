// reader_location.h - finds the mesh reader program, mdlc-mesh-reader
// (mesh_loader.h, issue 16).
#pragma once

#include <string>

namespace mdlc::mesh {

/// The environment variable that names the reader program, overriding the
/// search (tests point it at stand-ins; packagers at their own layout).
inline constexpr const char* kMeshReaderVariable = "MDLC_MESH_READER";

struct MeshReaderLocation {
  std::string program;  // empty: none found
  std::string why_none;  // when none: why, for the user
};

/// The reader program: $MDLC_MESH_READER when set; else
/// <prefix>/libexec/mdlc/mdlc-mesh-reader of the installed prefix holding
/// the library, module or program this code is linked into; else the one
/// this source tree built. Only the variable is read anew at each call;
/// the folders are searched once per process.
MeshReaderLocation FindMeshReader();

}  // namespace mdlc::mesh
