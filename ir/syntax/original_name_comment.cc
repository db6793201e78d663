// original_name_comment.cc - see original_name_comment.h.
#include "ir/syntax/original_name_comment.h"

#include <fmt/format.h>

namespace mdlc::syntax {
namespace {

constexpr std::string_view kTag = "mdlc:name";

std::string Encode(std::string_view value) {
  std::string out;
  for (size_t i = 0; i < value.size(); ++i) {
    const char c = value[i];
    if (c == '%' || c == '"' || (c == '-' && i > 0 && value[i - 1] == '-')) {
      out += fmt::format("%{:02X}", static_cast<unsigned char>(c));
    } else {
      out += c;
    }
  }
  return out;
}

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

std::optional<std::string> Decode(std::string_view value) {
  std::string out;
  for (size_t i = 0; i < value.size(); ++i) {
    if (value[i] != '%') {
      out += value[i];
      continue;
    }
    if (i + 2 >= value.size()) return std::nullopt;
    const int hi = HexDigit(value[i + 1]), lo = HexDigit(value[i + 2]);
    if (hi < 0 || lo < 0) return std::nullopt;
    out += static_cast<char>(hi * 16 + lo);
    i += 2;
  }
  return out;
}

/// `key="value"` at the start of `text` (after spaces); advances past it.
std::optional<std::string> Field(std::string_view& text, std::string_view key) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  if (!text.starts_with(key) || text.substr(key.size()).substr(0, 2) != "=\"") {
    return std::nullopt;
  }
  text.remove_prefix(key.size() + 2);
  const size_t end = text.find('"');
  if (end == std::string_view::npos) return std::nullopt;
  auto value = Decode(text.substr(0, end));
  text.remove_prefix(end + 1);
  return value;
}

}  // namespace

std::string FormatOriginalNameComment(std::string_view model, std::string_view name) {
  return fmt::format("{} model=\"{}\" name=\"{}\"", kTag, Encode(model), Encode(name));
}

std::optional<ParsedOriginalName> ParseOriginalNameComment(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\n')) text.remove_prefix(1);
  if (!text.starts_with(kTag) || text.substr(kTag.size()).substr(0, 1) != " ") return std::nullopt;
  text.remove_prefix(kTag.size());
  auto model = Field(text, "model");
  if (!model) return std::nullopt;
  auto name = Field(text, "name");
  if (!name) return std::nullopt;
  while (!text.empty() && (text.back() == ' ' || text.back() == '\n')) text.remove_suffix(1);
  if (!text.empty()) return std::nullopt;
  return ParsedOriginalName{std::move(*model), std::move(*name)};
}

}  // namespace mdlc::syntax
