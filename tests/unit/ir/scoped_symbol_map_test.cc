// Tests for ScopedSymbolMap: one table of names by (scope, symbol) whose
// root scope is indexed by symbol, each other scope's first name by scope,
// and the rest hashed. Whichever way a key is stored, it must behave as
// one map: a key is found where it was added, added once, and erased.
#include "ir/scoped_symbol_map.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <tuple>

#include "ir/frame_graph.h"
#include "ir/ids.h"

namespace mdlc::ir {
namespace {

constexpr uint32_t kRoot = 0;

TEST(ScopedSymbolMapTest, FindsEachKeyWhereverItIsKept) {
  ScopedSymbolMap<ModelId> names(kRoot);
  // root scope (by symbol), a scope's first name (by scope), its second (hashed)
  EXPECT_TRUE(names.TryAdd(kRoot, Symbol{7}, ModelId(uint32_t{1})).second);
  EXPECT_TRUE(names.TryAdd(3, Symbol{7}, ModelId(uint32_t{2})).second);
  EXPECT_TRUE(names.TryAdd(3, Symbol{8}, ModelId(uint32_t{3})).second);
  EXPECT_EQ(names.size(), 3u);

  ASSERT_NE(names.Find(kRoot, Symbol{7}), nullptr);
  EXPECT_EQ(*names.Find(kRoot, Symbol{7}), ModelId(uint32_t{1}));
  EXPECT_EQ(*names.Find(3, Symbol{7}), ModelId(uint32_t{2}));
  EXPECT_EQ(*names.Find(3, Symbol{8}), ModelId(uint32_t{3}));
  EXPECT_EQ(names.Find(kRoot, Symbol{8}), nullptr);
  EXPECT_EQ(names.Find(3, Symbol{9}), nullptr);
  EXPECT_EQ(names.Find(4, Symbol{7}), nullptr);
  EXPECT_EQ(names.Find(1000, Symbol{7}), nullptr);  // past every index
}

TEST(ScopedSymbolMapTest, TheFirstValueOfAKeyStays) {
  ScopedSymbolMap<ModelId> names(kRoot);
  for (uint32_t scope : {kRoot, 5u}) {
    for (uint32_t name : {4u, 6u}) {
      ASSERT_TRUE(names.TryAdd(scope, Symbol{name}, ModelId(uint32_t{name})).second);
      auto [held, added] = names.TryAdd(scope, Symbol{name}, ModelId(uint32_t{99}));
      EXPECT_FALSE(added);
      EXPECT_EQ(*held, ModelId(uint32_t{name}));
    }
  }
  EXPECT_EQ(names.size(), 4u);
}

TEST(ScopedSymbolMapTest, AValueCanBeReplacedThroughItsHolder) {
  ScopedSymbolMap<FrameNodeId> names(kRoot);
  for (uint32_t scope : {kRoot, 2u}) {
    for (uint32_t name : {1u, 2u}) {
      names.TryAdd(scope, Symbol{name}, FrameNodeId(uint32_t{1}));
      *names.TryAdd(scope, Symbol{name}, FrameNodeId(uint32_t{1})).first = FrameNodeId(uint32_t{8});
      EXPECT_EQ(*names.Find(scope, Symbol{name}), FrameNodeId(uint32_t{8}));
    }
  }
}

// An erased first name leaves its scope's index empty; a name added later
// may take it, and a name already hashed must still be found only once.
TEST(ScopedSymbolMapTest, ErasingKeepsEveryOtherKey) {
  ScopedSymbolMap<ModelId> names(ModelId().value);  // the module's: root is the invalid parent
  const uint32_t kTop = ModelId().value;
  names.TryAdd(kTop, Symbol{3}, ModelId(uint32_t{0}));
  names.TryAdd(0, Symbol{3}, ModelId(uint32_t{1}));   // scope 0's first
  names.TryAdd(0, Symbol{4}, ModelId(uint32_t{2}));   // hashed
  names.Erase(0, Symbol{3});
  names.Erase(kTop, Symbol{3});
  EXPECT_EQ(names.Find(0, Symbol{3}), nullptr);
  EXPECT_EQ(names.Find(kTop, Symbol{3}), nullptr);
  EXPECT_EQ(*names.Find(0, Symbol{4}), ModelId(uint32_t{2}));
  EXPECT_EQ(names.size(), 1u);
  // the hashed key is not added again into the emptied index
  EXPECT_FALSE(names.TryAdd(0, Symbol{4}, ModelId(uint32_t{9})).second);
  EXPECT_EQ(names.size(), 1u);
  EXPECT_TRUE(names.TryAdd(0, Symbol{5}, ModelId(uint32_t{3})).second);
  EXPECT_EQ(*names.Find(0, Symbol{5}), ModelId(uint32_t{3}));
  names.Erase(0, Symbol{4});
  EXPECT_EQ(names.Find(0, Symbol{4}), nullptr);
  EXPECT_EQ(names.size(), 1u);
}

// Against std::map, over random adds and erases in a few scopes: the same
// answers, the same size, and equality that ignores where a key is kept.
TEST(ScopedSymbolMapTest, AgreesWithAnOrderedMap) {
  std::mt19937 random(16);
  ScopedSymbolMap<ModelId> names(kRoot);
  std::map<std::pair<uint32_t, uint32_t>, ModelId> expected;
  for (int step = 0; step < 20000; ++step) {
    const uint32_t scope = random() % 6, name = 1 + random() % 40;
    const ModelId value(static_cast<uint32_t>(step));
    if (random() % 4 == 0) {
      names.Erase(scope, Symbol{name});
      expected.erase({scope, name});
    } else {
      const bool added = names.TryAdd(scope, Symbol{name}, value).second;
      EXPECT_EQ(added, expected.emplace(std::make_pair(scope, name), value).second);
    }
    const ModelId* found = names.Find(scope, Symbol{name});
    auto it = expected.find({scope, name});
    ASSERT_EQ(found != nullptr, it != expected.end());
    if (found) {
      EXPECT_EQ(*found, it->second);
    }
    ASSERT_EQ(names.size(), expected.size());
  }
  // the same entries added in another order are an equal table
  ScopedSymbolMap<ModelId> rebuilt(kRoot);
  for (auto it = expected.rbegin(); it != expected.rend(); ++it) {
    rebuilt.TryAdd(it->first.first, Symbol{it->first.second}, it->second);
  }
  EXPECT_TRUE(rebuilt == names);
  size_t visited = 0;
  names.ForEach([&](uint32_t scope, Symbol name, ModelId value) {
    ++visited;
    EXPECT_EQ(expected.at({scope, name.value}), value);
  });
  EXPECT_EQ(visited, expected.size());
}

}  // namespace
}  // namespace mdlc::ir
