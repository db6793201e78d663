// mjcf_assets.cc - <asset>: meshes and materials (MJCF-006, MJCF-050,
// BEYOND-001). Textures, height fields and skins have no place in the plant.
//
// A mesh may be any format assimp reads (BEYOND-001); the mesh passes load
// it later. Here it only gets its name (default: the file's stem), its
// path by MuJoCo's rule, its scale and its inertia mode; the resolve-assets
// pass checks that the file exists where the plant needs it.
#include <fmt/format.h>

#include <filesystem>

#include "frontend/mjcf/mjcf_reader_detail.h"

namespace mdlc::frontend::mjcf {
namespace {
namespace fs = std::filesystem;

void ReadMesh(MjcfReader& r, const xml::XmlElement& e) {
  r.CheckAttributes(e, "mesh");
  // meshes take defaults from their class, but have no childclass
  const Element m = r.Resolve(e, "mesh", "");
  const xml::XmlAttribute file = e.Attribute("file");
  const xml::XmlAttribute name_attr = e.Attribute("name");
  for (std::string_view a : {"smoothnormal", "maxhullvert", "refpos", "refquat", "material"}) {
    if (m.Get(a).present()) r.WarnUnsupported(e, a);
  }
  if (!file.present()) {
    // user vertices or a builtin shape: not loaded from a file
    r.WarnOnce(e.GetLoc(), DiagKind::UnsupportedAttribute, "mesh",
               e.Attribute("builtin").present() ? "builtin" : "vertex",
               "(a mesh without a file) is not supported; geoms using the mesh are ignored");
    return;
  }
  MeshAsset asset;
  asset.loc = e.GetLoc();
  asset.name = name_attr.present() ? std::string(name_attr.value)
                                   : fs::path(std::string(file.value)).stem().string();
  asset.mesh.uri = std::string(file.value);
  asset.mesh.uri_loc = file.loc;

  // MJCF-006: absolute file; else absolute meshdir/file; else
  // main_dir/meshdir/file (meshdir, else assetdir)
  const std::string& dir = !r.compiler.meshdir.empty() ? r.compiler.meshdir : r.compiler.assetdir;
  fs::path path(asset.mesh.uri);
  if (!path.is_absolute()) {
    fs::path d(dir);
    path = d.is_absolute() ? d / path : fs::path(r.main_dir) / d / path;
  }
  // whether the file exists, and whether that matters, is the
  // resolve-assets pass's to say: a mesh only visual geoms use is never read
  asset.mesh.resolved = path.lexically_normal().string();
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
  if (r.meshes.count(asset.name)) {
    r.diags()
        .Report(DiagKind::DuplicateName, name_attr.present() ? name_attr.loc : file.loc,
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
