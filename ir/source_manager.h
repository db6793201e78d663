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

#include "ir/limits.h"
#include "ir/location.h"

namespace mdlc {

/// Why LoadFile failed: the file could not be read, or it is over one of
/// the input limits (ir/limits.h), which callers report as limit-exceeded.
struct LoadError {
  bool over_limit = false;
  std::string message;
};

class SourceManager {
 public:
  SourceManager();
  ~SourceManager();
  SourceManager(const SourceManager&) = delete;
  SourceManager& operator=(const SourceManager&) = delete;

  /// Reads `path` into a new buffer. Returns nullopt (and fills `error`, if
  /// given) when the file cannot be read, is not a regular file, or would
  /// pass the file-size, total-size or include-depth limit. `included_from`
  /// records the include site for "in file included from" notes.
  std::optional<FileId> LoadFile(const std::string& path, Loc included_from = {},
                                 LoadError* error = nullptr);

  /// The limits LoadFile holds files to, and the XML reader documents to.
  const Limits& limits() const { return limits_; }
  void set_limits(const Limits& limits) { limits_ = limits; }
  /// How many files deep `id` is included: 0 for a file nothing included.
  uint32_t IncludeDepth(FileId id) const;

  /// Adds an in-memory buffer under a display name.
  FileId AddBuffer(std::string name, std::string contents, Loc included_from = {});

  /// A file id for text of `spelled_in` that a macro expansion placed
  /// elsewhere (clang's expansion locations): a Loc in it names the line and
  /// column where the text is written, and the id remembers where it was
  /// expanded and how (`note`, e.g. "in expansion of macro 'arm'"), so a
  /// diagnostic about expanded text can say both. Path, contents and lines
  /// are those of `spelled_in`.
  FileId AddExpansion(FileId spelled_in, Loc expanded_at, std::string note);
  /// A file id for `spelled_in`'s text read again from another place (a
  /// file included many times): its own "included from" place, the text,
  /// path and lines of `spelled_in`, nothing read or counted again. Fails
  /// like LoadFile when it would pass the include-depth limit.
  std::optional<FileId> AddInclusion(FileId spelled_in, Loc included_from,
                                     LoadError* error = nullptr);
  bool IsExpansion(FileId id) const;
  /// Where an expansion id's text was expanded; invalid for a file.
  Loc ExpandedAt(FileId id) const;
  const std::string& ExpansionNote(FileId id) const;
  /// The file whose text `id` shows: `id` itself unless it is an expansion.
  FileId SpellingFile(FileId id) const;

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
  // the buffer holding the text of `id` (an expansion's spelling file)
  const Buffer& Get(FileId id) const;
  // the entry of `id` itself
  const Buffer& Entry(FileId id) const;
  // the entry that places `id` (see IncludedFrom)
  const Buffer& Placement(FileId id) const;
  std::vector<std::unique_ptr<Buffer>> buffers_;
  Limits limits_;
  uint64_t loaded_bytes_ = 0;  // by LoadFile, against limits_.total_size
};

}  // namespace mdlc
