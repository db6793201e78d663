// resolve_assets.cc - the resolve-assets pass: finds the file behind every
// mesh reference (COMMON-010, COMMON-011), including the meshes MJCF
// primitives are fitted to (BEYOND-002).
//
// Reads: ir::Mesh::uri and the file each geometry was declared in, or
// ir::Mesh::resolved where the frontend already computed the path by its
// format's own rule (MJCF meshdir, MJCF-006). Writes: ir::Mesh::resolved, an
// existing file's path, or empty when there is none.
//
// A reference that cannot be resolved (unknown package, unsupported scheme)
// is an error at the attribute that wrote it, saying where it looked. A file
// that does not exist is an error when the plant needs it: for a collision
// geometry, a geometry with mass whose mass properties come from it, or a
// primitive sized from it. A mesh only visual geometries use is never read for the
// plant: its missing file, or the unknown package that would hold it, is a
// warning (-Wmissing-asset) and the geometry is kept. Each distinct (folder,
// uri) is resolved once and reported at most once, however many geometries
// use it.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <unordered_map>

#include "ir/assets/package_map.h"
#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {
namespace fs = std::filesystem;

class ResolveAssetsPass : public Pass {
 public:
  std::string_view name() const override { return "resolve-assets"; }
  std::string_view description() const override {
    return "Resolve mesh URIs (package://, model://, file://, paths) to existing files";
  }
  ir::VerifyLevel level_after() const override { return ir::VerifyLevel::Named; }
  bool Run(PassContext& ctx) override;
};

const ir::Body* BodyOf(const ir::Module& m, const ir::Geometry& g) {
  if (!g.body.resolved() || g.body.id.index() >= m.bodies.size()) return nullptr;
  return &m[g.body.id];
}

/// "geometry 'g' of body 'b'", as diagnostics name it.
std::string Describe(const ir::Module& m, const ir::Geometry& g, std::string_view kind) {
  std::string s = fmt::format("{}geometry '{}'", kind, m.Text(g.name));
  if (!g.body.name.empty()) s += fmt::format(" of body '{}'", m.Text(g.body.name));
  return s;
}

/// Why the plant reads the file of `g`'s mesh shape, or nullopt when it
/// never does (a mesh only drawn: illustration and perception roles).
std::optional<std::string> WhyShapeMeshIsNeeded(const ir::Module& m, const ir::Geometry& g) {
  if (g.roles & ir::kProximityRole) {
    return fmt::format("it is the shape of {}", Describe(m, g, "collision "));
  }
  // MJCF: a geom with mass (MJCF-031); a zero mass or density (Menagerie's
  // visual classes) makes the mesh's volume irrelevant
  const ir::Body* body = BodyOf(m, g);
  if (body && body->mass_from_geometry && !body->is_world && g.mass_contribution) {
    const ir::MassContribution& c = *g.mass_contribution;
    if (c.mass ? *c.mass != 0 : c.density != 0) {
      return fmt::format("the mass properties of {} come from it", Describe(m, g, ""));
    }
  }
  return std::nullopt;
}

/// "visual geometry 'g' of body 'b' (and 2 more)": the geometries that use a
/// file the plant never reads.
std::string Users(const ir::Module& m, const ir::Geometry& first, size_t users) {
  const bool drawn = first.roles & (ir::kIllustrationRole | ir::kPerceptionRole);
  std::string s = Describe(m, first, drawn ? "visual " : "");
  if (users > 1) s += fmt::format(" (and {} more)", users - 1);
  return s;
}

/// One distinct file reference and every mesh that makes it.
struct Reference {
  std::string uri;
  Loc loc;               // where the first use writes it
  std::string base_dir;  // the referring file's folder
  std::string path;      // computed by the frontend, or empty
  std::vector<ir::Mesh*> meshes;
  // the first use the plant needs the file for: why, and where
  std::optional<std::string> needed_by;
  Loc needed_loc, needed_geometry_loc;
  // the first use, and how many geometries use the file
  const ir::Geometry* first_user = nullptr;
  size_t users = 0;
};

/// The path of a reference no use of which the plant reads. An unknown
/// package is then what a missing file is (COMMON-011, relaxed): a warning,
/// and the geometries are kept; any other failure (an unsupported scheme)
/// stays an error.
std::optional<std::string> ResolveVisualOnly(const Reference& ref,
                                             const assets::PackageMap& packages,
                                             const ir::Module& m, DiagnosticEngine& diags) {
  DiagnosticEngine held;
  std::optional<std::string> path = assets::UriToPath(ref.uri, ref.base_dir, packages, ref.loc, held);
  for (const Diagnostic& d : held.diagnostics()) {
    const bool unknown_package = d.kind == DiagKind::FileNotFound;
    auto report = unknown_package
                      ? diags.Report(DiagKind::MissingAsset, d.loc,
                                     fmt::format("{}; {} is kept without its mesh file, which "
                                                 "the plant never reads",
                                                 d.message, Users(m, *ref.first_user, ref.users)))
                      : diags.Report(d.kind, d.loc, d.message);
    for (const DiagnosticNote& note : d.notes) report.Note(note.loc, note.message);
  }
  return path;
}

