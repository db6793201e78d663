#include "ir/printer.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <span>
#include <type_traits>
#include <variant>

#include "ir/overloaded.h"

namespace mdlc::ir {
namespace {

class Printer {
 public:
  Printer(const Module& m, const SourceManager& s, const PrintOptions& o)
      : m_(m), sources_(s), options_(o) {}

  std::string Run();
  void PrintFrameGraph();
  void PrintSceneEdits();
  void PrintInertiaScaledGains();

 private:
  std::string Num(double v) const {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    if (v == 0) return "0";  // folds -0
    return fmt::format("{}", v);
  }
  std::string Vec(const Eigen::Ref<const Eigen::VectorXd>& v) const {
    std::string out = "[";
    for (Eigen::Index i = 0; i < v.size(); ++i) out += (i ? " " : "") + Num(v[i]);
    return out + "]";
  }
  std::string List(std::span<const double> v) const {
    return Vec(Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size())));
  }
  std::string Pose(const Transform& X) const {
    if (X.IsIdentity()) return "identity";
    return fmt::format("{{p={} rpy={}}}", Vec(X.p), Vec(RpyFromRotation(X.R)));
  }
  std::string Where(Loc loc) const {
    if (!options_.locations || !loc.valid()) return "";
    return fmt::format("  loc({}:{}:{})",
                       std::filesystem::path(sources_.Path(loc.file)).filename().string(),
                       loc.line, loc.column);
  }
  std::string Name(Symbol s) const { return fmt::format("\"{}\"", m_.Text(s)); }
  std::string Model(ModelId id) const {
    return id.valid() && id.index() < m_.models.size() ? m_.ModelName(id)
                                                       : "<invalid>";
  }
  template <typename IdT>
  std::string RefText(const Ref<IdT>& ref, auto&& scoped) const {
    if (ref.resolved()) return scoped(ref.id);
    return fmt::format("?{}", Name(ref.name));
  }
  std::string BodyRef(const Ref<BodyId>& r) const {
    return RefText(r, [&](BodyId id) { return m_.ScopedName(id); });
  }
  std::string JointRef(const Ref<JointId>& r) const {
    return RefText(r, [&](JointId id) { return m_.ScopedName(id); });
  }
  std::string Shape(const ir::Shape& shape) const;
  std::string FrameRefText(const FrameRef& r) const {
    if (r.frame.valid()) return fmt::format("{}::{}", Model(m_[r.frame].model), m_.Text(m_[r.frame].name));
    if (r.body.valid()) return m_.ScopedName(r.body);
    return fmt::format("?{}", Name(r.name));
  }
  // a force element's field, as the entity's own VisitFields lists it
  std::string FieldText(double v) const { return Num(v); }
  std::string FieldText(const Eigen::Vector3d& v) const { return Vec(v); }
  std::string FieldText(const Ref<BodyId>& r) const { return BodyRef(r); }
  std::string FieldText(const Ref<JointId>& r) const { return JointRef(r); }
  std::string FieldText(const FrameRef& r) const { return FrameRefText(r); }

  const Module& m_;
  const SourceManager& sources_;
  const PrintOptions& options_;
  std::string out_;
};

std::string Printer::Shape(const ir::Shape& shape) const {
  struct V {
    const Printer& p;
    std::string operator()(const Box& b) const { return "box size=" + p.Vec(b.size); }
    std::string operator()(const Sphere& s) const { return "sphere radius=" + p.Num(s.radius); }
    std::string operator()(const Cylinder& c) const {
      return fmt::format("cylinder radius={} length={}", p.Num(c.radius), p.Num(c.length));
    }
    std::string operator()(const Capsule& c) const {
      return fmt::format("capsule radius={} length={}", p.Num(c.radius), p.Num(c.length));
    }
    std::string operator()(const Ellipsoid& e) const {
      return fmt::format("ellipsoid abc=[{} {} {}]", p.Num(e.a), p.Num(e.b), p.Num(e.c));
    }
    std::string operator()(const HalfSpace&) const { return "half_space"; }
    std::string operator()(const Mesh& m) const {
      return fmt::format("{} uri=\"{}\" scale={}", m.convex ? "convex" : "mesh", m.uri,
                         p.Vec(m.scale));
    }
  };
  return std::visit(V{*this}, shape);
}

