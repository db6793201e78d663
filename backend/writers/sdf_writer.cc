// sdf_writer.cc - the compiled model as SDFormat 1.9, with Drake's drake:
// extensions for what SDFormat itself cannot hold.
//
// Frames: every pose is taken with every joint at zero (q = 0, identity
// quaternions; a free body at its default pose). A model is posed where the
// plant's `__model__` frame of its instance is (on its canonical link; a
// model without one sits on its parent's frame), and each link's <pose> is
// its pose in its model's frame. A joint's
// <pose> is X_CM (its frame M in the child link, SDFormat's default
// relative_to), so the parent frame F that SDFormat implies (the joint frame
// at the links' poses) is X_PF = X_WP^-1 * X_WC * X_CM, the plant's X_PF.
// Body frames stay where they are; axes are in F, which is the joint frame
// at q = 0 (SDFormat 1.9's default for <xyz>).
//
// Structure: one <model> per model instance, a nested instance "outer::inner"
// as <model name="inner"> inside "outer"; several top-level models (or a
// gravity other than SDFormat's) make a <world>. A joint, constraint or
// filter group is written in the innermost model holding everything it
// names (world-level joints connect top-level models).
//
// Mapping (what cannot be written is a -Wlossy warning at its source):
//   weld -> fixed; revolute, prismatic, ball, universal -> the same;
//   screw -> screw with <thread_pitch>; planar -> <drake:joint>; a floating
//   joint on the world -> a free link at its default pose; coupler ->
//   <drake:mimic>; actuators -> the actuator SDFormat makes for a joint whose
//   effort is not 0, with drake:rotor_inertia, gear_ratio, controller_gains;
//   joint springs -> <spring_stiffness>/<spring_reference>; ball and distance
//   constraints, tendons, bushings, spring-dampers, collision filters -> their
//   drake: elements; cameras -> <sensor type="camera">.
#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <variant>

#include "backend/kinematics.h"
#include "backend/writers/sdf_writer_detail.h"

namespace mdlc::writers::sdf {

/// "a::b::c" -> {"a", "b", "c"}; "" -> {}.
std::vector<std::string> Split(const std::string& scoped) {
  std::vector<std::string> out;
  if (scoped.empty()) return out;
  size_t start = 0;
  for (size_t at; (at = scoped.find("::", start)) != std::string::npos; start = at + 2) {
    out.push_back(scoped.substr(start, at - start));
  }
  out.push_back(scoped.substr(start));
  return out;
}

std::string SdfWriter::Write() {
  LinkPoses();
  BuildModels();
  ModelPoses();
  LinkFrameRefs();
  BuildElements();
  out_.Open("sdf").Attr("version", "1.9").Attr("xmlns:drake", "http://drake.mit.edu");
  // top-level models in name order, as mdlc has always written them
  std::vector<ScopeId> tops = models_[kWorldScope].children;
  std::sort(tops.begin(), tops.end(),
            [&](ScopeId a, ScopeId b) { return models_[a].name < models_[b].name; });
  const bool gravity_default = plant_.gravity == Eigen::Vector3d(0, 0, -9.81);
  const ModelNode& world = models_[kWorldScope];
  use_world_ = tops.size() != 1 || !world.joints.empty() || !world.frames.empty() ||
               !world.elements.empty() || !gravity_default;
  if (use_world_) {
    out_.Open("world").Attr("name", "default");
    if (!gravity_default) out_.Open("gravity").Text(VectorText(plant_.gravity)).Close();
  }
  if (plant_.time_step != 0) {
    diags_.Report(DiagKind::Lossy, Loc{},
                  fmt::format("the time step ({} s) is not written: mdlc's SDFormat reader "
                              "takes none from a file",
                              plant_.time_step));
  }
  if (tops.empty()) {
    // SDFormat needs a model or a world; an empty world it is
    if (!use_world_) out_.Open("world").Attr("name", "default");
    use_world_ = true;
  }
  for (ScopeId top : tops) WriteModel(top);
  if (use_world_) {
    for (JointId j : world.joints) WriteJoint(j, kWorldScope);
    for (size_t f : world.frames) WriteFrame(f, kWorldScope);
    out_.Close();
  }
  out_.Close();
  return out_.Finish();
}

/// The model `name` in `parent`, made if it is not there yet.
ScopeId SdfWriter::ChildScope(ScopeId parent, const std::string& name, Loc loc) {
  const auto [it, added] = models_[parent].child_named.try_emplace(name, models_.size());
  if (!added) return it->second;
  ModelNode node;
  node.name = name;
  node.parent = parent;
  node.depth = models_[parent].depth + 1;
  node.loc = loc;
  models_.push_back(std::move(node));
  models_[parent].children.push_back(it->second);
  // a top-level model's name is not the world's to keep free
  if (parent != kWorldScope) models_[parent].names.Take(name);
  return it->second;
}

/// The model instance `m` is written as, made with the models enclosing it
/// if they are not there yet: a model per "::" in its name, so a URDF robot
/// named "a::b" is model b in model a. An empty part ("::a", "a::::b") is
/// written as "model": the world has no name to stand for it.
ScopeId SdfWriter::InstanceScope(size_t m) {
  // the instance and its ancestors not made yet, innermost first (a loop:
  // instances can nest thousands deep)
  std::vector<size_t> chain;
  for (size_t at = m; !instance_scope_[at];) {
    chain.push_back(at);
    const ModelId parent = plant_.model_instances.parent(at);
    if (!parent.valid()) break;
    at = parent.index();
  }
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    const ModelId parent = plant_.model_instances.parent(*it);
    ScopeId scope = parent.valid() ? *instance_scope_[parent.index()] : kWorldScope;
    bool empty_part = false;
    for (std::string part : Split(plant_.model_instances.local(*it))) {
      empty_part |= part.empty();
      scope = ChildScope(scope, part.empty() ? "model" : part, ModelLoc(*it));
    }
    if (empty_part) {
      diags_.Report(DiagKind::Lossy, ModelLoc(*it),
                    fmt::format("model instance '{}' has an empty name in its scope; it is "
                                "written as '{}'",
                                plant_.model_instances[*it], ScopedName(scope)));
    }
    instance_scope_[*it] = scope;
  }
  return *instance_scope_[m];
}

