// The corpus MJCF files that MuJoCo 3.3.8 (the reference MJCF compiler; the
// MuJoCo oracle test compares every file it loads) rejects, one by one: mdlc
// rejects what is truly broken with a located error (`file:line:col: error:`
// containing a keyword), and accepts, with the reason recorded, what Drake
// accepts or what is no model of its own (MuJoCo 2 models that MuJoCo 3 no
// longer reads, fragments meant to be included). Each entry cites the feature
// that decides it. Entries whose why begins "DISAGREE:" are files mdlc accepts
// although MuJoCo 3 rejects them for a reason mdlc should share: the table
// records what mdlc does today, the prefix marks it to be fixed. Entries whose
// why begins "TOLERATED:" are files mdlc accepts on purpose, with a warning,
// although MuJoCo 3 rejects them, for a reason that cannot affect the plant
// (a deliberate difference the README lists).
//
// The table must cover exactly the corpus MJCF files MuJoCo 3.3.8 rejects:
// ReferenceRejectsTable.MjcfCoversExactlyWhatMujoco338Rejects runs MuJoCo
// 3.3.8 (tests/oracle/mujoco_js/mujoco_dump.mjs under Node.js) over every
// mjcf row of the manifest, so a new corpus file cannot slip by. Each entry
// also records whether MuJoCo 2.2.2 loads the file, checked against the
// manifest's loads_in_reference column (a MuJoCo 2.2.2 verdict).
//
// Together with the oracle test this covers MJCF-092: every dm_control suite
// model and every Menagerie model of the corpus that MuJoCo 3.3.8 loads
// compiles (the STL meshes and sizes-from-meshes Drake fails on included),
// and agrees with MuJoCo; none of them is listed here.
//
// reference_rejects_test.cc runs the table (skipped when ../shared is
// absent); the coverage check is skipped without Node.js or the mujoco-js
// package (`npm ci` in tests/oracle/mujoco_js, which tools/setup.sh test
// runs).
#include "reference_rejects.h"

namespace mdlc::corpus {

// clang-format off
constexpr MjcfExpectation kMjcf[] = {
  {"drake/multibody/parsing/dm_control/suite/acrobot.xml", false, false, "cannot read the included file",
   "MJCF-001: ./common/visual.xml (and the other common/ includes) are not beside this copy of the "
   "dm_control acrobot; MuJoCo 3.3.8 cannot open them either"},
  {"drake/multibody/parsing/test/mujoco_parser_test/pendulum_geom.xml", false, true, "",
   "MJCF-001/008: a fragment (a bare <geom> under <mujoco>) that Drake's test includes inside a "
   "body; MuJoCo's schema rejects the geom at top level, mdlc warns that it is not a top-level "
   "MJCF element and compiles an empty model"},
  {"drake/multibody/parsing/test/mujoco_parser_test/scene.xml", false, false, "already included",
   "MJCF-001: pendulum.xml is included twice (directly and through nested.xml); MuJoCo includes "
   "each file at most once"},
  {"mujoco_menagerie/leap_hand/left_hand.xml", false, true, "",
   "TOLERATED: MJCF-006/050, COMMON-011: the mesh file assets/palm_left.obj is not in the corpus "
   "(only palm_right.obj is), which MuJoCo cannot open; only the visual-only geom palm_visual "
   "(contype=conaffinity=0) of a body with an <inertial> uses it, so the plant never reads it: "
   "mdlc warns (-Wmissing-asset) and keeps the geom"},
  {"mujoco_menagerie/leap_hand/scene_left.xml", false, true, "",
   "TOLERATED: MJCF-006/050, COMMON-011: includes left_hand.xml, whose mesh file "
   "assets/palm_left.obj is not in the corpus; only a visual-only geom uses it, so mdlc warns "
   "(-Wmissing-asset)"},
  {"mujoco_menagerie/shadow_hand/keyframes.xml", false, false, "qpos",
   "MJCF-008: a fragment of keyframes meant to be included after a hand; alone, its keys give 24 "
   "qpos values for a model with none"},
  {"mujoco/model/adhesion/active_adhesion.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/composite/cloth.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/composite/grid2pin.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/composite/loop.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/composite/particle.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/composite/rope.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/composite/softbox.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/flag/flag.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/hammock/hammock.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
};
// clang-format on

std::span<const MjcfExpectation> MjcfReferenceRejects() { return kMjcf; }

}  // namespace mdlc::corpus
