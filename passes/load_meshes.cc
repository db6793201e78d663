// load-meshes pass: finds out, for every mesh file the compiler computes
// with, whether it is a mesh and what the compile takes from it, in
// parallel, each file once (BEYOND-001): from the derived mesh cache when
// it knows the file's content, else by reading the file (issue 57).
//
// Which meshes: those whose geometry is needed, namely a mesh a primitive
// is fitted to (MJCF, BEYOND-002), a mesh geometry that contributes to a
// body's mass (MJCF mass_contribution on a mass_from_geometry body), and a
// proximity mesh of a body whose inertia comes from its collisions
// (SDFormat <inertial auto="true">). Other meshes (visuals, deformable .vtk
// volume meshes, ...) are not read, as Drake's parser does not read them:
// a placeholder or unreadable visual mesh is no error (resolve-assets has
// checked that the file is there).
//
// An MJCF inline mesh (ir::Mesh::inline_data) is no file: its triangles,
// or the convex hull of its points when it has no faces (point_cloud.h),
// go into the cache under its key, and no reader runs for it.
//
// Reads: ir::Mesh::resolved (set by resolve-assets). Writes:
// PassContext::meshes. A file that cannot be read, or holds no triangles,
// is an error at the attribute naming it. A COLLADA file that declares an up
// axis other than Z gets a note, once per compile, saying what was done
// with it (passes/mesh/io/mesh_axes.h).
#include <fmt/format.h>

#include <set>

#include "passes/mesh/point_cloud.h"
#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {

class LoadMeshesPass : public Pass {
 public:
  std::string_view name() const override { return "load-meshes"; }
  std::string_view description() const override {
    return "Read the mesh files that mass properties and fitted primitives need (each once, in "
           "parallel, unless the mesh cache knows them)";
  }
  ir::VerifyLevel level_after() const override { return ir::VerifyLevel::Named; }
  bool Run(PassContext& ctx) override {
    struct Use {
      std::string path;
      Loc loc;
    };
    std::vector<Use> uses;
    size_t files = 0;  // uses of mesh files (not inline meshes)
    for (const ir::Geometry& g : ctx.module.geometries) {
      auto add = [&](const ir::Mesh& mesh) {
        if (mesh.inline_data) {
          // an MJCF inline mesh: kept in the cache under its key, no file
          ctx.meshes->Provide(mesh.resolved,
                              mesh::TrianglesOfInlineMesh(*mesh.inline_data,
                                                          fmt::format("mesh '{}'", mesh.uri)));
        } else if (!mesh.resolved.empty()) {
          ++files;
        }
        // an unresolved mesh was reported by resolve-assets
        if (!mesh.resolved.empty()) {
          uses.push_back({mesh.resolved, mesh.uri_loc.valid() ? mesh.uri_loc : g.loc});
        }
      };
      if (g.fit_to_mesh) add(g.fit_to_mesh->mesh);
      const auto* mesh = std::get_if<ir::Mesh>(&g.shape);
      if (!mesh || !g.body.resolved()) continue;
      const ir::Body& b = ctx.module[g.body.id];
      const bool for_mass = (b.mass_from_geometry && g.mass_contribution) ||
                            (b.inertia_from_collisions && (g.roles & ir::kProximityRole));
      if (for_mass) add(*mesh);
    }
    if (uses.empty()) return true;
    std::vector<std::string> paths;
    for (const Use& u : uses) paths.push_back(u.path);
    if (files > 0 && !ctx.meshes->reader_missing().empty()) {
      // once per compile: the files are still read, but a crash of the mesh
      // importer on one of them would now take the compile down with it
      ctx.diags.Report(DiagKind::MeshReaderMissing, uses.front().loc,
                       fmt::format("mesh files are read inside mdlc, unprotected: {}",
                                   ctx.meshes->reader_missing()));
    }
    ctx.meshes->Survey(paths);

    // one report per place that names a bad file (MJCF geoms share their asset's)
    std::set<std::tuple<std::string, uint32_t, uint32_t, uint32_t>> reported;
    mesh::OffAxisColladaFiles off_axis;
    Loc off_axis_loc;  // where the first of them is named
    for (const Use& u : uses) {
      const mesh::MeshStatus m = ctx.meshes->Status(u.path);
      if (m.ok()) {
        const bool first = off_axis.empty();
        if (off_axis.Add(u.path, m.facts->declared_up, m.facts->turned_to_z_up) && first) {
          off_axis_loc = u.loc;
        }
        continue;
      }
      if (!reported.emplace(u.path, u.loc.file.value, u.loc.line, u.loc.column).second) {
        continue;
      }
      ctx.diags.Report(m.over_limit ? DiagKind::LimitExceeded : DiagKind::BadMesh, u.loc, m.error);
    }
    if (!off_axis.empty()) ctx.diags.Report(DiagKind::MeshAxes, off_axis_loc, off_axis.Note());
    return true;
  }
};

}  // namespace

std::unique_ptr<Pass> CreateLoadMeshesPass() { return std::make_unique<LoadMeshesPass>(); }

}  // namespace mdlc::passes
