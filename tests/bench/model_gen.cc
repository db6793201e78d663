// model_gen.cc - see model_gen.h. Mirrors build() and write_urdf() of
// gen_models.py; keep the two in step when either changes.
#include "model_gen.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>

namespace mdlc::bench {
namespace {

constexpr double kPi = std::numbers::pi;
using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;

// uniform doubles from a fixed engine, without std::uniform_real_distribution
// (whose output differs between standard libraries)
class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}
  double Unit() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Unit(); }
  int Below(int n) { return static_cast<int>(engine_() % static_cast<uint64_t>(n)); }

 private:
  std::mt19937_64 engine_;
};

// "%.6g", with "-0" written as "0" (the script's fmt())
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

// R = Rz(yaw) * Ry(pitch) * Rx(roll)
Mat3 RotationFromRpy(double r, double p, double y) {
  const double cr = std::cos(r), sr = std::sin(r), cp = std::cos(p), sp = std::sin(p);
  const double cy = std::cos(y), sy = std::sin(y);
  return {{{cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr},
           {sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr},
           {-sp, cp * sr, cp * cr}}};
}

// R * D * R^T for a diagonal D
Mat3 RotateDiagonal(const Mat3& R, const Vec3& d) {
  Mat3 out{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) out[i][j] += R[i][k] * d[k] * R[j][k];
    }
  }
  return out;
}

// a seed from a string, the same on every platform (std::hash is not)
uint64_t Fnv1a(std::string_view text) {
  uint64_t h = 0xcbf29ce484222325;
  for (unsigned char c : text) h = (h ^ c) * 0x100000001b3;
  return h;
}

enum class Kind { Box, Sphere, Cylinder, Capsule };

struct Geom {
  Kind kind;
  Vec3 dims;  // box: sides; sphere: radius; cylinder/capsule: radius, length
  Vec3 xyz, rpy;
  std::array<double, 4> rgba;
};

Geom MakeGeom(Rng& rng, Kind kind) {
  Geom g{};
  g.kind = kind;
  if (kind == Kind::Box) {
    g.dims = {rng.Uniform(0.04, 0.3), rng.Uniform(0.04, 0.3), rng.Uniform(0.04, 0.3)};
  } else if (kind == Kind::Sphere) {
    g.dims = {rng.Uniform(0.02, 0.15), 0, 0};
  } else {
    g.dims = {rng.Uniform(0.02, 0.1), rng.Uniform(0.05, 0.4), 0};
  }
  g.xyz = {rng.Uniform(-0.05, 0.05), rng.Uniform(-0.05, 0.05), rng.Uniform(0.0, 0.15)};
  g.rpy = {rng.Uniform(-kPi, kPi), rng.Uniform(-1.5, 1.5), rng.Uniform(-kPi, kPi)};
  g.rgba = {rng.Unit(), rng.Unit(), rng.Unit(), 1.0};
  return g;
}

void AppendOrigin(std::string& out, const char* indent, const Vec3& xyz, const Vec3& rpy) {
  out += indent;
  out += "<origin xyz=\"";
  AppendVector(out, xyz.data(), 3);
  out += "\" rpy=\"";
  AppendVector(out, rpy.data(), 3);
  out += "\"/>\n";
}

void AppendShape(std::string& out, const Geom& g) {
  out += "        ";
  if (g.kind == Kind::Box) {
    out += "<box size=\"";
    AppendVector(out, g.dims.data(), 3);
    out += "\"/>\n";
  } else if (g.kind == Kind::Sphere) {
    out += "<sphere radius=\"";
    AppendNumber(out, g.dims[0]);
    out += "\"/>\n";
  } else {
    // URDF has no capsule: the script writes it as a cylinder of the same size
    out += "<cylinder radius=\"";
    AppendNumber(out, g.dims[0]);
    out += "\" length=\"";
    AppendNumber(out, g.dims[1]);
    out += "\"/>\n";
  }
}

void AppendGeometry(std::string& out, const Geom& g, int link, bool visual) {
  const std::string index = std::to_string(link);
  out += visual ? "    <visual name=\"link_" : "    <collision name=\"link_";
  out += index;
  out += visual ? "_visual\">\n" : "_collision\">\n";
  AppendOrigin(out, "      ", g.xyz, g.rpy);
  out += "      <geometry>\n";
  AppendShape(out, g);
  out += "      </geometry>\n";
  if (visual) {
    out += "      <material name=\"material_" + index + "\">\n";
    out += "        <color rgba=\"";
    AppendVector(out, g.rgba.data(), 4);
    out += "\"/>\n      </material>\n    </visual>\n";
  } else {
    out += "    </collision>\n";
  }
}

}  // namespace

std::string_view ShapeName(Shape shape) { return shape == Shape::Chain ? "chain" : "tree"; }

