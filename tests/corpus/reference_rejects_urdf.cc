// The corpus URDFs that urdfdom rejects, one by one: mdlc accepts what Drake
// accepts (Drake extensions, Drake's laxer rules) and rejects what is truly
// broken with a located error. Each entry says why. Entries whose why begins
// "TOLERATED:" are files mdlc accepts on purpose, with a warning, although
// Drake rejects them, for a reason that cannot affect the plant (a
// deliberate difference the README lists). The table must cover every such
// file in the manifest, so a new corpus file cannot slip by.
//
// reference_rejects_test.cc runs the table (skipped when ../shared is
// absent).
#include "reference_rejects.h"

namespace mdlc::corpus {

// clang-format off
constexpr Expectation kUrdf[] = {
  {"drake/examples/acrobot/Acrobot.urdf", true, "",
   "URDF-003: a joint may name the link 'world' without defining it; urdfdom needs the link"},
  {"drake/multibody/benchmarking/cassie_v2.urdf", true, "",
   "TOLERATED: COMMON-011: its visual meshes (pelvis.obj, ...) are not in the corpus, an error "
   "for Drake; the plant never reads a visual mesh, so mdlc warns (-Wmissing-asset) and keeps "
   "the visuals. urdfdom's complaint (revolute joints without limits) is fine for Drake"},
  {"drake/multibody/benchmarks/acrobot/acrobot.urdf", true, "",
   "URDF-030: an unnamed inline visual material is fine for Drake"},
  {"drake/multibody/benchmarks/kuka_iiwa_robot/kuka_iiwa_robot.urdf", true, "",
   "URDF-013: a revolute joint without <limit> is unbounded in Drake"},
  {"drake/multibody/parsing/test/links_with_visuals_and_collisions.urdf", true, "",
   "URDF-004: an <inertial> without <inertia> has zero moments in Drake"},
  {"drake/multibody/parsing/test/sdf_parser_test/bad.urdf", false, "malformed XML",
   "COMMON-004: the file is not XML at all"},
  {"drake/multibody/parsing/test/sdf_parser_test/interface_api_test/arm.urdf", true, "",
   "URDF-013: revolute joints without <limit> are unbounded in Drake"},
  {"drake/multibody/parsing/test/urdf_parser_test/collision_filter_group_parsing_test.urdf", true, "",
   "URDF-017: several root links become free bodies in Drake; EXT-040 filter groups"},
  {"drake/multibody/parsing/test/urdf_parser_test/conflicting_materials.urdf", false,
   "defined again with different values", "URDF-030: one material name, two different colors"},
  {"drake/multibody/parsing/test/urdf_parser_test/duplicate_materials.urdf", true, "",
   "URDF-030: identical re-definitions of a material are fine for Drake"},
  {"drake/multibody/parsing/test/urdf_parser_test/joint_parsing_test.urdf", true, "",
   "EXT-001: drake:joint types (ball, universal, screw, planar); unbounded revolute joints"},
  {"drake/multibody/parsing/test/urdf_parser_test/joint_parsing_test_missing_screw_thread_pitch.urdf",
   false, "screw_thread_pitch", "EXT-002: a screw joint needs drake:screw_thread_pitch"},
  {"drake/multibody/parsing/test/urdf_parser_test/joint_parsing_test_missing_screw_thread_pitch_attribute.urdf",
   false, "screw_thread_pitch", "EXT-002: drake:screw_thread_pitch needs its value"},
  {"drake/multibody/parsing/test/urdf_parser_test/joint_parsing_test_tag_mismatch_1.urdf", false,
   "standard joint type", "EXT-001: a standard joint type inside <drake:joint>"},
  {"drake/multibody/parsing/test/urdf_parser_test/joint_parsing_test_tag_mismatch_2.urdf", false,
   "custom joint type", "EXT-001: a Drake joint type (ball) inside a plain <joint>"},
  {"drake/multibody/parsing/test/urdf_parser_test/non_conflicting_materials_2.urdf", true, "",
   "URDF-017: several root links become free bodies in Drake"},
  {"drake_models/pr2_description/urdf/pr2_simplified.urdf", true, "",
   "URDF-013: a prismatic joint without <limit> is unbounded in Drake"},
  {"example-robot-data/robots/ur_description/urdf/ur3.urdf", false, "missing required attribute 'name'",
   "COMMON-021: the robot has no name, so the model instance would have none"},
};
// clang-format on

std::span<const Expectation> UrdfReferenceRejects() { return kUrdf; }

}  // namespace mdlc::corpus
