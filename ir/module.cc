#include "ir/module.h"

namespace mdlc::ir {

Module::Module() {
  models.push_back({Intern("WorldModelInstance"), {}, SourceFormat::Internal, {}});
  models.push_back({Intern("DefaultModelInstance"), {}, SourceFormat::Internal, {}});
  Body world;
  world.name = Intern("world");
  world.model = kWorldModel;
  world.is_world = true;
  bodies.push_back(world);
}

std::string Module::ScopedName(ModelId model, Symbol local) const {
  std::string out(Text(models[model.index()].name));
  out += "::";
  out += Text(local);
  return out;
}

std::string Module::ScopedName(BodyId body) const {
  const Body& b = bodies[body.index()];
  if (b.is_world) return "world";
  return ScopedName(b.model, b.name);
}

std::string Module::ScopedName(JointId joint) const {
  const Joint& j = joints[joint.index()];
  return ScopedName(j.model, j.name);
}

}  // namespace mdlc::ir
