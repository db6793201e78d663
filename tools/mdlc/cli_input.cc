// cli_input.cc - see cli_input.h.
#include "cli_input.h"

#include <fmt/format.h>

#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include "ir/format.h"

namespace mdlc::cli {
namespace {

constexpr std::string_view kStdinName = "<stdin>";

/// The format of model text by its first element (or, for Model Directives,
/// its `directives:` key), as a user would tell it at a glance.
std::optional<Format> FormatFromContent(std::string_view text) {
  size_t at = 0;
  while ((at = text.find('<', at)) != std::string_view::npos) {
    const std::string_view rest = text.substr(at + 1);
    if (rest.starts_with('?') || rest.starts_with('!')) {  // declaration, comment
      ++at;
      continue;
    }
    return FormatFromRootElement(rest.substr(0, rest.find_first_of(" \t\r\n/>")));
  }
  if (text.find("directives:") != std::string_view::npos) return Format::Directives;
  return std::nullopt;
}

}  // namespace

bool IsInputFormatName(std::string_view name) {
  return name == "xacro" || FormatFromName(name).has_value();
}

std::optional<Input> InputFor(const std::string& file, const std::string& format_name,
                              std::string* problem) {
  const bool xacro = format_name == "xacro";
  const std::optional<Format> format =
      format_name.empty() || xacro ? std::nullopt : FormatFromName(format_name);
  if (file == "-") {
    // read once: a model on standard input is one input
    std::string text{std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>()};
    if (std::cin.bad()) {
      *problem = "cannot read the model from standard input";
      return std::nullopt;
    }
    // the frontend expands a buffer whose name ends in .xacro; relative
    // paths in the model are found from the current folder
    if (xacro) return Input::Text(std::move(text), std::string(kStdinName) + ".xacro");
    const std::optional<Format> named = format ? format : FormatFromContent(text);
    if (!named) {
      *problem = fmt::format(
          "the model on standard input has no root element mdlc knows "
          "(<robot>, <sdf>, <mujoco> or directives:); name its format with "
          "--format {}",
          kInputFormatNames);
      return std::nullopt;
    }
    return Input::Text(std::move(text), std::string(kStdinName), named);
  }
  if (xacro && !file.ends_with(".xacro")) {
    // the frontend tells a xacro file by its name: give the text one that
    // says so, in the same folder, so that its includes are found
    std::ifstream in(file, std::ios::binary);
    if (!in) {
      *problem = fmt::format("cannot read '{}'", file);
      return std::nullopt;
    }
    std::ostringstream text;
    text << in.rdbuf();
    return Input::Text(text.str(), file + ".xacro");
  }
  return Input::File(file, format);
}

}  // namespace mdlc::cli
