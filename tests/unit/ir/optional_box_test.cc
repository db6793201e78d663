// Tests for OptionalBox, the heap-held optional of rare entity members
// (a body's deformable properties, a geometry's fit-to-mesh request): it
// behaves as the std::optional it replaced, copies are deep, and it is one
// pointer wide, which is why it exists.
#include "ir/optional_box.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "ir/entities.h"

namespace mdlc {
namespace {

TEST(OptionalBox, EmptyUntilAssigned) {
  OptionalBox<std::string> box;
  EXPECT_FALSE(box.has_value());
  EXPECT_FALSE(box);
  box = std::string("deformable");
  ASSERT_TRUE(box);
  EXPECT_EQ(*box, "deformable");
  EXPECT_EQ(box->size(), 10u);
  box = std::nullopt;
  EXPECT_FALSE(box);
  box = std::string("again");
  box.reset();
  EXPECT_FALSE(box.has_value());
}

TEST(OptionalBox, CopiesAreDeepAndMovesTakeTheValue) {
  OptionalBox<std::string> original(std::string("mesh.obj"));
  OptionalBox<std::string> copy = original;
  copy->append("!");
  EXPECT_EQ(*original, "mesh.obj");
  EXPECT_EQ(*copy, "mesh.obj!");

  OptionalBox<std::string> assigned;
  assigned = original;
  EXPECT_TRUE(assigned == original);
  EXPECT_FALSE(assigned == copy);

  OptionalBox<std::string> moved = std::move(copy);
  EXPECT_EQ(*moved, "mesh.obj!");

  OptionalBox<std::string> empty;
  assigned = empty;
  EXPECT_FALSE(assigned);
  EXPECT_TRUE(assigned == empty);
}

TEST(OptionalBox, EntitiesCarryAPointerNotTheValue) {
  // the reason for the type: a table of bodies or geometries does not hold
  // the bytes of members almost none of them has
  EXPECT_EQ(sizeof(OptionalBox<ir::DeformableProperties>), sizeof(void*));
  EXPECT_LT(sizeof(OptionalBox<ir::MeshFit>), sizeof(std::optional<ir::MeshFit>));

  ir::Body body;
  EXPECT_FALSE(body.deformable);
  body.deformable = ir::DeformableProperties{};
  const ir::Body copy = body;
  body.deformable->youngs_modulus = 1;
  EXPECT_EQ(copy.deformable->youngs_modulus, 1e8);  // the copy kept its own
}

}  // namespace
}  // namespace mdlc
