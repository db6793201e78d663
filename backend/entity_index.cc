// entity_index.cc - the indices of a compiled model that entity_index.h names.
#include "backend/entity_index.h"

#include <variant>

namespace mdlc::backend {

namespace {

/// `items` grouped by the id each holds in `field` (a body, joint or model).
template <typename Item, typename Id>
EntityIndex ByField(size_t num_keys, const std::vector<Item>& items, Id Item::*field) {
  return EntityIndex(num_keys, items.size(), [&](size_t i) { return (items[i].*field).index(); });
}

}  // namespace

EntityIndex GeometriesByBody(const Plant& plant, const SceneGraph& scene) {
  return ByField(plant.bodies.size(), scene.geometries, &SceneGeometry::body);
}

EntityIndex CamerasByBody(const Plant& plant, const SceneGraph& scene) {
  return ByField(plant.bodies.size(), scene.cameras, &SceneCamera::body);
}

EntityIndex FramesByBody(const Plant& plant) {
  return ByField(plant.bodies.size(), plant.frames, &PlantFrame::body);
}

EntityIndex ActuatorsByJoint(const Plant& plant) {
  return ByField(plant.joints.size(), plant.actuators, &PlantActuator::joint);
}

EntityIndex CouplersByFollower(const Plant& plant) {
  return EntityIndex(plant.joints.size(), plant.constraints.size(), [&](size_t i) -> int64_t {
    const auto* c = std::get_if<CouplerConstraint>(&plant.constraints[i].payload);
    return c ? int64_t(c->joint0.index()) : EntityIndex::kNoKey;
  });
}

EntityIndex SpringsByJoint(const Plant& plant) {
  return EntityIndex(plant.joints.size(), plant.force_elements.size(), [&](size_t i) -> int64_t {
    const auto* s = std::get_if<JointSpring>(&plant.force_elements[i]);
    return s ? int64_t(s->joint.index()) : EntityIndex::kNoKey;
  });
}

EntityIndex BodiesByModel(const Plant& plant) {
  return EntityIndex(plant.model_instances.size(), plant.bodies.size(), [&](size_t b) -> int64_t {
    return b == 0 ? EntityIndex::kNoKey : int64_t(plant.bodies[b].model.index());
  });
}

EntityIndex JointsByModel(const Plant& plant) {
  return ByField(plant.model_instances.size(), plant.joints, &PlantJoint::model);
}

EntityIndex FramesByModel(const Plant& plant) {
  return ByField(plant.model_instances.size(), plant.frames, &PlantFrame::model);
}

}  // namespace mdlc::backend
