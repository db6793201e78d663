// stl_header.h - what a binary STL file's header says, for deciding whether
// a target reads the file (MuJoCo reads binary STL of at most 200,000
// faces, mjcf_geometry.cc) without reading the mesh.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace mdlc::writers {

/// The number of triangles a binary STL file declares in its header; nullopt
/// when `head` (the file's first 84 bytes or more) is not one (ASCII STL), or
/// when the count does not fit `file_size`.
std::optional<uint32_t> BinaryStlTriangleCount(std::string_view head, uint64_t file_size);

}  // namespace mdlc::writers
