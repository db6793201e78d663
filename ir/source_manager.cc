#include "ir/source_manager.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

namespace mdlc {

struct SourceManager::Buffer {
  std::string path;
  std::string contents;
  Loc included_from;
  uint32_t include_depth = 0;
  // an expansion (AddExpansion): the file whose text it shows, where it was
  // expanded and how; its own path and contents stay empty
  FileId spelled_in;
  Loc expanded_at;
  std::string expansion_note;
  // an inclusion (AddInclusion): the spelled file's text with its own
  // included_from and include_depth
  bool is_inclusion = false;
  // offsets of the first byte of each line; built on first use
  mutable std::vector<size_t> line_starts;
  // the line of the last lookup: frontends ask in nearly increasing order
  mutable size_t last_line_index = 0;

  const std::vector<size_t>& LineStarts() const {
    if (line_starts.empty()) {
      line_starts.reserve(contents.size() / 32 + 1);
      line_starts.push_back(0);
      const char* data = contents.data();
      const char* end = data + contents.size();
      for (const char* p = data; (p = static_cast<const char*>(std::memchr(p, '\n', end - p)));) {
        ++p;
        line_starts.push_back(static_cast<size_t>(p - data));
      }
    }
    return line_starts;
  }
};

SourceManager::SourceManager() = default;
SourceManager::~SourceManager() = default;

namespace {

// `path` as diagnostics print it and relative references start from: without
// repeated separators, "." and "name/.." (models/a//model.sdf ->
// models/a/model.sdf), when that names the same file (a "name/.." through a
// symbolic link may not, and then the path stays as written).
std::string TidyPath(const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path written(path);
  const fs::path tidy = written.lexically_normal();
  if (tidy.empty() || tidy.native() == path) return path;
  std::error_code ec, ec2;
  if (path.find("..") != std::string::npos &&
      fs::weakly_canonical(written, ec) != fs::weakly_canonical(tidy, ec2)) {
    return path;
  }
  return tidy.string();
}

}  // namespace

std::optional<FileId> SourceManager::LoadFile(const std::string& written_path, Loc included_from,
                                              LoadError* error) {
  const std::string path = TidyPath(written_path);
  auto fail = [&](bool over_limit, std::string message) -> std::optional<FileId> {
    if (error) *error = {over_limit, std::move(message)};
    return std::nullopt;
  };
  const uint32_t depth = included_from.valid() ? IncludeDepth(included_from.file) + 1 : 0;
  if (depth > limits_.include_depth) {
    return fail(true, fmt::format("'{}' would be included {} files deep, over the include-depth "
                                  "limit of {} (raise it with --limit include-depth=N)",
                                  path, depth, limits_.include_depth));
  }
  // a FIFO or a device would be read forever; a folder is no model
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) return fail(false, std::strerror(ENOENT));
  if (!std::filesystem::is_regular_file(status)) return fail(false, "not a regular file");
  const uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) return fail(false, ec.message());
  if (size > limits_.file_size) {
    return fail(true, fmt::format("'{}' is {}, over the file-size limit of {} (raise it with "
                                  "--limit file-size=BYTES)",
                                  path, FormatBytes(size), FormatBytes(limits_.file_size)));
  }
  if (loaded_bytes_ + size > limits_.total_size) {
    return fail(true, fmt::format("reading '{}' would bring the model files of this compile to "
                                  "{}, over the total-size limit of {} (raise it with --limit "
                                  "total-size=BYTES)",
                                  path, FormatBytes(loaded_bytes_ + size),
                                  FormatBytes(limits_.total_size)));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(false, std::strerror(errno));
  std::string contents(size, '\0');
  in.read(contents.data(), static_cast<std::streamsize>(size));
  // the file may have changed since its size was taken: keep what was read
  contents.resize(static_cast<size_t>(in.gcount()));
  if (in.bad()) return fail(false, "read error");
  loaded_bytes_ += contents.size();
  return AddBuffer(path, std::move(contents), included_from);
}

FileId SourceManager::AddBuffer(std::string name, std::string contents, Loc included_from) {
  auto buffer = std::make_unique<Buffer>();
  buffer->path = std::move(name);
  buffer->contents = std::move(contents);
  buffer->included_from = included_from;
  buffer->include_depth = included_from.valid() ? IncludeDepth(included_from.file) + 1 : 0;
  buffers_.push_back(std::move(buffer));
  return FileId{static_cast<uint32_t>(buffers_.size() - 1)};
}

