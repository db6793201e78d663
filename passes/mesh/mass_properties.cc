#include "passes/mesh/mass_properties.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include <limits>
#include <map>

#include "passes/mesh/convex_hull.h"
#include "passes/mesh/mujoco_eigen.h"

namespace mdlc::mesh {
namespace {

/// Inertia about the origin from second moments C = integral of x x^T.
Eigen::Matrix3d InertiaFromSecondMoments(const Eigen::Matrix3d& C) {
  return C.trace() * Eigen::Matrix3d::Identity() - C;
}

/// Integral of x x^T over a triangle's area (per unit area density), or over
/// the tetrahedron it spans with the origin: measure / k * (sum of the
/// corners' outer products + outer product of their sum), k = 12 for the
/// triangle and 20 for the tetrahedron.
Eigen::Matrix3d SecondMoment(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             const Eigen::Vector3d& c, double measure, double k) {
  const Eigen::Vector3d s = a + b + c;
  return measure / k *
         (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
}

}  // namespace

MassProperties SolidMassProperties(const TriangleMesh& mesh) {
  // pyramids from a point near the mesh keep the sums well conditioned
  Eigen::Vector3d ref = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : mesh.vertices) ref += v;
  if (!mesh.vertices.empty()) ref /= static_cast<double>(mesh.vertices.size());
  double volume = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Eigen::Vector3d a = mesh.corner(t, 0) - ref, b = mesh.corner(t, 1) - ref,
                          c = mesh.corner(t, 2) - ref;
    const double v = a.dot(b.cross(c)) / 6;  // signed tetrahedron (ref, a, b, c)
    volume += v;
    first += v * (a + b + c) / 4;
    second += SecondMoment(a, b, c, v, 20);
  }
  MassProperties out;
  out.measure = volume;
  if (volume == 0) return out;
  const Eigen::Vector3d com = first / volume;  // relative to ref
  out.com = com + ref;
  out.inertia = InertiaFromSecondMoments(second - volume * com * com.transpose());
  return out;
}

MassProperties ShellMassProperties(const TriangleMesh& mesh) {
  double area = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const double a = 0.5 * (mesh.corner(t, 1) - mesh.corner(t, 0))
                               .cross(mesh.corner(t, 2) - mesh.corner(t, 0))
                               .norm();
    area += a;
    first += a * (mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2)) / 3;
  }
  MassProperties out;
  out.measure = area;
  if (area == 0) return out;
  out.com = first / area;
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Eigen::Vector3d a = mesh.corner(t, 0) - out.com, b = mesh.corner(t, 1) - out.com,
                          c = mesh.corner(t, 2) - out.com;
    second += SecondMoment(a, b, c, 0.5 * (b - a).cross(c - a).norm(), 12);
  }
  out.inertia = InertiaFromSecondMoments(second);
  return out;
}

void PrincipalAxes(const Eigen::Matrix3d& inertia, Eigen::Vector3d* moments,
                   Eigen::Matrix3d* axes) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(inertia);
  // Eigen sorts increasing; MuJoCo's principal frame lists decreasing moments
  *moments = eig.eigenvalues().reverse();
  *axes = eig.eigenvectors().rowwise().reverse();
  if (axes->determinant() < 0) axes->col(2) *= -1;
}

bool ClearlyPositiveDefinite(const Eigen::Matrix3d& A, double scale) {
  constexpr double kMargin = 1e-10;
  const double m1 = A(0, 0);
  const double m2 = A(0, 0) * A(1, 1) - A(0, 1) * A(0, 1);
  const double m3 = A.determinant();
  return m1 > kMargin * scale && m2 > kMargin * scale * scale &&
         m3 > kMargin * scale * scale * scale;
}

namespace {

constexpr double kMinVal = 1e-15;  // MuJoCo's mjMINVAL

/// Area, centroid and unit normal of a triangle; area 0 (and the face
/// ignored) when its cross product is below kMinVal, as MuJoCo does.
struct Face {
  double area = 0;
  Eigen::Vector3d center, normal;
};
Face FaceOf(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  Face f;
  f.center = (a + b + c) / 3;
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double len = n.norm();
  if (len < kMinVal) return f;
  f.normal = n / len;
  f.area = len / 2;
  return f;
}

/// The first directed edge used by two faces (MuJoCo's orientation check,
/// faces with area above sqrt(kMinVal) only).
std::optional<std::pair<int, int>> RepeatedDirectedEdge(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> count;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    if (FaceOf(mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2)).area * 2 <=
        std::sqrt(kMinVal)) {
      continue;
    }
    for (int k = 0; k < 3; ++k) ++count[{tri[k], tri[(k + 1) % 3]}];
  }
  for (const auto& [edge, n] : count) {
    if (n > 1) return edge;
  }
  return std::nullopt;
}

}  // namespace

