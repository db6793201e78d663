// fit-to-mesh pass: MJCF primitive geoms that name a mesh take their size
// and pose from it, as MuJoCo fits them (BEYOND-002; mesh/mesh_fit.h has
// MuJoCo's rules).
//
// Reads: Geometry::fit_to_mesh, the mesh from PassContext::meshes (loaded by
// load-meshes). Writes: the geometry's shape (sized) and X_BG (composed with
// the primitive's pose in the mesh frame); the fit is consumed
// (fit_to_mesh cleared), so running the pass again changes nothing.
#include <fmt/format.h>

#include "passes/mesh/cached_properties.h"
#include "passes/mesh/mesh_fit.h"
#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {

class FitToMeshPass : public Pass {
 public:
  std::string_view name() const override { return "fit-to-mesh"; }
  std::string_view description() const override {
    return "Size and place primitives fitted to meshes (MJCF geoms with a primitive type and a "
           "mesh)";
  }
  ir::VerifyLevel level_after() const override { return ir::VerifyLevel::Named; }
  bool Run(PassContext& ctx) override {
    for (ir::Geometry& g : ctx.module.geometries) {
      if (!g.fit_to_mesh) continue;
      const ir::MeshFit fit = *g.fit_to_mesh;
      if (fit.mesh.resolved.empty()) continue;  // resolve-assets reported it
      if (!ctx.meshes->Status(fit.mesh.resolved).ok()) continue;  // load-meshes reported it
      std::string why;
      auto props = mesh::CachedMujocoMeshMassProperties(*ctx.meshes, fit.mesh.resolved,
                                                        fit.mesh.scale, fit.mesh_inertia, &why);
      std::optional<mesh::FittedPrimitive> fitted;
      if (props) fitted = mesh::FitPrimitive(*props, g.shape, fit.aabb, fit.fitscale, &why);
      if (!fitted) {
        ctx.diags
            .Report(DiagKind::BadMesh, g.loc,
                    fmt::format("cannot fit a {} to mesh '{}': {}", ir::ShapeTypeName(g.shape),
                                fit.mesh.uri, why))
            .Note(fit.mesh.uri_loc, "the mesh is named here");
        continue;
      }
      g.shape = fitted->shape;
      g.X_BG = g.X_BG * fitted->X_MG;
      g.fit_to_mesh.reset();
    }
    return true;
  }
};

}  // namespace

std::unique_ptr<Pass> CreateFitToMeshPass() { return std::make_unique<FitToMeshPass>(); }

}  // namespace mdlc::passes
