// mjcf_geometry.cc - the MJCF writer's geometry: <mesh> assets, <geom> with
// its shape, appearance and friction, frames as <site> and cameras as
// <camera> (mjcf_writer_detail.h).
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <variant>

#include "backend/writers/mjcf_writer_detail.h"
#include "ir/overloaded.h"
#include "backend/writers/stl_header.h"

namespace mdlc::writers::mjcf {
namespace {

// MuJoCo 3.3.8 reads binary STL (up to 200000 faces), OBJ and MSH meshes
constexpr uint32_t kMujocoMaxStlFaces = 200000;

std::string WhyMujocoCannotRead(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".obj" || ext == ".msh") return "";
  if (ext != ".stl") return "MuJoCo reads STL, OBJ and MSH meshes only";
  std::ifstream in(file, std::ios::binary);
  std::string head(84, '\0');
  in.read(head.data(), head.size());
  head.resize(in.gcount());
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  const auto faces = ec ? std::nullopt : BinaryStlTriangleCount(head, size);
  if (!faces) return "MuJoCo reads binary STL only, and this one is ASCII";
  if (*faces > kMujocoMaxStlFaces) {
    return fmt::format("MuJoCo reads at most {} faces from an STL file and it has {}",
                       kMujocoMaxStlFaces, *faces);
  }
  return "";
}

constexpr MeshTarget kMujoco{"MuJoCo", WhyMujocoCannotRead};

}  // namespace

void MjcfWriter::WriteMeshAssets() {
  bool open = false;
  std::map<std::pair<std::string, std::string>, std::string> assets;  // (file, scale) -> name
  std::map<std::pair<std::string, std::string>, std::string> inline_assets;  // (key, scale) -> name
  for (size_t i = 0; i < scene_.geometries.size(); ++i) {
    const backend::SceneGeometry& g = scene_.geometries[i];
    const Loc loc = GeometryLoc(i);
    const auto* mesh = std::get_if<ir::Mesh>(&g.shape);
    if (!mesh) continue;
    if (mesh->inline_data) {
      WriteInlineMesh(i, *mesh, inline_assets, &open);
      continue;
    }
    const std::optional<std::string> file = assets_.NameMesh(
        mesh->uri, mesh->resolved, mesh->uri_loc.valid() ? mesh->uri_loc : loc, kMujoco);
    if (auto why = assets_.UnconvertibleMesh(mesh->resolved)) {
      unconvertible_meshes_[i] = *why;
      continue;
    }
    const std::string scale =
        mesh->scale != Eigen::Vector3d::Ones() ? VectorText(mesh->scale) : std::string();
    auto [it, added] =
        assets.emplace(std::pair(file.value_or(""), scale), fmt::format("mesh{}", i));
    mesh_names_[i] = it->second;
    if (!added) continue;
    if (!open) out_.Open("asset");
    open = true;
    out_.Open("mesh").Attr("name", it->second);
    if (file) out_.Attr("file", *file);
    if (!scale.empty()) out_.Attr("scale", scale);
    out_.Close();
  }
  if (open) out_.Close();
}

// A mesh the source holds in its file (MJCF vertex and face lists) is written
// back the same way: its vertices in the mesh frame (the source's refpos and
// refquat already applied), its faces, or none for a point cloud, whose
// convex hull MuJoCo takes as mdlc does.
void MjcfWriter::WriteInlineMesh(size_t index, const ir::Mesh& mesh,
                                 std::map<std::pair<std::string, std::string>, std::string>& assets,
                                 bool* open) {
  const std::string scale =
      mesh.scale != Eigen::Vector3d::Ones() ? VectorText(mesh.scale) : std::string();
  auto [it, added] = assets.emplace(std::pair(mesh.resolved, scale), fmt::format("mesh{}", index));
  mesh_names_[index] = it->second;
  if (!added) return;
  if (!*open) out_.Open("asset");
  *open = true;
  std::string vertex, face;
  for (const Eigen::Vector3d& v : mesh.inline_data->vertices) {
    if (!vertex.empty()) vertex += "  ";
    vertex += VectorText(v);
  }
  for (const Eigen::Vector3i& f : mesh.inline_data->faces) {
    if (!face.empty()) face += "  ";
    face += fmt::format("{} {} {}", f[0], f[1], f[2]);
  }
  out_.Open("mesh").Attr("name", it->second).Attr("vertex", vertex);
  if (!face.empty()) out_.Attr("face", face);
  if (!scale.empty()) out_.Attr("scale", scale);
  out_.Close();
}

