// Tests of the resolve-frames pass through the SDFormat frontend: each case
// compiles a small model and checks the resolved poses against values
// worked out by hand (SDF-003..006, SDF-011, SDF-012, SDF-031, SDF-032,
// EXT-001). The corpus-wide comparison with libsdformat lives in
// tests/oracle/sdformat_oracle_test.cc.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "passes/pass.h"
#include "passes/pass_registry.h"
#include "tests/unit/sdf_test_util.h"
#include "tests/unit/test_values.h"

namespace mdlc::testing {
namespace {

using testing::kTol;

const ir::Body& BodyNamed(const ir::Module& m, std::string_view model, std::string_view name) {
  for (const ir::Body& b : m.bodies) {
    if (m.Text(b.name) == name && m.ModelName(b.model) == model) return b;
  }
  ADD_FAILURE() << "no body " << model << "::" << name;
  return m.bodies[0];
}
const ir::Frame& FrameNamed(const ir::Module& m, std::string_view model, std::string_view name) {
  for (const ir::Frame& f : m.frames) {
    if (m.Text(f.name) == name && m.ModelName(f.model) == model) return f;
  }
  ADD_FAILURE() << "no frame " << model << "::" << name;
  return m.frames[0];
}
// A model file to include: one link, p, half a meter up.
const std::pair<std::string, std::string> kPartFile{"part.sdf", R"(<?xml version='1.0'?>
<sdf version='1.9'><model name='part'><link name='p'><pose>0 0 0.5 0 0 0</pose></link></model></sdf>)"};

const ir::Joint& JointNamed(const ir::Module& m, std::string_view name) {
  for (const ir::Joint& j : m.joints) {
    if (m.Text(j.name) == name) return j;
  }
  ADD_FAILURE() << "no joint " << name;
  return m.joints[0];
}

TEST(ResolveFrames, RelativeToChainThroughNestedModels) {  // SDF-003, SDF-030, SDF-034
  SdfCompileResult r(R"(
  <model name='top'>
    <pose>1 0 0 0 0 0</pose>
    <link name='base'><pose>0 1 0 0 0 0</pose></link>
    <model name='inner'>
      <pose relative_to='base'>0 0 1 0 0 1.5707963267948966</pose>
      <link name='L'><pose>1 0 0 0 0 0</pose></link>
    </model>
    <frame name='F'><pose relative_to='inner::L'>1 0 0 0 0 0</pose></frame>
  </model>)");
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Module& m = r.compilation().module;
  // inner's frame at base (1,1,0) + 1 up, turned 90 degrees: L's x offset becomes +y
  const Transform X_WL = *BodyNamed(m, "top::inner", "L").default_pose;
  EXPECT_NEAR((X_WL.p - Eigen::Vector3d(1, 2, 1)).norm(), 0, kTol);
  // F is 1 along L's x, i.e. +y in world; attached to the model frame, whose
  // canonical link is base
  const ir::Frame& F = FrameNamed(m, "top", "F");
  EXPECT_EQ(m.Text(m[F.body.id].name), "base");
  const Transform X_WB = *BodyNamed(m, "top", "base").default_pose;
  EXPECT_NEAR(((X_WB * F.X_BF).p - Eigen::Vector3d(1, 3, 1)).norm(), 0, kTol);
}

TEST(ResolveFrames, AFrameWrittenBeforeItsLinkIsPlacedOnIt) {  // SDF-003, SDF-004
  // the pass writes a node's body-fixed pose as it reaches the node; a frame
  // that names a link written further down waits until that link is placed
  SdfCompileResult r(R"(
  <model name='top'>
    <frame name='early' attached_to='late'><pose relative_to='late'>0 0 2 0 0 0</pose></frame>
    <link name='first'/>
    <link name='late'><pose>1 0 0 0 0 1.5707963267948966</pose></link>
  </model>)");
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Module& m = r.compilation().module;
  const ir::Frame& early = FrameNamed(m, "top", "early");
  EXPECT_EQ(m.Text(m[early.body.id].name), "late");
  EXPECT_NEAR((early.X_BF.p - Eigen::Vector3d(0, 0, 2)).norm(), 0, kTol);
  EXPECT_TRUE(early.X_BF.R.isApprox(Eigen::Matrix3d::Identity(), kTol));
  // in the world, 2 above the link
  const Transform X_WL = *BodyNamed(m, "top", "late").default_pose;
  EXPECT_NEAR((X_WL.p - Eigen::Vector3d(1, 0, 0)).norm(), 0, kTol);
  EXPECT_NEAR(((X_WL * early.X_BF).p - Eigen::Vector3d(1, 0, 2)).norm(), 0, kTol);
}

TEST(ResolveFrames, PlacementFramePutsTheNamedFrameAtThePose) {  // SDF-005
  SdfCompileResult r(R"(
  <model name='top'>
    <link name='base'/>
    <model name='tool' placement_frame='tip'>
      <pose>0 0 2 0 0 0</pose>
      <link name='body'/>
      <frame name='tip'><pose>0 0 0.5 0 0 0</pose></frame>
    </model>
  </model>)");
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Module& m = r.compilation().module;
  // the tip lands at z = 2, so the tool's body (0.5 below its tip) is at 1.5
  EXPECT_NEAR(BodyNamed(m, "top::tool", "body").default_pose->p.z(), 1.5, kTol);
}

TEST(ResolveFrames, JointFrameAxisExpressedInTheModelFrame) {  // SDF-011, SDF-012
  SdfCompileResult r(R"(
  <model name='m'>
    <link name='a'/>
    <link name='b'><pose>0 0 1 0 0 1.5707963267948966</pose></link>
    <joint name='j' type='revolute'>
      <pose>0 0 0.25 0 0 0</pose>
      <parent>a</parent><child>b</child>
      <axis><xyz expressed_in='__model__'>1 0 0</xyz></axis>
    </joint>
  </model>)");
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Joint& j = JointNamed(r.compilation().module, "j");
  // J is posed in the child: 0.25 above b, which is turned 90 degrees about z
  EXPECT_NEAR((j.X_CM.p - Eigen::Vector3d(0, 0, 0.25)).norm(), 0, kTol);
  EXPECT_NEAR((j.X_PF.p - Eigen::Vector3d(0, 0, 1.25)).norm(), 0, kTol);
  // the model's x is J's -y
  EXPECT_NEAR((j.axis - Eigen::Vector3d(0, -1, 0)).norm(), 0, kTol);
}

TEST(ResolveFrames, OldFilesExpressAxesInTheModelFrame) {  // SDF-012 (1.4 conversion)
  SdfCompileResult r(R"(
  <model name='m'>
    <link name='a'/>
    <link name='b'><pose>0 0 1 0 0 1.5707963267948966</pose></link>
    <joint name='j' type='revolute'>
      <parent>a</parent><child>b</child>
      <axis><xyz>1 0 0</xyz></axis>
    </joint>
  </model>)");
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR((JointNamed(r.compilation().module, "j").axis - Eigen::Vector3d(1, 0, 0)).norm(), 0,
              kTol);
  // the same model as SDFormat 1.4: libsdformat's conversion expresses it in the model
  Compilation c;
  const auto dir = std::filesystem::temp_directory_path() / "mdlc_resolve_frames_v14";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "old.sdf") << R"(<?xml version='1.0'?><sdf version='1.4'>
  <model name='m'>
    <link name='a'/>
    <link name='b'><pose>0 0 1 0 0 1.5707963267948966</pose></link>
    <joint name='j' type='revolute'>
      <parent>a</parent><child>b</child>
      <axis><xyz>1 0 0</xyz></axis>
    </joint>
  </model></sdf>)";
  c.options.inputs = {Input::File((dir / "old.sdf").string())};
  ASSERT_TRUE(c.Run());
  EXPECT_NEAR((JointNamed(c.module, "j").axis - Eigen::Vector3d(0, -1, 0)).norm(), 0, kTol);
  std::filesystem::remove_all(dir);
}

