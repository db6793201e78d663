#include "passes/mesh/io/mesh_axes.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace mdlc::mesh {

bool IsCollada(std::string_view path) {
  if (path.size() < 4) return false;
  std::string ext(path.substr(path.size() - 4));
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".dae";
}

std::string_view UpAxisName(UpAxis up) {
  switch (up) {
    case UpAxis::kX: return "X_UP";
    case UpAxis::kY: return "Y_UP";
    case UpAxis::kZ: return "Z_UP";
    case UpAxis::kNone: break;
  }
  return "none";
}

std::optional<ColladaUpAxis> ColladaUpAxisFromName(std::string_view name) {
  if (name == "as-written") return ColladaUpAxis::kAsWritten;
  if (name == "apply") return ColladaUpAxis::kApply;
  return std::nullopt;
}

std::string_view ColladaUpAxisName(ColladaUpAxis mode) {
  return mode == ColladaUpAxis::kApply ? "apply" : "as-written";
}

Eigen::Matrix3d RotationToZUp(UpAxis up) {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  if (up == UpAxis::kY) {
    // right +x stays +x, up +y becomes +z, in +z becomes -y
    R << 1, 0, 0,
         0, 0, -1,
         0, 1, 0;
  } else if (up == UpAxis::kX) {
    // right -y becomes +x, up +x becomes +z, in +z becomes -y
    R << 0, -1, 0,
         0, 0, -1,
         1, 0, 0;
  }
  return R;
}

bool OffAxisColladaFiles::Add(const std::string& path, UpAxis declared, bool turned) {
  // glTF declares Y too, by its specification, and is always turned: no news
  if (!IsCollada(path) || (declared != UpAxis::kX && declared != UpAxis::kY)) return false;
  if (std::find(paths_.begin(), paths_.end(), path) != paths_.end()) return false;
  if (paths_.empty()) {
    first_declared_ = declared;
    first_turned_ = turned;
  }
  paths_.push_back(path);
  return true;
}

std::string OffAxisColladaFiles::Note() const {
  if (paths_.empty()) return "";
  const size_t more = paths_.size() - 1;
  const std::string others =
      more == 0 ? "" : fmt::format(" (as do {} more COLLADA file{})", more, more == 1 ? "" : "s");
  if (first_turned_) {
    return fmt::format("COLLADA mesh '{}' declares {}{}; turned to Z-up, as "
                       "--collada-up-axis=apply asks (RViz and Gazebo show such files as written)",
                       paths_.front(), UpAxisName(first_declared_), others);
  }
  return fmt::format("COLLADA mesh '{}' declares {}{}; its vertices are read as written, as RViz "
                     "and Gazebo show them (--collada-up-axis=apply turns such files to Z-up)",
                     paths_.front(), UpAxisName(first_declared_), others);
}

UpAxis ColladaDeclaredUpAxis(std::string_view head) {
  // only the document's own <asset>: a node's <asset> further on may declare
  // another axis, which (like assimp) mdlc does not read
  const size_t asset_end = head.find("</asset>");
  const std::string_view asset = head.substr(0, asset_end);
  const size_t open = asset.find("<up_axis>");
  if (open == std::string_view::npos) return UpAxis::kY;
  std::string_view value = asset.substr(open + 9);
  value = value.substr(0, value.find('<'));
  const size_t first = value.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return UpAxis::kY;
  value = value.substr(first, value.find_last_not_of(" \t\r\n") + 1 - first);
  if (value == "X_UP") return UpAxis::kX;
  if (value == "Z_UP") return UpAxis::kZ;
  return UpAxis::kY;
}

}  // namespace mdlc::mesh
