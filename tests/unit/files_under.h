// files_under.h - the text of every file under some folders, for the tests
// that hold a reader to an oracle on every model file there is.
#pragma once

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace mdlc::testing {

/// Calls f(path, text) for each regular file under `roots` (folders that
/// do not exist are skipped) whose extension is one of `extensions`.
template <typename F>
void ForEachFileUnder(const std::vector<std::filesystem::path>& roots,
                      std::initializer_list<std::string_view> extensions, F&& f) {
  namespace fs = std::filesystem;
  for (const fs::path& root : roots) {
    if (!fs::exists(root)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      if (!entry.is_regular_file()) continue;
      const std::string ext = entry.path().extension().string();
      bool wanted = false;
      for (std::string_view e : extensions) wanted = wanted || ext == e;
      if (!wanted) continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::stringstream text;
      text << in.rdbuf();
      f(entry.path().string(), text.str());
    }
  }
}

}  // namespace mdlc::testing
