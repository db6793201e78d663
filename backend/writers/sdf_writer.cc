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
#include <cmath>
#include <limits>
#include <functional>
#include <map>
#include <numbers>
#include <set>
#include <variant>

#include "backend/kinematics.h"
#include "backend/writers/asset_paths.h"
#include "backend/writers/writer.h"
#include "backend/writers/xml_out.h"
#include "ir/overloaded.h"

namespace mdlc::writers {
namespace {

using backend::PlantBody;
using backend::PlantJoint;
constexpr double kInf = std::numeric_limits<double>::infinity();

bool AllEqual(const std::vector<double>& values) {
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

std::string Join(const std::vector<std::string>& parts, size_t from = 0) {
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

/// A model: its links, joints, frames, nested models and drake: elements.
struct ModelNode {
  std::string scoped;  // "outer::inner"
  std::string name;    // "inner"
  Loc loc;
  std::vector<BodyId> links;
  std::vector<JointId> joints;
  std::vector<size_t> frames;
  std::vector<std::string> children;  // scoped names of nested models
  std::vector<std::function<void()>> elements;  // drake: elements, written last
  std::set<std::string> names;        // the model's one namespace
  /// The plant's frame for this model's `__model__`, when it is on one of
  /// the model's links: the model is posed there (X_WM, at q = 0) and its
  /// canonical link is that link, so the frame is SDFormat's own.
  std::optional<size_t> model_frame;
  Transform X_WM;
};

class SdfWriter {
 public:
  SdfWriter(const backend::CompiledModel& model, const ir::Module& module,
            const WriteOptions& options, DiagnosticEngine& diags)
      : plant_(model.plant),
        scene_(model.scene),
        m_(module),
        diags_(diags),
        assets_(options, diags) {}

  std::string Write() {
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

 private:
  // -- where everything goes

  // by value: the plant builds instance names as they are asked for
  std::string InstanceOf(BodyId body) const {
    if (body.index() == 0) return {};
    const size_t m = plant_.body(body).model.index();
    return m == 0 ? std::string() : plant_.model_instances[m];
  }
  ModelNode& Scope(const std::string& scoped) {
    if (scoped.empty()) return world_;
    return models_.at(scoped);
  }
  Loc BodyLoc(BodyId body) const {
    return body.index() < m_.bodies.size() ? m_.bodies[body.index()].loc : Loc{};
  }
  Loc JointLoc(JointId joint) const {
    return joint.index() < m_.joints.size() ? m_.joints[joint.index()].loc : Loc{};
  }
  Loc FrameLoc(size_t f) const { return f < m_.frames.size() ? m_.frames[f].loc : Loc{}; }
  Loc ModelLoc(size_t m) const { return m < m_.models.size() ? m_.models[m].loc : Loc{}; }

  void AddModel(const std::string& scoped, Loc loc) {
    const auto parts = Split(scoped);
    std::string path;
    for (size_t i = 0; i < parts.size(); ++i) {
      const std::string parent = path;
      path = Join(parts, 0);
      path = Join(std::vector<std::string>(parts.begin(), parts.begin() + i + 1));
      if (models_.count(path)) continue;
      ModelNode node;
      node.scoped = path;
      node.name = parts[i];
      node.loc = loc;
      models_.emplace(path, std::move(node));
      if (!parent.empty()) {
        models_.at(parent).children.push_back(path);
        models_.at(parent).names.insert(parts[i]);
      }
    }
  }

  /// A name SDFormat accepts and that is free in `scope`: "::" and reserved
  /// names are replaced, a taken name gets a suffix; each change reported.
  /// A compiler-made name (`named` false) changes without a word.
  std::string Claim(ModelNode& scope, const std::string& name, std::string_view kind, Loc loc,
                    bool named = true) {
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

  void BuildModels() {
    for (size_t m = 1; m < plant_.model_instances.size(); ++m) {
      bool used = false;
      for (size_t b = 1; b < plant_.bodies.size(); ++b) {
        used = used || plant_.bodies[b].model.index() == m;
      }
      if (used) AddModel(plant_.model_instances[m], ModelLoc(m));
    }
    // links first: their names are what the other elements refer to
    link_names_.assign(plant_.bodies.size(), "world");
    for (size_t b = 1; b < plant_.bodies.size(); ++b) {
      const PlantBody& body = plant_.bodies[b];
      const std::string& inst = InstanceOf(BodyId(b));
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
          models_.count(plant_.model_instances[frame.model.index()]) &&
          Within(plant_.model_instances[frame.model.index()], scope)) {
        ModelNode& model = models_.at(plant_.model_instances[frame.model.index()]);
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
  /// Model-level drake: elements, each in the innermost model holding what
  /// it names; what only the world could hold is reported.
  void BuildElements() {
    auto place = [&](const std::vector<std::string>& scopes, Loc loc, const std::string& what,
                     std::function<void(const std::string&)> write) {
      std::string scope = scopes.empty() ? "" : scopes[0];
      for (const std::string& s : scopes) scope = CommonScope(scope, s);
      if (scope.empty()) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("{} is dropped: it names links of different top-level models "
                                  "(or the world), and SDFormat reads drake: elements only in "
                                  "a model",
                                  what));
        return;
      }
      Scope(scope).elements.push_back([write, scope] { write(scope); });
    };
    for (size_t i = 0; i < plant_.constraints.size(); ++i) {
      const backend::PlantConstraint& c = plant_.constraints[i];
      const Loc loc = i < m_.constraints.size() ? m_.constraints[i].loc : Loc{};
      std::visit(
          ir::Overloaded{
              [&](const backend::CouplerConstraint&) {},  // the follower's <drake:mimic>
              [&](const backend::BallConstraint& k) {
                place({BodyScope(k.body_A), BodyScope(k.body_B)}, loc, "a ball constraint",
                      [this, k](const std::string& scope) {
                        out_.Open("drake:ball_constraint");
                        BodiesAndPoints(scope, "drake:ball_constraint", k.body_A, k.body_B,
                                        k.p_AP, k.p_BQ);
                        out_.Close();
                      });
              },
              [&](const backend::DistanceConstraint& k) {
                place({BodyScope(k.body_A), BodyScope(k.body_B)}, loc, "a distance constraint",
                      [this, k](const std::string& scope) {
                        const std::string p = "drake:distance_constraint";
                        out_.Open(p);
                        BodiesAndPoints(scope, p, k.body_A, k.body_B, k.p_AP, k.p_BQ);
                        Value(p + "_distance", k.distance);
                        Value(p + "_stiffness", k.stiffness);
                        Value(p + "_damping", k.damping);
                        out_.Close();
                      });
              },
              [&](const backend::WeldConstraint&) {
                diags_.Report(DiagKind::Lossy, loc,
                              "SDFormat has no weld constraint (Drake reads none); this one is "
                              "dropped");
              },
              [&](const backend::TendonConstraint& k) {
                std::vector<std::string> scopes;
                for (JointId j : k.joints) scopes.push_back(joint_scope_[j.index()]);
                const std::string first = scopes.empty() ? "" : scopes[0];
                if (!std::all_of(scopes.begin(), scopes.end(),
                                 [&](const std::string& s) { return s == first; }) ||
                    first.empty()) {
                  diags_.Report(DiagKind::Lossy, loc,
                                "a tendon constraint is dropped: its joints are not all of one "
                                "model, which <drake:tendon_constraint> needs");
                  return;
                }
                Scope(first).elements.push_back([this, k] {
                  const std::string p = "drake:tendon_constraint";
                  out_.Open(p);
                  for (size_t n = 0; n < k.joints.size(); ++n) {
                    out_.Open(p + "_joint")
                        .Attr("name", joint_names_[k.joints[n].index()])
                        .Attr("a", k.a[n])
                        .Close();
                  }
                  Value(p + "_offset", k.offset);
                  if (k.lower != -kInf) Value(p + "_lower_limit", k.lower);
                  if (k.upper != kInf) Value(p + "_upper_limit", k.upper);
                  if (k.stiffness != kInf) Value(p + "_stiffness", k.stiffness);
                  Value(p + "_damping", k.damping);
                  out_.Close();
                });
              },
          },
          c.payload);
    }
    for (const backend::ForceElement& f : plant_.force_elements) {
      std::visit(
          ir::Overloaded{
              [&](const backend::LinearBushingRpy& k) {
                auto a = frame_refs_.find(k.frameA), c = frame_refs_.find(k.frameC);
                if (a == frame_refs_.end() || c == frame_refs_.end()) {
                  diags_.Report(DiagKind::Lossy, Loc{},
                                fmt::format("the bushing between '{}' and '{}' is dropped: a "
                                            "frame it names is not written",
                                            k.frameA, k.frameC));
                  return;
                }
                const FrameRef fa = a->second, fc = c->second;
                place({fa.scope, fc.scope}, Loc{}, "a linear bushing",
                      [this, k, fa, fc](const std::string& scope) {
                        const std::string p = "drake:bushing_";
                        out_.Open("drake:linear_bushing_rpy");
                        Value(p + "frameA", Relative(scope, fa.scope, fa.name));
                        Value(p + "frameC", Relative(scope, fc.scope, fc.name));
                        Value(p + "torque_stiffness", k.torque_stiffness);
                        Value(p + "torque_damping", k.torque_damping);
                        Value(p + "force_stiffness", k.force_stiffness);
                        Value(p + "force_damping", k.force_damping);
                        out_.Close();
                      });
              },
              [&](const backend::LinearSpringDamper& k) {
                place({BodyScope(k.body_A), BodyScope(k.body_B)}, Loc{}, "a linear spring-damper",
                      [this, k](const std::string& scope) {
                        const std::string p = "drake:linear_spring_damper";
                        out_.Open(p);
                        BodiesAndPoints(scope, p, k.body_A, k.body_B, k.p_AP, k.p_BQ);
                        Value(p + "_free_length", k.free_length);
                        Value(p + "_stiffness", k.stiffness);
                        Value(p + "_damping", k.damping);
                        out_.Close();
                      });
              },
              [&](const backend::JointSpring&) {},  // the joint's <dynamics>
          },
          f);
    }
    int n = 0;
    for (const auto& pair : scene_.collision_filters) {
      const BodyId a = pair.first, b = pair.second;  // named copies: lambdas capture them
      if (a.index() == 0 || b.index() == 0) {
        const BodyId other = a.index() == 0 ? b : a;
        diags_.Report(DiagKind::Lossy, BodyLoc(other),
                      fmt::format("the collision filter between link '{}' and the world is "
                                  "dropped: a collision filter group cannot name the world",
                                  link_names_[other.index()]));
        continue;
      }
      const std::string name = fmt::format("filter{}", n++);
      place({BodyScope(a), BodyScope(b)}, BodyLoc(a),
            fmt::format("the collision filter between links '{}' and '{}'",
                        link_names_[a.index()], link_names_[b.index()]),
            [this, a, b, name](const std::string& scope) {
              out_.Open("drake:collision_filter_group").Attr("name", name);
              Value("drake:member", LinkRef(scope, a));
              Value("drake:member", LinkRef(scope, b));
              Value("drake:ignored_collision_filter_group", name);
              out_.Close();
            });
    }
    size_t ir_index = 0;
    for (const backend::SceneGeometry& g : scene_.geometries) {
      while (ir_index < m_.geometries.size() && m_.geometries[ir_index].roles == 0) ++ir_index;
      const Loc loc = ir_index < m_.geometries.size() ? m_.geometries[ir_index].loc : Loc{};
      ++ir_index;
      if (g.body.index() != 0) continue;
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("geometry '{}' on the world is dropped: SDFormat puts geometry "
                                "on links only",
                                g.name));
    }
    for (const backend::SceneCamera& c : scene_.cameras) {
      if (c.body.index() != 0) continue;
      diags_.Report(DiagKind::Lossy, Loc{},
                    fmt::format("camera '{}' on the world is dropped: SDFormat puts sensors "
                                "on links only",
                                c.name));
    }
  }
  void BodiesAndPoints(const std::string& scope, const std::string& prefix, BodyId A, BodyId B,
                       const Eigen::Vector3d& p_AP, const Eigen::Vector3d& p_BQ) {
    Value(prefix + "_body_A", LinkRef(scope, A));
    Value(prefix + "_p_AP", p_AP);
    Value(prefix + "_body_B", LinkRef(scope, B));
    Value(prefix + "_p_BQ", p_BQ);
  }

  /// A bushing may name a link's own frame ("instance::link").
  void LinkFrameRefs() {
    for (size_t b = 1; b < plant_.bodies.size(); ++b) {
      frame_refs_.emplace(plant_.ScopedName(plant_.bodies[b]),
                          FrameRef{body_scope_.at(b), link_names_[b]});
    }
  }

  /// Model poses: a parent's comes first (a prefix sorts first).
  void ModelPoses() {
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
  Transform ParentModelPose(const std::string& scoped) const {
    const auto parts = Split(scoped);
    if (parts.size() <= 1) return {};
    return models_.at(Join(std::vector<std::string>(parts.begin(), parts.end() - 1))).X_WM;
  }

  std::string BodyScope(BodyId body) const {
    if (body.index() == 0) return "";
    return body_scope_.at(body.index());
  }

  /// How an element written in `scope` names body `body`.
  std::string LinkRef(const std::string& scope, BodyId body) const {
    if (body.index() == 0) return "world";
    return Relative(scope, BodyScope(body), link_names_[body.index()]);
  }
  static std::string Relative(const std::string& scope, const std::string& owner,
                              const std::string& name) {
    const auto a = Split(scope), b = Split(owner);
    std::string prefix = Join(b, a.size());
    return prefix.empty() ? name : prefix + "::" + name;
  }

  // -- link poses: every joint at zero, free bodies at their default pose

  void LinkPoses() {
    Eigen::VectorXd q = Eigen::VectorXd::Zero(plant_.num_positions);
    for (const PlantJoint& j : plant_.joints) {
      if (IsFreeRoot(j)) {
        for (int k = 0; k < j.nq; ++k) q[j.q_start + k] = j.default_positions[k];
      }
    }
    X_WB_ = backend::BodyPosesInWorld(plant_, q);
  }
  static bool IsFloating(const PlantJoint& j) {
    return j.type == ir::JointType::QuaternionFloating || j.type == ir::JointType::RpyFloating;
  }
  static bool IsFreeRoot(const PlantJoint& j) {
    return IsFloating(j) && j.parent.index() == 0 && j.X_PF.IsIdentity() && j.X_CM.IsIdentity();
  }

  void Pose(const Transform& X, std::string_view relative_to = {}) {
    if (X.IsIdentity() && relative_to.empty()) return;
    out_.Open("pose");
    if (!relative_to.empty()) out_.Attr("relative_to", relative_to);
    out_.Text(fmt::format("{} {}", VectorText(X.p), VectorText(RpyFromRotation(X.R))));
    out_.Close();
  }
  void Value(std::string_view tag, double v) { out_.Open(tag).Text(NumberText(v)).Close(); }
  void Value(std::string_view tag, const Eigen::Vector3d& v) {
    out_.Open(tag).Text(VectorText(v)).Close();
  }
  void Value(std::string_view tag, std::string_view text) { out_.Open(tag).Text(text).Close(); }

  // -- models

  void WriteModel(const ModelNode& node) {
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

  // -- links

  void WriteLink(BodyId body) {
    const PlantBody& b = plant_.body(body);
    out_.Open("link").Attr("name", link_names_[body.index()]);
    Pose(models_.at(BodyScope(body)).X_WM.inverse() * X_WB_[body.index()]);
    if (b.deformable) {
      diags_.Report(DiagKind::Lossy, BodyLoc(body),
                    fmt::format("link '{}' is deformable; its deformable properties are not "
                                "written, so it is a massless rigid link",
                                b.name));
    }
    // always an <inertial>: without one SDFormat gives a link 1 kg
    out_.Open("inertial");
    Pose(Transform::FromTranslation(b.p_BoBcm_B));
    Value("mass", b.mass);
    const Eigen::Matrix3d& I = b.I_BBcm_B;
    out_.Open("inertia");
    Value("ixx", I(0, 0));
    Value("ixy", I(0, 1));
    Value("ixz", I(0, 2));
    Value("iyy", I(1, 1));
    Value("iyz", I(1, 2));
    Value("izz", I(2, 2));
    out_.Close();
    out_.Close();
    if (b.surface_velocity_axis) Value("drake:surface_velocity_axis", *b.surface_velocity_axis);
    WriteGeometries(body);
    WriteCameras(body);
    out_.Close();
  }

  // -- geometry

  void WriteGeometries(BodyId body) {
    std::set<std::string> visual_names, collision_names;
    size_t ir_index = 0;  // scene geometries are the IR's with a role, in order
    for (const backend::SceneGeometry& g : scene_.geometries) {
      while (ir_index < m_.geometries.size() && m_.geometries[ir_index].roles == 0) ++ir_index;
      const Loc loc = ir_index < m_.geometries.size() ? m_.geometries[ir_index].loc : Loc{};
      ++ir_index;
      if (g.body != body) continue;
      WriteGeometry(g, loc, visual_names, collision_names);
    }
  }

  static std::string Unique(std::set<std::string>& names, const std::string& name) {
    std::string out = name.empty() ? "geometry" : name;
    for (int n = 1; !names.insert(out).second; ++n) out = fmt::format("{}_{}", name, n);
    return out;
  }

  void WriteGeometry(const backend::SceneGeometry& g, Loc loc, std::set<std::string>& visuals,
                     std::set<std::string>& collisions) {
    const bool illustration = g.roles & ir::kIllustrationRole;
    const bool perception = g.roles & ir::kPerceptionRole;
    if (illustration || perception) {
      out_.Open("visual").Attr("name", Unique(visuals, g.name));
      Pose(g.X_BG);
      Shape(g, loc, /*collision=*/false);
      Material(g, loc);
      if (!illustration) {
        out_.Open("drake:illustration_properties").Attr("enabled", "false").Close();
      }
      if (!perception) {
        out_.Open("drake:perception_properties").Attr("enabled", "false").Close();
      }
      if (const ir::Property* accepting = Find(g, "renderer/accepting")) {
        if (const auto* names = std::get_if<std::vector<std::string>>(&accepting->value)) {
          for (const std::string& n : *names) Value("drake:accepting_renderer", n);
        }
      }
      out_.Close();
    }
    if (g.roles & ir::kProximityRole) {
      out_.Open("collision").Attr("name", Unique(collisions, g.name));
      Pose(g.X_BG);
      Shape(g, loc, /*collision=*/true);
      ProximityProperties(g, loc);
      out_.Close();
    }
  }

  void Shape(const backend::SceneGeometry& g, Loc loc, bool collision) {
    out_.Open("geometry");
    std::visit(ir::Overloaded{
                   [&](const ir::Box& s) {
                     out_.Open("box");
                     Value("size", s.size);
                     out_.Close();
                   },
                   [&](const ir::Sphere& s) {
                     out_.Open("sphere");
                     Value("radius", s.radius);
                     out_.Close();
                   },
                   [&](const ir::Cylinder& s) {
                     out_.Open("cylinder");
                     Value("radius", s.radius);
                     Value("length", s.length);
                     out_.Close();
                   },
                   [&](const ir::Capsule& s) {
                     out_.Open("capsule");
                     Value("radius", s.radius);
                     Value("length", s.length);
                     out_.Close();
                   },
                   [&](const ir::Ellipsoid& s) {
                     out_.Open("ellipsoid");
                     Value("radii", Eigen::Vector3d(s.a, s.b, s.c));
                     out_.Close();
                   },
                   [&](const ir::HalfSpace&) {
                     // a plane's +z normal is the half space's (X_BG holds it)
                     out_.Open("plane");
                     Value("normal", "0 0 1");
                     out_.Close();
                   },
                   [&](const ir::Mesh& s) {
                     out_.Open("mesh");
                     if (auto name =
                             assets_.Name(s.uri, s.resolved, s.uri_loc.valid() ? s.uri_loc : loc)) {
                       Value("uri", *name);
                     }
                     if (s.scale != Eigen::Vector3d::Ones()) Value("scale", s.scale);
                     if (s.convex && collision) out_.Open("drake:declare_convex").Close();
                     out_.Close();
                   },
               },
               g.shape);
    out_.Close();
  }

  static const ir::Property* Find(const backend::SceneGeometry& g, std::string_view key) {
    for (const ir::Property& p : g.properties) {
      if (p.key == key) return &p;
    }
    return nullptr;
  }

  void Material(const backend::SceneGeometry& g, Loc loc) {
    const ir::Property* diffuse = Find(g, "phong/diffuse");
    const ir::Property* texture = Find(g, "phong/diffuse_map");
    // SDFormat's other material colors, as the reader takes them
    static constexpr std::string_view kColors[] = {"ambient", "specular", "emissive"};
    auto is_color = [&](std::string_view key) {
      return std::any_of(std::begin(kColors), std::end(kColors),
                         [&](std::string_view c) { return key == fmt::format("phong/{}", c); });
    };
    bool colors = false;
    for (const ir::Property& p : g.properties) {
      if (is_color(p.key)) {
        const auto* rgba = std::get_if<std::vector<double>>(&p.value);
        colors = colors || (rgba && rgba->size() == 4);
      }
    }
    for (const ir::Property& p : g.properties) {
      if (is_color(p.key)) {
        const auto* rgba = std::get_if<std::vector<double>>(&p.value);
        if (rgba && rgba->size() == 4) continue;
      }
      if ((p.key.starts_with("phong/") && p.key != "phong/diffuse" &&
           p.key != "phong/diffuse_map") ||
          (p.key.starts_with("renderer/") && p.key != "renderer/accepting") ||
          p.key.starts_with("label/")) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("property '{}' of geometry '{}' has no SDFormat spelling; it "
                                  "is dropped",
                                  p.key, g.name));
      }
    }
    if (!diffuse && !texture && !colors) return;
    out_.Open("material");
    for (std::string_view c : kColors) {
      const ir::Property* p = Find(g, fmt::format("phong/{}", c));
      const auto* rgba = p ? std::get_if<std::vector<double>>(&p->value) : nullptr;
      if (rgba && rgba->size() == 4) {
        Value(c, VectorText(Eigen::Map<const Eigen::Vector4d>(rgba->data())));
      }
    }
    if (diffuse) {
      if (const auto* rgba = std::get_if<std::vector<double>>(&diffuse->value);
          rgba && rgba->size() == 4) {
        Value("diffuse", VectorText(Eigen::Map<const Eigen::Vector4d>(rgba->data())));
      }
    }
    if (texture) {
      if (const auto* path = std::get_if<std::string>(&texture->value)) {
        if (auto name = assets_.Name(*path, *path, loc)) Value("drake:diffuse_map", *name);
      }
    }
    out_.Close();
  }

  // <drake:proximity_properties> (EXT-020), values as element text
  void ProximityProperties(const backend::SceneGeometry& g, Loc loc) {
    struct Child {
      std::string_view key, tag;
    };
    static constexpr Child kValueChildren[] = {
        {"hydroelastic/resolution_hint", "drake:mesh_resolution_hint"},
        {"hydroelastic/hydroelastic_modulus", "drake:hydroelastic_modulus"},
        {"material/hunt_crossley_dissipation", "drake:hunt_crossley_dissipation"},
        {"material/point_contact_stiffness", "drake:point_contact_stiffness"},
        {"material/relaxation_time", "drake:relaxation_time"},
        {"hydroelastic/margin", "drake:hydroelastic_margin"},
    };
    bool open = false;
    auto open_once = [&] {
      if (!open) out_.Open("drake:proximity_properties");
      open = true;
    };
    for (const ir::Property& p : g.properties) {
      if (p.key.starts_with("phong/") || p.key.starts_with("renderer/") ||
          p.key.starts_with("label/")) {
        continue;  // appearance: the visual's
      }
      const double* number = std::get_if<double>(&p.value);
      const auto* vector = std::get_if<std::vector<double>>(&p.value);
      const auto* text = std::get_if<std::string>(&p.value);
      const auto child = std::find_if(std::begin(kValueChildren), std::end(kValueChildren),
                                      [&](const Child& c) { return c.key == p.key; });
      if (child != std::end(kValueChildren) && number) {
        open_once();
        Value(child->tag, *number);
      } else if (p.key == "material/coulomb_friction" && vector && vector->size() == 2) {
        open_once();
        Value("drake:mu_static", (*vector)[0]);
        Value("drake:mu_dynamic", (*vector)[1]);
      } else if (p.key == "hydroelastic/compliance_type" && text &&
                 (*text == "rigid" || *text == "compliant")) {
        open_once();
        out_.Open(*text == "rigid" ? "drake:rigid_hydroelastic" : "drake:compliant_hydroelastic")
            .Close();
      } else {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("proximity property '{}' of geometry '{}' has no SDFormat "
                                  "spelling; it is dropped",
                                  p.key, g.name));
      }
    }
    if (open) out_.Close();
  }

  // -- cameras: <sensor type="camera">, posed X_BC in the link

  void WriteCameras(BodyId body) {
    std::set<std::string> names;
    for (const backend::SceneCamera& c : scene_.cameras) {
      if (c.body != body) continue;
      // the reader names a camera "model/sensor"
      std::string name = c.name;
      const std::string& inst = plant_.model_instances[c.model.index()];
      if (name.starts_with(inst + "/")) name = name.substr(inst.size() + 1);
      out_.Open("sensor").Attr("name", Unique(names, name)).Attr("type", "camera");
      Pose(c.X_BC);
      out_.Open("camera");
      const double hfov = 2 * std::atan(std::tan(c.fov_y / 2) * c.width / c.height);
      Value("horizontal_fov", hfov);
      out_.Open("image");
      Value("width", std::to_string(c.width));
      Value("height", std::to_string(c.height));
      out_.Close();
      out_.Close();
      out_.Close();
    }
  }

  // -- joints

  void WriteJoint(JointId id, const std::string& scope) {
    const PlantJoint& j = plant_.joint(id);
    const Loc loc = JointLoc(id);
    const std::string name = joint_names_[id.index()];
    if (IsFloating(j)) {
      if (!IsFreeRoot(j)) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("floating joint '{}' has a parent other than the world or "
                                  "frames apart from its links' frames, which SDFormat cannot "
                                  "hold; link '{}' is written free",
                                  j.name, link_names_[j.child.index()]));
      } else if (!j.unnamed || j.type == ir::JointType::RpyFloating) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("{} joint '{}' is written as a free link: SDFormat names no "
                                  "floating joint{}",
                                  ir::JointTypeName(j.type), j.name,
                                  j.type == ir::JointType::RpyFloating
                                      ? ", and its coordinates become a quaternion's"
                                      : ""));
      }
      return;
    }
    if (j.type == ir::JointType::Planar) {
      WritePlanar(id, scope);
      return;
    }
    std::string_view type;
    switch (j.type) {
      case ir::JointType::Weld: type = "fixed"; break;
      case ir::JointType::Revolute: type = "revolute"; break;
      case ir::JointType::Prismatic: type = "prismatic"; break;
      case ir::JointType::Ball: type = "ball"; break;
      case ir::JointType::Universal: type = "universal"; break;
      case ir::JointType::Screw: type = "screw"; break;
      default:
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("{} joint '{}' has no SDFormat form; it is written as a "
                                  "fixed joint",
                                  ir::JointTypeName(j.type), j.name));
        type = "fixed";
    }
    out_.Open("joint").Attr("name", name).Attr("type", type);
    Value("parent", LinkRef(scope, j.parent));
    Value("child", LinkRef(scope, j.child));
    Pose(j.X_CM);
    if (type == "screw") {
      if (j.screw_thread_pitch == 0) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("screw joint '{}' has pitch 0, which SDFormat 1.9's "
                                  "<thread_pitch> cannot hold; 1 m per revolution is written",
                                  j.name));
      } else {
        // SDFormat 1.9: radians per meter, of the opposite handedness
        Value("thread_pitch", -2 * std::numbers::pi / j.screw_thread_pitch);
      }
    }
    if (type == "revolute" || type == "prismatic" || type == "screw") {
      Axis("axis", id, j, j.axis, 0);
    } else if (type == "universal") {
      // Drake's universal joint turns about F's x, then M's y
      Axis("axis", id, j, Eigen::Vector3d::UnitX(), 0);
      Axis("axis2", id, j, Eigen::Vector3d::UnitY(), 1);
    } else if (type == "ball") {
      if (j.damping[0] != 0 || !AllEqual(j.damping)) {
        if (!AllEqual(j.damping)) DampingLoss(j, loc);
        out_.Open("axis");
        out_.Open("dynamics");
        Value("damping", j.damping[0]);
        out_.Close();
        out_.Close();
      }
    }
    if (type != "fixed") {
      MultiDofLimits(j, loc);
      ActuatorParameters(id);
      MimicElements(id);
    }
    out_.Close();
    DefaultPositions(j, loc);
  }

  void DampingLoss(const PlantJoint& j, Loc loc) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("joint '{}' has a different damping per coordinate; SDFormat "
                              "holds one, so the first ({}) is written",
                              j.name, j.damping[0]));
  }

  void Axis(std::string_view tag, JointId id, const PlantJoint& j, const Eigen::Vector3d& xyz,
            int k) {
    const Loc loc = JointLoc(id);
    out_.Open(tag);
    Value("xyz", xyz);
    const double damping = j.damping.empty() ? 0 : j.damping[0];
    if (k == 0 && !AllEqual(j.damping)) DampingLoss(j, loc);
    const backend::JointSpring* spring = nullptr;
    for (const backend::ForceElement& f : plant_.force_elements) {
      if (const auto* s = std::get_if<backend::JointSpring>(&f); s && s->joint == id) spring = s;
    }
    if (damping != 0 || spring) {
      out_.Open("dynamics");
      Value("damping", damping);
      if (spring && k == 0) {
        Value("spring_reference", spring->nominal);
        Value("spring_stiffness", spring->stiffness);
      }
      out_.Close();
    }
    if (j.nv == 1) SingleDofLimit(id, j, loc);
    out_.Close();
  }

  /// The effort SDFormat writes: an actuated joint's is its actuator's
  /// limit; a joint without an actuator needs 0 (else SDFormat makes one).
  double EffortOf(JointId id, const PlantJoint& j, Loc loc) {
    const double joint_effort = j.effort.empty() ? kInf : j.effort[0];
    const backend::PlantActuator* actuator = nullptr;
    for (const backend::PlantActuator& a : plant_.actuators) {
      if (a.joint == id && !actuator) actuator = &a;
    }
    if (!actuator) {
      if (joint_effort != 0) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("joint '{}' has no actuator; SDFormat makes one for every "
                                  "joint whose effort limit is not 0, so its effort limit ({}) "
                                  "is written as 0",
                                  j.name, joint_effort));
      }
      return 0;
    }
    if (actuator->effort_limit != joint_effort && joint_effort != kInf) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("joint '{}' has effort limit {} and its actuator '{}' {}; "
                                "SDFormat holds one, so the actuator's is written",
                                j.name, joint_effort, actuator->name, actuator->effort_limit));
    }
    return actuator->effort_limit;
  }

  void SingleDofLimit(JointId id, const PlantJoint& j, Loc loc) {
    if (j.velocity_lower[0] != -j.velocity_upper[0]) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("joint '{}' has velocity limits [{}, {}]; SDFormat's are "
                                "symmetric, so +-{} is written",
                                j.name, j.velocity_lower[0], j.velocity_upper[0],
                                j.velocity_upper[0]));
    }
    if (j.acceleration_lower[0] != -j.acceleration_upper[0]) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("joint '{}' has acceleration limits [{}, {}]; SDFormat's are "
                                "symmetric, so +-{} is written",
                                j.name, j.acceleration_lower[0], j.acceleration_upper[0],
                                j.acceleration_upper[0]));
    }
    if (j.type == ir::JointType::Screw && (j.lower[0] != -kInf || j.upper[0] != kInf)) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("the position limits of screw joint '{}' are not written "
                                "(Drake reads none for a screw joint)",
                                j.name));
    }
    const double effort = EffortOf(id, j, loc);
    out_.Open("limit");
    if (j.type != ir::JointType::Screw) {
      // an absent side is unbounded to mdlc (libsdformat says +-1e16)
      if (j.lower[0] != -kInf) Value("lower", j.lower[0]);
      if (j.upper[0] != kInf) Value("upper", j.upper[0]);
    }
    // negative effort and velocity mean "unbounded" (SDF-013)
    Value("effort", effort == kInf ? -1.0 : effort);
    Value("velocity", j.velocity_upper[0] == kInf ? -1.0 : j.velocity_upper[0]);
    if (j.acceleration_upper[0] != kInf) Value("drake:acceleration", j.acceleration_upper[0]);
    out_.Close();
  }

  /// Limits of joints with more than one coordinate: SDFormat's are per
  /// single-dof axis, and Drake reads none for ball and universal joints.
  void MultiDofLimits(const PlantJoint& j, Loc loc) {
    if (j.nv <= 1) return;
    for (int k = 0; k < j.nv; ++k) {
      if (j.lower[k] != -kInf || j.upper[k] != kInf || j.velocity_upper[k] != kInf ||
          j.velocity_lower[k] != -kInf || j.effort[k] != kInf ||
          j.acceleration_upper[k] != kInf || j.acceleration_lower[k] != -kInf) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("the limits of {} joint '{}' are not written (Drake reads "
                                  "SDFormat limits for single-dof joints only)",
                                  ir::JointTypeName(j.type), j.name));
        return;
      }
    }
  }

  // drake:rotor_inertia, drake:gear_ratio, drake:controller_gains (SDF-021)
  void ActuatorParameters(JointId id) {
    const PlantJoint& j = plant_.joint(id);
    int count = 0;
    for (size_t i = 0; i < plant_.actuators.size(); ++i) {
      const backend::PlantActuator& a = plant_.actuators[i];
      if (a.joint != id) continue;
      const Loc loc = i < m_.actuators.size() ? m_.actuators[i].loc : Loc{};
      if (j.nv != 1 || j.type == ir::JointType::Planar) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("actuator '{}' of {} joint '{}' is dropped: SDFormat makes "
                                  "actuators for single-dof joints only",
                                  a.name, ir::JointTypeName(j.type), j.name));
        continue;
      }
      if (++count > 1) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("actuator '{}' is dropped: SDFormat makes one actuator per "
                                  "joint, and joint '{}' has another",
                                  a.name, j.name));
        continue;
      }
      if (!a.unnamed && a.name != j.name) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("actuator '{}' takes the name of its joint '{}': SDFormat "
                                  "names a joint's actuator after it",
                                  a.name, joint_names_[id.index()]));
      }
      if (a.rotor_inertia != 0) Value("drake:rotor_inertia", a.rotor_inertia);
      if (a.gear_ratio != 1) Value("drake:gear_ratio", a.gear_ratio);
      if (a.kp && a.kd) {
        out_.Open("drake:controller_gains").Attr("p", *a.kp).Attr("d", *a.kd).Close();
      } else if (a.kp || a.kd) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("actuator '{}' has only a {} gain; "
                                  "<drake:controller_gains> needs both, so none is written",
                                  a.name, a.kp ? "proportional" : "derivative"));
      }
    }
  }

  // a coupler whose follower is this joint becomes its <drake:mimic> (EXT-010)
  void MimicElements(JointId id) {
    for (size_t i = 0; i < plant_.constraints.size(); ++i) {
      const auto* coupler = std::get_if<backend::CouplerConstraint>(&plant_.constraints[i].payload);
      if (!coupler || coupler->joint0 != id) continue;
      const Loc loc = i < m_.constraints.size() ? m_.constraints[i].loc : Loc{};
      if (mimic_written_.count(id.index())) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("joint '{}' follows more than one joint; <drake:mimic> holds "
                                  "one, so this coupler is dropped",
                                  plant_.joint(coupler->joint0).name));
        continue;
      }
      if (joint_scope_[coupler->joint1.index()] != joint_scope_[id.index()]) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("the coupler of joint '{}' is dropped: <drake:mimic> names a "
                                  "joint of the same model, and joint '{}' is in another",
                                  plant_.joint(id).name, plant_.joint(coupler->joint1).name));
        continue;
      }
      mimic_written_.insert(id.index());
      out_.Open("drake:mimic")
          .Attr("joint", joint_names_[coupler->joint1.index()])
          .Attr("multiplier", coupler->gear_ratio)
          .Attr("offset", coupler->offset)
          .Close();
    }
  }

  void DefaultPositions(const PlantJoint& j, Loc loc) {
    if (std::all_of(j.default_positions.begin(), j.default_positions.end(),
                    [](double v) { return v == 0; })) {
      return;
    }
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("the default position of joint '{}' ({}) is not written (mdlc's "
                              "SDFormat reader takes no initial positions)",
                              j.name, VectorText(Eigen::Map<const Eigen::VectorXd>(
                                          j.default_positions.data(),
                                          static_cast<Eigen::Index>(j.default_positions.size())))));
  }

  // <drake:joint type="planar">: F and M are named frames (EXT-001)
  void WritePlanar(JointId id, const std::string& scope) {
    const PlantJoint& j = plant_.joint(id);
    const Loc loc = JointLoc(id);
    ModelNode& node = Scope(scope);
    auto frame_for = [&](BodyId body, const Transform& X, std::string_view suffix) {
      if (X.IsIdentity()) return LinkRef(scope, body);
      const std::string fname =
          Claim(node, fmt::format("{}_{}", joint_names_[id.index()], suffix), "frame", loc);
      out_.Open("frame").Attr("name", fname).Attr("attached_to", LinkRef(scope, body));
      Pose(X, LinkRef(scope, body));
      out_.Close();
      return fname;
    };
    const std::string parent = frame_for(j.parent, j.X_PF, "F");
    const std::string child = frame_for(j.child, j.X_CM, "M");
    out_.Open("drake:joint").Attr("name", joint_names_[id.index()]).Attr("type", "planar");
    Value("drake:parent", parent);
    Value("drake:child", child);
    Value("drake:damping", VectorText(Eigen::Map<const Eigen::VectorXd>(j.damping.data(), 3)));
    out_.Close();
    MultiDofLimits(j, loc);
    for (size_t i = 0; i < plant_.actuators.size(); ++i) {
      if (plant_.actuators[i].joint != id) continue;
      diags_.Report(DiagKind::Lossy, i < m_.actuators.size() ? m_.actuators[i].loc : Loc{},
                    fmt::format("actuator '{}' of planar joint '{}' is dropped: SDFormat makes "
                                "actuators for single-dof joints only",
                                plant_.actuators[i].name, j.name));
    }
    DefaultPositions(j, loc);
  }

  // -- frames

  void WriteFrame(size_t f, const std::string& scope) {
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

  const backend::Plant& plant_;
  const backend::SceneGraph& scene_;
  const ir::Module& m_;
  DiagnosticEngine& diags_;
  AssetPaths assets_;
  XmlOut out_;
  std::vector<Transform> X_WB_;  // link poses (see the top)
  std::map<std::string, ModelNode> models_;
  ModelNode world_;
  bool use_world_ = false;
  std::map<size_t, std::string> body_scope_;
  std::vector<std::string> link_names_, joint_names_, frame_names_, joint_scope_;
  struct FrameRef {
    std::string scope, name;
  };
  std::map<std::string, FrameRef> frame_refs_;  // plant scoped frame name -> written
  std::set<size_t> mimic_written_;
};

}  // namespace

std::optional<std::string> WriteSdf(const backend::CompiledModel& model,
                                    const ir::Module& module, const WriteOptions& options,
                                    DiagnosticEngine& diags) {
  return SdfWriter(model, module, options, diags).Write();
}

}  // namespace mdlc::writers