TEST(ResolveFrames, UniversalJointBuildsFramesFromBothAxes) {  // SDF-010
  SdfCompileResult r(R"(
  <model name='m'>
    <link name='a'/>
    <link name='b'/>
    <joint name='u' type='universal'>
      <parent>a</parent><child>b</child>
      <axis><xyz>0 0 1</xyz></axis>
      <axis2><xyz>1 0 0</xyz></axis2>
    </joint>
  </model>)");
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Joint& u = JointNamed(r.compilation().module, "u");
  // F's x is the first axis, its y the second
  EXPECT_NEAR((u.X_PF.R.col(0) - Eigen::Vector3d(0, 0, 1)).norm(), 0, kTol);
  EXPECT_NEAR((u.X_PF.R.col(1) - Eigen::Vector3d(1, 0, 0)).norm(), 0, kTol);
  EXPECT_NEAR((u.X_PF.R - u.X_CM.R).norm(), 0, kTol);
}

TEST(ResolveFrames, StaticModelsWeldEveryRootLinkWhereItStands) {  // SDF-006
  SdfCompileResult r(R"(
  <model name='shelf'>
    <static>true</static>
    <link name='frame'><pose>1 2 3 0 0 0</pose></link>
    <link name='board'><pose>1 2 4 0 0 0</pose></link>
    <joint name='fix' type='fixed'><parent>frame</parent><child>board</child></joint>
  </model>)");
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Module& m = r.compilation().module;
  const ir::Joint& weld = JointNamed(m, "sdformat_model_static_world_welds_to_frame");
  EXPECT_TRUE(weld.unnamed);
  EXPECT_EQ(weld.parent.id, ir::kWorldBody);
  EXPECT_NEAR((weld.X_PF.p - Eigen::Vector3d(1, 2, 3)).norm(), 0, kTol);
  for (const ir::Joint& j : m.joints) {  // board hangs on its fixed joint, not a second weld
    EXPECT_NE(m.Text(j.name), "sdformat_model_static_world_welds_to_board");
  }
}

