// source_manager.h - owns every buffer a compile reads and maps offsets to
// line and column.
//
// Buffers are never moved once loaded (each lives in its own heap block), so
// `std::string_view`s into them stay valid for the SourceManager's lifetime.
// The line table of a buffer is built lazily, the first time it is needed.
// Lookups remember the last line they found, so a SourceManager is for one
// thread at a time.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ir/location.h"

namespace mdlc {

class SourceManager {
 public:
  SourceManager();
  ~SourceManager();
  SourceManager(const SourceManager&) = delete;
  SourceManager& operator=(const SourceManager&) = delete;

  /// Reads `path` into a new buffer. Returns nullopt (and fills `error`, if
  /// given) when the file cannot be read. `included_from` records the include
  /// site for "in file included from" notes.
  std::optional<FileId> LoadFile(const std::string& path, Loc included_from = {},
                                 std::string* error = nullptr);

  /// Adds an in-memory buffer under a display name.
  FileId AddBuffer(std::string name, std::string contents, Loc included_from = {});

  std::string_view Contents(FileId id) const;
  const std::string& Path(FileId id) const;
  Loc IncludedFrom(FileId id) const;
  size_t FileCount() const;

  /// Location of a byte offset inside a buffer (1-based line and column).
  Loc LocForOffset(FileId id, size_t offset) const;
  /// Byte offset of the first character of a 1-based line.
  size_t LineStartOffset(FileId id, uint32_t line) const;
  /// The text of a 1-based line, without its newline.
  std::string_view LineText(FileId id, uint32_t line) const;

 private:
  struct Buffer;
  const Buffer& Get(FileId id) const;
  std::vector<std::unique_ptr<Buffer>> buffers_;
};

}  // namespace mdlc
