#include "passes/mesh/import/assimp_loader.h"

#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <absl/container/flat_hash_map.h>
#include <assimp/Importer.hpp>
#include <fmt/format.h>

#include <array>
#include <bit>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>

#include "passes/mesh/import/ply_header.h"

namespace mdlc::mesh {
namespace {

/// A vertex position as the weld compares it: the bits of its coordinates,
/// with -0 taken as 0 (the two are the same position).
using PositionKey = std::array<uint64_t, 3>;
PositionKey KeyOf(const aiVector3D& p) {
  PositionKey key;
  for (int k = 0; k < 3; ++k) {
    const double c = p[k] == 0 ? 0.0 : double{p[k]};
    std::memcpy(&key[k], &c, sizeof c);
  }
  return key;
}
/// A hash of the three words, mixed inline: the generic hash of a byte
/// range and a memcmp per probe were most of the weld's time.
struct PositionHash {
  size_t operator()(const PositionKey& k) const {
    uint64_t h = k[0] * 0x9e3779b97f4a7c15ULL;
    h ^= std::rotl(k[1] * 0xc2b2ae3d27d4eb4fULL, 31);
    h ^= std::rotl(k[2] * 0x165667b19e3779f9ULL, 17);
    h ^= h >> 32;
    h *= 0xd6e8feb86659fd93ULL;
    return static_cast<size_t>(h ^ (h >> 29));
  }
};
struct PositionEqual {
  bool operator()(const PositionKey& a, const PositionKey& b) const {
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
  }
};
/// Vertex ids by position; a hash table, as a mesh file can hold millions.
using WeldIndex = absl::flat_hash_map<PositionKey, int, PositionHash, PositionEqual>;

/// The colour the file gives `material`: glTF's base colour, else the
/// diffuse colour with the material's opacity; nullopt for one without a
/// colour and for the materials assimp makes up for a file that names none:
/// "DefaultMaterial" (OBJ, STL, COLLADA) or an unnamed white one (glTF, PLY).
std::optional<Eigen::Vector4d> MaterialColor(const aiMaterial& material) {
  aiString name;
  material.Get(AI_MATKEY_NAME, name);
  if (std::strcmp(name.C_Str(), AI_DEFAULT_MATERIAL_NAME) == 0) return std::nullopt;
  aiColor4D color;
  if (material.Get(AI_MATKEY_BASE_COLOR, color) != AI_SUCCESS) {
    if (material.Get(AI_MATKEY_COLOR_DIFFUSE, color) != AI_SUCCESS) return std::nullopt;
    float opacity = 1;
    if (material.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS) color.a = opacity;
  }
  if (name.length == 0 && color == aiColor4D(1, 1, 1, 1)) return std::nullopt;
  // assimp holds floats: each channel as the shortest decimal that names
  // the float, which is what the file wrote (0.9, not 0.899999976)
  const auto decimal = [](float x) { return std::strtod(fmt::format("{}", x).c_str(), nullptr); };
  const Eigen::Vector4d rgba(decimal(color.r), decimal(color.g), decimal(color.b),
                             decimal(color.a));
  // files hold anything; the reply carries channels in [0, 1]
  return rgba.cwiseMax(0.0).cwiseMin(1.0);
}

/// Starts a colour run at the next triangle of `out` when the colour
/// changes. A mesh without a colour of the file's own gets a grey run (a
/// neighbour of coloured ones must not take their colour); runs are
/// dropped at the end when no mesh had a colour.
void AddColorRun(const std::optional<Eigen::Vector4d>& color, TriangleMesh& out) {
  static const Eigen::Vector4d kNoColor(0.7, 0.7, 0.72, 1);
  const Eigen::Vector4d rgba = color.value_or(kNoColor);
  if (!out.colors.empty() && out.colors.back().rgba == rgba) return;
  if (!out.colors.empty() && out.colors.back().first_triangle == out.triangles.size()) {
    out.colors.back().rgba = rgba;  // the previous run got no triangle
    return;
  }
  out.colors.push_back({out.triangles.size(), rgba});
}

/// Appends the triangles of `node` and its children, placed by the
/// accumulated node transform, welding vertices by exact position (ids in
/// the order positions first occur).
void Collect(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
             WeldIndex& index, TriangleMesh& out, bool& any_color) {
  const aiMatrix4x4 world = parent * node.mTransformation;
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const aiMesh& m = *scene.mMeshes[node.mMeshes[i]];
    std::optional<Eigen::Vector4d> color;
    if (m.mMaterialIndex < scene.mNumMaterials) {
      color = MaterialColor(*scene.mMaterials[m.mMaterialIndex]);
    }
    any_color |= color.has_value();
    AddColorRun(color, out);
    std::vector<int> ids(m.mNumVertices);
    for (unsigned v = 0; v < m.mNumVertices; ++v) {
      const aiVector3D p = world * m.mVertices[v];
      auto [it, inserted] = index.emplace(KeyOf(p), static_cast<int>(out.vertices.size()));
      if (inserted) out.vertices.emplace_back(p.x, p.y, p.z);
      ids[v] = it->second;
    }
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
      const aiFace& face = m.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines have no area
      out.triangles.emplace_back(ids[face.mIndices[0]], ids[face.mIndices[1]],
                                 ids[face.mIndices[2]]);
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    Collect(scene, *node.mChildren[c], world, index, out, any_color);
  }
}

/// The first face, if any, that names a vertex its mesh does not have.
std::optional<std::string> FindBadFace(const aiScene& scene) {
  for (unsigned i = 0; i < scene.mNumMeshes; ++i) {
    const aiMesh& m = *scene.mMeshes[i];
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
      const aiFace& face = m.mFaces[f];
      for (unsigned k = 0; k < face.mNumIndices; ++k) {
        if (face.mIndices[k] >= m.mNumVertices) {
          return fmt::format("face {} names vertex {}, but there are only {} vertices", f,
                             face.mIndices[k], m.mNumVertices);
        }
      }
    }
  }
  return std::nullopt;
}

