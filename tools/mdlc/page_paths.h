// page_paths.h - file paths as the page `mdlc view` writes shows them: the
// page is a file people pass around, so it names files relative to the
// model's folder and never by an absolute path of the machine it was made on.
#pragma once

#include <string>
#include <vector>

namespace mdlc::tools {

class PagePaths {
 public:
  /// Paths are shown relative to the folder of `model_file` (the first file
  /// on the command line; the current folder for "-" or an empty name).
  explicit PagePaths(const std::string& model_file);

  /// `path` relative to the model's folder when it lies inside it, else its
  /// file name alone.
  std::string Show(const std::string& path) const;

  /// `text` (a note, an error message) with each of `paths`, and the model's
  /// folder, written as Show() writes them.
  std::string Scrub(std::string text, const std::vector<std::string>& paths) const;

 private:
  std::string base_;  // the model's folder, absolute and normal, ending in '/'
};

}  // namespace mdlc::tools
