// mass-from-geometry pass: MJCF bodies whose mass properties come from their
// geoms (compiler@inertiafromgeom; MJCF-031), then MuJoCo's whole-model
// corrections (compiler boundmass, boundinertia, balanceinertia,
// settotalmass; BEYOND-006), as MuJoCo 3.3.8 computes them.
//
// Per geometry with a MassContribution on a body with mass_from_geometry:
// * measure: the primitive's volume (its surface area with shellinertia,
//   shape_mass.h), or the mesh's per mesh@inertia (mesh/mass_properties.h);
//   half spaces have none; shellinertia on a mesh is an error (MuJoCo: the
//   mesh asset's inertia says it);
// * mass: geom@mass when given (0 stays 0; a measure of at most 1e-14 gives
//   nothing), else density * measure;
// * geometries of mass at most 1e-14 are left out; a body left with none is
//   massless (no Inertial), as in MuJoCo.
// The sum's inertia about the center of mass must have eigenvalues of at
// least 1e-14 when several geometries add up (MuJoCo's check).
//
// Then, per model instance with MassAdjustments, for each of its bodies
// that has mass properties from the file or from geometry: mass raised to
// boundmass, principal moments raised to boundinertia, moments violating
// A + B >= C replaced by their mean when balanceinertia; finally every
// mass and inertia of the model scaled so that the masses sum to
// settotalmass. (MuJoCo applies the first three to each body as it compiles
// it and the scaling after the whole model; bodies the frontend adds itself,
// without mass properties, are left alone.)
//
// Reads: Body::mass_from_geometry, Geometry::mass_contribution, shapes and
// X_BG (after fit-to-mesh), meshes from PassContext::meshes,
// ModelInstance::mass_adjustments. Writes: Body::inertial.
#include <fmt/format.h>

#include <Eigen/Eigenvalues>

#include "passes/mesh/cached_properties.h"
#include "passes/mesh/mass_properties.h"
#include "passes/mesh/mujoco_eigen.h"
#include "passes/pass_registry.h"
#include "passes/shape_mass.h"

namespace mdlc::passes {
namespace {

constexpr double kEps = 1e-14;  // MuJoCo's mjEPS

class MassFromGeometryPass : public Pass {
 public:
  std::string_view name() const override { return "mass-from-geometry"; }
  std::string_view description() const override {
    return "Compute MJCF bodies' mass properties from their geoms and apply the compiler's mass "
           "corrections";
  }
  ir::VerifyLevel level_after() const override { return ir::VerifyLevel::Named; }
  bool Run(PassContext& ctx) override {
    FromGeometry(ctx);
    Adjust(ctx);
    AlignFree(ctx);
    return true;
  }

 private:
  struct Part {
    double mass = 0;
    Eigen::Vector3d com = Eigen::Vector3d::Zero();      // in G
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about com, G axes
  };
  std::optional<Part> PartOf(PassContext& ctx, const ir::Geometry& g);
  void FromGeometry(PassContext& ctx);
  /// Every model's MassAdjustments, on the bodies they apply to.
  void Adjust(PassContext& ctx);
  /// boundmass, boundinertia and balanceinertia on one body.
  static void Bound(ir::Body& b, const ir::MassAdjustments& adj);
  /// Body::align_free: each such body's frame moved to its principal
  /// inertial frame, everything on it re-expressed.
  void AlignFree(PassContext& ctx);
  /// Per aligned body whose mass is one geometry's: MuJoCo's inertial frame
  /// for it (the geom's frame, a mesh's at its principal axes).
  std::vector<std::optional<Transform>> single_primitive_;
};

// The principal axes of an inertia about its COM (columns of R_IP, moments
// decreasing) as MuJoCo 3.3.8's compiler picks them (mesh::MujocoEigen), so
// that an aligned body's frame is MuJoCo's, not just one of the 24 frames
// that diagonalize the inertia.
Eigen::Matrix3d MujocoPrincipalAxes(const Eigen::Matrix3d& I) {
  Eigen::Vector3d moments;
  Eigen::Matrix3d axes;
  mesh::MujocoEigen(I, &moments, &axes);
  return axes;
}

void MassFromGeometryPass::AlignFree(PassContext& ctx) {
  ir::Module& m = ctx.module;
  std::vector<std::optional<Transform>> X_BP(m.bodies.size());
  bool any = false;
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    const ir::Body& b = m.bodies[i];
    if (!b.align_free || !b.inertial || b.inertial->mass <= 0) continue;
    const ir::Inertial& in = *b.inertial;
    const Eigen::Matrix3d I = InertiaMatrix(in);
    Transform P = in.X_BI;
    if (i < single_primitive_.size() && single_primitive_[i]) {
      P = *single_primitive_[i];  // MuJoCo copies the one geom's frame
    } else if (b.mass_from_geometry || !I.isDiagonal(0)) {
      // the geoms' sum, or a fullinertia: MuJoCo's principal axes
      P.R = in.X_BI.R * MujocoPrincipalAxes(I);
    }  // else an <inertial> quat with diaginertia: its frame
    X_BP[i] = P;
    any = true;
  }
  if (!any) return;
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    if (!X_BP[i]) continue;
    ir::Body& b = m.bodies[i];
    ir::Inertial& in = *b.inertial;
    const Transform X_PB = X_BP[i]->inverse();
    const Eigen::Matrix3d R_PI = X_PB.R * in.X_BI.R;
    const Eigen::Matrix3d I_P = R_PI * InertiaMatrix(in) * R_PI.transpose();
    in.X_BI = Transform::FromTranslation(X_PB * in.X_BI.p);
    SetInertiaMatrix(in, I_P);
    if (b.default_pose && !b.aligned_default_pose) b.default_pose = *b.default_pose * *X_BP[i];
  }
  auto moved = [&](const ir::Ref<BodyId>& body) -> const std::optional<Transform>* {
    if (!body.resolved() || body.id.index() >= X_BP.size() || !X_BP[body.id.index()]) {
      return nullptr;
    }
    return &X_BP[body.id.index()];
  };
  for (ir::Geometry& g : m.geometries) {
    if (auto* P = moved(g.body)) g.X_BG = (*P)->inverse() * g.X_BG;
  }
  for (ir::Frame& f : m.frames) {
    if (auto* P = moved(f.body)) f.X_BF = (*P)->inverse() * f.X_BF;
  }
  for (ir::Camera& c : m.cameras) {
    if (auto* P = moved(c.body)) c.X_BC = (*P)->inverse() * c.X_BC;
  }
  for (ir::Joint& j : m.joints) {
    const auto* P = moved(j.child);
    if (!P || j.type != ir::JointType::QuaternionFloating) continue;
    const ir::Body& b = m[j.child.id];
    if (b.aligned_default_pose || j.default_positions.size() != 7) continue;
    const auto& q = j.default_positions;
    Transform X_FM{Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix(),
                   Eigen::Vector3d(q[4], q[5], q[6])};
    X_FM = X_FM * j.X_CM.inverse() * **P * j.X_CM;
    Eigen::Quaterniond r(X_FM.R);
    if (r.w() < 0) r.coeffs() = -r.coeffs();
    j.default_positions = {r.w(), r.x(), r.y(), r.z(), X_FM.p.x(), X_FM.p.y(), X_FM.p.z()};
  }
}

