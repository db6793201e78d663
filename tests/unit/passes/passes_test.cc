// The default passes: name resolution, the kinematic tree, inertia checks,
// and the pass manager's contract (URDF-010, URDF-017, COMMON-030..033,
// COMMON-040, COMMON-041).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "ir/printer.h"
#include "ir/verifier.h"
#include "passes/name_index.h"
#include "passes/pass_registry.h"
#include "tests/unit/urdf_test_util.h"

namespace mdlc {
namespace {

using testing::Lowered;

TEST(ScopedNameTest, SplitsAtTheLastDelimiter) {  // COMMON-030, COMMON-031
  auto s = passes::SplitScopedName("a::b::c");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->scope, "a::b");
  EXPECT_EQ(s->element, "c");
  EXPECT_EQ(passes::SplitScopedName("c")->scope, "");
  EXPECT_FALSE(passes::SplitScopedName("::c"));
  EXPECT_FALSE(passes::SplitScopedName("a::"));
  EXPECT_FALSE(passes::SplitScopedName("a::::b"));
  EXPECT_FALSE(passes::SplitScopedName(""));
}

TEST(ClosestNameTest, SuggestsTyposOnly) {
  std::vector<std::string_view> names = {"shoulder", "elbow", "wrist"};
  EXPECT_EQ(passes::ClosestName("elbwo", names), "elbow");   // transposition
  EXPECT_EQ(passes::ClosestName("sholder", names), "shoulder");
  EXPECT_FALSE(passes::ClosestName("gripper", names));
}

TEST(LazyNameIndexTest, IndexesTheTableFromItsFirstEntityOnAtTheFirstLookup) {  // COMMON-030
  ir::Module m;
  std::vector<ir::Body> bodies(3);
  const ModelId arm(size_t{5}), other(size_t{6});
  bodies[0].name = m.Intern("link");  // before `first`: never indexed
  bodies[0].model = arm;
  bodies[1].name = m.Intern("link");
  bodies[1].model = arm;
  bodies[2].name = m.Intern("link");
  bodies[2].model = other;
  passes::LazyNameIndex<BodyId, std::vector<ir::Body>> index(bodies, 1);
  EXPECT_EQ(index.Find(arm, m.Intern("link")), BodyId(size_t{1}));
  EXPECT_EQ(index.Find(other, m.Intern("link")), BodyId(size_t{2}));
  EXPECT_EQ(index.Find(arm, m.Intern("tool")), std::nullopt);
  EXPECT_EQ(index.Find(ModelId(size_t{7}), m.Intern("link")), std::nullopt);
}

TEST(ResolveNamesTest, ResolvesAndSuggests) {  // URDF-010
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='base'/><link name='forearm'/>
    <joint name='j' type='fixed'><parent link='base'/><child link='foreram'/></joint></robot>)"));
  EXPECT_FALSE(l.RunPasses());
  ASSERT_EQ(l.diags.error_count(), 1u);
  const Diagnostic& d = l.diags.diagnostics()[0];
  EXPECT_EQ(d.kind, DiagKind::UnknownReference);
  EXPECT_NE(d.message.find("Could not find link 'foreram'"), std::string::npos);
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].message, "did you mean 'forearm'?");
  l.ExpectDiagnostic(DiagKind::UnknownReference, "Could not find link 'foreram'");
  EXPECT_EQ(d.loc.line, 2u);
}

TEST(ResolveNamesTest, WorldIsAlwaysTheWorldBody) {  // COMMON-032
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'/>
    <joint name='j' type='fixed'><parent link='world'/><child link='a'/></joint></robot>)"));
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
  EXPECT_EQ(l.Joint("j")->parent.id, ir::kWorldBody);
  EXPECT_EQ(l.module.joints.size(), 1u);  // welded to the world: no floating joint
}

