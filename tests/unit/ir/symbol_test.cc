// Tests for the SymbolTable: interning, and copies that stand on their own
// (a copy's index must point into the copy's strings, never the original's;
// run under AddressSanitizer, reading a copy after its original is gone was
// a heap-use-after-free).
#include "ir/symbol.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ir/module.h"

namespace mdlc {
namespace {

// short strings live inside std::string (SSO), long ones on the heap: both kinds
const std::vector<std::string> kNames = {
    "a", "base_link", "left_gripper_finger_joint_with_a_name_longer_than_any_small_buffer",
    "world", "link_0123456789_0123456789_0123456789"};

TEST(SymbolTableTest, InternsEqualTextToEqualSymbols) {
  SymbolTable t;
  const Symbol a = t.Intern("arm");
  EXPECT_EQ(t.Intern("arm"), a);
  EXPECT_NE(t.Intern("leg"), a);
  EXPECT_EQ(t.Text(a), "arm");
  EXPECT_EQ(t.Find("arm"), a);
  EXPECT_TRUE(t.Find("nope").empty());
  EXPECT_TRUE(t.Intern("").empty());
}

TEST(SymbolTableTest, CopyOutlivesItsOriginal) {
  auto original = std::make_unique<SymbolTable>();
  std::vector<Symbol> symbols;
  for (const auto& n : kNames) symbols.push_back(original->Intern(n));
  const SymbolTable copy = *original;
  original.reset();  // the copy must not read the original's strings
  ASSERT_EQ(copy.size(), kNames.size() + 1);
  for (size_t i = 0; i < kNames.size(); ++i) {
    EXPECT_EQ(copy.Find(kNames[i]), symbols[i]) << kNames[i];
    EXPECT_EQ(copy.Text(symbols[i]), kNames[i]);
  }
  EXPECT_TRUE(copy.Find("").empty());
  EXPECT_TRUE(copy.Find("not interned").empty());
}

TEST(SymbolTableTest, CopyAssignedTableOutlivesItsSource) {
  SymbolTable target;
  target.Intern("replaced");
  {
    SymbolTable source;
    for (const auto& n : kNames) source.Intern(n);
    target = source;
  }
  EXPECT_TRUE(target.Find("replaced").empty());
  for (const auto& n : kNames) EXPECT_FALSE(target.Find(n).empty()) << n;
  // interning more into the copy keeps old and new symbols apart
  const Symbol extra = target.Intern("extra_name_long_enough_to_live_on_the_heap_for_sure");
  EXPECT_EQ(target.Intern(kNames[2]), target.Find(kNames[2]));
  EXPECT_EQ(target.Text(extra), "extra_name_long_enough_to_live_on_the_heap_for_sure");
}

TEST(SymbolTableTest, CopiesAreIndependent) {
  SymbolTable a;
  a.Intern("shared");
  SymbolTable b = a;
  const Symbol only_b = b.Intern("only_in_b");
  EXPECT_TRUE(a.Find("only_in_b").empty());
  EXPECT_EQ(b.Find("only_in_b"), only_b);
  EXPECT_EQ(a.Find("shared"), b.Find("shared"));
}

TEST(SymbolTableTest, MovedTableKeepsItsSymbols) {
  SymbolTable a;
  std::vector<Symbol> symbols;
  for (const auto& n : kNames) symbols.push_back(a.Intern(n));
  SymbolTable b = std::move(a);
  for (size_t i = 0; i < kNames.size(); ++i) EXPECT_EQ(b.Find(kNames[i]), symbols[i]);
  SymbolTable c;
  c = std::move(b);
  for (size_t i = 0; i < kNames.size(); ++i) EXPECT_EQ(c.Find(kNames[i]), symbols[i]);
}

TEST(SymbolTableTest, ModuleCopyOutlivesItsOriginal) {
  auto original = std::make_unique<ir::Module>();
  const Symbol s = original->Intern(kNames[2]);
  const ir::Module copy = *original;
  original.reset();
  EXPECT_EQ(copy.symbols.Find(kNames[2]), s);
  EXPECT_EQ(copy.Text(s), kNames[2]);
}

}  // namespace
}  // namespace mdlc
