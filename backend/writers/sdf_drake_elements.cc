// sdf_drake_elements.cc - the SDFormat writer's model-level drake:
// elements: ball, distance and tendon constraints, bushings, spring-dampers
// and collision filter groups, each in the innermost model holding all it
// names (sdf_writer_detail.h).
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <variant>

#include "backend/writers/filter_declarations.h"
#include "backend/writers/sdf_writer_detail.h"
#include "ir/overloaded.h"

namespace mdlc::writers::sdf {

/// Queues `write` for the innermost model holding every one of `scopes`;
/// reports `what` dropped when only the world could hold it.
void SdfWriter::Place(const std::vector<ScopeId>& scopes, Loc loc, const std::string& what,
                      std::function<void(ScopeId)> write) {
  ScopeId scope = scopes.empty() ? kWorldScope : scopes[0];
  for (ScopeId s : scopes) scope = CommonScope(scope, s);
  if (scope == kWorldScope) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("{} is dropped: it names links of different top-level models "
                              "(or the world), and SDFormat reads drake: elements only in "
                              "a model",
                              what));
    return;
  }
  models_[scope].elements.push_back([write, scope] { write(scope); });
}

/// Model-level drake: elements, each in the innermost model holding what
/// it names; what only the world could hold is reported.
void SdfWriter::BuildElements() {
  for (size_t i = 0; i < plant_.constraints.size(); ++i) {
    const backend::PlantConstraint& c = plant_.constraints[i];
    const Loc loc = ConstraintLoc(i);
    std::visit(
        ir::Overloaded{
            [&](const backend::CouplerConstraint&) {},  // the follower's <drake:mimic>
            [&](const backend::BallConstraint& k) {
              Place({BodyScope(k.body_A), BodyScope(k.body_B)}, loc, "a ball constraint",
                    [this, k](ScopeId scope) {
                      out_.Open("drake:ball_constraint");
                      BodiesAndPoints(scope, "drake:ball_constraint", k.body_A, k.body_B,
                                      k.p_AP, k.p_BQ);
                      out_.Close();
                    });
            },
            [&](const backend::DistanceConstraint& k) {
              Place({BodyScope(k.body_A), BodyScope(k.body_B)}, loc, "a distance constraint",
                    [this, k](ScopeId scope) {
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
              std::vector<ScopeId> scopes;
              for (JointId j : k.joints) scopes.push_back(joint_scope_[j.index()]);
              const ScopeId first = scopes.empty() ? kWorldScope : scopes[0];
              if (!std::all_of(scopes.begin(), scopes.end(),
                               [&](ScopeId s) { return s == first; }) ||
                  first == kWorldScope) {
                diags_.Report(DiagKind::Lossy, loc,
                              "a tendon constraint is dropped: its joints are not all of one "
                              "model, which <drake:tendon_constraint> needs");
                return;
              }
              models_[first].elements.push_back([this, k] {
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
              auto a = frame_refs_.find(k.frame_A), c = frame_refs_.find(k.frame_C);
              if (a == frame_refs_.end() || c == frame_refs_.end()) {
                diags_.Report(DiagKind::Lossy, Loc{},
                              fmt::format("the bushing between '{}' and '{}' is dropped: a "
                                          "frame it names is not written",
                                          k.frame_A, k.frame_C));
                return;
              }
              const FrameRef fa = a->second, fc = c->second;
              Place({fa.scope, fc.scope}, Loc{}, "a linear bushing",
                    [this, k, fa, fc](ScopeId scope) {
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
              Place({BodyScope(k.body_A), BodyScope(k.body_B)}, Loc{}, "a linear spring-damper",
                    [this, k](ScopeId scope) {
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
  BuildFilterGroups();
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

void SdfWriter::BodiesAndPoints(ScopeId scope, const std::string& prefix, BodyId A,
                                BodyId B, const Eigen::Vector3d& p_AP,
                                const Eigen::Vector3d& p_BQ) {
  Value(prefix + "_body_A", LinkRef(scope, A));
  Value(prefix + "_p_AP", p_AP);
  Value(prefix + "_body_B", LinkRef(scope, B));
  Value(prefix + "_p_BQ", p_BQ);
}

/// One group per filter declaration (two for a group that ignores
/// another), in the innermost model holding its links. A declaration whose
/// links lie in several top-level models is split by model, as no group can
/// reach past one; its pairs across models are reported dropped, once per
/// declaration.
void SdfWriter::BuildFilterGroups() {
  const std::vector<FilterDeclaration> declarations = DeclarationsWithoutWorld(
      scene_.collision_filters, [&](BodyId body) {
        diags_.Report(DiagKind::Lossy, BodyLoc(body),
                      fmt::format("the collision filter between link '{}' and the world is "
                                  "dropped: a collision filter group cannot name the world",
                                  link_names_[body.index()]));
      });
  int n = 0;
  for (const FilterDeclaration& d : declarations) {
    // the declaration's members and ignored links by top-level model, in
    // the order the models first appear
    std::vector<ScopeId> tops;
    std::map<ScopeId, size_t> top_index;
    std::vector<FilterDeclaration> parts;
    auto part_of = [&](BodyId body) -> FilterDeclaration& {
      const auto [it, added] = top_index.try_emplace(TopLevelModel(BodyScope(body)), tops.size());
      if (added) {
        tops.push_back(it->first);
        parts.emplace_back();
      }
      return parts[it->second];
    };
    for (BodyId b : d.members) part_of(b).members.push_back(b);
    for (BodyId b : d.ignored) part_of(b).ignored.push_back(b);
    if (tops.size() > 1) {
      const BodyId first = d.members.front();
      diags_.Report(
          DiagKind::Lossy, BodyLoc(first),
          fmt::format("the collision filter of link '{}' between different top-level models "
                      "('{}', '{}'{}) is dropped: a collision filter group holds the links of "
                      "one model; it is kept within each model",
                      link_names_[first.index()], models_[tops[0]].name, models_[tops[1]].name,
                      tops.size() > 2 ? fmt::format(" and {} more", tops.size() - 2) : ""));
    }
    for (FilterDeclaration& part : parts) {
      const bool filters = d.ignores_itself() ? part.members.size() >= 2
                                              : !part.members.empty() && !part.ignored.empty();
      if (!filters) continue;
      std::vector<ScopeId> scopes;
      for (BodyId b : part.members) scopes.push_back(BodyScope(b));
      for (BodyId b : part.ignored) scopes.push_back(BodyScope(b));
      const std::string name = fmt::format("filter{}", n++);
      const std::string ignored = d.ignores_itself() ? name : fmt::format("filter{}", n++);
      const BodyId first = part.members.front();  // before `part` moves into the writer
      Place(scopes, BodyLoc(first),
            fmt::format("the collision filter group of link '{}'", link_names_[first.index()]),
            [this, part = std::move(part), name, ignored](ScopeId scope) {
              WriteFilterGroup(scope, part.members, name, ignored);
              if (!part.ignores_itself()) WriteFilterGroup(scope, part.ignored, ignored, "");
            });
    }
  }
}

void SdfWriter::WriteFilterGroup(ScopeId scope, const std::vector<BodyId>& members,
                                 const std::string& name, const std::string& ignored) {
  out_.Open("drake:collision_filter_group").Attr("name", name);
  for (BodyId b : members) Value("drake:member", LinkRef(scope, b));
  if (!ignored.empty()) Value("drake:ignored_collision_filter_group", ignored);
  out_.Close();
}

}  // namespace mdlc::writers::sdf