FileId SourceManager::AddExpansion(FileId spelled_in, Loc expanded_at, std::string note) {
  auto buffer = std::make_unique<Buffer>();
  buffer->spelled_in = SpellingFile(spelled_in);
  buffer->expanded_at = expanded_at;
  buffer->expansion_note = std::move(note);
  buffers_.push_back(std::move(buffer));
  return FileId{static_cast<uint32_t>(buffers_.size() - 1)};
}

std::optional<FileId> SourceManager::AddInclusion(FileId spelled_in, Loc included_from,
                                                  LoadError* error) {
  const uint32_t depth = included_from.valid() ? IncludeDepth(included_from.file) + 1 : 0;
  if (depth > limits_.include_depth) {
    if (error) {
      *error = {true, fmt::format("'{}' would be included {} files deep, over the include-depth "
                                  "limit of {} (raise it with --limit include-depth=N)",
                                  Path(spelled_in), depth, limits_.include_depth)};
    }
    return std::nullopt;
  }
  auto buffer = std::make_unique<Buffer>();
  buffer->spelled_in = SpellingFile(spelled_in);
  buffer->included_from = included_from;
  buffer->include_depth = depth;
  buffer->is_inclusion = true;
  buffers_.push_back(std::move(buffer));
  return FileId{static_cast<uint32_t>(buffers_.size() - 1)};
}

const SourceManager::Buffer& SourceManager::Entry(FileId id) const {
  return *buffers_.at(id.value);
}

const SourceManager::Buffer& SourceManager::Get(FileId id) const {
  const Buffer* entry = &Entry(id);
  while (entry->spelled_in.valid()) entry = &Entry(entry->spelled_in);
  return *entry;
}

// The entry that says where `id`'s text is included from: an inclusion, or
// the file an expansion's text is in.
const SourceManager::Buffer& SourceManager::Placement(FileId id) const {
  const Buffer* entry = &Entry(id);
  while (!entry->is_inclusion && entry->spelled_in.valid()) entry = &Entry(entry->spelled_in);
  return *entry;
}

bool SourceManager::IsExpansion(FileId id) const {
  const Buffer& entry = Entry(id);
  return entry.spelled_in.valid() && !entry.is_inclusion;
}
Loc SourceManager::ExpandedAt(FileId id) const { return Entry(id).expanded_at; }
const std::string& SourceManager::ExpansionNote(FileId id) const {
  return Entry(id).expansion_note;
}
FileId SourceManager::SpellingFile(FileId id) const {
  const Buffer& entry = Entry(id);
  return entry.spelled_in.valid() && !entry.is_inclusion ? entry.spelled_in : id;
}

std::string_view SourceManager::Contents(FileId id) const { return Get(id).contents; }
const std::string& SourceManager::Path(FileId id) const { return Get(id).path; }
// an expansion is included where its file is; an inclusion where it says
Loc SourceManager::IncludedFrom(FileId id) const { return Placement(id).included_from; }
uint32_t SourceManager::IncludeDepth(FileId id) const { return Placement(id).include_depth; }
size_t SourceManager::FileCount() const { return buffers_.size(); }

Loc SourceManager::LocForOffset(FileId id, size_t offset) const {
  const Buffer& buffer = Get(id);
  const auto& starts = buffer.LineStarts();
  auto on_line = [&](size_t i) {
    return i < starts.size() && starts[i] <= offset && (i + 1 == starts.size() || offset < starts[i + 1]);
  };
  // the same line as last time, or one of the next few; else a binary search
  size_t line_index = buffer.last_line_index;
  if (!on_line(line_index)) {
    size_t i = line_index + 1;
    const size_t limit = line_index + 4;
    while (i < limit && !on_line(i)) ++i;
    if (i < limit) {
      line_index = i;
    } else {
      auto it = std::upper_bound(starts.begin(), starts.end(), offset);
      line_index = static_cast<size_t>(it - starts.begin()) - 1;
    }
    buffer.last_line_index = line_index;
  }
  return Loc{id, static_cast<uint32_t>(line_index + 1),
             static_cast<uint32_t>(offset - starts[line_index] + 1)};
}

size_t SourceManager::LineStartOffset(FileId id, uint32_t line) const {
  const auto& starts = Get(id).LineStarts();
  if (line == 0 || line > starts.size()) return std::string::npos;
  return starts[line - 1];
}

std::string_view SourceManager::LineText(FileId id, uint32_t line) const {
  const Buffer& buffer = Get(id);
  const size_t start = LineStartOffset(id, line);
  if (start == std::string::npos) return {};
  std::string_view rest = std::string_view(buffer.contents).substr(start);
  const size_t end = rest.find('\n');
  std::string_view text = rest.substr(0, end);
  if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
  return text;
}

}  // namespace mdlc