std::string GenerateUrdf(Shape shape, int num_links) {
  const std::string name = std::string(ShapeName(shape)) + "_n" + std::to_string(num_links);
  Rng rng(Fnv1a(name + "/20240611"));  // the script's seed string
  std::string out;
  out.reserve(static_cast<size_t>(num_links) * 1250 + 256);
  out += "<?xml version=\"1.0\"?>\n<robot name=\"" + name + "\">\n";
  out += "  <link name=\"world\"/>\n";
  out += "  <joint name=\"world_weld\" type=\"fixed\">\n";
  out += "    <parent link=\"world\"/>\n";
  out += "    <child link=\"link_0\"/>\n";
  out += "  </joint>\n";
  static constexpr Kind kKinds[] = {Kind::Box, Kind::Sphere, Kind::Cylinder, Kind::Capsule};
  for (int i = 0; i < num_links; ++i) {
    const std::string index = std::to_string(i);
    const int parent = i == 0 ? -1 : shape == Shape::Chain ? i - 1 : (i - 1) / 3;

    // mass properties: principal moments of a box of the link's mass, turned
    // by a random rotation into a full but physically valid tensor
    const double mass = rng.Uniform(0.3, 5.0);
    const Vec3 com = {rng.Uniform(-0.03, 0.03), rng.Uniform(-0.03, 0.03), rng.Uniform(0.0, 0.12)};
    const Vec3 in_rpy = {rng.Uniform(-kPi, kPi), rng.Uniform(-1.5, 1.5), rng.Uniform(-kPi, kPi)};
    const double a = rng.Uniform(0.05, 0.3), b = rng.Uniform(0.05, 0.3), c = rng.Uniform(0.05, 0.3);
    const Vec3 principal = {mass * (b * b + c * c) / 12, mass * (a * a + c * c) / 12,
                            mass * (a * a + b * b) / 12};
    const Vec3 q_rpy = {rng.Uniform(-kPi, kPi), rng.Uniform(-1.5, 1.5), rng.Uniform(-kPi, kPi)};
    const Mat3 I = RotateDiagonal(RotationFromRpy(q_rpy[0], q_rpy[1], q_rpy[2]), principal);
    const Geom visual = MakeGeom(rng, kKinds[i % 4]);
    const Geom collision = MakeGeom(rng, kKinds[(i + 1) % 4]);

    // the inbound joint
    const Vec3 j_xyz = {rng.Uniform(-0.1, 0.1), rng.Uniform(-0.1, 0.1), rng.Uniform(0.05, 0.35)};
    const Vec3 j_rpy = {rng.Uniform(-0.8, 0.8), rng.Uniform(-0.8, 0.8), rng.Uniform(-kPi, kPi)};
    Vec3 axis = {0, 0, 0};
    if (const int k = rng.Below(4); k < 3) {
      axis[k] = rng.Unit() < 0.7 ? 1.0 : -1.0;
    } else {
      axis = {rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1)};
      double norm = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
      if (norm == 0) norm = 1;
      for (double& v : axis) v /= norm;
    }
    const double limits[4] = {-rng.Uniform(1.0, 3.0), rng.Uniform(1.0, 3.0),
                              rng.Uniform(10, 300), rng.Uniform(1, 10)};
    const double damping = rng.Uniform(0.05, 2.0), friction = rng.Uniform(0.0, 0.5);

    out += "  <link name=\"link_" + index + "\">\n";
    out += "    <inertial>\n";
    AppendOrigin(out, "      ", com, in_rpy);
    out += "      <mass value=\"";
    AppendNumber(out, mass);
    out += "\"/>\n";
    const double tensor[6] = {I[0][0], I[0][1], I[0][2], I[1][1], I[1][2], I[2][2]};
    static constexpr const char* kTensorNames[6] = {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"};
    out += "      <inertia";
    for (int k = 0; k < 6; ++k) {
      out += ' ';
      out += kTensorNames[k];
      out += "=\"";
      AppendNumber(out, tensor[k]);
      out += '"';
    }
    out += "/>\n    </inertial>\n";
    AppendGeometry(out, visual, i, /*visual=*/true);
    AppendGeometry(out, collision, i, /*visual=*/false);
    out += "  </link>\n";
    if (parent < 0) continue;
    out += "  <joint name=\"joint_" + index + "\" type=\"revolute\">\n";
    AppendOrigin(out, "    ", j_xyz, j_rpy);
    out += "    <parent link=\"link_" + std::to_string(parent) + "\"/>\n";
    out += "    <child link=\"link_" + index + "\"/>\n";
    out += "    <axis xyz=\"";
    AppendVector(out, axis.data(), 3);
    out += "\"/>\n    <limit";
    static constexpr const char* kLimitNames[4] = {"lower", "upper", "effort", "velocity"};
    for (int k = 0; k < 4; ++k) {
      out += ' ';
      out += kLimitNames[k];
      out += "=\"";
      AppendNumber(out, limits[k]);
      out += '"';
    }
    out += "/>\n    <dynamics damping=\"";
    AppendNumber(out, damping);
    out += "\" friction=\"";
    AppendNumber(out, friction);
    out += "\"/>\n  </joint>\n";
  }
  out += "</robot>\n";
  return out;
}

}  // namespace mdlc::bench
