// vtk_surface.cc - see vtk_surface.h.
#include "passes/mesh/vtk_surface.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>

namespace mdlc::mesh {
namespace {

constexpr int kVtkTetra = 10;

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

MeshOrError Error(const std::string& path, const std::string& why) {
  MeshOrError out;
  out.error = fmt::format("cannot read '{}' as a tetrahedral VTK mesh: {}", path, why);
  return out;
}

}  // namespace

bool IsVtk(const std::string& path) {
  const size_t dot = path.rfind('.');
  return dot != std::string::npos && Lower(path.substr(dot)) == ".vtk";
}

MeshOrError ReadVtkSurface(const std::string& path) {
  std::ifstream in(path);
  if (!in) return Error(path, "the file cannot be opened");
  std::string line;
  std::getline(in, line);  // # vtk DataFile Version x.y
  std::getline(in, line);  // title
  std::string word;
  in >> word;
  if (word != "ASCII") return Error(path, "only ASCII files are read");
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 4>> tets;
  std::vector<long> offsets, connectivity;  // version 5
  std::vector<int> types;
  while (in >> word) {
    if (word == "DATASET") {
      in >> word;
      if (word != "UNSTRUCTURED_GRID") return Error(path, "the dataset is not UNSTRUCTURED_GRID");
    } else if (word == "POINTS") {
      size_t n = 0;
      in >> n >> word;
      points.resize(n);
      for (auto& p : points) in >> p.x() >> p.y() >> p.z();
    } else if (word == "CELLS") {
      size_t n = 0, size = 0;
      in >> n >> size;
      // version 5 follows with OFFSETS and CONNECTIVITY; before, each cell
      // is its point count and points
      std::streampos at = in.tellg();
      std::string next;
      in >> next;
      if (next == "OFFSETS") {
        in >> word;
        offsets.resize(n);
        for (long& o : offsets) in >> o;
        in >> word >> word;  // CONNECTIVITY type
        connectivity.resize(size);
        for (long& c : connectivity) in >> c;
        continue;
      }
      in.seekg(at);
      for (size_t c = 0; c < n; ++c) {
        int count = 0;
        in >> count;
        std::vector<int> ids(count);
        for (int& id : ids) in >> id;
        if (count != 4) return Error(path, fmt::format("cell {} is not a tetrahedron", c));
        tets.push_back({ids[0], ids[1], ids[2], ids[3]});
      }
    } else if (word == "CELL_TYPES") {
      size_t n = 0;
      in >> n;
      types.resize(n);
      for (int& t : types) in >> t;
    } else if (word == "POINT_DATA" || word == "CELL_DATA" || word == "METADATA") {
      break;  // fields: not part of the shape
    }
    if (!in) return Error(path, fmt::format("malformed after '{}'", word));
  }
  for (size_t c = 0; c + 1 < offsets.size(); ++c) {
    if (offsets[c + 1] - offsets[c] != 4) {
      return Error(path, fmt::format("cell {} is not a tetrahedron", c));
    }
    const long* v = connectivity.data() + offsets[c];
    tets.push_back({int(v[0]), int(v[1]), int(v[2]), int(v[3])});
  }
  if (std::any_of(types.begin(), types.end(), [](int t) { return t != kVtkTetra; })) {
    return Error(path, "a cell is not a tetrahedron (type 10)");
  }
  if (tets.empty()) return Error(path, "it has no tetrahedra");
  for (const auto& t : tets) {
    for (int id : t) {
      if (id < 0 || size_t(id) >= points.size()) return Error(path, "a cell names no point");
    }
  }

  // each face of each tetrahedron, wound away from the vertex opposite it;
  // a face that two tetrahedra share is inside
  std::map<std::array<int, 3>, std::pair<Eigen::Vector3i, int>> faces;  // sorted -> face, uses
  for (const auto& t : tets) {
    for (int k = 0; k < 4; ++k) {
      Eigen::Vector3i f(t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]);
      const Eigen::Vector3d& a = points[f[0]];
      const Eigen::Vector3d n = (points[f[1]] - a).cross(points[f[2]] - a);
      if (n.dot(points[t[k]] - a) > 0) std::swap(f[1], f[2]);
      std::array<int, 3> key{f[0], f[1], f[2]};
      std::sort(key.begin(), key.end());
      auto& [face, uses] = faces[key];
      face = f;
      ++uses;
    }
  }
  auto mesh = std::make_shared<TriangleMesh>();
  std::vector<int> index(points.size(), -1);  // only the points the surface uses
  for (const auto& [key, entry] : faces) {
    if (entry.second != 1) continue;
    Eigen::Vector3i t;
    for (int k = 0; k < 3; ++k) {
      int& i = index[entry.first[k]];
      if (i < 0) {
        i = int(mesh->vertices.size());
        mesh->vertices.push_back(points[entry.first[k]]);
      }
      t[k] = i;
    }
    mesh->triangles.push_back(t);
  }
  MeshOrError out;
  out.mesh = std::move(mesh);
  return out;
}

}  // namespace mdlc::mesh
