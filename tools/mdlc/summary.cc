#include "summary.h"

#include <fmt/format.h>

#include <map>

#include "ir/count_text.h"

namespace mdlc::tools {

std::string FormatSummary(const backend::CompiledModel& model) {
  const backend::Plant& plant = model.plant;
  std::string out;
  out += fmt::format("model instances: {}\n", plant.model_instances.size());
  for (size_t m = 0; m < plant.model_instances.size(); ++m) {
    size_t bodies = 0, joints = 0;
    double mass = 0;
    for (const auto& b : plant.bodies) {
      if (b.model.index() == m && !b.is_world) {
        ++bodies;
        mass += b.mass;
      }
    }
    for (const auto& j : plant.joints) joints += j.model.index() == m;
    out += fmt::format("  {}: {}, {}, mass {:.6g} kg\n", plant.model_instances[m],
                       ir::CountOf(bodies, "body", "bodies"), ir::CountOf(joints, "joint"), mass);
  }
  double total_mass = 0;
  for (const auto& b : plant.bodies) total_mass += b.mass;
  std::map<std::string_view, int> by_type;
  for (const auto& j : plant.joints) ++by_type[ir::JointTypeName(j.type)];
  std::string types;
  for (const auto& [name, count] : by_type) {
    types += fmt::format("{}{} {}", types.empty() ? "" : ", ", count, name);
  }
  out += fmt::format("bodies: {} (plus world)\n", plant.bodies.size() - 1);
  out += fmt::format("joints: {}{}\n", plant.joints.size(), types.empty() ? "" : " (" + types + ")");
  out += fmt::format("positions: {}, velocities: {}\n", plant.num_positions, plant.num_velocities);
  size_t proximity = 0, illustration = 0, perception = 0;
  for (const auto& g : model.scene.geometries) {
    proximity += (g.roles & ir::kProximityRole) != 0;
    illustration += (g.roles & ir::kIllustrationRole) != 0;
    perception += (g.roles & ir::kPerceptionRole) != 0;
  }
  out += fmt::format("geometries: {} ({} proximity, {} illustration, {} perception)\n",
                     model.scene.geometries.size(), proximity, illustration, perception);
  out += fmt::format("actuators: {}, constraints: {}, frames: {}\n", plant.actuators.size(),
                     plant.constraints.size(), plant.frames.size());
  out += fmt::format("total mass: {:.6g} kg\n", total_mass);
  return out;
}

}  // namespace mdlc::tools
