// entity_index.cc - the indices of a compiled model that entity_index.h names.
#include "backend/entity_index.h"

#include <variant>

namespace mdlc::backend {

EntityIndex GeometriesByBody(const Plant& plant, const SceneGraph& scene) {
  return EntityIndex(plant.bodies.size(), scene.geometries.size(),
                     [&](size_t i) { return scene.geometries[i].body.index(); });
}

EntityIndex CamerasByBody(const Plant& plant, const SceneGraph& scene) {
  return EntityIndex(plant.bodies.size(), scene.cameras.size(),
                     [&](size_t i) { return scene.cameras[i].body.index(); });
}

EntityIndex FramesByBody(const Plant& plant) {
  return EntityIndex(plant.bodies.size(), plant.frames.size(),
                     [&](size_t i) { return plant.frames[i].body.index(); });
}

EntityIndex ActuatorsByJoint(const Plant& plant) {
  return EntityIndex(plant.joints.size(), plant.actuators.size(),
                     [&](size_t i) { return plant.actuators[i].joint.index(); });
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
  return EntityIndex(plant.model_instances.size(), plant.joints.size(),
                     [&](size_t j) { return plant.joints[j].model.index(); });
}

EntityIndex FramesByModel(const Plant& plant) {
  return EntityIndex(plant.model_instances.size(), plant.frames.size(),
                     [&](size_t f) { return plant.frames[f].model.index(); });
}

}  // namespace mdlc::backend
