// Tests for model instance names kept as parent + local name (issue 16):
// full names are built on demand, and a scoped name is resolved by walking
// nested instances by local name (COMMON-030, COMMON-031).
#include <gtest/gtest.h>

#include <string>

#include "ir/module.h"

namespace mdlc::ir {
namespace {

ModelId AddNested(Module& m, std::string_view local, ModelId parent) {
  return m.Add(ModelInstance{m.Intern(local), {}, SourceFormat::Sdf, {}, parent});
}

TEST(ModelNames, FullNameJoinsTheChainOfLocalNames) {
  Module m;
  const ModelId a = AddNested(m, "a", ModelId());
  const ModelId b = AddNested(m, "b", a);
  const ModelId c = AddNested(m, "c", b);
  EXPECT_EQ(m.ModelName(a), "a");
  EXPECT_EQ(m.ModelName(c), "a::b::c");
  EXPECT_EQ(m.ScopedName(c, m.Intern("link")), "a::b::c::link");
  EXPECT_EQ(m.ModelName(kWorldModel), "WorldModelInstance");
  // only local names are interned, never "a::b"
  EXPECT_TRUE(m.symbols.Find("a::b").empty());
}

TEST(ModelNames, FindsAScopedNameFromTheTopOrWithinAnInstance) {
  Module m;
  const ModelId a = AddNested(m, "a", ModelId());
  const ModelId b = AddNested(m, "b", a);
  const ModelId c = AddNested(m, "c", b);
  EXPECT_EQ(m.FindModel("a::b::c"), c);
  EXPECT_EQ(m.FindModel("a::b"), b);
  EXPECT_EQ(m.FindModel("b::c", a), c);
  EXPECT_EQ(m.FindModel("c", b), c);
  EXPECT_EQ(m.FindModel("DefaultModelInstance"), kDefaultModel);
}

TEST(ModelNames, MissingNamesAreNotFound) {
  Module m;
  const ModelId a = AddNested(m, "a", ModelId());
  AddNested(m, "b", a);
  EXPECT_FALSE(m.FindModel("b"));          // nested, so not at the top level
  EXPECT_FALSE(m.FindModel("a::x"));
  EXPECT_FALSE(m.FindModel("a::b::c"));
  EXPECT_FALSE(m.FindModel("a::b", a));    // "a::a::b"
  EXPECT_FALSE(m.FindModel(""));
  EXPECT_FALSE(m.FindModel("never_interned::b"));
}

TEST(ModelNames, SameLocalNameInDifferentParentsStaysApart) {
  Module m;
  const ModelId left = AddNested(m, "left", ModelId());
  const ModelId right = AddNested(m, "right", ModelId());
  const ModelId left_arm = AddNested(m, "arm", left);
  const ModelId right_arm = AddNested(m, "arm", right);
  EXPECT_EQ(m.FindModel("left::arm"), left_arm);
  EXPECT_EQ(m.FindModel("right::arm"), right_arm);
  EXPECT_FALSE(m.FindModel("arm"));
}

// a Model Directives namespace gives a top-level instance a name with "::"
TEST(ModelNames, TopLevelNamesMayHoldSeparators) {
  Module m;
  const ModelId ns_robot = AddNested(m, "ns::robot", ModelId());
  const ModelId ns = AddNested(m, "ns", ModelId());
  const ModelId inner = AddNested(m, "gripper", ns_robot);
  EXPECT_EQ(m.FindModel("ns::robot"), ns_robot);
  EXPECT_EQ(m.FindModel("ns"), ns);
  EXPECT_EQ(m.FindModel("ns::robot::gripper"), inner);
  EXPECT_EQ(m.ModelName(inner), "ns::robot::gripper");
}

// 5000 levels: every lookup walks local names, and no full name is interned
TEST(ModelNames, DeepNestingResolvesEveryLevel) {
  Module m;
  constexpr int kDepth = 5000;
  std::vector<ModelId> chain = {AddNested(m, "top", ModelId())};
  for (int i = 1; i < kDepth; ++i) {
    chain.push_back(AddNested(m, "m" + std::to_string(i), chain.back()));
  }
  std::string full = "top";
  for (int i = 1; i < kDepth; ++i) full += "::m" + std::to_string(i);
  EXPECT_EQ(m.ModelName(chain.back()), full);
  EXPECT_EQ(m.FindModel(full), chain.back());
  EXPECT_EQ(m.FindModel("m4998::m4999", chain[4997]), chain.back());
  // interned: the two built-in names, "world", and one local name per level
  EXPECT_LE(m.symbols.size(), static_cast<size_t>(kDepth) + 4);
}

// "<within>::name" also finds a top-level instance spelled that way
TEST(ModelNames, RelativeLookupFindsFlatNamesToo) {
  Module m;
  const ModelId r = AddNested(m, "r", ModelId());
  const ModelId flat = AddNested(m, "r::sub", ModelId());
  EXPECT_EQ(m.FindModel("sub", r), flat);
  EXPECT_FALSE(m.FindModel("other", r));
}

TEST(ModelNames, RenameAndRemoveKeepTheLookupInStep) {
  Module m;
  const ModelId parent = AddNested(m, "parent", ModelId());
  const ModelId urdf = AddNested(m, "parent::robot", ModelId());
  m.RenameModel(urdf, parent, m.Intern("robot"));
  EXPECT_EQ(m.ModelName(urdf), "parent::robot");
  EXPECT_EQ(m.FindModel("parent::robot"), urdf);
  EXPECT_EQ(m.FindModel("robot", parent), urdf);
  m.RemoveLastModel();
  EXPECT_FALSE(m.FindModel("parent::robot"));
  EXPECT_EQ(m.FindModel("parent"), parent);
}

}  // namespace
}  // namespace mdlc::ir
