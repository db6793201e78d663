// mjcf_assets.cc - <asset>: meshes and materials (MJCF-006, MJCF-050,
// BEYOND-001). Textures, height fields and skins have no place in the plant.
//
// A mesh may be any format assimp reads (BEYOND-001); the mesh passes load
// it later. Here it only gets its name (default: the file's stem), its
// path by MuJoCo's rule, its scale and its inertia mode; the resolve-assets
// pass checks that the file exists where the plant needs it.
//
// A mesh may also be written in the file (vertex, face, normal, texcoord),
// as MuJoCo 3.3.8 reads it: its vertices and faces travel in the IR
// (ir::InlineMesh) and the mesh passes take them from memory, the convex
// hull of the points when there are no faces (passes/mesh/point_cloud.h).
// A mesh made by a plugin or a builtin shape is left out with a warning;
// a geom naming it says so once and is left out too.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>

#include "frontend/mjcf/mjcf_reader_detail.h"

namespace mdlc::frontend::mjcf {
namespace {
namespace fs = std::filesystem;

/// A list of numbers written on the mesh itself (vertex, face, normal,
/// texcoord); nullopt after an error at the attribute.
std::optional<std::vector<double>> List(MjcfReader& r, const xml::XmlAttribute& a,
                                        std::string_view mesh) {
  auto values = xml::ParseDoubleList(a.value);
  if (!values) {
    r.diags().Report(DiagKind::BadValue, a.loc,
                     fmt::format("mesh '{}': {} must be a list of numbers", mesh, a.name));
  }
  return values;
}

/// An inline mesh (<mesh vertex="..." face="...">) as MuJoCo 3.3.8 takes it:
/// vertices in single precision, a multiple of 3 numbers, all finite, at
/// least 4 of them; faces a multiple of 3 indices of existing vertices (none:
/// the mesh is the convex hull of the points, taken by the mesh passes);
/// normals and texture coordinates checked as MuJoCo checks them, then
/// unused (the plant does not draw); refpos and refquat applied to the
/// vertices (v' = R(refquat)^T (v - refpos)), scale left to the mesh passes
/// as for a file. Every problem is an error, as MuJoCo refuses the model.
std::shared_ptr<ir::InlineMesh> ReadInlineMesh(MjcfReader& r, const xml::XmlElement& e,
                                               const Element& m, std::string_view name) {
  const xml::XmlAttribute vertex = e.Attribute("vertex");
  auto error = [&](Loc loc, std::string message) {
    r.diags().Report(DiagKind::BadValue, loc, fmt::format("mesh '{}': {}", name, message));
    return nullptr;
  };
  const auto v = List(r, vertex, name);
  if (!v) return nullptr;
  if (v->size() % 3 != 0) {
    return error(vertex.loc, fmt::format("vertex holds {} numbers, not a multiple of 3",
                                         v->size()));
  }
  auto mesh = std::make_shared<ir::InlineMesh>();
  for (size_t i = 0; i < v->size(); i += 3) {
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k) {
      const double x = (*v)[i + k];
      if (!std::isfinite(x) || std::abs(x) > std::numeric_limits<float>::max()) {
        return error(vertex.loc, fmt::format("vertex {} has a coordinate that is not a finite "
                                             "number ({})",
                                             i / 3, x));
      }
      p[k] = static_cast<float>(x);  // MuJoCo keeps mesh vertices as floats
    }
    mesh->vertices.push_back(p);
  }
  if (mesh->vertices.size() < 4) {
    return error(vertex.loc, fmt::format("vertex gives {} vertices; a mesh needs at least 4",
                                         mesh->vertices.size()));
  }
  if (const xml::XmlAttribute face = e.Attribute("face"); face.present()) {
    const auto f = List(r, face, name);
    if (!f) return nullptr;
    if (f->size() % 3 != 0) {
      return error(face.loc,
                   fmt::format("face holds {} indices, not a multiple of 3", f->size()));
    }
    const size_t n = mesh->vertices.size();
    for (size_t i = 0; i < f->size(); i += 3) {
      Eigen::Vector3i t;
      for (int k = 0; k < 3; ++k) {
        const double x = (*f)[i + k];
        if (x != std::floor(x) || x < 0 || x >= static_cast<double>(n)) {
          return error(face.loc, fmt::format("face {} names vertex {}, but the vertices are "
                                             "numbered 0 to {}",
                                             i / 3, x, n - 1));
        }
        t[k] = static_cast<int>(x);
      }
      mesh->faces.push_back(t);
    }
  }
  if (const xml::XmlAttribute normal = e.Attribute("normal"); normal.present()) {
    const auto nv = List(r, normal, name);
    if (!nv) return nullptr;
    if (nv->size() % 3 != 0) {
      return error(normal.loc,
                   fmt::format("normal holds {} numbers, not a multiple of 3", nv->size()));
    }
  }
  if (const xml::XmlAttribute texcoord = e.Attribute("texcoord"); texcoord.present()) {
    const auto tv = List(r, texcoord, name);
    if (!tv) return nullptr;
    if (tv->size() != 2 * mesh->vertices.size()) {
      return error(texcoord.loc,
                   fmt::format("texcoord holds {} numbers; with no face texture coordinates it "
                               "needs 2 per vertex, {}",
                               tv->size(), 2 * mesh->vertices.size()));
    }
  }
  // the mesh frame MuJoCo places the vertices in: refpos, then refquat
  Eigen::Vector3d refpos = Eigen::Vector3d::Zero();
  if (m.Get("refpos").present()) {
    auto p = r.Numbers(m, "refpos", 3);
    if (!p) return nullptr;
    refpos = Eigen::Vector3d((*p)[0], (*p)[1], (*p)[2]);
  }
  Eigen::Matrix3d R_T = Eigen::Matrix3d::Identity();
  if (m.Get("refquat").present()) {
    auto q = r.Numbers(m, "refquat", 4);
    if (!q) return nullptr;
    Eigen::Quaterniond quat((*q)[0], (*q)[1], (*q)[2], (*q)[3]);
    if (quat.norm() < 1e-15) return error(m.Get("refquat").loc, "refquat is zero");
    R_T = quat.normalized().toRotationMatrix().transpose();
  }
  for (Eigen::Vector3d& p : mesh->vertices) p = R_T * (p - refpos);
  return mesh;
}

/// A mesh mdlc keeps no geometry for: said once at the mesh; the geoms that
/// name it say it again, once (mjcf_geom.cc).
void LeaveOut(MjcfReader& r, const xml::XmlElement& e, std::string name, std::string why,
              std::string_view warning) {
  r.diags().Report(DiagKind::UnsupportedElement, e.GetLoc(),
                   fmt::format("mesh '{}' {}; the mesh is left out", name, warning));
  if (name.empty() || r.meshes.count(name)) return;
  MeshAsset asset;
  asset.name = name;
  asset.loc = e.GetLoc();
  asset.left_out = std::move(why);
  r.meshes.emplace(std::move(name), std::move(asset));
}

void ReadMesh(MjcfReader& r, const xml::XmlElement& e) {
  r.CheckAttributes(e, "mesh");
  // meshes take defaults from their class, but have no childclass
  const Element m = r.Resolve(e, "mesh", "");
  const xml::XmlAttribute file = e.Attribute("file");
  const xml::XmlAttribute vertex = e.Attribute("vertex");
  const xml::XmlAttribute name_attr = e.Attribute("name");
  const bool inline_mesh = !file.present() && vertex.present();
  for (std::string_view a : {"smoothnormal", "maxhullvert", "material"}) {
    if (m.Get(a).present()) r.WarnUnsupported(e, a);
  }
  if (!inline_mesh) {
    // a file mesh's reference frame is not modelled (an inline one's is)
    for (std::string_view a : {"refpos", "refquat"}) {
      if (m.Get(a).present()) r.WarnUnsupported(e, a);
    }
  }
  const std::string written_name(name_attr.present() ? name_attr.value : "");
  for (const xml::XmlElement& child : r.Children(e)) {
    if (child.Name() != "plugin") continue;
    // MuJoCo's mesh plugins (an SDF, a procedural shape) make the mesh
    // when the model is compiled: mdlc runs no plugin
    const xml::XmlAttribute plugin = child.Attribute("plugin");
    const xml::XmlAttribute instance = child.Attribute("instance");
    const std::string which =
        plugin.present() ? fmt::format("plugin '{}'", plugin.value)
        : instance.present() ? fmt::format("plugin instance '{}'", instance.value)
                             : std::string("a plugin");
    LeaveOut(r, e, written_name, fmt::format("it is made by {}, which mdlc cannot run", which),
             fmt::format("is made by {}, which mdlc cannot run", which));
    return;
  }
  if (!file.present() && !vertex.present()) {
    if (e.Attribute("builtin").present()) {
      LeaveOut(r, e, written_name, "it is a builtin shape, which mdlc does not build",
               fmt::format("is builtin shape '{}', which mdlc does not build",
                           e.Attribute("builtin").value));
    } else {
      r.diags().Report(DiagKind::BadValue, e.GetLoc(),
                       fmt::format("mesh '{}' has neither a file nor vertices", written_name));
    }
    return;
  }
  if (file.present() && vertex.present()) {
    r.diags().Report(DiagKind::BadValue, vertex.loc,
                     fmt::format("mesh '{}' has both a file and vertices; MuJoCo takes one",
                                 written_name));
    return;
  }
  MeshAsset asset;
  asset.loc = e.GetLoc();
  if (inline_mesh) {
    asset.name = written_name;
    auto data = ReadInlineMesh(r, e, m, asset.name);
    if (!data) {
      // reported at the mesh; its geoms say why they are left out, once,
      // not that they name an unknown mesh
      if (!asset.name.empty() && !r.meshes.count(asset.name)) {
        asset.left_out = "its definition has an error (reported where it is defined)";
        r.meshes.emplace(asset.name, std::move(asset));
      }
      return;
    }
    asset.mesh.uri = asset.name;
    asset.mesh.uri_loc = vertex.loc;
    // no file: the key the mesh passes keep it under (no path starts with '<')
    asset.mesh.resolved = fmt::format("<inline mesh '{}' of model {}>", asset.name,
                                      r.model.index());
    asset.mesh.inline_data = std::move(data);
  } else {
    asset.name = name_attr.present() ? written_name
                                     : fs::path(std::string(file.value)).stem().string();
    asset.mesh.uri = std::string(file.value);
    asset.mesh.uri_loc = file.loc;

    // MJCF-006: absolute file; else absolute meshdir/file; else
    // main_dir/meshdir/file (meshdir, else assetdir)
    const std::string& dir =
        !r.compiler.meshdir.empty() ? r.compiler.meshdir : r.compiler.assetdir;
    fs::path path(asset.mesh.uri);
    if (!path.is_absolute()) {
      fs::path d(dir);
      path = d.is_absolute() ? d / path : fs::path(r.main_dir) / d / path;
    }
    // whether the file exists, and whether that matters, is the
    // resolve-assets pass's to say: a mesh only visual geoms use is never read
    asset.mesh.resolved = path.lexically_normal().string();
  }
  if (m.Get("scale").present()) {
    if (auto s = r.Numbers(m, "scale", 3)) asset.mesh.scale = {(*s)[0], (*s)[1], (*s)[2]};
  }
  if (const auto inertia = m.Get("inertia"); inertia.present()) {
    if (inertia.value == "convex") asset.inertia = ir::MeshInertia::Convex;
    else if (inertia.value == "exact") asset.inertia = ir::MeshInertia::Exact;
    else if (inertia.value == "legacy") asset.inertia = ir::MeshInertia::Legacy;
    else if (inertia.value == "shell") asset.inertia = ir::MeshInertia::Shell;
    else {
      r.diags().Report(DiagKind::BadValue, inertia.loc,
                       fmt::format("mesh inertia must be convex, exact, legacy or shell, not '{}'",
                                   inertia.value));
    }
  }
  if (inline_mesh && asset.name.empty()) return;  // no geom can name it
  if (r.meshes.count(asset.name)) {
    r.diags()
        .Report(DiagKind::DuplicateName, name_attr.present() ? name_attr.loc : asset.mesh.uri_loc,
                fmt::format("repeated mesh name '{}'", asset.name))
        .Note(r.meshes[asset.name].loc, "the first mesh of that name is here");
    return;
  }
  std::string key = asset.name;
  r.meshes.emplace(std::move(key), std::move(asset));
}

void ReadMaterial(MjcfReader& r, const xml::XmlElement& e) {
  r.CheckAttributes(e, "material");
  const Element m = r.Resolve(e, "material", "");
  const xml::XmlAttribute name = e.Attribute("name");
  if (!name.present()) {
    r.WarnOnce(e.GetLoc(), DiagKind::UnsupportedAttribute, "material", "name",
               "is missing: an unnamed material cannot be used and is ignored");
    return;
  }
  ir::Material material;
  material.name = r.module().Intern(name.value);
  material.model = r.model;
  material.loc = e.GetLoc();
  if (m.Get("rgba").present()) {
    if (auto c = r.Numbers(m, "rgba", 4)) material.rgba = Eigen::Vector4d((*c)[0], (*c)[1], (*c)[2], (*c)[3]);
  }
  if (m.Get("texture").present()) r.WarnUnsupported(e, "texture");
  if (r.materials.count(std::string(name.value))) {
    r.diags().Report(DiagKind::DuplicateName, name.loc,
                     fmt::format("repeated material name '{}'", name.value));
    return;
  }
  r.materials.emplace(std::string(name.value), r.module().Add(std::move(material)));
}

}  // namespace

void MjcfReader::ReadAsset(const xml::XmlElement& asset) {
  for (const xml::XmlElement& e : Children(asset)) {
    const std::string_view tag = e.Name();
    if (tag == "mesh") {
      ReadMesh(*this, e);
    } else if (tag == "material") {
      ReadMaterial(*this, e);
    } else if (tag == "skin") {
      LeaveOut(e.GetLoc(), "<skin>", kSkinLeftOut);
    } else if (tag == "texture" || tag == "hfield" || tag == "model") {
      WarnOnce(e.GetLoc(), DiagKind::UnsupportedElement, "asset", tag);
    } else {
      WarnOnce(e.GetLoc(), DiagKind::UnknownElement, "asset", tag,
               "is not a MuJoCo asset and is ignored (MuJoCo rejects it)");
    }
  }
}

}  // namespace mdlc::frontend::mjcf