std::string LowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

/// The up axis a COLLADA file declares, read from its start (its <asset>
/// comes first); Y, COLLADA's default, when the start cannot be read.
UpAxis ColladaFileUpAxis(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(16384, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return ColladaDeclaredUpAxis(head);
}

/// Which way is up in the file at `path`, and whether mdlc turns it to Z-up
/// (mesh_axes.h): glTF always, as Drake does; COLLADA when asked.
void ReadAxes(const std::string& path, const MeshAxes& axes, TriangleMesh& mesh) {
  const std::string ext = LowerExtension(path);
  if (ext == ".gltf" || ext == ".glb") {
    mesh.declared_up = UpAxis::kY;
    mesh.turned_to_z_up = true;
  } else if (IsCollada(path)) {
    mesh.declared_up = ColladaFileUpAxis(path);
    mesh.turned_to_z_up =
        axes.collada == ColladaUpAxis::kApply && mesh.declared_up != UpAxis::kZ;
  }
  if (!mesh.turned_to_z_up) return;
  const Eigen::Matrix3d R = RotationToZUp(mesh.declared_up);
  for (Eigen::Vector3d& v : mesh.vertices) v = R * v;
}

// assimp's reason for a failed read, as the tail of mdlc's message: its
// own full stop and line breaks dropped
std::string ImporterError(const Assimp::Importer& importer) {
  std::string error = importer.GetErrorString();
  while (!error.empty() && (error.back() == '.' || std::isspace(uint8_t(error.back())))) {
    error.pop_back();
  }
  return error.empty() ? "assimp gave no reason" : error;
}

}  // namespace

MeshOrError ImportMesh(const std::string& path, const Limits& limits, const MeshAxes& axes) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    return {nullptr, fmt::format("cannot read mesh file '{}'", path)};
  }
  if (const uint64_t size = std::filesystem::file_size(path, ec); !ec && size > limits.file_size) {
    return {nullptr,
            fmt::format("mesh file '{}' is {}, over the file-size limit of {} (raise it with "
                        "--limit file-size=BYTES)",
                        path, FormatBytes(size), FormatBytes(limits.file_size)),
            true};
  }
  if (auto problem = CheckPlyHeader(path)) {
    return {nullptr, fmt::format("cannot read mesh file '{}': {}", path, *problem)};
  }
  Assimp::Importer importer;
  // assimp turns a COLLADA file's Z_UP into Y_UP by rotating the scene;
  // mdlc decides the axes itself (ReadAxes), so assimp's turn never leaks
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  // read with no processing first: assimp's steps trust the faces' vertex
  // indices, and a file whose faces name vertices it does not have would
  // make them read out of bounds (found by fuzz_mesh)
  const aiScene* scene = importer.ReadFile(path, 0);
  if (!scene || !scene->mRootNode) {
    return {nullptr,
            fmt::format("cannot read mesh file '{}': {}", path, ImporterError(importer))};
  }
  if (auto problem = FindBadFace(*scene)) {
    return {nullptr, fmt::format("cannot read mesh file '{}': {}", path, *problem)};
  }
  // Triangulate polygons (quads, n-gons); no other processing: normals and
  // texture coordinates do not matter for geometry (materials give only
  // the colours the viewer draws).
  scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_SortByPType);
  if (!scene || !scene->mRootNode) {
    return {nullptr,
            fmt::format("cannot read mesh file '{}': {}", path, ImporterError(importer))};
  }
  uint64_t vertices = 0;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) vertices += scene->mMeshes[i]->mNumVertices;
  if (vertices > limits.mesh_vertices) {
    return {nullptr,
            fmt::format("mesh file '{}' has {} vertices, over the mesh-vertices limit of {} "
                        "(raise it with --limit mesh-vertices=N)",
                        path, vertices, limits.mesh_vertices),
            true};
  }
  auto mesh = std::make_shared<TriangleMesh>();
  WeldIndex index;
  index.reserve(vertices);
  mesh->vertices.reserve(vertices);
  bool any_color = false;
  Collect(*scene, *scene->mRootNode, aiMatrix4x4(), index, *mesh, any_color);
  if (mesh->triangles.empty() && mesh->vertices.empty()) {
    return {nullptr, fmt::format("mesh file '{}' holds no triangles", path)};
  }
  // points without triangles (an OBJ of `v` lines only) are a point cloud:
  // the reader's caller takes their convex hull, as MuJoCo does (point_cloud.h)
  // a run after the last triangle (a mesh of points or lines at the end)
  if (!mesh->colors.empty() && mesh->colors.back().first_triangle == mesh->triangles.size()) {
    mesh->colors.pop_back();
  }
  if (!any_color) mesh->colors.clear();
  ReadAxes(path, axes, *mesh);
  return {std::move(mesh), {}};
}

}  // namespace mdlc::mesh