TEST(BuildKinematicTreeTest, RootsGetFloatingJointsNamedAfterTheirBody) {  // URDF-017
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'/><link name='b'/><link name='c'/>
    <joint name='a' type='fixed'><parent link='b'/><child link='c'/></joint></robot>)"));
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
  // 'a' and 'b' are roots; the joint name 'a' is taken, so Drake's rule prefixes '_'
  ASSERT_NE(l.Joint("_a"), nullptr);
  EXPECT_EQ(l.Joint("_a")->type, ir::JointType::QuaternionFloating);
  ASSERT_NE(l.Joint("b"), nullptr);
  EXPECT_TRUE(l.Joint("b")->unnamed);
  EXPECT_EQ(l.Joint("b")->parent.id, ir::kWorldBody);
  EXPECT_TRUE(ir::VerifyModule(l.module, ir::VerifyLevel::Tree, l.diags));
}

TEST(BuildKinematicTreeTest, JointToItselfAndWorldAsChildAreErrors) {
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'/>
    <joint name='self' type='fixed'><parent link='a'/><child link='a'/></joint>
    <joint name='up' type='fixed'><parent link='a'/><child link='world'/></joint></robot>)"));
  EXPECT_FALSE(l.RunPasses());
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::SelfJoint, "to itself"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::KinematicLoop, "world its child"));
}

TEST(BuildKinematicTreeTest, LongLoopIsFoundWithoutRecursion) {
  std::string urdf = "<robot name='r'>";
  const int n = 20000;
  for (int i = 0; i < n; ++i) urdf += "<link name='l" + std::to_string(i) + "'/>";
  for (int i = 0; i < n; ++i) {
    urdf += "<joint name='j" + std::to_string(i) + "' type='fixed'><parent link='l" +
            std::to_string(i) + "'/><child link='l" + std::to_string((i + 1) % n) + "'/></joint>";
  }
  urdf += "</robot>";
  Lowered l;
  ASSERT_TRUE(l.Read(urdf));
  EXPECT_FALSE(l.RunPasses());
  ASSERT_EQ(l.diags.error_count(), 1u);
  EXPECT_EQ(l.diags.diagnostics()[0].kind, DiagKind::KinematicLoop);
  EXPECT_EQ(l.diags.diagnostics()[0].notes.size(), static_cast<size_t>(n));
  l.ExpectDiagnostic(DiagKind::KinematicLoop, "kinematic loop through joints");
}

TEST(CheckInertiaTest, ReplacesNonPhysicalInertiaWithASphere) {  // COMMON-040
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'><inertial>
      <origin xyz='1 2 3' rpy='0 0 1'/><mass value='2'/>
      <inertia ixx='1' iyy='1' izz='5'/></inertial></link></robot>)"));
  ASSERT_TRUE(l.RunPasses());
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::NonPhysicalInertia, "triangle inequality: 1 + 1 < 5"));
  const ir::Inertial& in = *l.Body("a")->inertial;
  const double r = std::cbrt(3 * 2.0 / (4 * std::numbers::pi * 1000));
  EXPECT_DOUBLE_EQ(in.mass, 2);
  EXPECT_DOUBLE_EQ(in.ixx, 0.4 * 2 * r * r);
  EXPECT_EQ(in.ixx, in.izz);
  EXPECT_EQ(in.X_BI.p, Eigen::Vector3d(1, 2, 3));  // centred at the given COM
}

TEST(CheckInertiaTest, MomentsArePrintedAsWrittenNotToSeventeenDigits) {  // COMMON-040
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'><inertial><mass value='1'/>
      <inertia ixx='0.1' iyy='0.1' izz='0.5'/></inertial></link></robot>)"));
  ASSERT_TRUE(l.RunPasses());
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::NonPhysicalInertia, "triangle inequality: 0.1 + 0.1 < 0.5"))
      << l.Messages();
}

