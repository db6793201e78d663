#include "ir/verifier.h"

#include "ir/overloaded.h"

#include <fmt/format.h>

#include <set>
#include <type_traits>
#include <utility>

namespace mdlc::ir {
namespace {

class Verifier {
 public:
  Verifier(const Module& m, VerifyLevel level, DiagnosticEngine& d) : m_(m), level_(level), d_(d) {}

  bool Run() {
    if (m_.bodies.empty() || !m_.bodies[0].is_world) Fail({}, "body 0 must be the world body");
    for (const Body& b : m_.bodies) CheckModel(b.model, b.loc, "body");
    for (const Frame& f : m_.frames) {
      CheckModel(f.model, f.loc, "frame");
      CheckRef(f.body, m_.bodies.size(), "frame body");
    }
    for (const Joint& j : m_.joints) {
      CheckModel(j.model, j.loc, "joint");
      CheckRef(j.parent, m_.bodies.size(), "joint parent");
      CheckRef(j.child, m_.bodies.size(), "joint child");
      const size_t nv = static_cast<size_t>(JointVelocityCount(j.type));
      if (j.limits.lower.size() != nv || j.limits.upper.size() != nv || j.damping.size() != nv) {
        Fail(j.loc, fmt::format("joint '{}' has limit or damping vectors of the wrong size",
                                m_.Text(j.name)));
      }
      if (j.name.empty()) Fail(j.loc, "joint without a name");
    }
    for (const Geometry& g : m_.geometries) {
      CheckModel(g.model, g.loc, "geometry");
      CheckRef(g.body, m_.bodies.size(), "geometry body");
    }
    for (const Actuator& a : m_.actuators) CheckRef(a.joint, m_.joints.size(), "actuator joint");
    for (const Constraint& c : m_.constraints) {
      CheckModel(c.model, c.loc, "constraint");
      std::visit(
          Overloaded{
              [&](const CouplerConstraint& k) {
                CheckRef(k.joint0, m_.joints.size(), "coupler joint");
                CheckRef(k.joint1, m_.joints.size(), "coupler joint");
              },
              [&](const TendonConstraint& k) {
                for (const auto& j : k.joints) CheckRef(j, m_.joints.size(), "tendon joint");
                if (k.joints.size() != k.a.size()) {
                  Fail(c.loc, "tendon joints and coefficients differ in number");
                }
              },
              [&](const auto& between_bodies) {  // ball, distance, weld
                CheckRef(between_bodies.body_A, m_.bodies.size(), "constraint body");
                CheckRef(between_bodies.body_B, m_.bodies.size(), "constraint body");
              },
          },
          c.payload);
    }
    for (const CollisionFilterGroup& g : m_.filter_groups) {
      CheckModel(g.model, g.loc, "collision filter group");
      for (const auto& r : g.members) CheckRef(r, m_.bodies.size(), "filter group member");
      for (const auto& r : g.member_groups) CheckRef(r, m_.filter_groups.size(), "member group");
      for (const auto& r : g.ignored_groups) CheckRef(r, m_.filter_groups.size(), "ignored group");
    }
    for (const ForceElement& f : m_.force_elements) {
      CheckModel(f.model, f.loc, "force element");
      std::visit(Overloaded{
                     [&](const LinearBushingRpy& k) {
                       CheckFrameRef(k.frame_A);
                       CheckFrameRef(k.frame_C);
                     },
                     [&](const LinearSpringDamper& k) {
                       CheckRef(k.body_A, m_.bodies.size(), "spring body");
                       CheckRef(k.body_B, m_.bodies.size(), "spring body");
                     },
                     [&](const JointSpring& k) {
                       CheckRef(k.joint, m_.joints.size(), "spring joint");
                     },
                 },
                 f.payload);
    }
    for (const InertiaScaledGains& g : m_.inertia_scaled_gains) {
      CheckModel(g.model, g.loc, "inertia-scaled gains");
      for (const auto& j : g.joints) CheckId(j.joint, m_.joints.size(), g.loc, "joint");
      for (const auto& s : g.spring_dampers) {
        CheckId(s.joint, m_.joints.size(), s.loc, "springdamper joint");
        if (s.simple_body.valid()) {
          CheckId(s.simple_body, m_.bodies.size(), s.loc, "springdamper body");
        }
        if (!(s.timeconst > 0 && s.dampratio > 0)) {
          Fail(s.loc, "springdamper values must be positive");
        }
      }
      for (const auto& d : g.damp_ratios) {
        CheckId(d.actuator, m_.actuators.size(), d.loc, "dampratio actuator");
      }
    }
    if (level_ >= VerifyLevel::Tree) CheckTree();
    if (level_ >= VerifyLevel::Named) CheckNamesUnique();
    return ok_;
  }

