// sdf_include.cc - <include>: SDFormat and URDF files placed into a model or
// world, with name, pose, static and placement overrides, and merge-include
// (SDF-031..033).
//
// An included SDFormat model is read like a nested model (its own instance,
// scoped by the includer); with merge="true" its entities join the including
// model and its frame becomes the `_merged__NAME__model__` frame. An included
// URDF goes through mdlc's URDF frontend; its links are then entered into the
// frame graph at the poses its own kinematics give them, so SDFormat frames
// and joints can name them.
#include <fmt/format.h>

#include <deque>
#include <filesystem>
#include <unordered_map>

#include "ir/assets/package_map.h"
#include "frontend/sdf/model_folder.h"
#include "frontend/sdf/sdf_reader_detail.h"
#include "frontend/xml/trim.h"
#include "ir/load_report.h"

namespace mdlc::frontend::sdf {
namespace {
namespace fs = std::filesystem;

std::string DirectoryOf(const std::string& path) {
  size_t slash = path.rfind('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

bool EndsWith(std::string_view s, std::string_view suffix) {
  if (s.size() < suffix.size()) return false;
  for (size_t i = 0; i < suffix.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i]) {
      return false;
    }
  }
  return true;
}
}  // namespace

void SdfReader::ReadInclude(const xml::XmlElement& e, const SdfFile& file, ModelScope parent) {
  CheckChildren(e, {"uri", "name", "static", "pose", "placement_frame", "plugin"}, {});
  attrs_.WarnUnknownAttributes(e, {"merge"});
  auto uri = ChildText(e, "uri");
  if (!uri || uri->empty()) {
    diags().Report(DiagKind::MissingElement, e.GetLoc(), "<include> element missing 'uri'");
    return;
  }
  bool merge = false;
  if (auto m = attrs_.Bool(e, "merge")) merge = *m;
  if (merge && graph()[parent.scope].is_world) {
    diags().Report(DiagKind::BadValue, e.Attribute("merge").loc,
                   "merge-include is not allowed directly in a <world>: there is no model to "
                   "merge into");
    return;
  }
  const Loc uri_loc = e.Child("uri").GetLoc();
  std::optional<std::string> path =
      assets::ResolveUri(*uri, file.dir, ctx_.packages, uri_loc, diags());
  if (!path) return;
  std::error_code ec;
  if (fs::is_directory(*path, ec)) {
    path = ModelFileInFolder(*path, uri_loc, ctx_);
    if (!path) return;
  }
  // include cycles (SDF-033): the same file already on the include chain
  const std::string canonical = fs::weakly_canonical(*path, ec).string();
  for (const SdfFile* f = &file; f; f = f->included_from) {
    if (f->canonical == canonical) {
      auto diag = diags().Report(DiagKind::IncludeCycle, uri_loc,
                                 fmt::format("include cycle: '{}' includes itself", *uri));
      for (const SdfFile* g = &file; g; g = g->included_from) {
        diag.Note(g->include_loc.valid() ? g->include_loc : Loc{g->doc->file(), 1, 1},
                  fmt::format("'{}' is on the include chain", g->path));
        if (g == f) break;
      }
      return;
    }
  }

  ModelOverrides overrides;
  overrides.loc = e.GetLoc();
  if (auto name = ChildText(e, "name"); name && !name->empty()) overrides.name = *name;
  overrides.is_static = ChildBool(e, "static");
  overrides.pose = e.Child("pose");
  if (auto pf = ChildText(e, "placement_frame"); pf && !pf->empty()) {
    overrides.placement_frame = {module().Intern(*pf), e.Child("placement_frame").GetLoc()};
  }

  LoadError error;
  auto file_id = ctx_.sources.LoadFile(*path, uri_loc, &error);
  if (!file_id) {
    ReportLoadError(diags(), uri_loc, error, fmt::format("cannot read '{}'", *path));
    return;
  }
  // a .xacro is expanded with its defaults, and read as its root names
  const std::optional<Format> xacro_format =
      EndsWith(*path, ".xacro") ? XacroFormat(*file_id, ctx_.sources) : std::nullopt;
  if (EndsWith(*path, ".urdf") || xacro_format == Format::Urdf) {
    IncludeUrdf(*file_id, parent, overrides, merge);
    return;
  }
  if (EndsWith(*path, ".xml")) {
    diags().Report(DiagKind::NotImplemented, uri_loc,
                   fmt::format("including MJCF file '{}' is not implemented yet", *uri));
    return;
  }
  if (!EndsWith(*path, ".sdf") && xacro_format != Format::Sdf) {
    diags().Report(DiagKind::UnknownFormat, uri_loc,
                   fmt::format("'{}': only SDFormat (.sdf) and URDF (.urdf) files, or xacro "
                               "files of either, can be included",
                               *path));
    return;
  }
  std::shared_ptr<const xml::XmlDocument> doc = ParseXml(*file_id, ctx_);
  if (!doc) return;
  documents_.push_back(doc);
  ReserveRoomFor(*doc);
  auto included = std::make_unique<SdfFile>();
  included->doc = doc.get();
  included->path = *path;
  included->canonical = canonical;
  included->dir = DirectoryOf(*path);
  included->included_from = &file;
  included->include_loc = uri_loc;
  SdfFile& inc = *included;
  files_.push_back(std::move(included));

  xml::XmlElement root = doc->Root();
  if (root.Name() != "sdf") {
    diags().Report(DiagKind::WrongRoot, root.GetLoc(),
                   fmt::format("SDFormat file must have an <sdf> root element, found <{}>",
                               root.Name()));
    return;
  }
  if (auto v = root.Attribute("version"); v.present()) inc.version = ParseVersionNumber(v.value);
  xml::XmlElement model;
  for (auto child = root.FirstChild(); child; child = child.NextSibling()) {
    if (child.Name() == "model") {
      if (model) {
        diags()
            .Report(DiagKind::BadValue, child.GetLoc(),
                    "an included file must hold exactly one top-level <model>")
            .Note(model.GetLoc(), "the first model is here");
        return;
      }
      model = child;
    } else if (child.Name() == "world") {
      diags().Report(DiagKind::BadValue, child.GetLoc(),
                     "a <world> cannot be included: include files that hold a <model>");
      return;
    }
  }
  if (!model) {
    diags().Report(DiagKind::MissingElement, root.GetLoc(),
                   "the included file holds no <model>");
    return;
  }
  if (merge) {
    MergeModel(model, inc, parent, overrides);
  } else {
    ReadModelTree(model, inc, parent, &overrides);
  }
}

// merge="true": the model's entities join `parent`'s instance; its frame is a
// frame of the parent named _merged__NAME__model__ (SDF-032).
void SdfReader::MergeModel(const xml::XmlElement& model, const SdfFile& file, ModelScope parent,
                           const ModelOverrides& overrides) {
  auto written = attrs_.String(model, "name", xml::Need::Required);
  if (!written && !overrides.name) return;
  const std::string local = overrides.name ? *overrides.name : std::string(*written);
  FrameScopeId scope_id = OpenScope(model, parent, &overrides, local, parent.model,
                                    /*merged=*/true);
  ModelScope s{scope_id, parent.model, &file, graph()[scope_id].is_static,
               ModelFrameName(), parent.depth};
  const size_t pending = pending_models_.size();
  ReadModelBody(model, s);
  DrainPendingModels(pending);
  // the merged links are the parent's links too, for its canonical link
  auto& merged_links = graph()[scope_id].links;
  auto& parent_links = graph()[parent.scope].links;
  parent_links.insert(parent_links.end(), merged_links.begin(), merged_links.end());
}

void SdfReader::IncludeUrdf(FileId file, ModelScope parent, const ModelOverrides& overrides,
                            bool merge) {
  FrontendContext urdf_ctx = ctx_;
  urdf_ctx.options.model_name = overrides.name;
  urdf_ctx.options.auto_rename = false;
  urdf_ctx.options.name_prefix.clear();
  if (!graph()[parent.scope].is_world) {
    urdf_ctx.options.name_prefix = module().ModelName(parent.model) + "::";
  }
  const size_t first_body = module().bodies.size();
  const size_t first_frame = module().frames.size();
  auto model = ReadUrdf(file, urdf_ctx);
  if (!model) return;
  std::string local(module().Text(module()[*model].local_name));
  if (!urdf_ctx.options.name_prefix.empty()) {
    // the URDF reader named the instance in full: name it below its parent instead
    local = local.substr(urdf_ctx.options.name_prefix.size());
    module().RenameModel(*model, parent.model, module().Intern(local));
  }
  if (!CheckDefinedName(local, overrides.loc, "model")) return;

  if (merge) {
    // the URDF's entities join the including model; its instance goes away
    const ModelId urdf = *model;
    auto rehome = [&](auto& table) {
      for (auto& entity : table) {
        if (entity.model == urdf) entity.model = parent.model;
      }
    };
    rehome(module().bodies);
    rehome(module().frames);
    rehome(module().joints);
    rehome(module().geometries);
    rehome(module().materials);
    rehome(module().actuators);
    rehome(module().constraints);
    rehome(module().force_elements);
    rehome(module().filter_groups);
    rehome(module().cameras);
    module().RemoveLastModel();
    model = parent.model;
  }

  // the URDF's links, placed by its joints at zero configuration; its root
  // link is the canonical link
  std::unordered_map<uint32_t, BodyId> by_name;
  for (size_t b = first_body; b < module().bodies.size(); ++b) {
    by_name.emplace(module().bodies[b].name.value, BodyId(b));
  }
  std::unordered_map<uint32_t, std::vector<JointId>> children_of;
  std::vector<bool> is_child(module().bodies.size(), false);
  for (size_t j = 0; j < module().joints.size(); ++j) {
    const ir::Joint& joint = module().joints[j];
    if (joint.model != *model) continue;
    auto c = by_name.find(joint.child.name.value);
    if (c == by_name.end()) continue;
    is_child[c->second.index()] = true;
    children_of[joint.parent.name.value].push_back(JointId(j));
  }
  // X_ML: each link in the model frame; links hanging on the URDF's own
  // "world" link are fixed in the world instead (X_WL), whatever the include's pose
  std::vector<Transform> X_ML(module().bodies.size(), Transform::Identity());
  std::vector<bool> in_world(module().bodies.size(), false);
  std::deque<BodyId> queue;
  Symbol root_name;
  for (size_t b = first_body; b < module().bodies.size(); ++b) {
    if (!is_child[b]) {
      queue.push_back(BodyId(b));
      if (root_name.empty()) root_name = module().bodies[b].name;
    }
  }
  const Symbol world = module().bodies[0].name;
  if (auto it = children_of.find(world.value); it != children_of.end()) {
    for (JointId j : it->second) {
      const ir::Joint& joint = module()[j];
      const BodyId c = by_name[joint.child.name.value];
      X_ML[c.index()] = joint.X_PF * joint.X_CM.inverse();
      in_world[c.index()] = true;
      queue.push_back(c);
      if (root_name.empty()) root_name = joint.child.name;
    }
    diags().Report(DiagKind::UnsupportedValue, overrides.loc,
                   fmt::format("the included URDF attaches '{}' to its 'world' link: it stays "
                               "where the URDF puts it, whatever this include's pose",
                               module().Text(module()[it->second.front()].child.name)));
  }
  std::vector<bool> placed(module().bodies.size(), false);
  while (!queue.empty()) {
    BodyId b = queue.front();
    queue.pop_front();
    if (placed[b.index()]) continue;
    placed[b.index()] = true;
    auto it = children_of.find(module()[b].name.value);
    if (it == children_of.end()) continue;
    for (JointId j : it->second) {
      const ir::Joint& joint = module()[j];
      BodyId c = by_name[joint.child.name.value];
      X_ML[c.index()] = X_ML[b.index()] * joint.X_PF * joint.X_CM.inverse();
      in_world[c.index()] = in_world[b.index()];
      queue.push_back(c);
    }
  }

  ir::FrameScope scope;
  scope.name = module().Intern(local);
  scope.loc = overrides.loc;
  scope.parent = parent.scope;
  scope.model = *model;
  scope.canonical_link = {root_name, overrides.loc};
  scope.placement_frame = overrides.placement_frame;
  scope.is_static = parent.is_static || overrides.is_static.value_or(false);
  if (merge) scope.merged_into = parent.scope;
  const FrameScopeId scope_id = graph().Add(std::move(scope));
  graph()[parent.scope].children.push_back(scope_id);

  ir::FrameNode node;
  node.kind = ir::FrameNodeKind::Model;
  node.name = merge ? module().Intern(fmt::format("_merged__{}__model__", local))
                    : module().Intern(local);
  node.loc = overrides.loc;
  node.relative_to = RelativeTo(overrides.pose);
  if (node.relative_to.empty()) node.relative_to = {parent.model_frame_name, overrides.loc};
  node.X_RN = ReadPoseValue(overrides.pose);
  node.nested = scope_id;
  ir::Frame model_frame;
  model_frame.name = merge ? node.name : ModelFrameName();
  model_frame.model = *model;
  model_frame.loc = overrides.loc;
  node.target = ir::FrameTarget::Frame;
  node.target_index = module().Add(std::move(model_frame)).value;
  graph()[scope_id].frame = AddNode(parent, std::move(node));

  ModelScope s{scope_id, *model, parent.file, graph()[scope_id].is_static,
               ModelFrameName(), parent.depth + 1};
  for (size_t b = first_body; b < module().bodies.size(); ++b) {
    ir::FrameNode link;
    link.kind = ir::FrameNodeKind::Link;
    link.name = module().bodies[b].name;
    link.loc = module().bodies[b].loc;
    link.relative_to = {in_world[b] ? world : s.model_frame_name, overrides.loc};
    link.X_RN = X_ML[b];
    link.attached_to = {link.name, link.loc};
    link.target = ir::FrameTarget::Body;
    link.target_index = static_cast<uint32_t>(b);
    graph()[scope_id].links.push_back(AddNode(s, std::move(link)));
  }
  // URDF <frame>s keep their own body and pose; they become names SDFormat can use
  for (size_t f = first_frame; f < module().frames.size(); ++f) {
    const ir::Frame& frame = module().frames[f];
    if (frame.model != *model || frame.body.name.empty()) {
      continue;
    }
    ir::FrameNode fn;
    fn.kind = ir::FrameNodeKind::Frame;
    fn.name = frame.name;
    fn.loc = frame.loc;
    fn.relative_to = {frame.body.name, frame.loc};
    fn.X_RN = frame.X_BF;
    fn.attached_to = {frame.body.name, frame.loc};
    AddNode(s, std::move(fn));
  }
  if (merge) {
    auto& parent_links = graph()[parent.scope].links;
    parent_links.insert(parent_links.end(), graph()[scope_id].links.begin(),
                        graph()[scope_id].links.end());
  }
}

}  // namespace mdlc::frontend::sdf