TEST(CheckInertiaTest, MassRules) {  // COMMON-041
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'>
    <link name='massless'><inertial><mass value='0'/></inertial></link>
    <link name='zero_mass'><inertial><mass value='0'/><inertia ixx='1' iyy='1' izz='1'/></inertial></link>
    <link name='negative'><inertial><mass value='-1'/><inertia ixx='1' iyy='1' izz='1'/></inertial></link>
    <link name='negative_moment'><inertial><mass value='1'/><inertia ixx='-1' iyy='1' izz='1'/></inertial></link>
    <link name='fine'><inertial><mass value='1'/><inertia ixx='1' iyy='1' izz='2'/></inertial></link>
  </robot>)"));
  ASSERT_TRUE(l.RunPasses());
  EXPECT_EQ(l.Body("massless")->inertial->mass, 0);  // zero mass and inertia: accepted
  EXPECT_EQ(l.Body("zero_mass")->inertial->mass, 1);
  EXPECT_EQ(l.Body("negative")->inertial->mass, 1);
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::NonPositiveMass, "mass -1 is negative"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::NonPhysicalInertia, "principal moment -1 is negative"));
  EXPECT_EQ(l.Body("fine")->inertial->izz, 2);  // a flat disk is exactly on the boundary
  EXPECT_EQ(l.diags.warning_count(), 3u) << l.Messages();
  l.ExpectDiagnostic(DiagKind::NonPositiveMass, "'r::zero_mass' has non-physical inertia: mass is zero");
}

// COMMON-040 at the boundary, from both sides. Drake's test
// (RotationalInertia::CouldBePhysicallyValid) allows eps = 16 machine
// epsilons times max(1, trace/2): absolute for a small link (3.5527e-15
// kg m^2), relative for a large one. Each case sits at 0.85 eps (kept) or
// 1.15 eps (replaced) from the violated bound.
TEST(CheckInertiaTest, DrakesToleranceAtTheBoundary) {  // COMMON-040
  const double eps_small = 16 * std::numeric_limits<double>::epsilon();
  const double eps_large = eps_small * 100;  // trace/2 = 100
  const std::string small_kept = fmt::format("{:.17g}", 2e-4 + 0.85 * eps_small);
  const std::string small_replaced = fmt::format("{:.17g}", 2e-4 + 1.15 * eps_small);
  const std::string large_kept = fmt::format("{:.17g}", 100 + 0.85 * eps_large);
  const std::string large_replaced = fmt::format("{:.17g}", 100 + 1.15 * eps_large);
  const std::string negative_kept = fmt::format("{:.17g}", -0.85 * eps_small);
  const std::string negative_replaced = fmt::format("{:.17g}", -1.15 * eps_small);
  const std::vector<std::pair<std::string, bool>> cases = {
      // triangle inequality, small link: 1e-4 + 1e-4 < izz by ~3e-15
      {fmt::format("ixx='1e-4' iyy='1e-4' izz='{}'", small_kept), true},
      {fmt::format("ixx='1e-4' iyy='1e-4' izz='{}'", small_replaced), false},
      // triangle inequality, large body: relative allowance
      {fmt::format("ixx='50' iyy='50' izz='{}'", large_kept), true},
      {fmt::format("ixx='50' iyy='50' izz='{}'", large_replaced), false},
      // a principal moment just below zero
      {fmt::format("ixx='{}' iyy='1e-4' izz='1e-4'", negative_kept), true},
      {fmt::format("ixx='{}' iyy='1e-4' izz='1e-4'", negative_replaced), false},
      // products that are round-off from a CAD export
      {"ixx='1e-3' iyy='2e-3' izz='2.5e-3' ixy='2.4e-35' ixz='-1.7e-36' iyz='3e-37'", true},
  };
  for (const auto& [moments, kept] : cases) {
    Lowered l;
    ASSERT_TRUE(l.Read(fmt::format(R"(<robot name='r'><link name='a'><inertial><mass value='3'/>
        <inertia {}/></inertial></link></robot>)",
                                   moments)));
    ASSERT_TRUE(l.RunPasses()) << l.Messages();
    const ir::Inertial& in = *l.Body("a")->inertial;
    const bool sphere = in.ixx == in.iyy && in.iyy == in.izz && in.ixy == 0;
    EXPECT_EQ(l.diags.warning_count(), kept ? 0u : 1u) << moments << "\n" << l.Messages();
    if (!kept) l.ExpectDiagnostic(DiagKind::NonPhysicalInertia, "using a solid sphere");
    EXPECT_EQ(!sphere, kept) << moments;
  }
}

