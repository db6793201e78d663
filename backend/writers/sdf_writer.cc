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
#include <span>

#include "backend/kinematics.h"
#include "backend/writers/sdf_writer_detail.h"

namespace mdlc::writers::sdf {

bool AllEqual(std::span<const double> values) {
  return std::adjacent_find(values.begin(), values.end(), std::not_equal_to<>()) ==
         values.end();
}

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

std::string Join(const std::vector<std::string>& parts, size_t from) {
  std::string out;
  for (size_t i = from; i < parts.size(); ++i) {
    if (!out.empty()) out += "::";
    out += parts[i];
  }
  return out;
}

/// The innermost scope holding both: "a::b" and "a::c" -> "a"; "" is the world.
std::string CommonScope(const std::string& x, const std::string& y) {
  const auto a = Split(x), b = Split(y);
  std::vector<std::string> common;
  for (size_t i = 0; i < a.size() && i < b.size() && a[i] == b[i]; ++i) common.push_back(a[i]);
  return Join(common);
}

bool Within(const std::string& scope, const std::string& inner) {
  return scope.empty() || inner == scope || inner.starts_with(scope + "::");
}

std::string SdfWriter::Write() {
  LinkPoses();
  BuildModels();
  ModelPoses();
  LinkFrameRefs();
  BuildElements();
  out_.Open("sdf").Attr("version", "1.9").Attr("xmlns:drake", "http://drake.mit.edu");
  std::vector<std::string> tops;
  for (const auto& [scoped, node] : models_) {
    if (Split(scoped).size() == 1) tops.push_back(scoped);
  }
  const bool gravity_default = plant_.gravity == Eigen::Vector3d(0, 0, -9.81);
  use_world_ = tops.size() != 1 || !world_.joints.empty() || !world_.frames.empty() ||
               !world_.elements.empty() || !gravity_default;
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
  for (const std::string& top : tops) WriteModel(models_.at(top));
  if (use_world_) {
    for (JointId j : world_.joints) WriteJoint(j, "");
    for (size_t f : world_.frames) WriteFrame(f, "");
    out_.Close();
  }
  out_.Close();
  return out_.Finish();
}

std::string SdfWriter::InstanceOf(BodyId body) const {
  if (body.index() == 0) return {};
  const size_t m = plant_.body(body).model.index();
  return instance_scope_[m];
}

ModelNode& SdfWriter::Scope(const std::string& scoped) {
  if (scoped.empty()) return world_;
  return models_.at(scoped);
}

/// Adds model `scoped` and each enclosing model not added yet. Instances
/// come parents first, so mostly one scope is looked up: looking up every
/// enclosing scope of every model cost the cube of the nesting depth.
/// Scopes split at each "::" from the left, as `Split` does.
void SdfWriter::AddModel(const std::string& scoped, Loc loc) {
  std::vector<size_t> ends;  // where each enclosing scope's name ends
  for (size_t at = scoped.find("::"); at != std::string::npos; at = scoped.find("::", at + 2)) {
    ends.push_back(at);
  }
  const auto prefix = [&](size_t level) {
    return level == ends.size() ? scoped : scoped.substr(0, ends[level]);
  };
  size_t first_missing = ends.size() + 1;
  while (first_missing > 0 && !models_.count(prefix(first_missing - 1))) --first_missing;
  for (size_t level = first_missing; level <= ends.size(); ++level) {
    const size_t begin = level == 0 ? 0 : ends[level - 1] + 2;
    ModelNode node;
    node.scoped = prefix(level);
    node.name = node.scoped.substr(begin);
    node.loc = loc;
    const std::string name = node.name;
    const std::string path = node.scoped;
    models_.emplace(path, std::move(node));
    if (level > 0) {
      ModelNode& parent = models_.at(prefix(level - 1));
      parent.children.push_back(path);
      parent.names.insert(name);
    }
  }
}

/// The scope each model instance is written in: its name, with an empty
/// part ("::a", "a::::b") written as "model". The world's scope is the
/// empty string, so an empty part cannot name a model.
void SdfWriter::InstanceScopes() {
  instance_scope_.assign(plant_.model_instances.size(), "");
  for (size_t m = 1; m < plant_.model_instances.size(); ++m) {
    const std::string& name = plant_.model_instances[m];
    auto parts = Split(name);
    for (std::string& part : parts) {
      if (part.empty()) part = "model";
    }
    instance_scope_[m] = Join(parts);
    if (instance_scope_[m] != name) {
      diags_.Report(DiagKind::Lossy, ModelLoc(m),
                    fmt::format("model instance '{}' has an empty name in its scope; it is "
                                "written as '{}'",
                                name, instance_scope_[m]));
    }
  }
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
  if (scope.names.count(out)) {
    const std::string base = fmt::format("{}_{}", out, kind);
    out = base;
    for (int n = 1; scope.names.count(out); ++n) out = fmt::format("{}_{}", base, n);
  }
  if (out != name && named) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("{} '{}' is written as '{}': SDFormat forbids '::' and reserved "
                              "names, and a model's links, joints, frames and nested models "
                              "share one namespace",
                              kind, name, out));
  }
  scope.names.insert(out);
  return out;
}