std::optional<MassFromGeometryPass::Part> MassFromGeometryPass::PartOf(PassContext& ctx,
                                                                        const ir::Geometry& g) {
  const ir::MassContribution& c = *g.mass_contribution;
  double measure = 0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  Eigen::Matrix3d unit = Eigen::Matrix3d::Zero();
  if (const auto* mesh = std::get_if<ir::Mesh>(&g.shape)) {
    if (c.shell) {
      ctx.diags.Report(DiagKind::BadMassProperties, g.loc,
                       fmt::format("geom '{}': shellinertia does not apply to a mesh; a mesh's "
                                   "inertia is set on the mesh asset (inertia=\"shell\")",
                                   ctx.module.Text(g.name)));
      return std::nullopt;
    }
    if (mesh->resolved.empty()) return std::nullopt;  // resolve-assets reported it
    if (!ctx.meshes->Status(mesh->resolved).ok()) return std::nullopt;  // load-meshes reported it
    std::string why;
    auto props = mesh::CachedMujocoMeshMassProperties(*ctx.meshes, mesh->resolved, mesh->scale,
                                                      c.mesh_inertia, &why);
    if (!props) {
      ctx.diags
          .Report(DiagKind::BadMassProperties, g.loc,
                  fmt::format("geom '{}': no mass properties from mesh '{}': {}",
                              ctx.module.Text(g.name), mesh->uri, why))
          .Note(mesh->uri_loc, "the mesh is named here");
      return std::nullopt;
    }
    measure = props->mass.measure;
    com = props->mass.com;
    unit = props->mass.inertia;
  } else {
    auto u = c.shell ? MujocoShellOf(g.shape) : SolidOf(g.shape);
    if (!u) return Part{};  // half space: nothing
    measure = u->measure;
    unit = u->inertia;
  }
  Part p;
  if (c.mass) {
    if (*c.mass != 0 && measure > kEps) p.mass = *c.mass;
  } else if (c.density != 0) {
    p.mass = c.density * measure;
  }
  if (p.mass < 0 || measure < 0) {
    ctx.diags.Report(DiagKind::BadMassProperties, g.loc,
                     fmt::format("geom '{}': mass or density is negative", ctx.module.Text(g.name)));
    return std::nullopt;
  }
  p.com = com;
  if (p.mass > 0) p.inertia = unit * (p.mass / measure);
  return p;
}