// check-inertia skips the eigen-decomposition when an inertia is clearly
// physical (Sylvester's criterion with a margin, on I and on trace/2 - I).
// The verdict must be the eigen-decomposition's every time: random
// rotations of principal moments inside, on and just across both bounds, at
// scales from 1e-9 to 1e3, each compared with the rule of COMMON-040
// applied to the moments Eigen finds for the same (printed) numbers.
TEST(CheckInertiaTest, VerdictIsTheEigenDecompositionsEverywhere) {  // COMMON-040
  std::mt19937_64 rng(40);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double tolerance = 16 * std::numeric_limits<double>::epsilon();
  std::string urdf = "<robot name='r'>";
  std::vector<bool> expect_kept;
  for (int i = 0; i < 3000; ++i) {
    const double scale = std::pow(10.0, -9 + 12 * unit(rng));
    double p0 = scale * (0.05 + unit(rng)), p1 = scale * (0.05 + unit(rng));
    double p2 = std::min(p0 + p1, scale * (0.05 + unit(rng)));
    const double slack = tolerance * std::max(1.0, 0.5 * (p0 + p1 + p2));
    switch (i % 6) {
      case 0: break;                                          // inside
      case 1: p2 = p0 + p1; break;                            // a flat disk
      case 2: p2 = p0 + p1 + slack * (unit(rng) * 4 - 2); break;  // across the triangle bound
      case 3: p0 = slack * (unit(rng) * 4 - 2); break;        // across zero
      case 4: p0 = 0; p1 = p2; break;                         // a thin rod
      case 5: p0 = p1 = p2 = scale * 1e-7; break;             // tiny and round
    }
    const Eigen::Matrix3d R =
        Eigen::Quaterniond(Eigen::Vector4d::NullaryExpr([&](Eigen::Index) { return unit(rng) - 0.5; })
                               .normalized())
            .toRotationMatrix();
    const Eigen::Matrix3d I = R * Eigen::Vector3d(p0, p1, p2).asDiagonal() * R.transpose();
    // what the file says, exactly, and Eigen's moments for it
    auto text = [](double v) { return fmt::format("{:.17g}", v); };
    Eigen::Matrix3d read;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) read(r, c) = std::strtod(text(I(std::min(r, c), std::max(r, c))).c_str(), nullptr);
    }
    const Eigen::Vector3d d =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(read, Eigen::EigenvaluesOnly).eigenvalues();
    const double eps = tolerance * std::max(1.0, 0.5 * std::abs(read.trace()));
    expect_kept.push_back(!(d[0] + eps < 0) && !(d[0] + d[1] + eps < d[2]));
    urdf += fmt::format(
        "<link name='l{}'><inertial><mass value='1'/><inertia ixx='{}' ixy='{}' ixz='{}' "
        "iyy='{}' iyz='{}' izz='{}'/></inertial></link>",
        i, text(I(0, 0)), text(I(0, 1)), text(I(0, 2)), text(I(1, 1)), text(I(1, 2)),
        text(I(2, 2)));
  }
  urdf += "</robot>";
  Lowered l;
  ASSERT_TRUE(l.Read(urdf));
  l.RunPasses();
  size_t kept = 0;
  for (size_t i = 0; i < expect_kept.size(); ++i) {
    const bool replaced = l.HasDiagnostic(DiagKind::NonPhysicalInertia, fmt::format("'r::l{}' ", i));
    EXPECT_EQ(!replaced, expect_kept[i]) << "link l" << i;
    kept += expect_kept[i];
  }
  // both verdicts are well represented
  EXPECT_GT(kept, 1500u);
  EXPECT_GT(expect_kept.size() - kept, 200u);
}

