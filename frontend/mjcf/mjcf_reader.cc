// mjcf_reader.cc - the MJCF frontend's entry point and its phases (MJCF-001,
// MJCF-008, COMMON-021): document and includes, settings and assets from
// anywhere in the file, then the worldbody and the model elements.
#include <absl/container/flat_hash_map.h>
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <tuple>

#include "frontend/mjcf/mjcf_capacity.h"
#include "frontend/mjcf/mjcf_reader_detail.h"
#include "frontend/mjcf/mjcf_replicate.h"
#include "frontend/model_naming.h"

namespace mdlc::frontend::mjcf {
namespace {

std::optional<ModelId> Read(FileId file, FrontendContext& ctx) {
  std::shared_ptr<const xml::XmlDocument> doc = ParseXml(file, ctx);
  if (!doc) return std::nullopt;
  const xml::XmlElement root = doc->Root();
  if (root.Name() != "mujoco") {
    ctx.diags.Report(DiagKind::WrongRoot, root.GetLoc(),
                     fmt::format("an MJCF file must have a <mujoco> root element, found <{}>",
                                 root.Name()));
    return std::nullopt;
  }
  const std::string path = ctx.sources.Path(file);
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  const std::string main_dir = parent.empty() ? std::string(1, '.') : parent.string();

  MjcfReader r(ctx, main_dir);
  r.document.documents.push_back(doc);
  // phase 1: every include, before anything is read (MJCF-001)
  if (!LoadIncludes(root, main_dir, ctx, r.document)) return std::nullopt;

  // the model instance (COMMON-021): MuJoCo loads a file without a name,
  // so mdlc names it after the file, with a warning
  r.CheckAttributes(root, "mujoco");
  const xml::XmlAttribute model_attr = root.Attribute("model");
  std::string name;
  if (model_attr.present() && !model_attr.value.empty()) {
    name = std::string(model_attr.value);
  } else {
    name = std::filesystem::path(path).stem().string();
    if (!ctx.options.model_name) {
      ctx.diags.Report(DiagKind::MissingModelName, root.GetLoc(),
                       fmt::format("<mujoco> has no 'model' name; the model instance is named "
                                   "'{}' after the file",
                                   name));
    }
  }
  auto model = AddModelInstance(name, root.GetLoc(), ir::SourceFormat::Mjcf, ctx);
  if (!model) return std::nullopt;
  r.model = *model;
  r.model_name = ctx.module.ModelName(*model);
  // the instance is new: its joints are the ones added from here on
  const size_t first_joint = ctx.module.joints.size();

  std::vector<xml::XmlElement> top = r.Children(root);
  // phase 2: settings, defaults and assets, wherever they stand
  for (const auto& e : top) {
    if (e.Name() == "compiler") r.ReadCompiler(e);
  }
  // <replicate> and <attach>: the rest reads the document they expand to
  if (Expansion x = ExpandReplicateAndAttach(r, root, {path}); x.failed) {
    return std::nullopt;
  } else if (x.document) {
    r.document.documents.push_back(x.document);
    top = r.Children(x.document->Root());
  }
  for (const auto& e : top) {
    if (e.Name() == "option") r.ReadOption(e);
  }
  for (const auto& e : top) {
    if (e.Name() == "default") {
      r.defaults.Read(e, ctx.diags, &r.document);
      r.CheckDefaultAttributes(e);
    }
  }
  for (const auto& e : top) {
    if (e.Name() == "asset") r.ReadAsset(e);
  }
  ctx.module[r.model].mass_adjustments = r.compiler.mass_adjustments;

  // phase 3: the body tree, then what refers to it
  ReserveEntities(ctx.module, MjcfEntityRoom(r.document.documents));
  r.body_order.push_back(ir::kWorldBody);
  r.bodies.Insert(ctx.module.Intern("world"), ir::kWorldBody);
  for (const auto& e : top) {
    if (e.Name() == "worldbody") r.LowerWorldBody(e);
  }
  // a mesh no geom uses is never read (resolve-assets checks the others'
  // files); MuJoCo would fail to open a missing one, so say so
  std::vector<const MeshAsset*> unused;
  for (const auto& [name, asset] : r.meshes) {
    std::error_code ec;
    if (asset.mesh.inline_data || !asset.left_out.empty()) continue;  // no file
    if (!asset.used && !std::filesystem::exists(asset.mesh.resolved, ec)) unused.push_back(&asset);
  }
  std::sort(unused.begin(), unused.end(), [](const MeshAsset* a, const MeshAsset* b) {
    const Loc &x = a->mesh.uri_loc, &y = b->mesh.uri_loc;
    return std::tie(x.file.value, x.line, x.column) < std::tie(y.file.value, y.line, y.column);
  });
  for (const MeshAsset* asset : unused) {
    ctx.diags.Report(DiagKind::MissingAsset, asset->mesh.uri_loc,
                     fmt::format("'{}' resolves to '{}', which does not exist; mesh '{}' is "
                                 "kept without its file, which no geom uses",
                                 asset->mesh.uri, asset->mesh.resolved, asset->name));
  }
  // Drake names a floating joint after its body, prefixing '_' while the
  // name is taken by another joint of the model
  ir::Module& m = ctx.module;
  if (!r.free_joints.empty()) {
    // How many of the model's joints bear each name, so a scene of many
    // free bodies names each in constant time. As in Drake, which adds the
    // floating joints one by one in body order, a floating joint not yet
    // named holds no name: its placeholder (the body's name) does not count.
    absl::flat_hash_map<Symbol, int, SymbolHash> joints_named;
    for (size_t j = first_joint; j < m.joints.size(); ++j) {
      if (m.joints[j].model == r.model) ++joints_named[m.joints[j].name];
    }
    for (JointId id : r.free_joints) --joints_named[m[id].name];
    for (JointId id : r.free_joints) {
      std::string joint_name(m.Text(m[m[id].child.id].name));
      auto taken = [&](const std::string& n) {
        const Symbol s = m.symbols.Find(n);
        if (s.empty()) return false;
        const auto it = joints_named.find(s);
        return it != joints_named.end() && it->second > 0;
      };
      while (taken(joint_name)) joint_name = "_" + joint_name;
      m[id].name = m.Intern(joint_name);
      ++joints_named[m[id].name];
    }
  }
  LowerModelElements(r, top);
  // BEYOND-007/008: gains from the inertia at qpos0, for the backend
  if (!r.scaled_gains.empty()) {
    r.scaled_gains.model = r.model;
    r.scaled_gains.loc = root.GetLoc();
    m.inertia_scaled_gains.push_back(std::move(r.scaled_gains));
  }

  for (const auto& e : top) {
    const std::string_view tag = e.Name();
    if (tag == "compiler" || tag == "option" || tag == "default" || tag == "asset" ||
        tag == "worldbody" || tag == "equality" || tag == "tendon" || tag == "actuator" ||
        tag == "contact" || tag == "keyframe") {
      continue;
    }
    r.ReadOtherTopLevel(e);
  }
  if (ctx.diags.has_errors()) return std::nullopt;
  return r.model;
}

}  // namespace
}  // namespace mdlc::frontend::mjcf

namespace mdlc::frontend {

std::optional<ModelId> ReadMjcf(FileId file, FrontendContext& ctx) {
  return mjcf::Read(file, ctx);
}

}  // namespace mdlc::frontend