// Model Directives' edits awaiting apply-directives (names, not results);
// `seen` is how many instances the directive's lookups may see
void Printer::PrintSceneEdits() {
  for (size_t i = 0; i < m_.scene_edits.size(); ++i) {
    const SceneEdit& edit = m_.scene_edits[i];
    out_ += fmt::format("  scene_edit #{} seen={} ", i, edit.visible_models);
    std::visit(
        [&](const auto& e) {
          using E = std::decay_t<decltype(e)>;
          if constexpr (std::is_same_v<E, AddFrameEdit>) {
            out_ += fmt::format("add_frame {} instance={} base={} X_PF={}", Name(e.name),
                                e.instance.empty() ? "-" : Name(e.instance),
                                Name(e.base_frame.name), Pose(e.X_PF));
          } else if constexpr (std::is_same_v<E, AddWeldEdit>) {
            out_ += fmt::format("add_weld parent={} child={} X_PC={}", Name(e.parent.name),
                                Name(e.child.name), Pose(e.X_PC));
          } else if constexpr (std::is_same_v<E, DefaultJointPositionsEdit>) {
            out_ += fmt::format("default_joint_positions model={} joint={} positions={}",
                                Model(e.model), Name(e.joint), List(e.positions));
          } else {
            out_ += fmt::format("default_free_body_pose model={} frame={} base={} X={}",
                                Model(e.model), Name(e.frame),
                                e.base_frame ? Name(e.base_frame->name) : "world", Pose(e.X_PC));
          }
          out_ += Where(e.loc) + "\n";
        },
        edit.edit);
  }
}

// MJCF gains awaiting the backend's mass matrix at qpos0 (requests, not results)
void Printer::PrintInertiaScaledGains() {
  auto joint = [&](JointId id) {
    return id.index() < m_.joints.size() ? m_.ScopedName(id) : std::string("<invalid>");
  };
  for (const InertiaScaledGains& g : m_.inertia_scaled_gains) {
    std::string joints;
    for (const auto& j : g.joints) {
      joints += fmt::format("{}{}", joints.empty() ? "" : " ", joint(j.joint));
      if (j.qpos0 != 0) joints += "@" + Num(j.qpos0);
      if (j.armature != 0) joints += "+armature=" + Num(j.armature);
    }
    out_ += fmt::format("  inertia_scaled_gains model={} joints=[{}]{}\n", Model(g.model), joints,
                        Where(g.loc));
    for (const auto& s : g.spring_dampers) {
      out_ += fmt::format("    springdamper joint={} timeconst={} dampratio={} springref={}",
                          joint(s.joint), Num(s.timeconst), Num(s.dampratio),
                          Num(s.springref));
      if (s.simple_body.valid() && s.simple_body.index() < m_.bodies.size()) {
        out_ += " simple_body=" + m_.ScopedName(s.simple_body);
      }
      out_ += Where(s.loc) + "\n";
    }
    for (const auto& d : g.damp_ratios) {
      out_ += fmt::format("    dampratio actuator={} dampratio={}{}\n",
                          d.actuator.index() < m_.actuators.size()
                              ? Name(m_[d.actuator].name)
                              : std::string("<invalid>"),
                          Num(d.dampratio), Where(d.loc));
    }
  }
}