TEST(ResolveFrames, DrakeJointBindsTheNamedFrames) {  // EXT-001
  SdfCompileResult r(R"(
  <model name='m'>
    <link name='a'/>
    <link name='b'><pose>5 0 0 0 0 0</pose></link>
    <frame name='fa' attached_to='a'><pose>0 0 1 0 0 0</pose></frame>
    <frame name='fb' attached_to='b'><pose relative_to='b'>0 2 0 0 0 0</pose></frame>
    <drake:joint name='p' type='planar'>
      <drake:parent>fa</drake:parent>
      <drake:child>fb</drake:child>
      <drake:damping>0 0 0</drake:damping>
    </drake:joint>
  </model>)");
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Joint& p = JointNamed(r.compilation().module, "p");
  EXPECT_NEAR((p.X_PF.p - Eigen::Vector3d(0, 0, 1)).norm(), 0, kTol);
  EXPECT_NEAR((p.X_CM.p - Eigen::Vector3d(0, 2, 0)).norm(), 0, kTol);
}

TEST(ResolveFrames, MergedModelFrameNamesTheMergedModel) {  // SDF-032
  SdfCompileResult r(R"(
  <model name='top'>
    <link name='base'/>
    <include merge='true'>
      <uri>part.sdf</uri>
      <pose>0 0 1 0 0 0</pose>
    </include>
    <frame name='above'><pose relative_to='_merged__part__model__'>0 0 1 0 0 0</pose></frame>
  </model>)",
                     {kPartFile});
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Module& m = r.compilation().module;
  // merged links join the including instance
  EXPECT_NEAR(BodyNamed(m, "top", "p").default_pose->p.z(), 1.5, kTol);
  const ir::Frame& merged = FrameNamed(m, "top", "_merged__part__model__");
  EXPECT_EQ(m.Text(m[merged.body.id].name), "p");
  EXPECT_NEAR(merged.X_BF.p.z(), -0.5, kTol);
}

