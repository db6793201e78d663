// inertia-from-collisions pass: SDFormat's <inertial auto="true"> (SDF-007):
// a body's mass properties are those of its collision geometry, solid, at
// the given density (a collision's own <density>, else the inertial's, else
// 1000 kg/m^3).
//
// Primitives use the closed forms of shape_mass.h. Meshes (BEYOND-001) use
// the mesh loaded by load-meshes, scaled: the exact solid when the surface
// is closed and consistently oriented, else (with a warning) its convex
// hull; a mesh declared convex always uses its hull, as Drake does.
//
// Reads: Body::inertia_from_collisions, the proximity geometries of such a
// body with their poses (so it runs after resolve-frames), meshes from
// PassContext::meshes. Writes: Body::inertial (mass, center of mass, inertia
// about it in the body frame). Half spaces, with no finite volume, are
// reported and left out.
#include <fmt/format.h>

#include "passes/mesh/cached_properties.h"
#include "passes/mesh/convex_hull.h"
#include "passes/mesh/mass_properties.h"
#include "passes/pass_registry.h"
#include "passes/shape_mass.h"

namespace mdlc::passes {
namespace {

class InertiaFromCollisionsPass : public Pass {
 public:
  std::string_view name() const override { return "inertia-from-collisions"; }
  std::string_view description() const override {
    return "Compute mass properties from collision geometry where the file asks (SDFormat "
           "<inertial auto=\"true\">)";
  }
  ir::VerifyLevel level_after() const override { return ir::VerifyLevel::Named; }
  bool Run(PassContext& ctx) override;

 private:
  /// The solid a mesh geometry stands for, per unit density; nullopt when
  /// it has none (reported here, or already by an earlier pass).
  std::optional<mesh::MassProperties> MeshSolid(PassContext& ctx, const ir::Geometry& g,
                                                const ir::Mesh& mesh);
};

std::optional<mesh::MassProperties> InertiaFromCollisionsPass::MeshSolid(PassContext& ctx,
                                                                         const ir::Geometry& g,
                                                                         const ir::Mesh& m) {
  if (m.resolved.empty()) return std::nullopt;  // resolve-assets reported it
  if (!ctx.meshes->Status(m.resolved).ok()) return std::nullopt;  // load-meshes reported it
  const mesh::CollisionSolid solid =
      mesh::CachedCollisionSolid(*ctx.meshes, m.resolved, m.scale, m.convex);
  if (solid.used_hull && !m.convex) {
    ctx.diags.Report(DiagKind::MeshNotClosed, m.uri_loc.valid() ? m.uri_loc : g.loc,
                     fmt::format("mesh '{}' of collision '{}' is not a closed, outward-oriented "
                                 "surface; its convex hull is used for the mass properties",
                                 m.uri, ctx.module.Text(g.name)));
  }
  if (!solid.mass) {
    ctx.diags.Report(DiagKind::BadMassProperties, g.loc,
                     fmt::format("collision '{}': mesh '{}' encloses no volume ({})",
                                 ctx.module.Text(g.name), m.uri, solid.error));
    return std::nullopt;
  }
  return solid.mass;
}

bool InertiaFromCollisionsPass::Run(PassContext& ctx) {
  ir::Module& m = ctx.module;
  bool any = false;
  for (const ir::Body& b : m.bodies) any |= b.inertia_from_collisions.has_value();
  if (!any) return true;
  std::vector<MassSum> sums(m.bodies.size());
  for (const ir::Geometry& g : m.geometries) {
    if (!(g.roles & ir::kProximityRole) || !g.body.resolved()) continue;
    const ir::Body& b = m[g.body.id];
    if (!b.inertia_from_collisions) continue;
    mesh::MassProperties unit;
    if (const auto* mesh = std::get_if<ir::Mesh>(&g.shape)) {
      auto solid = MeshSolid(ctx, g, *mesh);
      if (!solid) continue;
      unit = *solid;
    } else if (auto solid = SolidOf(g.shape)) {
      unit.measure = solid->measure;
      unit.inertia = solid->inertia;
    } else {
      ctx.diags.Report(DiagKind::NotImplementedYet, g.loc,
                       fmt::format("collision '{}' ({}) is left out of the mass properties of "
                                   "'{}': it has no finite volume",
                                   m.Text(g.name), ir::ShapeTypeName(g.shape), m.Text(b.name)));
      continue;
    }
    const double density = g.density.value_or(*b.inertia_from_collisions);
    sums[g.body.id.index()].Add(density * unit.measure, g.X_BG, unit.com,
                                density * unit.inertia);
  }
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    ir::Body& b = m.bodies[i];
    if (!b.inertia_from_collisions) continue;
    const MassSum& s = sums[i];
    if (s.parts() == 0 || s.mass() <= 0) {
      ctx.diags.Report(DiagKind::BadValue, b.loc,
                       fmt::format("link '{}' asks for mass properties from its collisions "
                                   "(<inertial auto=\"true\">) but has no collision with a "
                                   "volume",
                                   m.Text(b.name)));
      continue;
    }
    ir::Inertial in = s.ToInertial(b.inertial ? b.inertial->loc : b.loc);
    if (b.inertia_from_collisions_mass) {
      // a given mass wins: the densities only shape the distribution
      SetInertiaMatrix(in, InertiaMatrix(in) * (*b.inertia_from_collisions_mass / s.mass()));
      in.mass = *b.inertia_from_collisions_mass;
    }
    b.inertial = in;
  }
  return true;
}

}  // namespace

std::unique_ptr<Pass> CreateInertiaFromCollisionsPass() {
  return std::make_unique<InertiaFromCollisionsPass>();
}

}  // namespace mdlc::passes