// SDFormat's frame graph as the frontend recorded it (names, not results)
void Printer::PrintFrameGraph() {
  const FrameGraph& g = m_.frame_graph;
  auto ref = [&](const NameRef& r) { return r.empty() ? std::string("-") : Name(r.name); };
  for (size_t i = 0; i < g.scopes.size(); ++i) {
    const FrameScope& s = g.scopes[i];
    out_ += fmt::format("  frame_scope #{} {} model={} frame=#{}", i, Name(s.name), Model(s.model),
                        s.frame.value);
    if (s.parent.valid()) out_ += fmt::format(" parent=#{}", s.parent.value);
    if (s.merged_into.valid()) out_ += fmt::format(" merged_into=#{}", s.merged_into.value);
    if (s.is_static) out_ += " static";
    if (!s.canonical_link.empty()) out_ += " canonical_link=" + ref(s.canonical_link);
    if (!s.placement_frame.empty()) out_ += " placement_frame=" + ref(s.placement_frame);
    out_ += Where(s.loc) + "\n";
  }
  static constexpr const char* kKinds[] = {"world", "model", "link", "joint", "frame", "anchor"};
  static constexpr const char* kTargets[] = {"none", "body", "frame", "joint", "geometry", "camera"};
  for (size_t i = 0; i < g.nodes.size(); ++i) {
    const FrameNode& n = g.nodes[i];
    out_ += fmt::format("  frame_node #{} {} {} scope=#{}", i, kKinds[static_cast<int>(n.kind)],
                        n.name.empty() ? std::string("-") : Name(n.name), n.scope.value);
    if (!n.relative_to.empty()) {
      out_ += fmt::format(" X_{}={}", ref(n.relative_to), Pose(n.X_RN));
    }
    if (!n.attached_to.empty()) out_ += " attached_to=" + ref(n.attached_to);
    if (n.target != FrameTarget::None) {
      out_ += fmt::format(" -> {}#{}", kTargets[static_cast<int>(n.target)], n.target_index);
    }
    out_ += Where(n.loc) + "\n";
  }
  for (const JointFrameSpec& j : g.joints) {
    out_ += fmt::format("  frame_joint joint=#{} node=#{} parent={}", j.joint.value, j.node.value,
                        ref(j.parent));
    for (int k = 0; k < j.axis_count; ++k) {
      out_ += fmt::format(" axis{}={}", k + 1, Vec(j.xyz[k]));
      if (!j.expressed_in[k].empty()) out_ += "@" + ref(j.expressed_in[k]);
    }
    out_ += "\n";
  }
}

