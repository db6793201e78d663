// ply_header.h - a check of a PLY file's header before assimp reads it.
// assimp's PLY reader does not return on some malformed headers (an
// `element` line without a count was found by fuzz_mesh), so mdlc rejects
// what no valid PLY file can hold first.
#pragma once

#include <optional>
#include <string>

namespace mdlc::mesh {

/// nullopt when `path` is not a PLY file or its header is well formed: it
/// ends (`end_header`) within the first 64 KiB, and each `element` line has
/// a name and a count that, in an ASCII file, does not exceed the file's
/// size. Otherwise what is wrong.
std::optional<std::string> CheckPlyHeader(const std::string& path);

}  // namespace mdlc::mesh
