// cached_properties.cc - see cached_properties.h.
#include "passes/mesh/cached_properties.h"

#include <fmt/format.h>

#include "passes/mesh/convex_hull.h"

namespace mdlc::mesh {
namespace {

// MassProperties as 13 doubles: measure, com, inertia (column-major)
void Put(const MassProperties& m, std::vector<double>& out) {
  out.push_back(m.measure);
  out.insert(out.end(), m.com.data(), m.com.data() + 3);
  out.insert(out.end(), m.inertia.data(), m.inertia.data() + 9);
}
const double* Get(const double* in, MassProperties& m) {
  m.measure = *in++;
  for (int k = 0; k < 3; ++k) m.com[k] = *in++;
  for (int k = 0; k < 9; ++k) m.inertia.data()[k] = *in++;
  return in;
}
template <typename Matrix>
void PutMatrix(const Matrix& m, std::vector<double>& out) {
  out.insert(out.end(), m.data(), m.data() + m.size());
}
template <typename Matrix>
const double* GetMatrix(const double* in, Matrix& m) {
  for (Eigen::Index k = 0; k < m.size(); ++k) m.data()[k] = *in++;
  return in;
}
constexpr size_t kMujocoValues = 13 + 9 + 3 + 3 + 3 + 3;

std::optional<std::string> KeyFor(MeshCache& meshes, const std::string& path,
                                  std::string_view what, const Eigen::Vector3d& scale) {
  if (!meshes.derived()) return std::nullopt;
  const MeshStatus status = meshes.Status(path);
  const std::optional<ContentDigest> digest = meshes.Digest(path);
  if (!status.ok() || !digest) return std::nullopt;
  // hex floats: the exact scale, not a rounding of it; the same bytes read
  // with other axes (--collada-up-axis) are another mesh
  return DerivedMeshCache::Key(
      *digest, fmt::format("{}|scale={:a},{:a},{:a}|up={},turned={}", what, scale.x(), scale.y(),
                           scale.z(), UpAxisName(status.facts->declared_up),
                           status.facts->turned_to_z_up));
}

/// The mesh at `path`, read now that it is needed; null, with `*error`
/// set, when it cannot be (changed on disk since it was surveyed).
std::shared_ptr<const TriangleMesh> Triangles(MeshCache& meshes, const std::string& path,
                                              std::string* error) {
  MeshOrError m = meshes.Get(path);
  if (!m.ok()) *error = m.error;
  return m.mesh;
}

}  // namespace

std::optional<MujocoMeshProperties> CachedMujocoMeshMassProperties(
    MeshCache& meshes, const std::string& path, const Eigen::Vector3d& scale,
    ir::MeshInertia mode, std::string* error) {
  DerivedMeshCache* cache = meshes.derived();
  const auto key =
      KeyFor(meshes, path, fmt::format("mujoco-mass|mode={}|axes=jacobi", static_cast<int>(mode)), scale);
  if (key) {
    if (auto values = cache->Load(*key); values && values->size() == kMujocoValues) {
      MujocoMeshProperties p;
      const double* in = Get(values->data(), p.mass);
      in = GetMatrix(in, p.R_MP);
      in = GetMatrix(in, p.principal_moments);
      in = GetMatrix(in, p.inertia_box);
      in = GetMatrix(in, p.aabb_min);
      GetMatrix(in, p.aabb_max);
      return p;
    }
  }
  const auto mesh = Triangles(meshes, path, error);
  if (!mesh) return std::nullopt;
  auto p = MujocoMeshMassProperties(Scaled(*mesh, scale), mode, error);
  if (p && key) {
    std::vector<double> values;
    Put(p->mass, values);
    PutMatrix(p->R_MP, values);
    PutMatrix(p->principal_moments, values);
    PutMatrix(p->inertia_box, values);
    PutMatrix(p->aabb_min, values);
    PutMatrix(p->aabb_max, values);
    cache->Store(*key, values);
  }
  return p;
}

CollisionSolid CachedCollisionSolid(MeshCache& meshes, const std::string& path,
                                    const Eigen::Vector3d& scale, bool convex) {
  DerivedMeshCache* cache = meshes.derived();
  const auto key = KeyFor(meshes, path, fmt::format("collision-solid|convex={}", convex), scale);
  if (key) {
    if (auto values = cache->Load(*key); values && values->size() == 14) {
      CollisionSolid s;
      s.used_hull = (*values)[0] != 0;
      Get(values->data() + 1, s.mass.emplace());
      return s;
    }
  }
  CollisionSolid s;
  const auto mesh = Triangles(meshes, path, &s.error);
  if (!mesh) return s;
  const TriangleMesh scaled = Scaled(*mesh, scale);
  if (!convex) {
    const MeshTopology topo = AnalyzeTopology(scaled);
    if (topo.closed && topo.consistently_oriented) {
      MassProperties solid = SolidMassProperties(scaled);
      if (solid.measure > 0) s.mass = solid;
    }
  }
  if (!s.mass) {
    s.used_hull = true;
    auto hull = ConvexHull(scaled.vertices, &s.error);
    if (!hull) return s;  // not stored: rare, and reported each time
    s.mass = SolidMassProperties(*hull);
  }
  if (key) {
    std::vector<double> values = {s.used_hull ? 1.0 : 0.0};
    Put(*s.mass, values);
    cache->Store(*key, values);
  }
  return s;
}

}  // namespace mdlc::mesh
