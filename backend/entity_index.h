// entity_index.h - a compiled model's entities grouped by the body, joint
// or model instance they belong to, built in one pass. The writers and the
// inspection commands ask for a body's geometries or a joint's actuators
// here; scanning every entity for each body made writing N bodies cost N²
// (issue 16: a world of 100,000 one-link models took 78 s to write as URDF,
// 100 times its 10,000-model time).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "backend/plant.h"
#include "backend/scene_graph.h"

namespace mdlc::backend {

/// Entity indices grouped by key, each group in entity order (compressed
/// rows: one offset per key, one index per entity).
class EntityIndex {
 public:
  static constexpr int64_t kNoKey = -1;

  EntityIndex() = default;
  /// Groups entities 0..num_entities-1 by `key_of(i)`, a key below
  /// `num_keys` or kNoKey for an entity in no group.
  template <typename KeyOf>
  EntityIndex(size_t num_keys, size_t num_entities, KeyOf key_of) : begin_(num_keys + 1, 0) {
    std::vector<int64_t> keys(num_entities);
    for (size_t i = 0; i < num_entities; ++i) {
      keys[i] = key_of(i);
      if (keys[i] != kNoKey) ++begin_[keys[i] + 1];
    }
    for (size_t k = 0; k < num_keys; ++k) begin_[k + 1] += begin_[k];
    items_.resize(begin_[num_keys]);
    std::vector<uint32_t> next(begin_.begin(), begin_.end() - 1);
    for (size_t i = 0; i < num_entities; ++i) {
      if (keys[i] != kNoKey) items_[next[keys[i]]++] = static_cast<uint32_t>(i);
    }
  }

  /// The entities of `key`, in entity order; none for a key out of range.
  std::span<const uint32_t> operator[](size_t key) const {
    if (key + 1 >= begin_.size()) return {};
    return {items_.data() + begin_[key], begin_[key + 1] - begin_[key]};
  }

 private:
  std::vector<uint32_t> begin_, items_;
};

// The indices the writers and the inspection commands ask.
EntityIndex GeometriesByBody(const Plant& plant, const SceneGraph& scene);
EntityIndex CamerasByBody(const Plant& plant, const SceneGraph& scene);
EntityIndex FramesByBody(const Plant& plant);
EntityIndex ActuatorsByJoint(const Plant& plant);
/// The coupler constraints by the joint that follows (joint0).
EntityIndex CouplersByFollower(const Plant& plant);
/// The joint springs among the force elements, by joint.
EntityIndex SpringsByJoint(const Plant& plant);
/// Bodies (the world's left out), joints and frames by model instance.
EntityIndex BodiesByModel(const Plant& plant);
EntityIndex JointsByModel(const Plant& plant);
EntityIndex FramesByModel(const Plant& plant);

}  // namespace mdlc::backend
