// build_scene_graph.cc - geometries with final properties, cameras, filters.
#include "backend/build_scene_graph.h"

#include <algorithm>
#include <cstddef>

#include "backend/collision_filters.h"
#include "backend/ref_check.h"

namespace mdlc::backend {

namespace {

bool HasKey(const std::vector<ir::Property>& properties, std::string_view key) {
  return std::any_of(properties.begin(), properties.end(),
                     [&](const ir::Property& p) { return p.key == key; });
}

/// Sorted by key, one entry per key (the last one given wins), in place: a
/// geometry has a handful of properties, for which a stable sort's buffer
/// and a second vector would be two allocations per geometry.
std::vector<ir::Property> Canonical(std::vector<ir::Property> properties) {
  auto by_key = [](const ir::Property& a, const ir::Property& b) { return a.key < b.key; };
  constexpr size_t kInsertionSortMax = 16;
  if (properties.size() <= kInsertionSortMax) {
    for (size_t i = 1; i < properties.size(); ++i) {  // stable: equal keys never pass
      for (size_t j = i; j > 0 && by_key(properties[j], properties[j - 1]); --j) {
        std::swap(properties[j], properties[j - 1]);
      }
    }
  } else {
    std::stable_sort(properties.begin(), properties.end(), by_key);
  }
  size_t kept = 0;
  for (size_t i = 0; i < properties.size(); ++i) {
    if (i + 1 < properties.size() && properties[i + 1].key == properties[i].key) continue;
    if (kept != i) properties[kept] = std::move(properties[i]);
    ++kept;
  }
  properties.erase(properties.begin() + static_cast<std::ptrdiff_t>(kept), properties.end());
  for (ir::Property& p : properties) {
    auto* names = std::get_if<std::vector<std::string>>(&p.value);
    if (names && p.key == "renderer/accepting") std::sort(names->begin(), names->end());
  }
  return properties;
}

class SceneBuilder {
 public:
  SceneBuilder(const ir::Module& module, DiagnosticEngine& diags) : m_(module), diags_(diags) {}

  std::optional<SceneGraph> Build(const Plant& plant) {
    // at most one registered geometry per IR geometry: sized once
    scene_.geometries.reserve(m_.geometries.size());
    for (const ir::Geometry& g : m_.geometries) {
      // a geometry with no role (an MJCF geom kept only for its share of the
      // body's mass) is never registered, as Drake registers nothing for it
      if (g.roles != 0) AddGeometry(g);
    }
    for (const ir::Camera& c : m_.cameras) AddCamera(c);
    if (!ok_) return std::nullopt;
    auto filters = ComputeCollisionFilters(m_, plant, scene_.geometries, diags_);
    if (!filters) return std::nullopt;
    scene_.collision_filters = std::move(*filters);
    return std::move(scene_);
  }

 private:
  BodyId ResolveBody(const ir::Ref<BodyId>& ref, Loc loc) {
    if (!CheckRef(m_, ref, m_.bodies.size(), "body", loc, diags_)) ok_ = false;
    return ref.id;
  }
  void CheckEntityModel(ModelId model, Loc loc) {
    if (!CheckModel(m_, model, loc, diags_)) ok_ = false;
  }

  void AddGeometry(const ir::Geometry& src) {
    CheckEntityModel(src.model, src.loc);
    SceneGeometry& g = scene_.geometries.emplace_back();
    g.name = m_.Text(src.name);
    g.model = src.model;
    g.body = ResolveBody(src.body, src.loc);
    g.X_BG = src.X_BG;
    g.shape = src.shape;
    g.roles = src.roles;
    g.unnamed = src.unnamed;
    g.properties = Canonical(WithAppearance(src));
  }

  /// The IR properties plus color and texture for the geometries that show.
  std::vector<ir::Property> WithAppearance(const ir::Geometry& src) {
    if (!(src.roles & (ir::kIllustrationRole | ir::kPerceptionRole))) return src.properties;
    std::vector<ir::Property> properties;
    properties.reserve(src.properties.size() + 2);  // and the color and texture
    properties.assign(src.properties.begin(), src.properties.end());
    const ir::Material* material = nullptr;
    if (!src.material.name.empty() || src.material.id.valid()) {
      if (CheckRef(m_, src.material, m_.materials.size(), "material", src.loc, diags_)) {
        material = &m_[src.material.id];
      } else {
        ok_ = false;
      }
    }
    std::optional<Eigen::Vector4d> rgba = src.rgba;
    if (!rgba && material) rgba = material->rgba;
    if (rgba && !HasKey(properties, "phong/diffuse")) {
      properties.push_back({"phong/diffuse", std::vector<double>(rgba->data(), rgba->data() + 4)});
    }
    if (material && !material->texture.empty() && !HasKey(properties, "phong/diffuse_map")) {
      properties.push_back({"phong/diffuse_map", material->texture});
    }
    return properties;
  }

  void AddCamera(const ir::Camera& src) {
    CheckEntityModel(src.model, src.loc);
    scene_.cameras.push_back({std::string(m_.Text(src.name)), src.model,
                              ResolveBody(src.body, src.loc), src.X_BC, src.width, src.height,
                              src.fov_y, src.unnamed});
  }

  const ir::Module& m_;
  DiagnosticEngine& diags_;
  SceneGraph scene_;
  bool ok_ = true;
};

}  // namespace

std::optional<SceneGraph> BuildSceneGraph(const ir::Module& module, const Plant& plant,
                                          DiagnosticEngine& diags) {
  return SceneBuilder(module, diags).Build(plant);
}

}  // namespace mdlc::backend