TEST(PassManagerTest, StopsAtTheFirstPassThatFails) {
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'/>
    <joint name='j' type='fixed'><parent link='a'/><child link='missing'/></joint></robot>)"));
  std::vector<std::string> printed;
  passes::PassInstrumentation inst;
  inst.print_after_all = true;
  inst.print_sink = [&](std::string_view s) {
    if (s.starts_with("// -----")) printed.emplace_back(s);
  };
  passes::PassManager pm(inst);
  pm.AddDefaultPipeline();
  passes::PassContext ctx{l.module, l.diags, l.sources};
  EXPECT_FALSE(pm.Run(ctx));
  ASSERT_EQ(printed.size(), 2u);  // resolve-frames (nothing to do for URDF), then resolve-names
  EXPECT_NE(printed[0].find("resolve-frames"), std::string::npos);
  EXPECT_NE(printed[1].find("resolve-names"), std::string::npos);
  l.ExpectDiagnostic(DiagKind::UnknownReference, "Could not find link 'missing'");
}

TEST(PassManagerTest, EveryRegisteredPassCanBeCreatedByName) {
  for (const auto& info : passes::RegisteredPasses()) {
    auto pass = passes::CreatePass(info.name);
    ASSERT_TRUE(pass) << info.name;
    EXPECT_EQ(pass->name(), info.name);
    EXPECT_FALSE(pass->description().empty());
  }
  EXPECT_FALSE(passes::CreatePass("no-such-pass"));
}

TEST(VerifierTest, CatchesUnresolvedReferencesAndBrokenTrees) {
  ir::Module m;
  ir::Body b;
  b.name = m.Intern("a");
  b.model = ir::kDefaultModel;
  m.Add(b);
  ir::Joint j;
  j.name = m.Intern("j");
  j.model = ir::kDefaultModel;
  j.parent = {m.Intern("world"), {}, ir::kWorldBody};
  j.child = {m.Intern("a"), {}, {}};
  m.Add(j);
  DiagnosticEngine diags;
  EXPECT_TRUE(ir::VerifyModule(m, ir::VerifyLevel::Raw, diags));
  EXPECT_FALSE(ir::VerifyModule(m, ir::VerifyLevel::Resolved, diags));
  m.joints[0].child.id = BodyId(uint32_t{1});
  DiagnosticEngine more;
  EXPECT_TRUE(ir::VerifyModule(m, ir::VerifyLevel::Tree, more));
  m.joints.push_back(m.joints[0]);  // a second inboard joint
  EXPECT_FALSE(ir::VerifyModule(m, ir::VerifyLevel::Tree, more));
  EXPECT_EQ(more.diagnostics()[0].kind, DiagKind::VerifierFailure);
}

TEST(PrinterTest, DumpIsDeterministicAndLocated) {
  const char* urdf = R"(<robot name='r'><link name='a'/>
    <joint name='j' type='continuous'><parent link='world'/><child link='a'/></joint></robot>)";
  Lowered a, b;
  ASSERT_TRUE(a.Read(urdf));
  ASSERT_TRUE(b.Read(urdf));
  ASSERT_TRUE(a.RunPasses());
  ASSERT_TRUE(b.RunPasses());
  const std::string dump = ir::PrintModule(a.module, a.sources);
  EXPECT_EQ(dump, ir::PrintModule(b.module, b.sources));
  EXPECT_NE(dump.find("joint #0 \"j\" model=r revolute parent=world child=r::a"),
            std::string::npos)
      << dump;
  EXPECT_NE(dump.find("loc(test.urdf:2:5)"), std::string::npos) << dump;
  ir::PrintOptions no_locs;
  no_locs.locations = false;
  EXPECT_EQ(ir::PrintModule(a.module, a.sources, no_locs).find("loc("), std::string::npos);
}

}  // namespace
}  // namespace mdlc