void SdfWriter::BuildModels() {
  InstanceScopes();
  // a model instance is written when it has a body
  std::vector<bool> has_body(plant_.model_instances.size(), false);
  for (size_t b = 1; b < plant_.bodies.size(); ++b) has_body[plant_.bodies[b].model.index()] = true;
  for (size_t m = 1; m < plant_.model_instances.size(); ++m) {
    if (has_body[m]) AddModel(instance_scope_[m], ModelLoc(m));
  }
  // links first: their names are what the other elements refer to
  link_names_.assign(plant_.bodies.size(), "world");
  for (size_t b = 1; b < plant_.bodies.size(); ++b) {
    const PlantBody& body = plant_.bodies[b];
    const std::string inst = InstanceOf(BodyId(b));
    if (inst.empty()) {
      // a body of the world instance: SDFormat has links only in models
      AddModel("world_bodies", BodyLoc(BodyId(b)));
      diags_.Report(DiagKind::Lossy, BodyLoc(BodyId(b)),
                    fmt::format("link '{}' belongs to no model; it is written in model "
                                "'world_bodies'",
                                body.name));
      body_scope_[b] = "world_bodies";
    } else {
      body_scope_[b] = inst;
    }
    ModelNode& node = Scope(body_scope_[b]);
    link_names_[b] = Claim(node, body.name, "link", BodyLoc(BodyId(b)));
    node.links.push_back(BodyId(b));
  }
  joint_names_.resize(plant_.joints.size());
  joint_scope_.resize(plant_.joints.size());
  for (size_t j = 0; j < plant_.joints.size(); ++j) {
    const PlantJoint& joint = plant_.joints[j];
    std::string scope = CommonScope(BodyScope(joint.parent), BodyScope(joint.child));
    // a joint to the world is written in its child's model (parent "world")
    if (joint.parent.index() == 0) scope = BodyScope(joint.child);
    joint_scope_[j] = scope;
    ModelNode& node = Scope(scope);
    joint_names_[j] = Claim(node, joint.name, "joint", JointLoc(JointId(j)), !joint.unnamed);
    node.joints.push_back(JointId(j));
  }
  frame_names_.resize(plant_.frames.size());
  for (size_t f = 0; f < plant_.frames.size(); ++f) {
    const backend::PlantFrame& frame = plant_.frames[f];
    if (frame.unnamed) continue;
    const std::string scope = BodyScope(frame.body);
    if (frame.name == "__model__" && frame.model.index() > 0 && frame.body.index() != 0 &&
        models_.count(instance_scope_[frame.model.index()]) &&
        Within(instance_scope_[frame.model.index()], scope)) {
      ModelNode& model = models_.at(instance_scope_[frame.model.index()]);
      if (!model.model_frame) {
        model.model_frame = f;
        continue;
      }
    }
    ModelNode& node = Scope(scope);
    frame_names_[f] = Claim(node, frame.name, "frame", FrameLoc(f));
    node.frames.push_back(f);
    const size_t m = frame.model.index();
    const std::string inst = m == 0 ? "" : plant_.model_instances[m];
    frame_refs_[inst.empty() ? frame.name : inst + "::" + frame.name] = {scope,
                                                                        frame_names_[f]};
  }
}

/// A bushing may name a link's own frame ("instance::link").
void SdfWriter::LinkFrameRefs() {
  for (size_t b = 1; b < plant_.bodies.size(); ++b) {
    frame_refs_.emplace(plant_.ScopedName(plant_.bodies[b]),
                        FrameRef{body_scope_.at(b), link_names_[b]});
  }
}

/// Model poses: a parent's comes first (a prefix sorts first).
void SdfWriter::ModelPoses() {
  for (auto& [scoped, node] : models_) {
    const auto parts = Split(scoped);
    const Transform X_WP =
        parts.size() > 1
            ? models_.at(Join(std::vector<std::string>(parts.begin(), parts.end() - 1))).X_WM
            : Transform{};
    node.X_WM = X_WP;
    if (node.model_frame) {
      const backend::PlantFrame& frame = plant_.frames[*node.model_frame];
      node.X_WM = X_WB_[frame.body.index()] * frame.X_BF;
    }
  }
}

Transform SdfWriter::ParentModelPose(const std::string& scoped) const {
  const auto parts = Split(scoped);
  if (parts.size() <= 1) return {};
  return models_.at(Join(std::vector<std::string>(parts.begin(), parts.end() - 1))).X_WM;
}

std::string SdfWriter::BodyScope(BodyId body) const {
  if (body.index() == 0) return "";
  return body_scope_.at(body.index());
}

/// How an element written in `scope` names body `body`.
std::string SdfWriter::LinkRef(const std::string& scope, BodyId body) const {
  if (body.index() == 0) return "world";
  return Relative(scope, BodyScope(body), link_names_[body.index()]);
}

std::string SdfWriter::Relative(const std::string& scope, const std::string& owner,
                                const std::string& name) {
  const auto a = Split(scope), b = Split(owner);
  std::string prefix = Join(b, a.size());
  return prefix.empty() ? name : prefix + "::" + name;
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

void SdfWriter::WriteModel(const ModelNode& node) {
  out_.Open("model").Attr("name", node.name);
  if (node.model_frame) {
    const BodyId body = plant_.frames[*node.model_frame].body;
    out_.Attr("canonical_link", Relative(node.scoped, BodyScope(body), link_names_[body.index()]));
  }
  Pose(ParentModelPose(node.scoped).inverse() * node.X_WM);
  for (BodyId b : node.links) WriteLink(b);
  for (JointId j : node.joints) WriteJoint(j, node.scoped);
  for (size_t f : node.frames) WriteFrame(f, node.scoped);
  for (const std::string& child : node.children) WriteModel(models_.at(child));
  for (const auto& element : node.elements) element();
  out_.Close();
}

void SdfWriter::WriteFrame(size_t f, const std::string& scope) {
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
