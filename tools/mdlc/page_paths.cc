// page_paths.cc - paths relative to the model's folder (page_paths.h).
#include "page_paths.h"

#include <algorithm>
#include <filesystem>

namespace mdlc::tools {
namespace fs = std::filesystem;

namespace {

std::string Absolute(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::absolute(path.empty() ? "." : path, ec);
  return (ec ? fs::path(path) : p).lexically_normal().string();
}

void ReplaceAll(std::string& text, const std::string& from, const std::string& to) {
  if (from.empty()) return;
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
}

}  // namespace

PagePaths::PagePaths(const std::string& model_file) {
  const bool named = !model_file.empty() && model_file != "-";
  base_ = named ? fs::path(Absolute(model_file)).parent_path().string() : Absolute(".");
  if (base_.empty() || base_.back() != '/') base_ += '/';
}

std::string PagePaths::Show(const std::string& path) const {
  if (path.empty()) return path;
  const std::string absolute = Absolute(path);
  if (absolute.starts_with(base_)) return absolute.substr(base_.size());
  return fs::path(absolute).filename().string();
}

std::string PagePaths::Scrub(std::string text, const std::vector<std::string>& paths) const {
  // longest first, so that no path is cut by a shorter one it starts with
  std::vector<std::string> sorted = paths;
  std::sort(sorted.begin(), sorted.end(),
            [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
  for (const std::string& path : sorted) {
    ReplaceAll(text, path, Show(path));
    ReplaceAll(text, Absolute(path), Show(path));
  }
  ReplaceAll(text, base_, "");
  return text;
}

}  // namespace mdlc::tools
