// sdf_reader.cc - the <sdf> root, <world> and <model>: model instances, name
// scopes, the frame graph's model nodes, and dispatch to the element readers
// (SDF-001, SDF-002, SDF-005, SDF-006, SDF-030, SDF-034, SDF-035).
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "frontend/entity_capacity.h"
#include "frontend/model_naming.h"
#include "frontend/sdf/sdf_reader_detail.h"
#include "ir/scoped_name.h"

namespace mdlc::frontend {

std::optional<ModelId> ReadSdf(FileId file, FrontendContext& ctx) {
  sdf::SdfReader reader(ctx);
  return reader.ReadRootFile(file);
}

}  // namespace mdlc::frontend

namespace mdlc::frontend::sdf {
namespace {
// "1.9" -> 109; nullopt when it is not MAJOR.MINOR, with at most four digits
// of major and two of minor version (no overflow, found by fuzz_sdf)
std::optional<int> ParseVersion(std::string_view text) {
  size_t dot = text.find('.');
  if (dot == std::string_view::npos || dot == 0 || dot + 1 >= text.size()) return std::nullopt;
  if (dot > 4 || text.size() - dot - 1 > 2) return std::nullopt;
  int major = 0, minor = 0;
  for (size_t i = 0; i < dot; ++i) {
    if (text[i] < '0' || text[i] > '9') return std::nullopt;
    major = major * 10 + (text[i] - '0');
  }
  for (size_t i = dot + 1; i < text.size(); ++i) {
    if (text[i] < '0' || text[i] > '9') return std::nullopt;
    minor = minor * 10 + (text[i] - '0');
  }
  return major * 100 + minor;
}

std::string DirectoryOf(const std::string& path) {
  size_t slash = path.rfind('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}
}  // namespace

bool SdfReader::CheckDefinedName(std::string_view name, Loc loc, std::string_view kind,
                                 int version) {
  if (name.empty()) {
    diags().Report(DiagKind::InvalidName, loc, fmt::format("the {} name must not be empty", kind));
    return false;
  }
  // SDFormat 1.7 and older allowed "::" in names (flattened models used it)
  if (version >= 108 && name.find("::") != std::string_view::npos) {
    diags().Report(DiagKind::InvalidName, loc,
                   fmt::format("{} name '{}' must not contain '::': the delimiter of scoped names "
                               "is reserved for references",
                               kind, name));
    return false;
  }
  if (name == "world" || (name.size() >= 4 && name.starts_with("__") && name.ends_with("__"))) {
    diags().Report(DiagKind::ReservedName, loc,
                   fmt::format("the supplied {} name '{}' is reserved", kind, name));
    return false;
  }
  return true;
}

namespace {
// The order in which libsdformat loads a model's or world's entities, for
// its renaming of names shared across kinds: a kind loaded later yields the
// name to one loaded earlier (-1: a kind that never takes part).
int LoadRank(ir::FrameNodeKind kind) {
  switch (kind) {
    case ir::FrameNodeKind::Link:
    case ir::FrameNodeKind::Model: return 0;
    case ir::FrameNodeKind::Joint: return 1;
    case ir::FrameNodeKind::Frame: return 2;
    default: return -1;
  }
}
}  // namespace

FrameNodeId SdfReader::AddNode(const ModelScope& s, ir::FrameNode node) {
  // merged models publish their names into the scope they merge into; the
  // graph's name index is the table of names defined so far
  ir::FrameGraph& g = graph();
  const FrameScopeId ns = g.Namespace(s.scope);
  const FrameNodeId id(g.nodes.size());
  node.scope = s.scope;
  const auto [holder, inserted] = g.names.TryAdd(ns.value, node.name, id);
  if (inserted) return g.Add(std::move(node));

  // the node that has the name; nodes do not move until this one is added
  const FrameNodeId first_id = *holder;
  ir::FrameNode& first = g[first_id];
  const int first_rank = LoadRank(first.kind), node_rank = LoadRank(node.kind);
  // libsdformat loads links and nested models, then joints, then frames,
  // and renames a later kind that shares an earlier one's name NAME_joint
  // or NAME_frame, wherever it stands in the file: in a model before
  // SDFormat 1.7 (an error from 1.7 on), in a world always. So do we.
  const bool in_world = g[s.scope].is_world;
  if ((in_world || (s.file && s.file->version < 107)) && first_rank >= 0 && node_rank >= 0 &&
      first_rank != node_rank) {
    const bool rename_first = first_rank > node_rank;
    const FrameNodeId renamed_id = rename_first ? first_id : id;
    ir::FrameNode& renamed = rename_first ? first : node;
    const ir::FrameNode& keeper = rename_first ? node : first;
    const char* kind = renamed.kind == ir::FrameNodeKind::Joint ? "joint" : "frame";
    const char* keeper_kind = keeper.kind == ir::FrameNodeKind::Link    ? "link"
                              : keeper.kind == ir::FrameNodeKind::Joint ? "joint"
                              : in_world                                ? "model"
                                                                        : "nested model";
    const std::string new_name = fmt::format("{}_{}", module().Text(renamed.name), kind);
    diags()
        .Report(DiagKind::RenamedDuplicate, renamed.loc,
                fmt::format("the name '{}' is also given to a {} of this {}; as libsdformat "
                            "does {}, this {} is renamed '{}'",
                            module().Text(renamed.name), keeper_kind,
                            in_world ? "world" : "model",
                            in_world ? "in a world" : "for files older than SDFormat 1.7", kind,
                            new_name))
        .Note(keeper.loc, fmt::format("the {} that keeps the name is here", keeper_kind));
    renamed.name = module().Intern(new_name);
    switch (renamed.target) {
      case ir::FrameTarget::Joint: RenameJoint(JointId(renamed.target_index), renamed.name); break;
      case ir::FrameTarget::Frame: module().frames[renamed.target_index].name = renamed.name; break;
      default: break;
    }
    if (rename_first) *holder = id;  // the newcomer takes the name over
    g.names.TryAdd(ns.value, renamed.name, renamed_id);
  } else {
    diags()
        .Report(DiagKind::DuplicateName, node.loc,
                fmt::format("the name '{}' is already used by a link, joint, frame or model "
                            "of this model",
                            module().Text(node.name)))
        .Note(first.loc, "first defined here");
  }
  return g.Add(std::move(node));
}

void SdfReader::RenameJoint(JointId joint, Symbol name) {
  ir::Joint& j = module()[joint];
  if (joint.index() < joint_names_counted_) {
    --joint_name_counts_[ScopedKey{j.model.value, j.name.value}];
    ++joint_name_counts_[ScopedKey{j.model.value, name.value}];
  }
  j.name = name;
  // a joint renamed after it was read (a nested model read later took its
  // name) takes along the actuator made for it and named after it
  if (auto it = joint_actuators_.find(joint.value); it != joint_actuators_.end()) {
    ir::Actuator& a = module()[it->second];
    a.name = a.joint.name = name;
  }
}

bool SdfReader::JointNameTaken(ModelId model, Symbol name) {
  const auto& joints = module().joints;
  for (; joint_names_counted_ < joints.size(); ++joint_names_counted_) {
    const ir::Joint& j = joints[joint_names_counted_];
    ++joint_name_counts_[ScopedKey{j.model.value, j.name.value}];
  }
  auto it = joint_name_counts_.find(ScopedKey{model.value, name.value});
  return it != joint_name_counts_.end() && it->second > 0;
}

FrameNodeId SdfReader::AddAnchor(const ModelScope& s, const xml::XmlElement& pose_element,
                                 Symbol link_name, FrameNodeId link_node, Loc loc,
                                 ir::FrameTarget target, uint32_t index) {
  ir::FrameNode node;
  node.kind = ir::FrameNodeKind::Anchor;
  node.scope = s.scope;
  node.loc = loc;
  node.relative_to = RelativeTo(pose_element);
  if (node.relative_to.empty()) node.relative_to = {link_name, loc};
  node.X_RN = ReadPoseValue(pose_element);
  node.attached_to = {link_name, loc};
  node.attached_node = link_node;
  node.target = target;
  node.target_index = index;
  return graph().Add(std::move(node));
}

void SdfReader::CheckChildren(const xml::XmlElement& e,
                              std::initializer_list<std::string_view> known,
                              std::initializer_list<std::string_view> unsupported) {
  for (auto child = e.FirstChild(); child; child = child.NextSibling()) {
    CheckChild(e, child, {known.begin(), known.size()},
               {unsupported.begin(), unsupported.size()});
  }
}

void SdfReader::ReportUnknownChild(const xml::XmlElement& e, const xml::XmlElement& child,
                                   std::span<const std::string_view> known,
                                   std::span<const std::string_view> unsupported) {
  std::string_view tag = child.Name();
  if (Listed(unsupported, tag)) {
    diags().Report(DiagKind::UnsupportedElement, child.GetLoc(),
                   fmt::format("element <{}> in <{}> is not supported and is ignored",
                               tag, e.Name()));
  } else if (tag.starts_with("drake:")) {
    diags().Report(DiagKind::UnknownElement, child.GetLoc(),
                   fmt::format("unsupported element <{}> in <{}> is ignored", tag, e.Name()));
  } else if (tag.find(':') == std::string_view::npos) {
    auto diag = diags().Report(DiagKind::UnknownSdfElement, child.GetLoc(),
                               fmt::format("<{}> is not an SDFormat element of <{}>", tag,
                                           e.Name()));
    std::vector<std::string_view> candidates(known.begin(), known.end());
    candidates.insert(candidates.end(), unsupported.begin(), unsupported.end());
    if (auto best = ir::ClosestName(tag, candidates)) {
      diag.Note(child.GetLoc(), fmt::format("did you mean <{}>?", *best));
    }
  }
  // other namespaces (gazebo:, ignition:, ...) belong to other tools (SDF-001)
}

void SdfReader::ReserveRoomFor(const xml::XmlDocument& doc) {
  const EntityRoom room = SdfEntityRoom(doc);
  ReserveEntities(module(), room);
  // every node but the anchors of visuals, collisions and sensors has a
  // name; the names table indexes a model's name in the world and the first
  // name in each model's scope without hashing, and hashes the rest
  const size_t named = room.frame_nodes - room.geometries;
  graph().names.Reserve(named > 2 * room.models ? named - 2 * room.models : 0);
}

std::optional<ModelId> SdfReader::ReadRootFile(FileId file_id) {
  std::shared_ptr<const xml::XmlDocument> doc = ParseXml(file_id, ctx_);
  if (!doc) return std::nullopt;
  documents_.push_back(doc);
  ReserveRoomFor(*doc);
  auto file = std::make_unique<SdfFile>();
  file->doc = doc.get();
  file->path = std::string(ctx_.sources.Path(file_id));
  file->dir = DirectoryOf(file->path);
  const SdfFile& root_file = *file;
  files_.push_back(std::move(file));

  std::error_code fs_error;
  xml::XmlElement sdf = doc->Root();
  if (sdf.Name() != "sdf") {
    diags().Report(DiagKind::WrongRoot, sdf.GetLoc(),
                   fmt::format("SDFormat file must have an <sdf> root element, found <{}>",
                               sdf.Name()));
    return std::nullopt;
  }
  auto version_text = attrs_.String(sdf, "version", xml::Need::Required);
  if (!version_text) return std::nullopt;
  auto version = ParseVersion(*version_text);
  files_.back()->canonical = std::filesystem::weakly_canonical(files_.back()->path, fs_error).string();
  if (!version || *version < 100) {
    diags().Report(DiagKind::BadValue, sdf.Attribute("version").loc,
                   fmt::format("unsupported SDFormat version '{}'", *version_text));
    return std::nullopt;
  }
  files_.back()->version = *version;
  attrs_.WarnUnknownAttributes(sdf, {"version", "xmlns:drake", "xmlns:xacro"});

  // the graph's name index holds every node this reader adds; it holds
  // them all if the graph starts here (other files' readers keep it too)
  if (graph().nodes.empty()) graph().names_complete = true;

  // the world scope: its frame is the world body's
  ir::FrameScope world_scope;
  world_scope.name = module().Intern("world");
  world_scope.model = ir::kWorldModel;
  world_scope.is_world = true;
  const FrameScopeId world_id = graph().Add(world_scope);
  ir::FrameNode world_node;
  world_node.kind = ir::FrameNodeKind::World;
  world_node.name = module().Intern("world");
  world_node.scope = world_id;
  world_node.target = ir::FrameTarget::Body;
  world_node.target_index = ir::kWorldBody.value;
  graph()[world_id].frame = graph().Add(std::move(world_node));
  ModelScope world{world_id, ir::kWorldModel, &root_file, false, module().Intern("world")};

  xml::XmlElement model_element, world_element;
  for (auto child = sdf.FirstChild(); child; child = child.NextSibling()) {
    std::string_view tag = child.Name();
    if (tag == "model") {
      if (model_element) {
        diags()
            .Report(DiagKind::BadValue, child.GetLoc(),
                    "a model file must hold exactly one top-level <model> (use a <world> for "
                    "several)")
            .Note(model_element.GetLoc(), "the first model is here");
        return std::nullopt;
      }
      model_element = child;
    } else if (tag == "world") {
      if (world_element) {
        diags()
            .Report(DiagKind::BadValue, child.GetLoc(), "an SDFormat file may hold only one <world>")
            .Note(world_element.GetLoc(), "the first world is here");
        return std::nullopt;
      }
      world_element = child;
    } else if (tag == "light" || tag == "actor") {
      diags().Report(DiagKind::UnsupportedElement, child.GetLoc(),
                     fmt::format("element <{}> in <sdf> is not supported and is ignored",
                                 tag));
    } else {
      CheckChildren(sdf, {"model", "world", "light", "actor"});
      break;
    }
  }
  if (world_element && ctx_.options.single_model) {
    diags().Report(DiagKind::BadValue, world_element.GetLoc(),
                   "this file holds a <world>, but one model is expected here (add_model loads "
                   "exactly one <model>)");
    return std::nullopt;
  }
  if (model_element && world_element) {
    diags()
        .Report(DiagKind::BadValue, model_element.GetLoc(),
                "an SDFormat file holds either one <model> or one <world>, not both")
        .Note(world_element.GetLoc(), "the world is here");
    return std::nullopt;
  }
  // the root holds one model, light or actor, never two kinds (SDF-002)
  for (auto child = sdf.FirstChild(); child && model_element; child = child.NextSibling()) {
    if (child.Name() == "light" || child.Name() == "actor") {
      diags()
          .Report(DiagKind::BadValue, child.GetLoc(),
                  fmt::format("the <sdf> root may hold only one of <model>, <light> or <actor>, "
                              "but holds a <{}> beside the model",
                              child.Name()))
          .Note(model_element.GetLoc(), "the model is here");
      return std::nullopt;
    }
  }
  if (world_element) return ReadWorld(world_element, root_file);
  if (!model_element) {
    diags().Report(DiagKind::MissingElement, sdf.GetLoc(),
                   "the SDFormat file holds no <model> and no <world>");
    return std::nullopt;
  }
  if (ir::NameRef r = RelativeTo(model_element.Child("pose")); !r.empty()) {
    diags().Report(DiagKind::BadValue, r.loc,
                   "the pose of a top-level model must not have a relative_to attribute: "
                   "nothing lies outside it");
  }
  return ReadModelTree(model_element, root_file, world, nullptr);
}

std::optional<ModelId> SdfReader::ReadWorld(const xml::XmlElement& e, const SdfFile& file) {
  auto name = attrs_.String(e, "name", xml::Need::Required);
  if (!name) return std::nullopt;
  static constexpr std::string_view kWorldChildren[] = {
      "model", "include", "frame", "joint", "audio", "wind", "gravity",
      "magnetic_field", "atmosphere", "gui", "physics", "scene", "plugin",
      "road", "spherical_coordinates", "state", "population", "light", "actor"};
  const FrameScopeId world_id{uint32_t{0}};
  ModelScope world{world_id, ir::kWorldModel, &file, false, module().Intern("world")};
  std::vector<xml::XmlElement> joints;
  for (auto child = e.FirstChild(); child; child = child.NextSibling()) {
    CheckChild(e, child, kWorldChildren, {});
    std::string_view tag = child.Name();
    if (tag == "model") {
      ReadModelTree(child, file, world, nullptr);
    } else if (tag == "include") {
      ReadInclude(child, file, world);
    } else if (tag == "frame") {
      ReadFrame(child, world);
    } else if (tag == "joint") {
      joints.push_back(child);  // world joints connect models, which may come later
    } else if (tag == "light" || tag == "actor") {
      diags().Report(DiagKind::UnsupportedElement, child.GetLoc(),
                     fmt::format("element <{}> in <world> is not supported and is ignored",
                                 tag));
    } else if (tag == "gravity") {
      // the plant's gravity, as MJCF's <option gravity> gives it
      if (auto g = TextVector3(child)) module().gravity = *g;
    }
    // physics, scene, plugins...: simulator settings, not the model
  }
  for (const xml::XmlElement& j : joints) ReadJoint(j, world);
  if (!first_model_) {
    // a world with no model is a valid (empty) scene
    return ir::kWorldModel;
  }
  return first_model_;
}

int SdfReader::ParseVersionNumber(std::string_view text) {
  return ParseVersion(text).value_or(109);
}

std::optional<ModelId> SdfReader::ReadModelTree(const xml::XmlElement& e, const SdfFile& file,
                                                ModelScope parent,
                                                const ModelOverrides* overrides) {
  const size_t pending = pending_models_.size();
  auto model = ReadModel(e, file, parent, overrides);
  DrainPendingModels(pending);
  return model;
}

void SdfReader::DrainPendingModels(size_t down_to) {
  while (pending_models_.size() > down_to) {
    PendingModel next = pending_models_.back();
    pending_models_.pop_back();
    ReadModel(next.element, *next.file, next.parent, nullptr);
  }
}

std::optional<ModelId> SdfReader::ReadModel(const xml::XmlElement& e, const SdfFile& file,
                                            ModelScope parent,
                                            const ModelOverrides* overrides) {
  auto written_name = attrs_.String(e, "name", xml::Need::Required);
  attrs_.WarnUnknownAttributes(e, {"name", "canonical_link", "placement_frame"});
  std::string local_name =
      overrides && overrides->name ? *overrides->name : std::string(written_name.value_or(""));
  const Loc loc = overrides ? overrides->loc : e.GetLoc();
  if (!written_name && !(overrides && overrides->name)) return std::nullopt;
  if (!CheckDefinedName(local_name, loc, "model", file.version)) return std::nullopt;

  // bounded: outputs that print the instance's full name grow with the
  // square of its depth (ir/limits.h)
  const uint64_t depth = parent.depth + 1;
  if (const uint64_t limit = ctx_.sources.limits().model_depth; depth > limit) {
    diags().Report(DiagKind::LimitExceeded, loc,
                   fmt::format("model '{}' would be nested {} deep, over the model-depth limit "
                               "of {} (raise it with --limit model-depth=N)",
                               local_name, depth, limit));
    return std::nullopt;
  }
  const bool top_level = graph()[parent.scope].is_world;
  std::optional<ModelId> model;
  if (top_level && &file == files_.front().get() && !first_model_) {
    // the root file's first model takes --model-name and --auto-rename
    model = AddModelInstance(local_name, loc, ir::SourceFormat::Sdf, ctx_);
  } else if (top_level) {
    FrontendContext plain = ctx_;
    plain.options.model_name.reset();
    model = AddModelInstance(local_name, loc, ir::SourceFormat::Sdf, plain);
  } else {
    // named by its parent and its own name: never spelled out in full (issue 16)
    model = module().Add(ir::ModelInstance{module().Intern(local_name), loc, ir::SourceFormat::Sdf,
                                           {}, parent.model});
  }
  if (!model) return std::nullopt;
  if (!first_model_) first_model_ = model;

  const FrameScopeId scope_id = OpenScope(e, parent, overrides, local_name, *model, false);
  ModelScope s{scope_id, *model, &file, graph()[scope_id].is_static, ModelFrameName(), depth};
  ReadModelBody(e, s);
  return model;
}

FrameScopeId SdfReader::OpenScope(const xml::XmlElement& e, const ModelScope& parent,
                                  const ModelOverrides* overrides, const std::string& local_name,
                                  ModelId model, bool merged) {
  const Loc loc = overrides ? overrides->loc : e.GetLoc();
  const Symbol local = module().Intern(local_name);
  ir::FrameScope scope;
  scope.name = local;
  scope.loc = loc;
  scope.parent = parent.scope;
  if (merged) scope.merged_into = parent.scope;
  scope.model = model;
  if (auto a = e.Attribute("canonical_link"); a.present()) {
    scope.canonical_link = {module().Intern(a.value), a.loc};
  }
  if (overrides && !overrides->placement_frame.empty()) {
    scope.placement_frame = overrides->placement_frame;
  } else if (auto a = e.Attribute("placement_frame"); a.present()) {
    scope.placement_frame = {module().Intern(a.value), a.loc};
  }
  bool is_static = parent.is_static;
  if (auto s = ChildBool(e, "static")) is_static = is_static || *s;
  if (overrides && overrides->is_static) is_static = is_static || *overrides->is_static;
  scope.is_static = is_static;
  const FrameScopeId scope_id = graph().Add(std::move(scope));
  graph()[parent.scope].children.push_back(scope_id);

  // Drake gives every SDFormat model instance a `__model__` frame (COMMON-024);
  // a merged model's frame is a frame of the model it merges into (SDF-032)
  const Symbol node_name =
      merged ? module().Intern(fmt::format("_merged__{}__model__", local_name)) : local;
  ir::Frame model_frame;
  model_frame.name = merged ? node_name : ModelFrameName();
  model_frame.model = model;
  model_frame.loc = loc;
  const FrameId model_frame_id = module().Add(std::move(model_frame));

  xml::XmlElement pose = overrides && overrides->pose ? overrides->pose : e.Child("pose");
  ir::FrameNode node;
  node.kind = ir::FrameNodeKind::Model;
  node.name = node_name;
  node.loc = loc;
  node.relative_to = RelativeTo(pose);
  if (node.relative_to.empty()) node.relative_to = {parent.model_frame_name, loc};
  node.X_RN = ReadPoseValue(pose);
  node.nested = scope_id;
  node.target = ir::FrameTarget::Frame;
  node.target_index = model_frame_id.value;
  graph()[scope_id].frame = AddNode(parent, std::move(node));
  return scope_id;
}

void SdfReader::ReadModelBody(const xml::XmlElement& e, ModelScope& s) {
  static constexpr std::string_view kModelChildren[] = {
      "static", "self_collide", "allow_auto_disable", "include", "model",
      "enable_wind", "frame", "pose", "link", "joint", "plugin", "drake:joint",
      "drake:collision_filter_group", "drake:linear_bushing_rpy",
      "drake:linear_spring_damper", "drake:ball_constraint",
      "drake:distance_constraint", "drake:tendon_constraint"};
  static constexpr std::string_view kModelUnsupported[] = {"gripper"};
  std::vector<xml::XmlElement> joints, drake_elements, nested;
  for (auto child = e.FirstChild(); child; child = child.NextSibling()) {
    // the next link's subtree while this one is read (XmlElement::PrefetchSubtree)
    if (xml::XmlElement next = child.NextSibling()) next.PrefetchSubtree();
    CheckChild(e, child, kModelChildren, kModelUnsupported);
    std::string_view tag = child.Name();
    if (tag == "link") {
      ReadLink(child, s);
    } else if (tag == "model") {
      nested.push_back(child);
    } else if (tag == "include") {
      ReadInclude(child, *s.file, s);
    } else if (tag == "frame") {
      ReadFrame(child, s);
    } else if (tag == "joint") {
      joints.push_back(child);
    } else if (tag.starts_with("drake:")) {
      drake_elements.push_back(child);
    } else if (tag == "self_collide" || tag == "enable_wind" || tag == "allow_auto_disable") {
      if (auto v = TextBool(child); v && *v) {
        diags().Report(DiagKind::UnsupportedElement, child.GetLoc(),
                       fmt::format("element <{}> in <model> is not supported and is ignored",
                                   tag));
      }
    }
  }
  // joints after every link, as Drake adds them; their frames may be in
  // nested models not read yet, which is fine: the resolve-frames pass binds them
  for (size_t i = 0; i < joints.size(); ++i) {
    if (i + 1 < joints.size()) joints[i + 1].PrefetchSubtree();
    ReadJoint(joints[i], s);
  }
  for (const xml::XmlElement& d : drake_elements) ReadDrakeModelElement(d, s);
  // nested models go on the work list, last first, so they are read in document order
  for (auto it = nested.rbegin(); it != nested.rend(); ++it) {
    pending_models_.push_back({*it, s.file, s});
  }
}

}  // namespace mdlc::frontend::sdf