void MjcfWriter::WriteGeometries(BodyId body) {
  for (uint32_t i : Owned(geometries_by_body_, body)) {
    WriteGeometry(i, scene_.geometries[i], GeometryLoc(i));
  }
}

void MjcfWriter::WriteGeometry(size_t index, const backend::SceneGeometry& g, Loc loc) {
  const bool visual = g.roles & (ir::kIllustrationRole | ir::kPerceptionRole);
  const bool collision = g.roles & ir::kProximityRole;
  if (!visual && !collision) return;
  if (auto it = unconvertible_meshes_.find(index); it != unconvertible_meshes_.end()) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("geometry '{}' is dropped: MuJoCo cannot read its mesh '{}', "
                              "and mdlc cannot write it as OBJ ({})",
                              g.name, std::get<ir::Mesh>(g.shape).uri, it->second));
    return;
  }
  if (visual && (g.roles & (ir::kIllustrationRole | ir::kPerceptionRole)) !=
                    (ir::kIllustrationRole | ir::kPerceptionRole)) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("geometry '{}' has only the {} role; an MJCF visual geom has "
                              "both illustration and perception",
                              g.name,
                              (g.roles & ir::kIllustrationRole) ? "illustration"
                                                                : "perception"));
  }
  out_.Open("geom");
  std::string name;
  if (!g.unnamed) out_.Attr("name", name = geom_names_.TakeUnique(Named(g.model, g.name)));
  std::visit(ir::Overloaded{
                 [&](const ir::Box& s) {
                   out_.Attr("type", "box").Attr("size", Eigen::Vector3d(s.size / 2));
                 },
                 [&](const ir::Sphere& s) {
                   out_.Attr("type", "sphere").Attr("size", PositiveSize(g, s.radius, loc));
                 },
                 [&](const ir::Cylinder& s) {
                   out_.Attr("type", "cylinder")
                       .Attr("size", VectorText(Eigen::Vector2d(s.radius, s.length / 2)));
                 },
                 [&](const ir::Capsule& s) {
                   out_.Attr("type", "capsule")
                       .Attr("size", VectorText(Eigen::Vector2d(s.radius, s.length / 2)));
                 },
                 [&](const ir::Ellipsoid& s) {
                   out_.Attr("type", "ellipsoid")
                       .Attr("size", Eigen::Vector3d(s.a, s.b, s.c));
                 },
                 // MuJoCo's plane is infinite; its size only draws it
                 [&](const ir::HalfSpace&) {
                   out_.Attr("type", "plane").Attr("size", "0 0 1");
                 },
                 [&](const ir::Mesh& s) {
                   out_.Attr("type", "mesh").Attr("mesh", mesh_names_[index]);
                   if (s.convex && collision) ConvexLoss(g, loc);
                 },
             },
             g.shape);
  Pose(InWrittenLink(g.body, g.X_BG));
  if (!collision) out_.Attr("contype", "0").Attr("conaffinity", "0");
  if (!visual) out_.Attr("group", "3");  // mdlc and Drake: no visual for group > 2
  if (visual) Appearance(g, loc);
  if (collision) Friction(g, loc);
  if (!g.unnamed) OriginalName(g.model, g.name, name);
  out_.Close();
}

void MjcfWriter::ConvexLoss(const backend::SceneGeometry& g, Loc loc) {
  diags_.Report(DiagKind::Lossy, loc,
                fmt::format("the convex declaration of mesh geometry '{}' is dropped: MuJoCo "
                            "collides with every mesh's convex hull, as declared, but MJCF "
                            "has no flag for it, so the written geom reads back as a plain "
                            "mesh",
                            g.name));
}

