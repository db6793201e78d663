// Tests for the plant's model instance names, kept as parent + local name
// and spelled out in full only when read (issue 16).
#include "backend/model_instance_names.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "backend/plant.h"

namespace mdlc::backend {
namespace {

TEST(ModelInstanceNames, BuildsFullNamesFromParents) {
  ModelInstanceNames names;
  names.Add("WorldModelInstance", ModelId());
  names.Add("top", ModelId());
  names.Add("mid", ModelId(uint32_t{1}));
  names.Add("leaf", ModelId(uint32_t{2}));
  EXPECT_EQ(names.size(), 4u);
  EXPECT_EQ(names[3], "top::mid::leaf");
  EXPECT_EQ(names.back(), "top::mid::leaf");
  EXPECT_EQ(names.Scoped(ModelId(uint32_t{2}), "link"), "top::mid::link");
  // an entity of no known instance keeps its local name
  EXPECT_EQ(names.Scoped(ModelId(), "link"), "link");
  std::vector<std::string> iterated;
  for (const std::string& name : names) iterated.push_back(name);
  EXPECT_EQ(iterated, names.ToVector());
  EXPECT_EQ(iterated, (std::vector<std::string>{"WorldModelInstance", "top", "top::mid",
                                                "top::mid::leaf"}));
}

TEST(ModelInstanceNames, PlantScopesBodiesAndJoints) {
  Plant plant;
  plant.model_instances.Add("WorldModelInstance", ModelId());
  plant.model_instances.Add("outer", ModelId());
  plant.model_instances.Add("inner", ModelId(uint32_t{1}));
  PlantBody world;
  world.name = "world";
  world.is_world = true;
  world.model = ModelId(uint32_t{0});
  PlantBody link;
  link.name = "link";
  link.model = ModelId(uint32_t{2});
  PlantJoint joint;
  joint.name = "j";
  joint.model = ModelId(uint32_t{2});
  EXPECT_EQ(plant.ScopedName(world), "world");
  EXPECT_EQ(plant.ScopedName(link), "outer::inner::link");
  EXPECT_EQ(plant.ScopedName(joint), "outer::inner::j");
}

}  // namespace
}  // namespace mdlc::backend
