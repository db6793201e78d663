// mechanism.h - the random robot the benchmark models describe, drawn once
// and written by each format's generator (model_gen.cc for URDF,
// model_gen_sdf.cc's sdf_chain, model_gen_mjcf.cc for MJCF).
//
// It mirrors build() of bench/gen_models.py in the shared directory: the same
// draws in the same order and ranges, so every format describes the same
// robot and file sizes are comparable with the script's. The random values
// differ from Python's (its seeding is not reproduced); output is
// deterministic: same arguments, same robot.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace mdlc::bench {

enum class Shape { Chain, Tree };
std::string_view ShapeName(Shape shape);

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;

/// Uniform doubles from a fixed engine, without std::uniform_real_distribution
/// (whose output differs between standard libraries).
class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}
  double Unit() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Unit(); }
  int Below(int n) { return static_cast<int>(engine_() % static_cast<uint64_t>(n)); }

 private:
  std::mt19937_64 engine_;
};

/// A seed from a string, the same on every platform (std::hash is not).
uint64_t Fnv1a(std::string_view text);

/// "%.6g", with "-0" written as "0" (the script's fmt()).
void AppendNumber(std::string& out, double x);
/// Numbers separated by single spaces (the script's fv()).
void AppendVector(std::string& out, const double* v, int size);
/// prefix + decimal index (not `"literal" + std::to_string(i)`, which makes
/// GCC 12 warn falsely under -Wrestrict).
std::string Numbered(std::string_view prefix, int index);

/// R = Rz(yaw) * Ry(pitch) * Rx(roll), the URDF convention.
Mat3 RotationFromRpy(double r, double p, double y);
/// The quaternion (w, x, y, z) of RotationFromRpy(r, p, y).
std::array<double, 4> QuaternionFromRpy(double r, double p, double y);
/// R * D * R^T for a diagonal D.
Mat3 RotateDiagonal(const Mat3& R, const Vec3& d);
/// R * T * R^T.
Mat3 RotateTensor(const Mat3& R, const Mat3& T);

enum class GeomKind { Box, Sphere, Cylinder, Capsule };

struct GeomDraw {
  GeomKind kind;
  Vec3 dims;  // box: sides; sphere: radius; cylinder/capsule: radius, (full) length
  Vec3 xyz, rpy;
  std::array<double, 4> rgba;
};

/// One link and its inbound joint (none for link 0).
struct LinkDraw {
  int parent = -1;  // chain: i - 1, tree: (i - 1) / 3
  double mass = 0;
  Vec3 com, in_rpy;  // the inertial frame in the link frame
  Mat3 inertia;      // about the COM, in the inertial frame (full, physically valid)
  GeomDraw visual, collision;
  Vec3 j_xyz, j_rpy;  // joint origin in the parent link frame
  Vec3 axis;          // unit
  double lower = 0, upper = 0, effort = 0, velocity = 0, damping = 0, friction = 0;
};

/// The `shape` robot with `num_links` links, drawn from the seed string
/// "{shape}_n{num_links}/20240611" (the script's).
std::vector<LinkDraw> DrawMechanism(Shape shape, int num_links);

}  // namespace mdlc::bench