 private:
  void Fail(Loc loc, std::string message) {
    ok_ = false;
    d_.Report(DiagKind::VerifierFailure, loc, "IR verifier: " + message);
  }
  void CheckModel(ModelId id, Loc loc, const char* what) {
    if (!id.valid() || id.index() >= m_.models.size()) {
      Fail(loc, fmt::format("{} has an invalid model instance id", what));
    }
  }
  template <typename IdT>
  void CheckRef(const Ref<IdT>& ref, size_t table_size, const char* what) {
    if (ref.id.valid() && ref.id.index() >= table_size) {
      Fail(ref.loc, fmt::format("{} reference is out of range", what));
    }
    if (level_ >= VerifyLevel::Resolved && !ref.id.valid()) {
      Fail(ref.loc, fmt::format("{} reference '{}' is unresolved", what, m_.Text(ref.name)));
    }
  }
  template <typename IdT>
  void CheckId(IdT id, size_t table_size, Loc loc, const char* what) {
    if (!id.valid() || id.index() >= table_size) {
      Fail(loc, fmt::format("{} id is invalid or out of range", what));
    }
  }
  void CheckFrameRef(const FrameRef& ref) {
    if ((ref.frame.valid() && ref.frame.index() >= m_.frames.size()) ||
        (ref.body.valid() && ref.body.index() >= m_.bodies.size())) {
      Fail(ref.loc, "frame reference is out of range");
    }
    if (level_ >= VerifyLevel::Resolved && !ref.resolved()) {
      Fail(ref.loc, fmt::format("frame reference '{}' is unresolved", m_.Text(ref.name)));
    }
  }
  void CheckTree() {
    std::vector<int> inboard(m_.bodies.size(), 0);
    for (const Joint& j : m_.joints) {
      if (j.child.id.valid() && j.child.id.index() < inboard.size()) ++inboard[j.child.id.index()];
    }
    for (size_t i = 1; i < m_.bodies.size(); ++i) {
      if (inboard[i] != 1) {
        Fail(m_.bodies[i].loc, fmt::format("body '{}' has {} inboard joints, expected 1",
                                           m_.ScopedName(BodyId(i)), inboard[i]));
      }
    }
    if (inboard[0] != 0) Fail({}, "the world body is the child of a joint");
  }

  // plant-json never holds two entities of a kind with one (instance, name),
  // nor two geometries of one name on a body in one role
  void CheckNamesUnique() {
    CheckUnique(m_.bodies, "body", [](const Body& b) { return Scopes{b.model.value}; });
    CheckUnique(m_.frames, "frame", [](const Frame& f) { return Scopes{f.model.value}; });
    CheckUnique(m_.joints, "joint", [](const Joint& j) { return Scopes{j.model.value}; });
    CheckUnique(m_.actuators, "actuator", [](const Actuator& a) { return Scopes{a.model.value}; });
    CheckUnique(m_.cameras, "camera", [](const Camera& c) { return Scopes{c.model.value}; });
    CheckUnique(m_.geometries, "geometry", [](const Geometry& g) { return NameScopes(g); });
  }
  using Scopes = std::vector<uint64_t>;
  template <typename Entity, typename ScopesOf>
  void CheckUnique(const std::vector<Entity>& table, const char* what, ScopesOf scopes_of) {
    std::set<std::pair<uint64_t, uint32_t>> seen;
    for (const Entity& e : table) {
      if constexpr (std::is_same_v<Entity, Body>) {
        if (e.is_world) continue;
      }
      for (uint64_t scope : scopes_of(e)) {
        if (!seen.insert({scope, e.name.value}).second) {
          Fail(e.loc, fmt::format("two {} entities are named '{}' in model instance '{}'", what,
                                  m_.Text(e.name), m_.ModelName(e.model)));
          break;
        }
      }
    }
  }

  const Module& m_;
  VerifyLevel level_;
  DiagnosticEngine& d_;
  bool ok_ = true;
};

}  // namespace

bool VerifyModule(const Module& module, VerifyLevel level, DiagnosticEngine& diags) {
  return Verifier(module, level, diags).Run();
}

}  // namespace mdlc::ir
