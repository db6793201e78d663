// stl_header.cc - see stl_header.h.
#include "backend/writers/stl_header.h"

namespace mdlc::writers {

std::optional<uint32_t> BinaryStlTriangleCount(std::string_view head, uint64_t file_size) {
  // 80 bytes of header, a little-endian count, 50 bytes per triangle; an
  // ASCII file ("solid ...") does not match that size
  if (head.size() < 84) return std::nullopt;
  uint32_t count = 0;
  for (int k = 3; k >= 0; --k) count = count << 8 | static_cast<unsigned char>(head[80 + k]);
  if (file_size != 84 + uint64_t{count} * 50) return std::nullopt;
  return count;
}

}  // namespace mdlc::writers
