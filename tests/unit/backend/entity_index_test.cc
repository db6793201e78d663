// EntityIndex (backend/entity_index.h): entities grouped by key in one pass,
// as the writers and `mdlc tree` ask for a body's or a joint's (issue 16).
#include "backend/entity_index.h"

#include <gtest/gtest.h>

#include <vector>

namespace mdlc::backend {
namespace {

std::vector<uint32_t> Of(const EntityIndex& index, size_t key) {
  const auto group = index[key];
  return {group.begin(), group.end()};
}

TEST(EntityIndex, GroupsEachKeysEntitiesInEntityOrder) {
  const std::vector<int64_t> keys = {2, 0, EntityIndex::kNoKey, 2, 0, 2};
  const EntityIndex index(4, keys.size(), [&](size_t i) { return keys[i]; });
  EXPECT_EQ(Of(index, 0), (std::vector<uint32_t>{1, 4}));
  EXPECT_EQ(Of(index, 1), (std::vector<uint32_t>{}));
  EXPECT_EQ(Of(index, 2), (std::vector<uint32_t>{0, 3, 5}));
  EXPECT_EQ(Of(index, 3), (std::vector<uint32_t>{}));
  EXPECT_TRUE(index[4].empty());  // past the keys: nothing, not a fault
  EXPECT_TRUE(EntityIndex()[0].empty());
}

}  // namespace
}  // namespace mdlc::backend
