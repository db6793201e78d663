// location.h - where in the source an IR entity or diagnostic comes from.
//
// A Loc is a (file, line, column) triple, 1-based; 0 means "unknown" for line
// and column, and an invalid FileId means "no file" (e.g. command-line input).
#pragma once

#include <cstdint>

namespace mdlc {

/// Index of a buffer owned by the SourceManager.
struct FileId {
  uint32_t value = UINT32_MAX;
  bool valid() const { return value != UINT32_MAX; }
  friend bool operator==(FileId, FileId) = default;
};

struct Loc {
  FileId file;
  uint32_t line = 0;    // 1-based; 0 = unknown
  uint32_t column = 0;  // 1-based; 0 = unknown
  bool valid() const { return file.valid(); }
  friend bool operator==(const Loc&, const Loc&) = default;
};

}  // namespace mdlc
