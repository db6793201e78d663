// scene_graph.h - the geometry side of a compiled model: plain data.
//
// Geometries are registered on plant bodies (X_BG; body 0 = world for
// anchored geometry), in IR order. `properties` is the final property map,
// sorted by key with one entry per key; an illustration or perception
// geometry's color appears as "phong/diffuse" [r, g, b, a] there. Collision
// filters are kept as the declarations that make them (collision_filters.h
// says which pairs); Pairs() lists the pairs, sorted by the bodies' scoped
// names.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ir/entities.h"
#include "ir/ids.h"
#include "ir/transform.h"

namespace mdlc::backend {

struct Plant;

/// Which body pairs never collide, kept as the declarations that filter
/// them: single pairs (a joint's two bodies), sets whose bodies all filter
/// each other (a weld composite, a group that ignores itself) and pairs of
/// sets whose bodies filter every body of the other (a group that ignores
/// another). A welded composite of N bodies filters N(N-1)/2 pairs and is
/// held in N numbers; only output that lists the pairs pays for them. Only
/// bodies with proximity geometry are held.
class CollisionFilters {
 public:
  using BodyPairs = std::vector<std::pair<BodyId, BodyId>>;
  using BodySets = std::vector<std::vector<BodyId>>;
  using BodySetPairs = std::vector<std::pair<std::vector<BodyId>, std::vector<BodyId>>>;

  CollisionFilters() = default;
  /// Filters `pairs`, every two bodies of each set, and every body of the
  /// first of a set pair with every body of its second (a body never with
  /// itself). ComputeCollisionFilters (collision_filters.h) makes them.
  CollisionFilters(BodyPairs pairs, BodySets sets, BodySetPairs set_pairs);

  /// True when `a` and `b` are two bodies whose collisions are filtered.
  /// One binary search per declaration `a` is part of.
  bool Filtered(BodyId a, BodyId b) const;
  /// Every filtered pair, each pair and the list ordered by the bodies'
  /// scoped names, without duplicates; time and memory in proportion to the
  /// pairs (times a logarithm).
  BodyPairs Pairs(const Plant& plant) const;

  /// The declarations as made: single pairs (each smaller index first,
  /// sorted, unique), sets and set pairs, in the order they were declared.
  /// A writer writes them as filter groups, one per declaration.
  const BodyPairs& pairs() const { return pairs_; }
  const BodySets& sets() const { return sets_; }
  const BodySetPairs& set_pairs() const { return set_pairs_; }

 private:
  // a body's part in a declaration: set s is tag 3s, the sides of set pair
  // p are 3p + 1 and 3p + 2
  static uint64_t Tag(size_t index, uint64_t kind) { return 3 * uint64_t{index} + kind; }
  bool HasTag(BodyId body, uint64_t tag) const;

  BodyPairs pairs_;  // each (smaller index, larger), sorted, unique
  BodySets sets_;
  BodySetPairs set_pairs_;
  std::vector<std::pair<uint32_t, uint64_t>> tags_;  // (body index, tag), sorted, unique
};

struct SceneGeometry {
  std::string name;
  ModelId model;
  BodyId body;
  Transform X_BG;
  ir::Shape shape;
  uint8_t roles = 0;  // ir::GeometryRole bits
  std::vector<ir::Property> properties;  // sorted by key, keys unique
  bool unnamed = false;  // named by the compiler
};

struct SceneCamera {
  std::string name;
  ModelId model;
  BodyId body;
  Transform X_BC;  // Drake camera frame: +z forward, +x right, +y down
  int width = 640, height = 480;
  double fov_y = 0;
  bool unnamed = false;  // named by the compiler
};

struct SceneGraph {
  std::vector<SceneGeometry> geometries;
  /// Body pairs whose collisions are filtered out.
  CollisionFilters collision_filters;
  std::vector<SceneCamera> cameras;
};

}  // namespace mdlc::backend