// The SDFormat reader keeps the graph's name index as it adds nodes, and the
// pass looks references up in it (issue 16: one table, where the reader and
// the pass each built their own). The index is every named node by
// namespace and name, the first of a name keeping it; a graph built without
// it makes the pass index the nodes itself, with the same results.
TEST(ResolveFrames, TheReadersNameIndexServesThePass) {  // SDF-003, SDF-030, SDF-032
  SdfCompileResult r(R"(
  <model name='top'>
    <link name='base'/>
    <model name='inner'>
      <pose relative_to='base'>0 0 1 0 0 0.5</pose>
      <link name='L'><pose>1 0 0 0 0 0</pose>
        <collision name='c'><pose>0 1 0 0 0 0</pose>
          <geometry><sphere><radius>1</radius></sphere></geometry></collision></link>
      <frame name='F' attached_to='L'><pose relative_to='__model__'>0 0 2 0 0 0</pose></frame>
    </model>
    <include merge='true'><uri>part.sdf</uri><pose relative_to='inner::F'>0 0 1 0 0 0</pose></include>
    <joint name='j' type='revolute'><pose relative_to='inner::F'/>
      <parent>base</parent><child>inner::L</child><axis><xyz>0 1 0</xyz></axis></joint>
    <frame name='above'><pose relative_to='_merged__part__model__'>0 0 1 0 0 0</pose></frame>
  </model>)",
                     {kPartFile});
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Module& m = r.compilation().module;
  const ir::FrameGraph& g = m.frame_graph;
  ASSERT_TRUE(g.names_complete);
  ir::FrameGraph indexed_from_nodes = g;
  indexed_from_nodes.IndexNames();
  EXPECT_EQ(g.names, indexed_from_nodes.names);
  // top, base, inner, L, F, j, p, the merged model's frame, above
  EXPECT_EQ(g.names.size(), 9u);

  // the pass again on the compiled module, with the reader's index and
  // without it
  auto resolve_again = [&](bool with_index) {
    ir::Module copy = m;
    if (!with_index) {
      copy.frame_graph.names.clear();
      copy.frame_graph.names_complete = false;
    }
    DiagnosticEngine diags;
    passes::PassContext ctx{copy, diags, r.compilation().sources};
    EXPECT_TRUE(passes::CreateResolveFramesPass()->Run(ctx));
    return copy;
  };
  const ir::Module indexed = resolve_again(true), unindexed = resolve_again(false);
  auto same = [](const Transform& a, const Transform& b) { return a.R == b.R && a.p == b.p; };
  ASSERT_EQ(indexed.frames.size(), unindexed.frames.size());
  for (size_t i = 0; i < indexed.frames.size(); ++i) {
    EXPECT_EQ(indexed.frames[i].body.id, unindexed.frames[i].body.id);
    EXPECT_TRUE(same(indexed.frames[i].X_BF, unindexed.frames[i].X_BF)) << i;
  }
  for (size_t i = 0; i < indexed.geometries.size(); ++i) {
    EXPECT_TRUE(same(indexed.geometries[i].X_BG, unindexed.geometries[i].X_BG)) << i;
  }
  for (size_t i = 1; i < indexed.bodies.size(); ++i) {
    ASSERT_TRUE(indexed.bodies[i].default_pose && unindexed.bodies[i].default_pose);
    EXPECT_TRUE(same(*indexed.bodies[i].default_pose, *unindexed.bodies[i].default_pose)) << i;
  }
  const ir::Joint& j = JointNamed(indexed, "j");
  const ir::Joint& j_unindexed = JointNamed(unindexed, "j");
  EXPECT_TRUE(same(j.X_PF, j_unindexed.X_PF));
  EXPECT_TRUE(same(j.X_CM, j_unindexed.X_CM));
  EXPECT_EQ(j.axis, j_unindexed.axis);
  // and both as the compile left them
  EXPECT_TRUE(same(j.X_PF, JointNamed(m, "j").X_PF));
  EXPECT_NEAR(BodyNamed(indexed, "top", "p").default_pose->p.z(),
              BodyNamed(m, "top", "p").default_pose->p.z(), 0);
}

