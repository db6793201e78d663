// ply_header.cc - see ply_header.h.
#include "passes/mesh/import/ply_header.h"

#include <fmt/format.h>

#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace mdlc::mesh {

std::optional<std::string> CheckPlyHeader(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(64 * 1024, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  if (!head.starts_with("ply\n") && !head.starts_with("ply\r\n")) return std::nullopt;
  std::error_code ec;
  const uintmax_t size = std::filesystem::file_size(path, ec);
  std::istringstream lines(head);
  bool ascii = false;
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    if (w.empty()) continue;
    if (w[0] == "end_header") return std::nullopt;
    if (w[0] == "format" && w.size() > 1) ascii = w[1] == "ascii";
    if (w[0] != "element") continue;
    uintmax_t count = 0;
    const bool number =
        w.size() == 3 &&
        std::from_chars(w[2].data(), w[2].data() + w[2].size(), count).ptr == w[2].data() + w[2].size();
    if (!number) return fmt::format("its PLY header line '{}' gives no element count", line);
    if (ascii && !ec && count > size) {
      return fmt::format("its PLY header declares {} '{}' elements, more than a file of {} bytes "
                         "can hold",
                         count, w[1], size);
    }
  }
  return "its PLY header does not end (no end_header in the first 64 KiB)";
}

}  // namespace mdlc::mesh