void MassFromGeometryPass::FromGeometry(PassContext& ctx) {
  ir::Module& m = ctx.module;
  bool any = false;
  for (const ir::Body& b : m.bodies) any |= b.mass_from_geometry && !b.is_world;
  if (!any) return;
  std::vector<MassSum> sums(m.bodies.size());
  single_primitive_.assign(m.bodies.size(), std::nullopt);
  for (const ir::Geometry& g : m.geometries) {
    if (!g.mass_contribution || !g.body.resolved()) continue;
    const ir::Body& b = m[g.body.id];
    if (!b.mass_from_geometry || b.is_world) continue;
    auto part = PartOf(ctx, g);
    if (!part || part->mass <= kEps) continue;
    MassSum& sum = sums[g.body.id.index()];
    sum.Add(part->mass, g.X_BG, part->com, part->inertia);
    // MuJoCo takes the one geom's frame as the body's inertial frame: a
    // primitive's own, a mesh's moved to the mesh's principal frame
    std::optional<Transform> frame;
    if (sum.parts() == 1 && b.align_free) {
      frame = g.X_BG;
      if (std::holds_alternative<ir::Mesh>(g.shape)) {
        frame = g.X_BG * Transform{MujocoPrincipalAxes(part->inertia), part->com};
      }
    }
    single_primitive_[g.body.id.index()] = frame;
  }
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    ir::Body& b = m.bodies[i];
    if (!b.mass_from_geometry || b.is_world) continue;
    const MassSum& s = sums[i];
    if (s.parts() == 0) {
      b.inertial.reset();  // massless, as MuJoCo leaves it
      continue;
    }
    ir::Inertial in = s.ToInertial(b.loc);
    if (s.parts() > 1) {
      const double smallest =
          Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(s.inertia_about_com()).eigenvalues()[0];
      if (smallest < kEps) {
        ctx.diags.Report(DiagKind::BadMassProperties, b.loc,
                         fmt::format("body '{}': the inertia its geoms add up to has a principal "
                                     "moment below 1e-14",
                                     m.Text(b.name)));
        continue;
      }
    }
    b.inertial = in;
  }
}

void MassFromGeometryPass::Adjust(PassContext& ctx) {
  // every model's corrections in one walk over the bodies, and the scaling
  // in a second: a walk per model made a scene of N MJCF models cost N^2
  ir::Module& m = ctx.module;
  auto adjustments = [&](const ir::Body& b) -> const ir::MassAdjustments* {
    if (b.is_world || !(b.inertial || b.mass_from_geometry)) return nullptr;
    const auto& adj = m[b.model].mass_adjustments;
    return adj ? &*adj : nullptr;
  };
  std::vector<double> total_mass(m.models.size(), 0.0);
  bool any_total = false;
  for (ir::Body& b : m.bodies) {
    const ir::MassAdjustments* adj = adjustments(b);
    if (!adj) continue;
    Bound(b, *adj);
    if (adj->total_mass && *adj->total_mass > 0 && b.inertial) {
      total_mass[b.model.index()] += b.inertial->mass;
      any_total = true;
    }
  }
  if (!any_total) return;
  for (ir::Body& b : m.bodies) {
    const ir::MassAdjustments* adj = adjustments(b);
    if (!adj || !adj->total_mass || *adj->total_mass <= 0 || !b.inertial) continue;
    constexpr double kMinVal = 1e-15;  // MuJoCo's mjMINVAL: no division by zero
    const double scale =
        std::max(kMinVal, *adj->total_mass / std::max(kMinVal, total_mass[b.model.index()]));
    ir::Inertial& in = *b.inertial;
    in.mass *= scale;
    SetInertiaMatrix(in, InertiaMatrix(in) * scale);
  }
}

void MassFromGeometryPass::Bound(ir::Body& b, const ir::MassAdjustments& adj) {
  if (!b.inertial) {
    if (adj.bound_mass <= 0 && adj.bound_inertia <= 0) return;
    b.inertial.emplace();  // massless until bounded, at the body origin
    b.inertial->loc = b.loc;
  }
  ir::Inertial& in = *b.inertial;
  in.mass = std::max(in.mass, adj.bound_mass);
  const Eigen::Matrix3d I = InertiaMatrix(in);
  const double trace = I.trace();
  // no bound above zero and no balancing: only a moment below zero would
  // change, and a clearly positive definite inertia has none (the common
  // case, found without an eigen-decomposition per body)
  if (adj.bound_inertia <= 0 && !adj.balance_inertia && trace > 0 &&
      mesh::ClearlyPositiveDefinite(I, trace)) {
    return;
  }
  Eigen::Vector3d moments;
  Eigen::Matrix3d axes;
  mesh::PrincipalAxes(I, &moments, &axes);
  bool changed = false;
  for (int k = 0; k < 3; ++k) {
    if (moments[k] < adj.bound_inertia) {
      moments[k] = adj.bound_inertia;
      changed = true;
    }
  }
  // MuJoCo's test is exact, no tolerance
  const double a = moments[0], b2 = moments[1], c = moments[2];
  if (adj.balance_inertia && (a + b2 < c || a + c < b2 || b2 + c < a)) {
    moments.setConstant(moments.sum() / 3);
    changed = true;
  }
  if (changed) SetInertiaMatrix(in, axes * moments.asDiagonal() * axes.transpose());
}

}  // namespace

std::unique_ptr<Pass> CreateMassFromGeometryPass() {
  return std::make_unique<MassFromGeometryPass>();
}

}  // namespace mdlc::passes
