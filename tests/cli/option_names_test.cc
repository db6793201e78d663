// option_names_test.cc - the command line refuses a name it does not know
// (issue 59): `-Wno-typo`, `-Werror=typo`, `--print-after=typo` and
// `--passes=typo` used to do nothing at all. Each is now bad usage, exit
// status 2 like any bad flag, with the nearest known name when one is a
// typo away. None of these runs a compile.
#include "cli_fixture.h"

namespace mdlc::cli_test {
namespace {

class OptionNamesCliTest : public CliFixture {
 protected:
  // one link: the refused flags stop mdlc before it reads the model
  Outcome Compile(const std::string& flags) {
    return Mdlc("compile --emit=none " + flags + " " +
                Write("m.urdf", "<robot name=\"r\"><link name=\"a\"/></robot>").string());
  }
};

TEST_F(OptionNamesCliTest, DisabledWarningGroupIsChecked) {
  const Outcome r = Compile("-Wno-jiont");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "mdlc: error: unknown warning group 'jiont' in -Wno-jiont; did you mean "
                   "'joint'?\n");
  EXPECT_EQ(r.out, "");
  const Outcome far = Compile("-Wno-typo");  // no group is near: where they are listed
  EXPECT_EQ(far.status, 2);
  EXPECT_EQ(far.err, "mdlc: error: unknown warning group 'typo' in -Wno-typo; mdlc "
                     "--list-warnings lists the groups\n");
}

TEST_F(OptionNamesCliTest, ErrorWarningGroupIsChecked) {
  const Outcome r = Compile("-Werror=inertai");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "mdlc: error: unknown warning group 'inertai' in -Werror=inertai; did you "
                   "mean 'inertia'?\n");
  EXPECT_EQ(Compile("-Wtypo").status, 2);
}

TEST_F(OptionNamesCliTest, PrintAfterPassIsChecked) {
  const Outcome r = Compile("--print-after=check-jionts");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "mdlc: error: unknown pass 'check-jionts' in --print-after; did you mean "
                   "'check-joints'?\n");
}

TEST_F(OptionNamesCliTest, PassesAreChecked) {
  const Outcome r = Compile("--passes=resolve-frames,resolve-nmes");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "mdlc: error: unknown pass 'resolve-nmes' in --passes; did you mean "
                   "'resolve-names'?\n");
  const Outcome far = Compile("--passes=typo");
  EXPECT_EQ(far.status, 2);
  EXPECT_NE(far.err.find("mdlc --list-passes lists the passes"), std::string::npos) << far.err;
}

TEST_F(OptionNamesCliTest, LimitsAndValuesNameTheNearest) {
  Outcome r = Compile("--limit dept=3");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "mdlc: error: unknown limit 'dept' in --limit; did you mean 'depth'?\n");
  r = Compile("--collada-up-axis=aply");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "mdlc: error: unknown value 'aply' for --collada-up-axis; did you mean "
                   "'apply'?\n");
}

TEST_F(OptionNamesCliTest, KnownNamesAreTaken) {
  // two passes make no plant: --emit=ir stops after them
  const Outcome r = Mdlc("compile --emit=ir -o /dev/null -Wno-joint -Werror=names -Wunknown "
                         "--passes=resolve-frames,resolve-names --print-after=resolve-names " +
                         Write("m.urdf", "<robot name=\"r\"><link name=\"a\"/></robot>").string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("IR dump after resolve-names"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace mdlc::cli_test
