// UniqueNames, the namespace every writer gives clashing names a suffix in
// (issue 16: 10,000 links' collisions all named "collision" took the MJCF
// writer 15 s, counting suffixes from 1 for each).
#include "backend/writers/unique_names.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <string>

namespace mdlc::writers {
namespace {

// what the writers did before: the first free suffix, counted from 1
std::string NaiveUnique(std::set<std::string>& taken, const std::string& name) {
  if (taken.insert(name).second) return name;
  std::string out;
  for (int n = 1; !taken.insert(out = fmt::format("{}_{}", name, n)).second; ++n) {
  }
  return out;
}

TEST(WriterUniqueNames, ClashesTakeTheNextSuffixInOrder) {
  UniqueNames names;
  EXPECT_EQ(names.TakeUnique("collision"), "collision");
  for (int n = 1; n < 10000; ++n) {
    ASSERT_EQ(names.TakeUnique("collision"), fmt::format("collision_{}", n));
  }
  EXPECT_TRUE(names.contains("collision_9999"));
  EXPECT_FALSE(names.contains("collision_10000"));
}

TEST(WriterUniqueNames, ASuffixTakenOtherwiseIsSkipped) {
  UniqueNames names;
  EXPECT_TRUE(names.Take("a"));
  EXPECT_TRUE(names.Take("a_2"));  // a link named so, say
  EXPECT_FALSE(names.Take("a"));
  EXPECT_EQ(names.TakeUnique("a"), "a_1");
  EXPECT_EQ(names.TakeUnique("a"), "a_3");
  EXPECT_TRUE(names.Take("a_5"));
  EXPECT_EQ(names.TakeSuffixed("a"), "a_4");
  EXPECT_EQ(names.TakeSuffixed("a"), "a_6");
  EXPECT_EQ(names.TakeSuffixed(""), "_1");  // an empty base, as written before
}

// Whatever mix of names and clashes, the same names as counting from 1:
// conversions write what they wrote before, byte for byte.
TEST(WriterUniqueNames, AgreesWithCountingFromOneOnRandomClashes) {
  std::mt19937 rng(20261129);
  for (int trial = 0; trial < 50; ++trial) {
    UniqueNames names;
    std::set<std::string> naive;
    for (int op = 0; op < 400; ++op) {
      const std::string base = std::string(1, static_cast<char>('a' + rng() % 3));
      switch (rng() % 3) {
        case 0: {  // a name that may be some other name's suffixed form
          const std::string name = rng() % 2 ? base : fmt::format("{}_{}", base, rng() % 12);
          ASSERT_EQ(names.Take(name), naive.insert(name).second) << name;
          break;
        }
        case 1:
          ASSERT_EQ(names.TakeUnique(base), NaiveUnique(naive, base));
          break;
        default: {
          const std::string suffixed = names.TakeSuffixed(base);
          std::string expected;
          for (int n = 1; !naive.insert(expected = fmt::format("{}_{}", base, n)).second; ++n) {
          }
          ASSERT_EQ(suffixed, expected);
        }
      }
    }
  }
}

}  // namespace
}  // namespace mdlc::writers