/// The file beside `path` whose name differs from it only in case
/// (Base_Collision.STL for base_collision.stl): the model was likely written
/// on a file system that ignores case. Empty when there is none.
std::string SameNameButCase(const std::string& path) {
  const fs::path missing(path);
  auto lower = [](std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
  };
  const std::string wanted = lower(missing.filename().string());
  std::error_code ec;
  for (fs::directory_iterator it(missing.parent_path(), ec), end; !ec && it != end;
       it.increment(ec)) {
    if (lower(it->path().filename().string()) == wanted) return it->path().string();
  }
  return {};
}

/// A note naming the file that differs only in case, when there is one.
void NoteCaseMismatch(InFlightDiagnostic& diag, Loc loc, const std::string& path) {
  const std::string beside = SameNameButCase(path);
  if (beside.empty()) return;
  diag.Note(loc, fmt::format("did you mean '{}'? file names differ in case, and this file "
                             "system tells them apart",
                             fs::path(beside).filename().string()));
}

/// A note naming a later copy of the package that has the file, when the
/// package path holds two and the one used lacks it (COMMON-013).
void NoteShadowedCopy(InFlightDiagnostic& diag, Loc loc, const std::string& uri,
                      const assets::PackageMap& packages) {
  const std::optional<std::string> copy = packages.ShadowedCopyHolding(uri);
  if (!copy) return;
  diag.Note(loc, fmt::format("'{}' is in another copy of the package, which the package path "
                             "holds too but the first copy found shadows",
                             *copy));
}

bool ResolveAssetsPass::Run(PassContext& ctx) {
  const assets::PackageMap& packages = ctx.packages;
  const ir::Module& m = ctx.module;

  std::vector<Reference> refs;
  std::unordered_map<std::string, size_t> by_key;  // "dir\n" + uri, or "\n" + path
  auto add = [&](const ir::Geometry& g, ir::Mesh* mesh, std::optional<std::string> why) {
    if (mesh->inline_data) return;  // an MJCF inline mesh: no file to find
    const Loc loc = mesh->uri_loc.valid() ? mesh->uri_loc : g.loc;
    const std::string base_dir =
        loc.valid() ? fs::path(ctx.sources.Path(loc.file)).parent_path().string()
                    : std::string(".");
    const std::string key = mesh->resolved.empty() ? base_dir + "\n" + mesh->uri
                                                   : "\n" + mesh->resolved;
    auto [it, inserted] = by_key.emplace(key, refs.size());
    if (inserted) refs.push_back({mesh->uri, loc, base_dir, mesh->resolved, {}, {}, {}, {}, &g, 0});
    Reference& ref = refs[it->second];
    ref.meshes.push_back(mesh);
    ++ref.users;
    if (why && !ref.needed_by) {
      ref.needed_by = std::move(why);
      ref.needed_loc = loc;
      ref.needed_geometry_loc = g.loc;
    }
  };
  for (ir::Geometry& g : ctx.module.geometries) {
    if (auto* mesh = std::get_if<ir::Mesh>(&g.shape)) add(g, mesh, WhyShapeMeshIsNeeded(m, g));
    // the mesh an MJCF primitive is fitted to (BEYOND-002)
    if (g.fit_to_mesh) {
      add(g, &g.fit_to_mesh->mesh,
          fmt::format("{} takes its size from it", Describe(m, g, "")));
    }
  }

  for (Reference& ref : refs) {
    std::optional<std::string> path;
    if (!ref.path.empty()) {
      path = ref.path;
    } else if (ref.needed_by) {
      // an unknown package or unsupported scheme is an error when the plant
      // needs the file
      path = assets::UriToPath(ref.uri, ref.base_dir, packages, ref.needed_loc, ctx.diags);
    } else {
      path = ResolveVisualOnly(ref, packages, m, ctx.diags);
    }
    std::error_code ec;
    std::string resolved;
    if (path && fs::exists(*path, ec)) {
      resolved = fs::path(*path).lexically_normal().string();
    } else if (path && ref.needed_by) {
      auto diag = ctx.diags.Report(
          DiagKind::FileNotFound, ref.needed_loc,
          fmt::format("'{}' resolves to '{}', which does not exist", ref.uri, *path));
      NoteCaseMismatch(diag, ref.needed_loc, *path);
      NoteShadowedCopy(diag, ref.needed_loc, ref.uri, packages);
      diag.Note(ref.needed_geometry_loc,
                fmt::format("the plant reads this file: {}", *ref.needed_by));
    } else if (path) {
      // COMMON-011, relaxed: nothing in the plant reads a visual mesh
      auto diag = ctx.diags.Report(
          DiagKind::MissingAsset, ref.loc,
          fmt::format("'{}' resolves to '{}', which does not exist; {} is kept without its "
                      "mesh file, which the plant never reads",
                      ref.uri, *path, Users(m, *ref.first_user, ref.users)));
      NoteCaseMismatch(diag, ref.loc, *path);
      NoteShadowedCopy(diag, ref.loc, ref.uri, packages);
    }
    for (ir::Mesh* mesh : ref.meshes) mesh->resolved = resolved;
  }
  return true;
}

}  // namespace

std::unique_ptr<Pass> CreateResolveAssetsPass() { return std::make_unique<ResolveAssetsPass>(); }

}  // namespace mdlc::passes
