// mjcf_constraints.cc - the MJCF writer's contact excludes, equality
// constraints (<joint polycoef>, <connect>, <weld> between sites) and fixed
// tendons (mjcf_writer_detail.h).
#include <fmt/format.h>

#include <algorithm>
#include <variant>

#include "backend/collision_filters.h"
#include "backend/writers/mjcf_writer_detail.h"
#include "ir/overloaded.h"

namespace mdlc::writers::mjcf {

void MjcfWriter::WriteContacts() {
  const std::vector<uint32_t> composite = backend::WeldedComposites(plant_);
  auto one_composite = [&](BodyId a, BodyId b) {
    return composite[a.index()] == composite[b.index()];
  };
  std::set<std::pair<size_t, size_t>> excluded;  // written bodies, by index
  auto exclude = [&](BodyId a, BodyId b) {
    if (one_composite(a, b)) return;
    const BodyId x = Owner(a), y = Owner(b);
    if (x != y) excluded.insert({std::min(x.index(), y.index()), std::max(x.index(), y.index())});
  };
  const backend::CollisionFilters& filters = scene_.collision_filters;
  for (const auto& [a, b] : filters.pairs()) exclude(a, b);
  for (const std::vector<BodyId>& set : filters.sets()) {
    if (std::all_of(set.begin(), set.end(), [&](BodyId b) { return one_composite(set[0], b); })) {
      continue;  // a welded composite, or a group within one
    }
    for (size_t i = 0; i < set.size(); ++i) {
      for (size_t k = i + 1; k < set.size(); ++k) exclude(set[i], set[k]);
    }
  }
  for (const auto& [side_a, side_b] : filters.set_pairs()) {
    for (BodyId a : side_a) {
      for (BodyId b : side_b) exclude(a, b);
    }
  }
  if (excluded.empty()) return;
  out_.Open("contact");
  for (const auto& [x, y] : excluded) {
    out_.Open("exclude")
        .Attr("body1", BodyName(BodyId(x)))
        .Attr("body2", BodyName(BodyId(y)))
        .Close();
  }
  out_.Close();
}

std::pair<std::string, std::string> MjcfWriter::ConstraintSites(size_t i, BodyId A,
                                                                const Transform& X_AP, BodyId B,
                                                                const Transform& X_BQ) {
  const std::string a = site_names_.TakeUnique(fmt::format("constraint{}_P", i));
  const std::string b = site_names_.TakeUnique(fmt::format("constraint{}_Q", i));
  extra_sites_[Owner(A).index()].emplace_back(a, InWrittenLink(A, X_AP));
  extra_sites_[Owner(B).index()].emplace_back(b, InWrittenLink(B, X_BQ));
  return {a, b};
}

void MjcfWriter::WriteEqualities() {
  bool open = false;
  auto open_once = [&] {
    if (!open) out_.Open("equality");
    open = true;
  };
  for (size_t i = 0; i < plant_.constraints.size(); ++i) {
    const backend::PlantConstraint& c = plant_.constraints[i];
    const Loc loc = ConstraintLoc(i);
    std::visit(
        ir::Overloaded{
            [&](const backend::CouplerConstraint& k) {
              const auto ref0 = WrittenRef(k.joint0), ref1 = WrittenRef(k.joint1);
              if (!ref0 || !ref1) {
                diags_.Report(DiagKind::Lossy, loc,
                              fmt::format("the coupler of joint '{}' to joint '{}' is "
                                          "dropped: a joint it couples has no MJCF hinge or "
                                          "slide",
                                          plant_.joint(k.joint0).name,
                                          plant_.joint(k.joint1).name));
                return;
              }
              // MuJoCo: q0 - ref0 = c0 + c1 (q1 - ref1)
              const double c0 = k.offset - *ref0 + k.gear_ratio * *ref1;
              open_once();
              out_.Open("joint")
                  .Attr("joint1", JointName(k.joint0))
                  .Attr("joint2", JointName(k.joint1))
                  .Attr("polycoef", VectorText((Eigen::VectorXd(5) << c0, k.gear_ratio, 0,
                                                0, 0)
                                                   .finished()))
                  .Close();
            },
            [&](const backend::BallConstraint&) {
              open_once();
              out_.Open("connect")
                  .Attr("site1", constraint_sites_[i].first)
                  .Attr("site2", constraint_sites_[i].second)
                  .Close();
            },
            [&](const backend::DistanceConstraint& k) {
              diags_.Report(DiagKind::Lossy, loc,
                            fmt::format("the distance constraint between bodies '{}' and "
                                        "'{}' is dropped: MuJoCo 3 has no distance equality",
                                        BodyName(k.body_A), BodyName(k.body_B)));
            },
            [&](const backend::WeldConstraint&) {
              open_once();
              out_.Open("weld")
                  .Attr("site1", constraint_sites_[i].first)
                  .Attr("site2", constraint_sites_[i].second)
                  .Close();
            },
            [&](const backend::TendonConstraint&) {},  // WriteTendons
        },
        c.payload);
  }
  if (open) out_.Close();
}

void MjcfWriter::PrepareConstraintSites() {
  constraint_sites_.resize(plant_.constraints.size());
  for (size_t i = 0; i < plant_.constraints.size(); ++i) {
    const backend::PlantConstraint& c = plant_.constraints[i];
    if (const auto* k = std::get_if<backend::BallConstraint>(&c.payload)) {
      constraint_sites_[i] =
          ConstraintSites(i, k->body_A, Transform::FromTranslation(k->p_AP), k->body_B,
                          Transform::FromTranslation(k->p_BQ));
    } else if (const auto* w = std::get_if<backend::WeldConstraint>(&c.payload)) {
      constraint_sites_[i] = ConstraintSites(i, w->body_A, w->X_AP, w->body_B, w->X_BQ);
    }
  }
}

void MjcfWriter::WriteTendons() {
  bool open = false;
  for (size_t i = 0; i < plant_.constraints.size(); ++i) {
    const auto* k = std::get_if<backend::TendonConstraint>(&plant_.constraints[i].payload);
    if (!k) continue;
    const Loc loc = ConstraintLoc(i);
    const double lo = k->lower - k->offset, hi = k->upper - k->offset;
    const bool rigid = k->stiffness == kInf;
    std::string why;
    if (rigid && (lo == -kInf || hi == kInf)) why = "a rigid tendon needs two finite bounds";
    if (rigid && lo >= hi) why = "MuJoCo's tendon range must not be empty";
    if (!rigid && k->stiffness <= 0) why = "a tendon spring needs a positive stiffness";
    if (!rigid && (lo == -kInf || hi == kInf)) why = "a tendon spring needs finite lengths";
    for (JointId j : k->joints) {
      const Kind kind = KindOf(plant_.joint(j));
      if (kind != Kind::Hinge && kind != Kind::Slide) why = "a joint of it is not 1-dof";
    }
    if (!why.empty()) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("the tendon constraint is dropped: {}", why));
      continue;
    }
    if (!open) out_.Open("tendon");
    open = true;
    out_.Open("fixed").Attr("name", fmt::format("tendon{}", i));
    if (rigid) {
      out_.Attr("range", VectorText(Eigen::Vector2d(lo, hi)));
      if (k->damping != 0) {
        diags_.Report(DiagKind::Lossy, loc,
                      "the damping of a rigid tendon constraint is dropped");
      }
    } else {
      out_.Attr("stiffness", k->stiffness)
          .Attr("damping", k->damping)
          .Attr("springlength", VectorText(Eigen::Vector2d(lo, hi)));
    }
    for (size_t n = 0; n < k->joints.size(); ++n) {
      out_.Open("joint").Attr("joint", JointName(k->joints[n])).Attr("coef", k->a[n]).Close();
    }
    out_.Close();
  }
  if (open) out_.Close();
}

}  // namespace mdlc::writers::mjcf
