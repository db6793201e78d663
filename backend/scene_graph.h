// scene_graph.h - the geometry side of a compiled model: plain data.
//
// Geometries are registered on plant bodies (X_BG; body 0 = world for
// anchored geometry), in IR order. `properties` is the final property map,
// sorted by key with one entry per key; an illustration or perception
// geometry's color appears as "phong/diffuse" [r, g, b, a] there. Collision
// filters are unordered body pairs, each pair and the list sorted by the
// bodies' scoped names (collision_filters.h says which pairs).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ir/entities.h"
#include "ir/ids.h"
#include "ir/transform.h"

namespace mdlc::backend {

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
  std::vector<std::pair<BodyId, BodyId>> collision_filters;
  std::vector<SceneCamera> cameras;
};

}  // namespace mdlc::backend
