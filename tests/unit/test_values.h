// test_values.h - constants and small value builders that many unit tests
// use. They live here, once, because the test targets are compiled in
// batches of files (MDLC_UNITY_BUILD, CMakeLists.txt): two files of a batch
// may not each define their own.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <string_view>
#include <vector>

#include "ir/entities.h"
#include "ir/module.h"

namespace mdlc::testing {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
/// Agreement expected of values computed in double from exact inputs.
inline constexpr double kTol = 1e-12;

/// The symmetric 3x3 matrix with these moments and products (an inertia).
inline Eigen::Matrix3d Sym(double xx, double yy, double zz, double xy, double xz, double yz) {
  Eigen::Matrix3d m;
  m << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  return m;
}

/// The first entity of a module's `table` (bodies, joints) named `name`;
/// null when none is. What the frontend fixtures' Body() and Joint() ask.
template <typename Entity>
const Entity* FindNamed(const ir::Module& module, const std::vector<Entity>& table,
                        std::string_view name) {
  for (const Entity& e : table) {
    if (module.Text(e.name) == name) return &e;
  }
  return nullptr;
}

/// The property `key` of geometry `g` (null when it has none).
inline const ir::Property* Find(const ir::Geometry& g, std::string_view key) {
  for (const auto& p : g.properties) {
    if (p.key == key) return &p;
  }
  return nullptr;
}
/// The number property `key` of `g` (a failure and NaN when it has none).
inline double Number(const ir::Geometry& g, std::string_view key) {
  const ir::Property* p = Find(g, key);
  EXPECT_NE(p, nullptr) << key;
  return p ? std::get<double>(p->value) : std::nan("");
}
/// The vector property `key` of `g` (a failure and empty when it has none).
inline std::vector<double> Numbers(const ir::Geometry& g, std::string_view key) {
  const ir::Property* p = Find(g, key);
  EXPECT_NE(p, nullptr) << key;
  return p ? std::get<std::vector<double>>(p->value) : std::vector<double>{};
}

}  // namespace mdlc::testing
