// mesh_model_gen.cc - see mesh_model_gen.h. bench_meshes.cc writes the files
// once per process, before any timed loop: writing them is not measured.
#include "mesh_model_gen.h"

#include <fmt/format.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace mdlc::bench {
namespace {

namespace fs = std::filesystem;

using Vec = std::array<double, 3>;

// binary STL is little-endian; the bytes below are copied as the host holds them
static_assert(std::endian::native == std::endian::little, "binary STL is written little-endian");

Vec Sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec Cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// the fractional part of k times an irrational: spread over [0, 1) without
// repeating, so every body gets radii of its own
double Spread(int k, double irrational) {
  const double x = k * irrational;
  return x - std::floor(x);
}

struct Ellipsoid {
  Vec radii;
  int stacks;  // latitude bands, pole to pole
  int slices;  // longitude sectors
};

Ellipsoid BodyEllipsoid(int k) {
  const int stacks = 12 + k % 5;
  return {{0.04 + 0.03 * Spread(k, 0.6180339887498949), 0.04 + 0.03 * Spread(k, 0.7548776662466927),
           0.04 + 0.03 * Spread(k, 0.5698402909980532)},
          stacks, 2 * stacks + k % 3};
}

// The ellipsoid's triangles, each counter-clockwise seen from outside (the
// normal, right-handed, points out), as MuJoCo's and mdlc's volume
// computations expect of a closed mesh. Vertices: the north pole, then
// stacks - 1 rings of `slices` from north to south, then the south pole.
std::vector<std::array<Vec, 3>> Triangles(const Ellipsoid& e) {
  std::vector<Vec> v;
  auto point = [&](double theta, double phi) {
    return Vec{e.radii[0] * std::sin(theta) * std::cos(phi),
               e.radii[1] * std::sin(theta) * std::sin(phi), e.radii[2] * std::cos(theta)};
  };
  v.push_back({0, 0, e.radii[2]});
  for (int i = 1; i < e.stacks; ++i) {
    for (int j = 0; j < e.slices; ++j) {
      v.push_back(point(std::numbers::pi * i / e.stacks, 2 * std::numbers::pi * j / e.slices));
    }
  }
  v.push_back({0, 0, -e.radii[2]});
  const int south = static_cast<int>(v.size()) - 1;
  auto ring = [&](int i, int j) { return v[1 + (i - 1) * e.slices + j % e.slices]; };

  // going south, then east, turns outward: (south) x (east) is the normal
  std::vector<std::array<Vec, 3>> t;
  for (int j = 0; j < e.slices; ++j) t.push_back({v[0], ring(1, j), ring(1, j + 1)});
  for (int i = 1; i + 1 < e.stacks; ++i) {
    for (int j = 0; j < e.slices; ++j) {
      t.push_back({ring(i, j), ring(i + 1, j), ring(i, j + 1)});
      t.push_back({ring(i, j + 1), ring(i + 1, j), ring(i + 1, j + 1)});
    }
  }
  for (int j = 0; j < e.slices; ++j) {
    t.push_back({ring(e.stacks - 1, j), v[south], ring(e.stacks - 1, j + 1)});
  }
  return t;
}

void Put(std::string& out, const void* bytes, size_t size) {
  out.append(static_cast<const char*>(bytes), size);
}

void PutVec(std::string& out, const Vec& a) {
  for (double x : a) {
    const float f = static_cast<float>(x);
    Put(out, &f, sizeof f);
  }
}

// Binary STL: an 80-byte header (which must not begin with "solid", the
// mark of the text form), the triangle count, then per triangle its normal,
// its three vertices and a 2-byte attribute.
std::string BinaryStl(const std::vector<std::array<Vec, 3>>& triangles, int k) {
  std::string out = fmt::format("mdlc benchmark mesh {}", k);
  out.resize(80, ' ');
  const uint32_t count = static_cast<uint32_t>(triangles.size());
  Put(out, &count, sizeof count);
  for (const auto& tri : triangles) {
    Vec n = Cross(Sub(tri[1], tri[0]), Sub(tri[2], tri[0]));
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n) x /= length;
    PutVec(out, n);
    for (const Vec& p : tri) PutVec(out, p);
    const uint16_t attribute = 0;
    Put(out, &attribute, sizeof attribute);
  }
  return out;
}

void WriteFile(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
  if (!out) throw std::runtime_error(fmt::format("cannot write '{}'", path.string()));
}

}  // namespace

std::string MeshBodiesModelName(int bodies) { return fmt::format("mesh_bodies_n{}.xml", bodies); }

fs::path WriteMeshBodiesModel(const fs::path& dir, int bodies) {
  fs::create_directories(dir);
  std::string xml = fmt::format("<mujoco model=\"mesh_bodies_n{}\">\n  <asset>\n", bodies);
  for (int k = 0; k < bodies; ++k) {
    WriteFile(dir / fmt::format("m{}.stl", k), BinaryStl(Triangles(BodyEllipsoid(k)), k));
    xml += fmt::format("    <mesh name=\"m{0}\" file=\"m{0}.stl\"/>\n", k);
  }
  // free bodies side by side on a square grid, apart enough not to touch
  const int side = static_cast<int>(std::ceil(std::sqrt(bodies)));
  xml += "  </asset>\n  <worldbody>\n";
  for (int k = 0; k < bodies; ++k) {
    xml += fmt::format(
        "    <body name=\"b{0}\" pos=\"{1} {2} 1\">\n      <freejoint/>\n"
        "      <geom type=\"mesh\" mesh=\"m{0}\"/>\n    </body>\n",
        k, 0.2 * (k % side), 0.2 * (k / side));
  }
  xml += "  </worldbody>\n</mujoco>\n";
  const fs::path model = dir / MeshBodiesModelName(bodies);
  WriteFile(model, xml);
  return model;
}

}  // namespace mdlc::bench
