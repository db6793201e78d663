// sdf_drake_elements.cc - the SDFormat writer's model-level drake:
// elements: ball, distance and tendon constraints, bushings, spring-dampers
// and collision filter groups, each in the innermost model holding all it
// names (sdf_writer_detail.h).
#include <fmt/format.h>

#include <algorithm>
#include <variant>

#include "backend/writers/sdf_writer_detail.h"
#include "ir/overloaded.h"

namespace mdlc::writers::sdf {

/// Model-level drake: elements, each in the innermost model holding what
/// it names; what only the world could hold is reported.
void SdfWriter::BuildElements() {
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
    const Loc loc = ConstraintLoc(i);
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
  for (const auto& pair : scene_.collision_filters.Pairs(plant_)) {
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
  for (size_t i = 0; i < scene_.geometries.size(); ++i) {
    const backend::SceneGeometry& g = scene_.geometries[i];
    if (g.body.index() != 0) continue;
    diags_.Report(DiagKind::Lossy, GeometryLoc(i),
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

void SdfWriter::BodiesAndPoints(const std::string& scope, const std::string& prefix, BodyId A,
                                BodyId B, const Eigen::Vector3d& p_AP,
                                const Eigen::Vector3d& p_BQ) {
  Value(prefix + "_body_A", LinkRef(scope, A));
  Value(prefix + "_p_AP", p_AP);
  Value(prefix + "_body_B", LinkRef(scope, B));
  Value(prefix + "_p_BQ", p_BQ);
}

}  // namespace mdlc::writers::sdf