std::optional<MujocoMeshProperties> MujocoMeshMassProperties(const TriangleMesh& mesh,
                                                             ir::MeshInertia mode,
                                                             std::string* error) {
  auto fail = [&](std::string why) -> std::optional<MujocoMeshProperties> {
    if (error) *error = std::move(why);
    return std::nullopt;
  };
  using MI = ir::MeshInertia;
  if (mesh.vertices.size() < 4) return fail("a mesh needs at least 4 vertices");
  if (mode == MI::Exact) {
    if (auto edge = RepeatedDirectedEdge(mesh)) {
      return fail(fmt::format("the faces have inconsistent orientation (two faces run the "
                              "edge between vertices {} and {} the same way); mesh inertia "
                              "'exact' needs a consistently oriented surface",
                              edge->first + 1, edge->second + 1));
    }
  }
  // the faces the solid modes integrate over: the hull's for convex
  TriangleMesh hull;
  const TriangleMesh* solid = &mesh;
  if (mode == MI::Convex) {
    std::string why;
    auto h = ConvexHull(mesh.vertices, &why);
    if (!h) return fail("cannot compute the convex hull: " + why);
    hull = std::move(*h);
    solid = &hull;
  }

  // area-weighted centroid of the (mesh's own) faces: the apex of the
  // pyramids that give the volume and the center of mass
  double area = 0;
  Eigen::Vector3d facecen = Eigen::Vector3d::Zero();
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Face f = FaceOf(mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2));
    area += f.area;
    facecen += f.area * f.center;
  }
  if (area < kMinVal) return fail("the mesh's surface area is too small");
  facecen /= area;

  MujocoMeshProperties out;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  if (mode == MI::Shell) {
    com = facecen;  // the surface's own centroid
  } else {
    double volume = 0;
    for (size_t t = 0; t < solid->triangles.size(); ++t) {
      const Face f = FaceOf(solid->corner(t, 0), solid->corner(t, 1), solid->corner(t, 2));
      double v = (f.center - facecen).dot(f.normal) * f.area / 3;
      if (f.area == 0) v = 0;
      if (mode == MI::Legacy) v = std::abs(v);
      volume += v;
      com += v * (0.75 * f.center + 0.25 * facecen);  // the pyramid's centroid
    }
    if (volume < kMinVal) {
      return fail(volume < 0 ? "the mesh's volume is negative (misoriented faces)"
                             : "the mesh's volume is too small; mesh inertia 'shell' may fit");
    }
    com /= volume;
  }

  // second moments about the center of mass, from pyramids with apex there
  // (triangles for the shell); MuJoCo keeps the measure summed here
  double measure = 0;
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  const TriangleMesh& faces = mode == MI::Shell ? mesh : *solid;
  for (size_t t = 0; t < faces.triangles.size(); ++t) {
    const Eigen::Vector3d a = faces.corner(t, 0) - com, b = faces.corner(t, 1) - com,
                          c = faces.corner(t, 2) - com;
    const Face f = FaceOf(a, b, c);
    if (f.area == 0) continue;
    double m = mode == MI::Shell ? f.area : f.center.dot(f.normal) * f.area / 3;
    if (mode == MI::Legacy) m = std::abs(m);
    measure += m;
    second += SecondMoment(a, b, c, m, mode == MI::Shell ? 12 : 20);
  }
  out.mass.measure = measure;
  out.mass.com = com;
  out.mass.inertia = InertiaFromSecondMoments(second);

  Eigen::Vector3d e;
  // MuJoCo's own solver: its signs of the axes are the frame fitted
  // primitives take (mujoco_eigen.h)
  MujocoEigen(out.mass.inertia, &e, &out.R_MP);
  out.principal_moments = e;
  if (e[2] <= 0) return fail("the mesh's inertia has a non-positive principal moment");
  constexpr double rtol = 1e-6, atol = 1e-9;
  if (e[0] + e[1] < e[2] * (1 - rtol) - atol || e[0] + e[2] < e[1] * (1 - rtol) - atol ||
      e[1] + e[2] < e[0] * (1 - rtol) - atol) {
    return fail("the mesh's principal moments violate the triangle inequality A + B >= C");
  }
  const double mm = out.mass.measure;
  out.inertia_box = 0.5 * Eigen::Vector3d(std::sqrt(6 * (e[1] + e[2] - e[0]) / mm),
                                          std::sqrt(6 * (e[0] + e[2] - e[1]) / mm),
                                          std::sqrt(6 * (e[0] + e[1] - e[2]) / mm));
  out.aabb_min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  out.aabb_max = -out.aabb_min;
  for (const Eigen::Vector3d& v : mesh.vertices) {
    const Eigen::Vector3d p = out.R_MP.transpose() * (v - com);
    out.aabb_min = out.aabb_min.cwiseMin(p);
    out.aabb_max = out.aabb_max.cwiseMax(p);
  }
  return out;
}

}  // namespace mdlc::mesh