// Before SDFormat 1.7 a joint could share its child link's name: the reader
// renames the joint NAME_joint, as libsdformat does, and indexes it so; the
// link keeps the name, and the joint's child is the link. From 1.7 on the
// same file is an error, as libsdformat 12 makes it.
TEST(ResolveFrames, OldFilesRenameAJointNamedAsItsLink) {  // SDF-001, SDF-011
  SdfCompileResult r("<model name='top'><include><uri>old.sdf</uri></include></model>",
                     {{"old.sdf", R"(<?xml version='1.0'?><sdf version='1.6'>
  <model name='old'>
    <link name='base'/>
    <link name='arm'><pose>0 0 1 0 0 0</pose></link>
    <joint name='arm' type='revolute'><parent>base</parent><child>arm</child>
      <axis><xyz>0 0 1</xyz></axis></joint>
  </model></sdf>)"}});
  ASSERT_TRUE(r.ok()) << r.Messages();
  r.ExpectDiagnostic(DiagKind::RenamedDuplicate, "this joint is renamed 'arm_joint'");
  const ir::Module& m = r.compilation().module;
  const ir::FrameGraph& g = m.frame_graph;
  auto indexed = [&](std::string_view name) -> const ir::FrameNode* {
    const Symbol symbol = m.symbols.Find(name);
    const ir::FrameNode* found = nullptr;
    g.names.ForEach([&](uint32_t, Symbol key, FrameNodeId id) {
      if (key == symbol && g[id].name == symbol) found = &g[id];
    });
    return found;
  };
  ASSERT_NE(indexed("arm"), nullptr);
  EXPECT_EQ(indexed("arm")->kind, ir::FrameNodeKind::Link);
  ASSERT_NE(indexed("arm_joint"), nullptr);
  EXPECT_EQ(indexed("arm_joint")->kind, ir::FrameNodeKind::Joint);
  const ir::Joint& joint = JointNamed(m, "arm_joint");
  EXPECT_EQ(m.Text(m[joint.child.id].name), "arm");
  EXPECT_NEAR(BodyNamed(m, "top::old", "arm").default_pose->p.z(), 1, kTol);

  SdfCompileResult v17("<model name='top'><include><uri>old17.sdf</uri></include></model>",
                       {{"old17.sdf", R"(<?xml version='1.0'?><sdf version='1.7'>
  <model name='old'>
    <link name='base'/>
    <link name='arm'/>
    <joint name='arm' type='revolute'><parent>base</parent><child>arm</child>
      <axis><xyz>0 0 1</xyz></axis></joint>
  </model></sdf>)"}});
  EXPECT_FALSE(v17.ok());
  v17.ExpectDiagnostic(DiagKind::DuplicateName, "the name 'arm' is already used");
}

// libsdformat loads a model's links before its frames, so in a file older
// than SDFormat 1.7 a <frame> that takes a link's name first is the one
// renamed (NAME_frame), wherever it stands; the link keeps the name, its
// geometry stays on it, and a reference to the name means the link.
TEST(ResolveFrames, OldFilesRenameAFrameNamedAsALinkWhereverItStands) {  // SDF-001, SDF-003
  SdfCompileResult r("<model name='top'><include><uri>old.sdf</uri></include></model>",
                     {{"old.sdf", R"(<?xml version='1.0'?><sdf version='1.6'>
  <model name='old'>
    <link name='base'/>
    <frame name='arm'><pose>0 0 5 0 0 0</pose></frame>
    <frame name='tip' attached_to='arm'><pose relative_to='arm'>0 0 0.5 0 0 0</pose></frame>
    <link name='arm'><pose>0 0 1 0 0 0</pose>
      <collision name='c'><pose>0.25 0 0 0 0 0</pose><geometry><sphere><radius>0.1</radius></sphere></geometry></collision>
      <visual name='v'><geometry><sphere><radius>0.1</radius></sphere></geometry></visual>
    </link>
  </model></sdf>)"}});
  ASSERT_TRUE(r.ok()) << r.Messages();
  r.ExpectDiagnostic(DiagKind::RenamedDuplicate, "this frame is renamed 'arm_frame'");
  const ir::Module& m = r.compilation().module;
  const ir::Body& arm = BodyNamed(m, "top::old", "arm");
  EXPECT_NEAR(arm.default_pose->p.z(), 1, kTol);
  ASSERT_EQ(m.geometries.size(), 2u);
  for (const ir::Geometry& geom : m.geometries) {
    EXPECT_EQ(m.Text(m[geom.body.id].name), "arm") << m.Text(geom.name);
  }
  EXPECT_NEAR(m.geometries[0].X_BG.p.x(), 0.25, kTol);
  EXPECT_TRUE(m.geometries[1].X_BG.p.isZero(kTol));
  // 'tip' names the link, not the renamed frame 5 m up
  const ir::Frame& tip = FrameNamed(m, "top::old", "tip");
  EXPECT_EQ(m.Text(m[tip.body.id].name), "arm");
  EXPECT_NEAR(tip.X_BF.p.z(), 0.5, kTol);
  const ir::Frame& renamed = FrameNamed(m, "top::old", "arm_frame");
  EXPECT_EQ(m.Text(m[renamed.body.id].name), "base");  // the model frame's canonical link
  EXPECT_NEAR(renamed.X_BF.p.z(), 5, kTol);
}

// A nested model is read after its parent's joints but keeps a name it
// shares with one of them (SDFormat 1.6): the joint already read is renamed
// after the fact, and the actuator made for it and named after it follows.
TEST(ResolveFrames, AJointRenamedForANestedModelTakesItsActuatorAlong) {  // SDF-001, SDF-020
  SdfCompileResult r("<model name='top'><include><uri>old.sdf</uri></include></model>",
                     {{"old.sdf", R"(<?xml version='1.0'?><sdf version='1.6'>
  <model name='old'>
    <link name='base'/>
    <joint name='sub' type='revolute'><parent>base</parent><child>sub::l</child>
      <axis><xyz>0 0 1</xyz><limit><effort>5</effort></limit></axis></joint>
    <model name='sub'><link name='l'/></model>
  </model></sdf>)"}});
  ASSERT_TRUE(r.ok()) << r.Messages();
  r.ExpectDiagnostic(DiagKind::RenamedDuplicate,
                     "the name 'sub' is also given to a nested model of this model; as "
                     "libsdformat does for files older than SDFormat 1.7, this joint is renamed "
                     "'sub_joint'");
  const ir::Module& m = r.compilation().module;
  const ir::Joint& joint = JointNamed(m, "sub_joint");
  EXPECT_EQ(m.Text(m[joint.child.id].name), "l");
  ASSERT_EQ(m.actuators.size(), 1u);
  EXPECT_EQ(m.Text(m.actuators[0].name), "sub_joint");
  EXPECT_EQ(m.Text(m.actuators[0].joint.name), "sub_joint");
}

// In a world libsdformat renames a <frame> that shares a model's name in
// every version (NAME_frame); the model keeps the name, and a reference to
// it means the model.
TEST(ResolveFrames, AWorldFrameNamedAsAModelIsRenamedInEveryVersion) {  // SDF-001, SDF-003
  SdfCompileResult r(R"(
  <world name='w'>
    <frame name='ground'><pose>0 0 3 0 0 0</pose></frame>
    <model name='ground'><pose>0 2 0 0 0 0</pose><link name='L'/></model>
    <frame name='above' attached_to='ground'><pose relative_to='ground'>0 0 1 0 0 0</pose></frame>
  </world>)");
  ASSERT_TRUE(r.ok()) << r.Messages();
  r.ExpectDiagnostic(DiagKind::RenamedDuplicate,
                     "the name 'ground' is also given to a model of this world; as libsdformat "
                     "does in a world, this frame is renamed 'ground_frame'");
  const ir::Module& m = r.compilation().module;
  const ir::Frame& renamed = FrameNamed(m, "WorldModelInstance", "ground_frame");
  EXPECT_NEAR(renamed.X_BF.p.z(), 3, kTol);
  const ir::Frame& above = FrameNamed(m, "WorldModelInstance", "above");
  EXPECT_EQ(m.Text(m[above.body.id].name), "L");
  EXPECT_NEAR(above.X_BF.p.z(), 1, kTol);
}

TEST(ResolveFrames, CyclesAndDanglingNamesAreLocatedErrors) {  // SDF-004
  SdfCompileResult cycle(R"(
  <model name='m'>
    <link name='L'/>
    <frame name='A'><pose relative_to='B'/></frame>
    <frame name='B'><pose relative_to='A'/></frame>
  </model>)");
  EXPECT_FALSE(cycle.ok());
  EXPECT_NE(cycle.Messages().find("relative_to cycle: m::A -> m::B -> m::A"), std::string::npos)
      << cycle.Messages();
  cycle.ExpectDiagnostic(DiagKind::FrameCycle, "relative_to cycle: m::A -> m::B -> m::A");
  SdfCompileResult dangling(R"(
  <model name='m'>
    <link name='L'><pose relative_to='nowhere'/></link>
  </model>)");
  EXPECT_FALSE(dangling.ok());
  EXPECT_NE(dangling.Messages().find("relative_to name 'nowhere' does not match"),
            std::string::npos);
  dangling.ExpectDiagnostic(DiagKind::UnknownReference, "relative_to name 'nowhere' does not match");
}

TEST(ResolveFrames, DeepChainsNeedNoRecursion) {  // SDF-003: 20,000 frames in one chain
  std::string body = "<model name='m'><link name='L'/><frame name='f0'/>";
  for (int i = 1; i < 20000; ++i) {
    body += fmt::format("<frame name='f{}'><pose relative_to='f{}'>0 0 0.001 0 0 0</pose></frame>",
                        i, i - 1);
  }
  body += "</model>";
  SdfCompileResult r(body);
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_NEAR(FrameNamed(r.compilation().module, "m", "f19999").X_BF.p.z(), 19.999, 1e-9);
}

}  // namespace
}  // namespace mdlc::testing