/// "outer::inner", for messages: built on demand, as it is O(depth).
std::string SdfWriter::ScopedName(ScopeId scope) const {
  std::vector<ScopeId> chain;
  for (ScopeId at = scope; at != kWorldScope; at = models_[at].parent) chain.push_back(at);
  std::string out;
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    if (!out.empty()) out += "::";
    out += models_[*it].name;
  }
  return out;
}

/// The innermost model holding both; the world holds every model.
ScopeId SdfWriter::CommonScope(ScopeId a, ScopeId b) const {
  while (models_[a].depth > models_[b].depth) a = models_[a].parent;
  while (models_[b].depth > models_[a].depth) b = models_[b].parent;
  while (a != b) {
    a = models_[a].parent;
    b = models_[b].parent;
  }
  return a;
}

/// Whether `inner` is `scope` or nested in it.
bool SdfWriter::Within(ScopeId scope, ScopeId inner) const {
  while (models_[inner].depth > models_[scope].depth) inner = models_[inner].parent;
  return inner == scope;
}

/// The top-level model `scope` is in (the world for the world).
ScopeId SdfWriter::TopLevelModel(ScopeId scope) const {
  while (models_[scope].depth > 1) scope = models_[scope].parent;
  return scope;
}

/// A name SDFormat accepts and that is free in `scope`: "::" and reserved
/// names are replaced, a taken name gets a suffix; each change reported.
/// A compiler-made name (`named` false) changes without a word.
std::string SdfWriter::Claim(ModelNode& scope, const std::string& name, std::string_view kind,
                             Loc loc, bool named) {
  std::string out = name;
  for (size_t at; (at = out.find("::")) != std::string::npos;) out.replace(at, 2, "__");
  if (out.empty()) out = std::string(kind);
  if (out == "world" || out.starts_with("__")) out = fmt::format("{}_{}", kind, out);
  if (!scope.names.Take(out)) out = scope.names.TakeUnique(fmt::format("{}_{}", out, kind));
  if (out != name && named) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("{} '{}' is written as '{}': SDFormat forbids '::' and reserved "
                              "names, and a model's links, joints, frames and nested models "
                              "share one namespace",
                              kind, name, out));
  }
  return out;
}

