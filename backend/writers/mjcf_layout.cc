// mjcf_layout.cc - see mjcf_layout.h.
#include "backend/writers/mjcf_layout.h"

#include <map>
#include <string>
#include <variant>

#include "ir/overloaded.h"

namespace mdlc::writers {
namespace {

using backend::PlantBody;
using backend::PlantJoint;

bool IsHingeOrSlide(const PlantJoint& j) {
  return j.type == ir::JointType::Revolute || j.type == ir::JointType::Prismatic;
}

/// The bodies something besides joints is on: geometry, a named frame, a
/// camera, a constraint or force element, a surface velocity, deformable
/// properties.
std::vector<bool> Occupied(const backend::Plant& plant, const backend::SceneGraph& scene) {
  std::vector<bool> occupied(plant.bodies.size(), false);
  auto mark = [&](BodyId b) {
    if (b.valid() && b.index() < occupied.size()) occupied[b.index()] = true;
  };
  for (const auto& g : scene.geometries) mark(g.body);
  for (const auto& c : scene.cameras) mark(c.body);
  std::map<std::string, BodyId> by_scoped_name;  // bushings name frames so
  for (size_t b = 0; b < plant.bodies.size(); ++b) {
    const PlantBody& body = plant.bodies[b];
    by_scoped_name.emplace(plant.ScopedName(body), BodyId(b));
    if (body.surface_velocity_axis || body.deformable) mark(BodyId(b));
  }
  for (const auto& f : plant.frames) {
    if (f.unnamed) continue;
    mark(f.body);
    const std::string& instance = plant.model_instances[f.model.index()];
    by_scoped_name.emplace(instance + "::" + f.name, f.body);
  }
  for (const auto& c : plant.constraints) {
    std::visit(ir::Overloaded{
                   [&](const backend::CouplerConstraint&) {},
                   [&](const backend::TendonConstraint&) {},
                   [&](const auto& k) {
                     mark(k.body_A);
                     mark(k.body_B);
                   },
               },
               c.payload);
  }
  for (const auto& f : plant.force_elements) {
    std::visit(ir::Overloaded{
                   [&](const backend::LinearBushingRpy& k) {
                     for (const std::string* name : {&k.frame_A, &k.frame_C}) {
                       if (auto it = by_scoped_name.find(*name); it != by_scoped_name.end()) {
                         mark(it->second);
                       }
                     }
                   },
                   [&](const backend::LinearSpringDamper& k) {
                     mark(k.body_A);
                     mark(k.body_B);
                   },
                   [&](const backend::JointSpring&) {},
               },
               f);
  }
  return occupied;
}

/// m, c, I of a body with those of the bodies fused into it, all in the
/// body's frame: I about the combined center of mass (parallel-axis theorem).
void Combine(double& m, Eigen::Vector3d& c, Eigen::Matrix3d& I, const PlantBody& other,
             const Transform& X_BO) {
  const double m_o = other.mass;
  const Eigen::Vector3d c_o = X_BO * other.p_BoBcm_B;
  const Eigen::Matrix3d I_o = X_BO.R * other.I_BBcm_B * X_BO.R.transpose();
  const double total = m + m_o;
  const Eigen::Vector3d c_new = total > 0 ? Eigen::Vector3d((m * c + m_o * c_o) / total) : c;
  auto shift = [](double mass, const Eigen::Vector3d& d) {
    return Eigen::Matrix3d(mass *
                           (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose()));
  };
  I = I + shift(m, c - c_new) + I_o + shift(m_o, c_o - c_new);
  m = total;
  c = c_new;
}

}  // namespace

MjcfBodyLayout PlanMjcfBodies(const backend::Plant& plant, const backend::SceneGraph& scene,
                              bool fuse_fixed) {
  using Role = MjcfBodyLayout::Role;
  const size_t n = plant.bodies.size();
  MjcfBodyLayout layout;
  layout.role.assign(n, Role::Written);
  layout.owner.resize(n);
  layout.X_OB.assign(n, Transform());
  layout.parent.assign(n, BodyId());
  layout.joints.assign(n, {});
  layout.fused.assign(n, {});
  for (size_t b = 0; b < n; ++b) layout.owner[b] = BodyId(b);

  std::vector<std::vector<BodyId>> children(n);
  for (size_t b = 1; b < n; ++b) {
    const PlantBody& body = plant.bodies[b];
    if (body.parent.valid()) children[body.parent.index()].push_back(BodyId(b));
  }

  // merged: massless, unoccupied links of a hinge/slide chain
  const std::vector<bool> occupied = Occupied(plant, scene);
  for (size_t b = 1; b < n; ++b) {
    const PlantBody& body = plant.bodies[b];
    if (!body.inbound_joint.valid() || occupied[b] || body.mass != 0 || !body.I_BBcm_B.isZero(0) ||
        children[b].size() != 1) {
      continue;
    }
    const PlantBody& child = plant.body(children[b][0]);
    if (!IsHingeOrSlide(plant.joint(body.inbound_joint)) || !child.inbound_joint.valid() ||
        !IsHingeOrSlide(plant.joint(child.inbound_joint))) {
      continue;
    }
    layout.role[b] = Role::Merged;
  }

  // parents first: a fused body's owner is its parent's
  for (BodyId id : plant.body_order) {
    const size_t b = id.index();
    const PlantBody& body = plant.bodies[b];
    if (b == 0 || !body.inbound_joint.valid() || layout.role[b] == Role::Merged) continue;
    const PlantJoint& j = plant.joint(body.inbound_joint);
    if (fuse_fixed && j.type == ir::JointType::Weld && j.parent.index() != 0) {
      // its parent is written or fused (a merged body's only child hangs on a hinge or slide)
      layout.role[b] = Role::Fused;
      layout.owner[b] = layout.owner[j.parent.index()];
      layout.X_OB[b] = layout.X_OB[j.parent.index()] * j.X_PF * j.X_CM.inverse();
      layout.fused[layout.owner[b].index()].push_back(id);
      continue;
    }
    // a written body: its joints back up through the merged bodies above it
    std::vector<JointId> chain{body.inbound_joint};
    BodyId p = j.parent;
    while (layout.role[p.index()] == Role::Merged) {
      layout.owner[p.index()] = id;
      chain.insert(chain.begin(), plant.body(p).inbound_joint);
      p = plant.body(p).parent;
    }
    layout.parent[b] = p;  // written or fused: WriteBody nests it in owner[p]
    layout.joints[b] = std::move(chain);
  }

  layout.mass.resize(n);
  layout.p_BoBcm_B.resize(n);
  layout.I_BBcm_B.resize(n);
  for (size_t b = 0; b < n; ++b) {
    const PlantBody& body = plant.bodies[b];
    layout.mass[b] = body.mass;
    layout.p_BoBcm_B[b] = body.p_BoBcm_B;
    layout.I_BBcm_B[b] = body.I_BBcm_B;
    for (BodyId f : layout.fused[b]) {
      Combine(layout.mass[b], layout.p_BoBcm_B[b], layout.I_BBcm_B[b], plant.body(f),
              layout.X_OB[f.index()]);
    }
  }
  return layout;
}

}  // namespace mdlc::writers
