// mechanism.cc - see mechanism.h. Mirrors build() of gen_models.py draw for
// draw; keep the two in step when either changes.
#include "mechanism.h"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace mdlc::bench {
namespace {

constexpr double kPi = std::numbers::pi;

GeomDraw DrawGeom(Rng& rng, GeomKind kind) {
  GeomDraw g{};
  g.kind = kind;
  if (kind == GeomKind::Box) {
    g.dims = {rng.Uniform(0.04, 0.3), rng.Uniform(0.04, 0.3), rng.Uniform(0.04, 0.3)};
  } else if (kind == GeomKind::Sphere) {
    g.dims = {rng.Uniform(0.02, 0.15), 0, 0};
  } else {
    g.dims = {rng.Uniform(0.02, 0.1), rng.Uniform(0.05, 0.4), 0};
  }
  g.xyz = {rng.Uniform(-0.05, 0.05), rng.Uniform(-0.05, 0.05), rng.Uniform(0.0, 0.15)};
  g.rpy = {rng.Uniform(-kPi, kPi), rng.Uniform(-1.5, 1.5), rng.Uniform(-kPi, kPi)};
  g.rgba = {rng.Unit(), rng.Unit(), rng.Unit(), 1.0};
  return g;
}

}  // namespace

std::string_view ShapeName(Shape shape) { return shape == Shape::Chain ? "chain" : "tree"; }

uint64_t Fnv1a(std::string_view text) {
  uint64_t h = 0xcbf29ce484222325;
  for (unsigned char c : text) h = (h ^ c) * 0x100000001b3;
  return h;
}

void AppendNumber(std::string& out, double x) {
  char buf[32];
  const int n = std::snprintf(buf, sizeof buf, "%.6g", x);
  if (n == 2 && buf[0] == '-' && buf[1] == '0') {
    out += '0';
  } else {
    out.append(buf, static_cast<size_t>(n));
  }
}

void AppendVector(std::string& out, const double* v, int size) {
  for (int i = 0; i < size; ++i) {
    if (i > 0) out += ' ';
    AppendNumber(out, v[i]);
  }
}

std::string Numbered(std::string_view prefix, int index) {
  std::string out(prefix);
  out += std::to_string(index);
  return out;
}

Mat3 RotationFromRpy(double r, double p, double y) {
  const double cr = std::cos(r), sr = std::sin(r), cp = std::cos(p), sp = std::sin(p);
  const double cy = std::cos(y), sy = std::sin(y);
  return {{{cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr},
           {sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr},
           {-sp, cp * sr, cp * cr}}};
}

std::array<double, 4> QuaternionFromRpy(double r, double p, double y) {
  const double cr = std::cos(r / 2), sr = std::sin(r / 2), cp = std::cos(p / 2),
               sp = std::sin(p / 2), cy = std::cos(y / 2), sy = std::sin(y / 2);
  return {cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy,
          cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy};
}

Mat3 RotateDiagonal(const Mat3& R, const Vec3& d) {
  Mat3 out{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) out[i][j] += R[i][k] * d[k] * R[j][k];
    }
  }
  return out;
}

Mat3 RotateTensor(const Mat3& R, const Mat3& T) {
  Mat3 rt{}, out{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) rt[i][j] += R[i][k] * T[k][j];
    }
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) out[i][j] += rt[i][k] * R[j][k];
    }
  }
  return out;
}

std::vector<LinkDraw> DrawMechanism(Shape shape, int num_links) {
  const std::string name = std::string(ShapeName(shape)) + "_n" + std::to_string(num_links);
  Rng rng(Fnv1a(name + "/20240611"));  // the script's seed string
  static constexpr GeomKind kKinds[] = {GeomKind::Box, GeomKind::Sphere, GeomKind::Cylinder,
                                        GeomKind::Capsule};
  std::vector<LinkDraw> links(static_cast<size_t>(num_links));
  for (int i = 0; i < num_links; ++i) {
    LinkDraw& L = links[static_cast<size_t>(i)];
    L.parent = i == 0 ? -1 : shape == Shape::Chain ? i - 1 : (i - 1) / 3;
    // mass properties: principal moments of a box of the link's mass, turned
    // by a random rotation into a full but physically valid tensor
    L.mass = rng.Uniform(0.3, 5.0);
    L.com = {rng.Uniform(-0.03, 0.03), rng.Uniform(-0.03, 0.03), rng.Uniform(0.0, 0.12)};
    L.in_rpy = {rng.Uniform(-kPi, kPi), rng.Uniform(-1.5, 1.5), rng.Uniform(-kPi, kPi)};
    const double a = rng.Uniform(0.05, 0.3), b = rng.Uniform(0.05, 0.3), c = rng.Uniform(0.05, 0.3);
    const Vec3 principal = {L.mass * (b * b + c * c) / 12, L.mass * (a * a + c * c) / 12,
                            L.mass * (a * a + b * b) / 12};
    const Vec3 q_rpy = {rng.Uniform(-kPi, kPi), rng.Uniform(-1.5, 1.5), rng.Uniform(-kPi, kPi)};
    L.inertia = RotateDiagonal(RotationFromRpy(q_rpy[0], q_rpy[1], q_rpy[2]), principal);
    L.visual = DrawGeom(rng, kKinds[i % 4]);
    L.collision = DrawGeom(rng, kKinds[(i + 1) % 4]);

    // the inbound joint
    L.j_xyz = {rng.Uniform(-0.1, 0.1), rng.Uniform(-0.1, 0.1), rng.Uniform(0.05, 0.35)};
    L.j_rpy = {rng.Uniform(-0.8, 0.8), rng.Uniform(-0.8, 0.8), rng.Uniform(-kPi, kPi)};
    L.axis = {0, 0, 0};
    if (const int k = rng.Below(4); k < 3) {
      L.axis[static_cast<size_t>(k)] = rng.Unit() < 0.7 ? 1.0 : -1.0;
    } else {
      L.axis = {rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1)};
      double norm = std::sqrt(L.axis[0] * L.axis[0] + L.axis[1] * L.axis[1] + L.axis[2] * L.axis[2]);
      if (norm == 0) norm = 1;
      for (double& v : L.axis) v /= norm;
    }
    L.lower = -rng.Uniform(1.0, 3.0);
    L.upper = rng.Uniform(1.0, 3.0);
    L.effort = rng.Uniform(10, 300);
    L.velocity = rng.Uniform(1, 10);
    L.damping = rng.Uniform(0.05, 2.0);
    L.friction = rng.Uniform(0.0, 0.5);
  }
  return links;
}

}  // namespace mdlc::bench