void SdfWriter::BuildModels() {
  // frames by their plant names, which bushings refer to: full names cost
  // the square of the nesting depth, so they are made only for bushings
  bushings_ = std::any_of(plant_.force_elements.begin(), plant_.force_elements.end(),
                          [](const backend::ForceElement& f) {
                            return std::holds_alternative<backend::LinearBushingRpy>(f);
                          });
  // a model instance is written when it has a body
  instance_scope_.assign(plant_.model_instances.size(), std::nullopt);
  std::vector<bool> has_body(plant_.model_instances.size(), false);
  for (size_t b = 1; b < plant_.bodies.size(); ++b) has_body[plant_.bodies[b].model.index()] = true;
  for (size_t m = 1; m < plant_.model_instances.size(); ++m) {
    if (has_body[m]) InstanceScope(m);
  }
  // links first: their names are what the other elements refer to
  link_names_.assign(plant_.bodies.size(), "world");
  body_scope_.assign(plant_.bodies.size(), kWorldScope);
  for (size_t b = 1; b < plant_.bodies.size(); ++b) {
    const PlantBody& body = plant_.bodies[b];
    const size_t m = body.model.index();
    if (m == 0) {
      // a body of the world instance: SDFormat has links only in models
      body_scope_[b] = ChildScope(kWorldScope, "world_bodies", BodyLoc(BodyId(b)));
      diags_.Report(DiagKind::Lossy, BodyLoc(BodyId(b)),
                    fmt::format("link '{}' belongs to no model; it is written in model "
                                "'world_bodies'",
                                body.name));
    } else {
      body_scope_[b] = *instance_scope_[m];
    }
    ModelNode& node = models_[body_scope_[b]];
    link_names_[b] = Claim(node, body.name, "link", BodyLoc(BodyId(b)));
    node.links.push_back(BodyId(b));
  }
  joint_names_.resize(plant_.joints.size());
  joint_scope_.resize(plant_.joints.size());
  for (size_t j = 0; j < plant_.joints.size(); ++j) {
    const PlantJoint& joint = plant_.joints[j];
    // a joint to the world is written in its child's model (parent "world");
    // the common scope of the world and a model N deep is found in N steps,
    // and a world of models nested N deep, each floating, has N such joints
    const ScopeId scope = joint.parent.index() == 0
                              ? BodyScope(joint.child)
                              : CommonScope(BodyScope(joint.parent), BodyScope(joint.child));
    joint_scope_[j] = scope;
    ModelNode& node = models_[scope];
    joint_names_[j] = Claim(node, joint.name, "joint", JointLoc(JointId(j)), !joint.unnamed);
    node.joints.push_back(JointId(j));
  }
  frame_names_.resize(plant_.frames.size());
  for (size_t f = 0; f < plant_.frames.size(); ++f) {
    const backend::PlantFrame& frame = plant_.frames[f];
    if (frame.unnamed) continue;
    const ScopeId scope = BodyScope(frame.body);
    const std::optional<ScopeId> instance = instance_scope_[frame.model.index()];
    if (frame.name == "__model__" && frame.model.index() > 0 && frame.body.index() != 0 &&
        instance && Within(*instance, scope)) {
      ModelNode& model = models_[*instance];
      if (!model.model_frame) {
        model.model_frame = f;
        continue;
      }
    }
    ModelNode& node = models_[scope];
    frame_names_[f] = Claim(node, frame.name, "frame", FrameLoc(f));
    node.frames.push_back(f);
    if (bushings_) {
      const size_t m = frame.model.index();
      frame_refs_[m == 0 ? frame.name : plant_.model_instances.Scoped(frame.model, frame.name)] =
          {scope, frame_names_[f]};
    }
  }
}

/// A bushing may name a link's own frame ("instance::link").
void SdfWriter::LinkFrameRefs() {
  if (!bushings_) return;
  for (size_t b = 1; b < plant_.bodies.size(); ++b) {
    frame_refs_.emplace(plant_.ScopedName(plant_.bodies[b]),
                        FrameRef{body_scope_.at(b), link_names_[b]});
  }
}

/// Model poses: a parent is made before the models nested in it.
void SdfWriter::ModelPoses() {
  for (ScopeId scope = 0; scope < models_.size(); ++scope) {
    ModelNode& node = models_[scope];
    node.X_WM = ParentModelPose(scope);
    if (node.model_frame) {
      const backend::PlantFrame& frame = plant_.frames[*node.model_frame];
      node.X_WM = X_WB_[frame.body.index()] * frame.X_BF;
    }
  }
}

Transform SdfWriter::ParentModelPose(ScopeId scope) const {
  const ModelNode& node = models_[scope];
  return node.depth > 1 ? models_[node.parent].X_WM : Transform{};
}