double MjcfWriter::PositiveSize(const backend::SceneGeometry& g, double size, Loc loc) {
  if (size > 0) return size;
  diags_.Report(DiagKind::Lossy, loc,
                fmt::format("geometry '{}' has size {}; MJCF needs a positive size, so {} "
                            "is written",
                            g.name, size, std::numeric_limits<double>::min()));
  return std::numeric_limits<double>::min();
}

void MjcfWriter::Appearance(const backend::SceneGeometry& g, Loc loc) {
  if (const ir::Property* diffuse = FindProperty(g, "phong/diffuse")) {
    if (const auto* rgba = std::get_if<std::vector<double>>(&diffuse->value);
        rgba && rgba->size() == 4) {
      out_.Attr("rgba", VectorText(Eigen::Map<const Eigen::Vector4d>(rgba->data())));
    }
  }
  for (const ir::Property& p : g.properties) {
    if (p.key == "phong/diffuse" || !IsAppearanceProperty(p)) continue;
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("illustration property '{}' of geometry '{}' is not written "
                              "(the MJCF writer writes a geom's rgba only)",
                              p.key, g.name));
  }
}

void MjcfWriter::Friction(const backend::SceneGeometry& g, Loc loc) {
  for (const ir::Property& p : g.properties) {
    if (IsAppearanceProperty(p)) continue;
    const auto* v = std::get_if<std::vector<double>>(&p.value);
    if (p.key == "material/coulomb_friction" && v && v->size() == 2) {
      out_.Attr("friction", (*v)[0]);
      if ((*v)[1] != (*v)[0]) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("geometry '{}' has static friction {} and dynamic {}; "
                                  "MJCF's sliding friction is one, so the static one is "
                                  "written",
                                  g.name, (*v)[0], (*v)[1]));
      }
      continue;
    }
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("proximity property '{}' of geometry '{}' has no MJCF "
                              "spelling; it is dropped",
                              p.key, g.name));
  }
}

void MjcfWriter::WriteSites(BodyId body) {
  for (uint32_t f : Owned(frames_by_body_, body)) {
    const backend::PlantFrame& frame = plant_.frames[f];
    if (frame.unnamed) continue;
    const std::string name = site_names_.TakeUnique(Named(frame.model, frame.name));
    out_.Open("site").Attr("name", name);
    Pose(InWrittenLink(frame.body, frame.X_BF));
    OriginalName(frame.model, frame.name, name);
    out_.Close();
  }
  for (BodyId fused : layout_.fused[body.index()]) {
    out_.Open("site").Attr("name", fused_site_names_.at(fused.index()));
    Pose(InWrittenLink(fused, Transform()));
    out_.Close();
  }
  for (const auto& [name, p_LP] : extra_sites_[body.index()]) {
    out_.Open("site").Attr("name", name);
    Pose(p_LP);
    out_.Close();
  }
}

void MjcfWriter::WriteCameras(BodyId body) {
  for (uint32_t i : Owned(cameras_by_body_, body)) {
    const backend::SceneCamera& c = scene_.cameras[i];
    // Drake's camera looks along +z with +y down; MuJoCo's along -z with
    // +y up: a half turn about x between the two
    const Eigen::Matrix3d flip = Eigen::Vector3d(1, -1, -1).asDiagonal();
    out_.Open("camera");
    std::string name;
    if (!c.unnamed) out_.Attr("name", name = camera_names_.TakeUnique(Named(c.model, c.name)));
    Pose(InWrittenLink(c.body, c.X_BC * Transform::FromRotation(flip)));
    out_.Attr("fovy", c.fov_y * 180.0 / M_PI);
    out_.Attr("resolution", fmt::format("{} {}", c.width, c.height));
    // the reader names a camera "model/camera"
    if (!c.unnamed) OriginalName(c.model, c.name, names_.model_name() + "/" + name);
    out_.Close();
  }
}

}  // namespace mdlc::writers::mjcf
