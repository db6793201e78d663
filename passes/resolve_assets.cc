// resolve_assets.cc - the resolve-assets pass: finds the file behind every
// mesh reference (COMMON-010, COMMON-011), including the meshes MJCF
// primitives are fitted to (BEYOND-002).
//
// Reads: ir::Mesh::uri and the file each geometry was declared in. Writes:
// ir::Mesh::resolved, an existing file's path. A reference that cannot be
// resolved is an error at the attribute that wrote it, saying where it looked.
// Each distinct (folder, uri) is resolved once, however many geometries use it.
#include <filesystem>
#include <unordered_map>

#include "frontend/package_map.h"
#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {

class ResolveAssetsPass : public Pass {
 public:
  std::string_view name() const override { return "resolve-assets"; }
  std::string_view description() const override {
    return "Resolve mesh URIs (package://, model://, file://, paths) to existing files";
  }
  ir::VerifyLevel level_after() const override { return ir::VerifyLevel::Named; }
  bool Run(PassContext& ctx) override;
};

bool ResolveAssetsPass::Run(PassContext& ctx) {
  static const frontend::PackageMap kNoPackages;
  const frontend::PackageMap& packages = ctx.packages ? *ctx.packages : kNoPackages;
  const size_t errors_before = ctx.diags.error_count();
  std::unordered_map<std::string, std::optional<std::string>> resolved;  // "dir\n" + uri
  auto resolve = [&](const ir::Geometry& g, ir::Mesh* mesh) {
    if (!mesh || !mesh->resolved.empty()) return;
    const Loc loc = mesh->uri_loc.valid() ? mesh->uri_loc : g.loc;
    const std::string base_dir =
        loc.valid() ? std::filesystem::path(ctx.sources.Path(loc.file)).parent_path().string()
                    : std::string(".");
    const std::string key = base_dir + "\n" + mesh->uri;
    auto it = resolved.find(key);
    if (it == resolved.end()) {
      it = resolved.emplace(key, frontend::ResolveUri(mesh->uri, base_dir, packages, loc, ctx.diags))
               .first;
    }
    if (it->second) mesh->resolved = *it->second;
  };
  for (ir::Geometry& g : ctx.module.geometries) {
    resolve(g, std::get_if<ir::Mesh>(&g.shape));
    // the mesh an MJCF primitive is fitted to (BEYOND-002)
    if (g.fit_to_mesh) resolve(g, &g.fit_to_mesh->mesh);
  }
  return ctx.diags.error_count() == errors_before;
}

}  // namespace

std::unique_ptr<Pass> CreateResolveAssetsPass() { return std::make_unique<ResolveAssetsPass>(); }

}  // namespace mdlc::passes