std::string Printer::Run() {
  out_ += "module {\n";
  for (size_t i = 0; i < m_.models.size(); ++i) {
    out_ += fmt::format("  model #{} \"{}\"{}\n", i, m_.ModelName(ModelId(i)),
                        Where(m_.models[i].loc));
  }
  for (size_t i = 0; i < m_.bodies.size(); ++i) {
    const Body& b = m_.bodies[i];
    out_ += fmt::format("  body #{} {} model={}", i, Name(b.name), Model(b.model));
    if (b.is_world) out_ += " world";
    if (b.inertial) {
      const Inertial& in = *b.inertial;
      out_ += fmt::format(" mass={} X_BI={} inertia=[{} {} {} {} {} {}]", Num(in.mass),
                          Pose(in.X_BI), Num(in.ixx), Num(in.iyy), Num(in.izz), Num(in.ixy),
                          Num(in.ixz), Num(in.iyz));
    }
    if (b.surface_velocity_axis) out_ += " surface_velocity_axis=" + Vec(*b.surface_velocity_axis);
    if (b.default_pose) out_ += " default_pose=" + Pose(*b.default_pose);
    if (b.inertia_from_collisions) {
      out_ += " inertia_from_collisions(density=" + Num(*b.inertia_from_collisions) + ")";
    }
    if (b.deformable) {
      const DeformableProperties& d = *b.deformable;
      out_ += fmt::format(
          " deformable{{youngs_modulus={} poissons_ratio={} mass_damping={} "
          "stiffness_damping={} mass_density={} material_model={}",
          Num(d.youngs_modulus), Num(d.poissons_ratio), Num(d.mass_damping),
          Num(d.stiffness_damping), Num(d.mass_density), d.material_model);
      if (d.resolution_hint) out_ += " resolution_hint=" + Num(*d.resolution_hint);
      for (const auto& wall : d.wall_boundary_conditions) {
        out_ += fmt::format(" wall={{point={} normal={}}}", Vec(wall.point_on_plane),
                            Vec(wall.outward_normal));
      }
      out_ += "}";
    }
    if (b.unnamed) out_ += " unnamed";
    out_ += Where(b.loc) + "\n";
  }
  for (size_t i = 0; i < m_.frames.size(); ++i) {
    const Frame& f = m_.frames[i];
    out_ += fmt::format("  frame #{} {} model={} body={} X_BF={}{}{}\n", i, Name(f.name),
                        Model(f.model), BodyRef(f.body), Pose(f.X_BF),
                        f.unnamed ? " unnamed" : "", Where(f.loc));
  }
  for (size_t i = 0; i < m_.joints.size(); ++i) {
    const Joint& j = m_.joints[i];
    out_ += fmt::format("  joint #{} {} model={} {} parent={} child={} X_PF={} X_CM={}", i,
                        Name(j.name), Model(j.model), JointTypeName(j.type), BodyRef(j.parent),
                        BodyRef(j.child), Pose(j.X_PF), Pose(j.X_CM));
    if (j.type == JointType::Curvilinear) {
      const CurvilinearPath& path = j.curvilinear_path;
      std::string segments;
      for (const auto& seg : path.segments) {
        segments += fmt::format("{}({} {})", segments.empty() ? "" : " ", Num(seg.length),
                                Num(seg.curvature));
      }
      out_ += fmt::format(" path={{tangent={} normal={} segments=[{}]{}}}",
                          Vec(path.initial_tangent), Vec(path.plane_normal), segments,
                          path.periodic ? " periodic" : "");
    } else if (JointVelocityCount(j.type) == 1) {
      out_ += " axis=" + Vec(j.axis);
    }
    if (j.type == JointType::Screw) out_ += " pitch=" + Num(j.screw_thread_pitch);
    if (JointVelocityCount(j.type) > 0) {
      out_ += fmt::format(" lower={} upper={} velocity={} effort={} damping={}",
                          List(j.limits.lower), List(j.limits.upper),
                          List(j.limits.velocity_upper), List(j.limits.effort), List(j.damping));
    }
    if (!j.default_positions.empty()) out_ += " default=" + List(j.default_positions);
    if (j.unnamed) out_ += " unnamed";
    out_ += Where(j.loc) + "\n";
  }
  for (size_t i = 0; i < m_.materials.size(); ++i) {
    const Material& mat = m_.materials[i];
    out_ += fmt::format("  material #{} {} model={}", i, Name(mat.name), Model(mat.model));
    if (mat.rgba) out_ += " rgba=" + Vec(*mat.rgba);
    if (!mat.texture.empty()) out_ += fmt::format(" texture=\"{}\"", mat.texture);
    out_ += Where(mat.loc) + "\n";
  }
  for (size_t i = 0; i < m_.geometries.size(); ++i) {
    const Geometry& g = m_.geometries[i];
    std::string roles;
    ForEachRoleName(g.roles, [&](std::string_view role) {
      if (!roles.empty()) roles += ',';
      roles += role;
    });
    out_ += fmt::format("  geometry #{} {} model={} body={} roles={} {} X_BG={}", i, Name(g.name),
                        Model(g.model), BodyRef(g.body), roles, Shape(g.shape), Pose(g.X_BG));
    if (g.rgba) out_ += " rgba=" + Vec(*g.rgba);
    for (const Property& p : g.properties) {
      out_ += " " + p.key + "=" + std::visit([&](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool>) return v ? "true" : "false";
        else if constexpr (std::is_same_v<T, double>) return Num(v);
        else if constexpr (std::is_same_v<T, std::string>) return "\"" + v + "\"";
        else if constexpr (std::is_same_v<T, std::vector<double>>) return List(v);
        else return fmt::format("[{}]", fmt::join(v, " "));
      }, p.value);
    }
    if (g.unnamed) out_ += " unnamed";
    out_ += Where(g.loc) + "\n";
  }
  for (size_t i = 0; i < m_.actuators.size(); ++i) {
    const Actuator& a = m_.actuators[i];
    out_ += fmt::format("  actuator #{} {} model={} joint={} effort={} gear={} rotor_inertia={}",
                        i, Name(a.name), Model(a.model), JointRef(a.joint), Num(a.effort_limit),
                        Num(a.gear_ratio), Num(a.rotor_inertia));
    if (a.kp) out_ += " kp=" + Num(*a.kp);
    if (a.kd) out_ += " kd=" + Num(*a.kd);
    if (a.unnamed) out_ += " unnamed";
    out_ += Where(a.loc) + "\n";
  }
  for (size_t i = 0; i < m_.constraints.size(); ++i) {
    const Constraint& c = m_.constraints[i];
    out_ += fmt::format("  constraint #{} {} model={}", i, ConstraintTypeName(c.type()), Model(c.model));
    std::visit(
        Overloaded{
            [&](const CouplerConstraint& k) {
              out_ += fmt::format(" joint0={} joint1={} gear_ratio={} offset={}",
                                  JointRef(k.joint0), JointRef(k.joint1), Num(k.gear_ratio),
                                  Num(k.offset));
            },
            [&](const BallConstraint& k) {
              out_ += fmt::format(" body_A={} p_AP={} body_B={} p_BQ={}", BodyRef(k.body_A),
                                  Vec(k.p_AP), BodyRef(k.body_B), Vec(k.p_BQ));
            },
            [&](const DistanceConstraint& k) {
              out_ += fmt::format(" body_A={} p_AP={} body_B={} p_BQ={} distance={} "
                                  "stiffness={} damping={}",
                                  BodyRef(k.body_A), Vec(k.p_AP), BodyRef(k.body_B),
                                  Vec(k.p_BQ), Num(k.distance), Num(k.stiffness),
                                  Num(k.damping));
            },
            [&](const WeldConstraint& k) {
              out_ += fmt::format(" body_A={} X_AP={} body_B={} X_BQ={}", BodyRef(k.body_A),
                                  Pose(k.X_AP), BodyRef(k.body_B), Pose(k.X_BQ));
            },
            [&](const TendonConstraint& k) {
              std::string joints;
              for (const auto& j : k.joints) joints += (joints.empty() ? "" : " ") + JointRef(j);
              out_ += fmt::format(" joints=[{}] a={} offset={} lower={} upper={} stiffness={} "
                                  "damping={}",
                                  joints, List(k.a), Num(k.offset), Num(k.lower), Num(k.upper),
                                  Num(k.stiffness), Num(k.damping));
            },
        },
        c.payload);
    out_ += Where(c.loc) + "\n";
  }
  for (size_t i = 0; i < m_.filter_groups.size(); ++i) {
    const CollisionFilterGroup& g = m_.filter_groups[i];
    auto group_ref = [&](const Ref<FilterGroupId>& r) {
      if (!r.resolved()) return fmt::format("?{}", Name(r.name));
      const CollisionFilterGroup& target = m_.filter_groups[r.id.index()];
      return fmt::format("{}::{}", Model(target.model), m_.Text(target.name));
    };
    std::string members, groups, ignored;
    for (const auto& r : g.members) members += (members.empty() ? "" : " ") + BodyRef(r);
    for (const auto& r : g.member_groups) groups += (groups.empty() ? "" : " ") + group_ref(r);
    for (const auto& r : g.ignored_groups) ignored += (ignored.empty() ? "" : " ") + group_ref(r);
    out_ += fmt::format("  collision_filter_group #{} {} model={} members=[{}] member_groups=[{}] "
                        "ignored=[{}]{}\n",
                        i, Name(g.name), Model(g.model), members, groups, ignored, Where(g.loc));
  }
  for (size_t i = 0; i < m_.force_elements.size(); ++i) {
    const ForceElement& f = m_.force_elements[i];
    out_ += fmt::format("  force_element #{} model={}", i, Model(f.model));
    std::visit(
        [&](const auto& k) {
          out_ += fmt::format(" {}", k.kKind);
          k.VisitFields([&](std::string_view name, const auto& field) {
            out_ += fmt::format(" {}={}", name, FieldText(field));
          });
        },
        f.payload);
    out_ += Where(f.loc) + "\n";
  }
  for (size_t i = 0; i < m_.cameras.size(); ++i) {
    const Camera& c = m_.cameras[i];
    out_ += fmt::format("  camera #{} {} model={} body={} X_BC={} size={}x{} fov_y={}", i,
                        Name(c.name), Model(c.model), BodyRef(c.body), Pose(c.X_BC), c.width,
                        c.height, Num(c.fov_y));
    if (c.unnamed) out_ += " unnamed";
    out_ += Where(c.loc) + "\n";
  }
  PrintInertiaScaledGains();
  PrintFrameGraph();
  PrintSceneEdits();
  out_ += "}\n";
  return std::move(out_);
}

}  // namespace

std::string PrintModule(const Module& module, const SourceManager& sources,
                        const PrintOptions& options) {
  return Printer(module, sources, options).Run();
}

}  // namespace mdlc::ir