ScopeId SdfWriter::BodyScope(BodyId body) const {
  return body.index() == 0 ? kWorldScope : body_scope_.at(body.index());
}

/// How an element written in `scope` names body `body`.
std::string SdfWriter::LinkRef(ScopeId scope, BodyId body) const {
  if (body.index() == 0) return "world";
  return Relative(scope, BodyScope(body), link_names_[body.index()]);
}

/// How an element written in `scope` names `name` of model `owner`, nested
/// in `scope`: "inner::name".
std::string SdfWriter::Relative(ScopeId scope, ScopeId owner, const std::string& name) const {
  std::vector<ScopeId> chain;
  for (; models_[owner].depth > models_[scope].depth; owner = models_[owner].parent) {
    chain.push_back(owner);
  }
  std::string out;
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) out += models_[*it].name + "::";
  return out + name;
}

void SdfWriter::LinkPoses() {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(plant_.num_positions);
  for (const PlantJoint& j : plant_.joints) {
    if (IsFreeRoot(j)) {
      for (int k = 0; k < j.nq; ++k) q[j.q_start + k] = j.default_positions[k];
    }
  }
  X_WB_ = backend::BodyPosesInWorld(plant_, q);
}

bool SdfWriter::IsFreeRoot(const PlantJoint& j) {
  return IsFloating(j) && j.parent.index() == 0 && j.X_PF.IsIdentity() && j.X_CM.IsIdentity();
}

void SdfWriter::Pose(const Transform& X, std::string_view relative_to) {
  if (X.IsIdentity() && relative_to.empty()) return;
  out_.Open("pose");
  if (!relative_to.empty()) out_.Attr("relative_to", relative_to);
  out_.Text(fmt::format("{} {}", VectorText(X.p), VectorText(RpyFromRotation(X.R))));
  out_.Close();
}

void SdfWriter::Value(std::string_view tag, double v) {
  out_.Open(tag).Text(NumberText(v)).Close();
}

void SdfWriter::Value(std::string_view tag, const Eigen::Vector3d& v) {
  out_.Open(tag).Text(VectorText(v)).Close();
}

void SdfWriter::Value(std::string_view tag, std::string_view text) {
  out_.Open(tag).Text(text).Close();
}

void SdfWriter::WriteModel(ScopeId top) {
  // a loop, not recursion: a model nested 20,000 deep overflowed the stack
  std::vector<std::pair<ScopeId, size_t>> open;  // a model, its next child to write
  auto open_model = [&](ScopeId scope) {
    const ModelNode& node = models_[scope];
    out_.Open("model").Attr("name", node.name);
    if (node.model_frame) {
      const BodyId body = plant_.frames[*node.model_frame].body;
      out_.Attr("canonical_link", Relative(scope, BodyScope(body), link_names_[body.index()]));
    }
    Pose(ParentModelPose(scope).inverse() * node.X_WM);
    for (BodyId b : node.links) WriteLink(b);
    for (JointId j : node.joints) WriteJoint(j, scope);
    for (size_t f : node.frames) WriteFrame(f, scope);
    open.emplace_back(scope, 0);
  };
  open_model(top);
  while (!open.empty()) {
    const ModelNode& node = models_[open.back().first];
    if (open.back().second < node.children.size()) {
      open_model(node.children[open.back().second++]);
      continue;
    }
    for (const auto& element : node.elements) element();
    out_.Close();
    open.pop_back();
  }
}

void SdfWriter::WriteFrame(size_t f, ScopeId scope) {
  const backend::PlantFrame& frame = plant_.frames[f];
  if (frame.body.index() == 0 && !use_world_) {
    diags_.Report(DiagKind::Lossy, FrameLoc(f),
                  fmt::format("frame '{}' on the world is dropped: only an SDFormat world "
                              "holds frames on the world",
                              frame.name));
    return;
  }
  const std::string link = LinkRef(scope, frame.body);
  out_.Open("frame").Attr("name", frame_names_[f]).Attr("attached_to", link);
  Pose(frame.X_BF, link);
  out_.Close();
}

}  // namespace mdlc::writers::sdf

namespace mdlc::writers {

std::optional<std::string> WriteSdf(const backend::CompiledModel& model,
                                    const ir::Module& module, const WriteOptions& options,
                                    DiagnosticEngine& diags) {
  return sdf::SdfWriter(model, module, options, diags).Write();
}

}  // namespace mdlc::writers
