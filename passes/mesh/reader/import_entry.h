// import_entry.h - the one function the import module (mdlc_mesh_import.cc)
// exports, as the opener (in_process_reader.cc) and the module both see it.
#pragma once

#include <cstddef>

/// Receives the answer: a mesh reply (mesh_wire.h) when the function returns
/// 0; otherwise a message saying what went wrong, with 2 when the request
/// was malformed and 3 when reading threw (out of memory). The bytes are
/// valid only during the call.
typedef void (*MdlcMeshImportSink)(void* context, const char* bytes, size_t size);

/// The exported name; a new version of the request or of the reply's
/// calling convention gets a new name, so that a module of another build is
/// refused when it is opened rather than misread.
#define MDLC_MESH_IMPORT_ENTRY mdlc_mesh_import_v2
#define MDLC_MESH_IMPORT_ENTRY_NAME "mdlc_mesh_import_v2"

/// int MDLC_MESH_IMPORT_ENTRY(int argc, const char* const* argv,
///                            MdlcMeshImportSink sink, void* context):
/// answers the request argv[0..argc) (mesh_wire.h) through `sink`.
typedef int (*MdlcMeshImportFunction)(int argc, const char* const* argv,
                                      MdlcMeshImportSink sink, void* context);
