// memory_stream.h - a text in memory, handed to libxml2's reader a piece at
// a time (xmlCtxtReadIO's read callback). xmlCtxtReadMemory would copy the
// whole buffer first; through this callback the parser holds a few
// kilobytes of it at a time. The benchmarks' SAX floor reads the same way.
//
// The text may come in two parts, read one after the other: a document
// whose XML declaration mdlc mends (xml_declaration.h) is read as the
// mended declaration, then the rest of the original text.
#pragma once

#include <algorithm>
#include <cstring>
#include <string_view>

namespace mdlc::xml {

struct MemoryStream {
  std::string_view rest;
  std::string_view then = {};  // read after `rest`
  static int Read(void* context, char* out, int size) {
    auto* self = static_cast<MemoryStream*>(context);
    if (self->rest.empty()) std::swap(self->rest, self->then);
    const size_t n = std::min(self->rest.size(), static_cast<size_t>(std::max(size, 0)));
    if (n == 0) return 0;  // at the end: an empty view may hold no pointer to copy from
    std::memcpy(out, self->rest.data(), n);
    self->rest.remove_prefix(n);
    return static_cast<int>(n);
  }
};

}  // namespace mdlc::xml
