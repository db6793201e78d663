// json_writer.h - a small streaming JSON writer with byte-exact output.
//
// The caller emits keys and values in the order it wants them printed; the
// writer adds commas, quotes and escapes. Contract:
// - strings are escaped per RFC 8259 (", \, control characters); bytes that
//   are not valid UTF-8 become U+FFFD, so the output is always valid JSON;
// - doubles print as the shortest text that round-trips (fmt "{}"), -0 as
//   0, and NaN or infinities as null;
// - containers opened at nesting depth < `pretty_depth` put each element on
//   its own line, indented two spaces per level; deeper ones are compact
//   (`[1,2]`, `{"a":1}`), so big dumps stay line-oriented and diffable;
//   Layout::Compact keeps a shallow container on one line all the same.
// Misuse (a value where a key is due, unbalanced End*) is a programming
// error and is not diagnosed.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace mdlc::backend {

class JsonWriter {
 public:
  enum class Layout { ByDepth, Compact };

  explicit JsonWriter(int pretty_depth = 0) : pretty_depth_(pretty_depth) {}

  JsonWriter& BeginObject(Layout layout = Layout::ByDepth);
  JsonWriter& EndObject();
  JsonWriter& BeginArray(Layout layout = Layout::ByDepth);
  JsonWriter& EndArray();
  JsonWriter& Key(std::string_view key);

  JsonWriter& String(std::string_view value);
  JsonWriter& Number(double value);
  JsonWriter& Int(int64_t value);
  JsonWriter& Bool(bool value);
  JsonWriter& Null();

  /// The document so far (complete once every container is closed).
  const std::string& str() const { return out_; }
  std::string Take() { return std::move(out_); }

 private:
  void BeforeValue();
  void Open(char bracket, Layout layout);
  void Close(char bracket);
  void Indent(size_t depth);

  struct Level {
    bool pretty;
    bool empty = true;
  };
  int pretty_depth_;
  std::vector<Level> stack_;
  bool after_key_ = false;
  std::string out_;
};

/// Appends `text` as a quoted JSON string to `out`.
void AppendJsonString(std::string& out, std::string_view text);

}  // namespace mdlc::backend
