// The corpus SDFormat files that libsdformat 12 rejects, one by one: mdlc
// accepts what Drake accepts (model:// through the package map, URDF includes,
// inertia that Drake only warns about) and rejects what is truly broken with a
// located error. Each entry says why, citing the feature that decides it.
// Entries whose why begins "DISAGREE:" are files mdlc accepts although they
// break a rule of the SDFormat specification that Drake's libsdformat enforces
// too: the table records what mdlc does today, the prefix marks it to be fixed.
// Entries whose why begins "GAP:" are files mdlc rejects for a reason Drake
// would not have (an SDFormat feature mdlc lacks). Entries whose why begins
// "TOLERATED:" are files mdlc accepts on purpose, with a warning, although
// libsdformat (and so Drake) rejects them, for a reason that cannot affect
// the plant (a deliberate difference the README lists). The table must cover every
// such file in the manifest, so a new corpus file cannot slip by.
//
// reference_rejects_test.cc runs the table (skipped when ../shared is
// absent). An entry whose error is about the file itself (its name), raised
// before the file is read, has no line: `located` false.
#include "reference_rejects.h"

namespace mdlc::corpus {

// clang-format off
constexpr Expectation kSdf[] = {
  {"drake/examples/multibody/four_bar/dev/four_bar_loop.sdf", false, "malformed XML",
   "COMMON-004: '--' inside a comment is not well-formed XML (libsdformat, on tinyxml2, got past"
   " it and rejected frame 'Wd' attached_to 'world', SDF-004)"},
  {"drake/examples/multibody/four_bar/dev/four_bar_weld.sdf", false, "malformed XML",
   "COMMON-004: '--' inside a comment is not well-formed XML (libsdformat, on tinyxml2, got past"
   " it and rejected frame 'Wd' attached_to 'world', SDF-004)"},
  {"drake/geometry/render_gltf_client/test/example_scene.sdf", false, "does not exist",
   "COMMON-011: the included 006_mustard_bottle.sdf is not in the corpus"},
  {"drake/multibody/parsing/test/sdf_parser_test/include_models.sdf", true, "",
   "SDF-031: libsdformat could not resolve model://simple_robot1 without a path; Drake resolves "
   "model:// through the package map"},
  {"drake/multibody/parsing/test/sdf_parser_test/interface_api_test/arm_merge_include.sdf", true, "",
   "SDF-011, SDF-032: a joint may name the nested model 'flange' as its parent and a merge-"
   "included frame as its child; Drake's interface_api_test loads it, libsdformat 12 could not"},
  {"drake/multibody/parsing/test/sdf_parser_test/interface_api_test/arm_with_gripper_merge_include.sdf", true, "",
   "SDF-031, SDF-032: merge-including arm.urdf goes through the URDF frontend as in Drake; "
   "libsdformat cannot read URDF includes"},
  {"drake/multibody/parsing/test/sdf_parser_test/interface_api_test/top.sdf", true, "",
   "SDF-031: including arm.urdf goes through the URDF frontend as in Drake; libsdformat cannot "
   "read URDF includes"},
  {"drake/multibody/parsing/test/sdf_parser_test/interface_api_test/top_merge_include.sdf", false, "MJCF",
   "GAP: SDF-031 lists SDF and URDF includes only and mdlc does not include MJCF (arm.xml) yet; "
   "Drake's interface_api_test includes it; libsdformat cannot read it"},
  {"drake/multibody/parsing/test/sdf_parser_test/interface_api_test/top_merge_include_in_nested_model.sdf", false, "MJCF",
   "GAP: includes top_merge_include.sdf, whose MJCF include (arm.xml) mdlc does not support yet "
   "(SDF-031); Drake loads it"},
  {"drake/multibody/parsing/test/sdf_parser_test/interface_api_test/top_merge_include_world.sdf", false, "MJCF",
   "GAP: includes top_merge_include.sdf, whose MJCF include (arm.xml) mdlc does not support yet "
   "(SDF-031); Drake loads it"},
  {"drake/multibody/parsing/test/sdf_parser_test/merge_include_models.sdf", true, "",
   "SDF-031, SDF-032: libsdformat could not resolve model://simple_robot1 without a path; Drake "
   "resolves model:// through the package map"},
  {"drake/multibody/parsing/test/sdf_parser_test/two_models.sdf", false, "exactly one top-level <model>",
   "SDF-002: two top-level models in a model file"},
  {"example-robot-data/robots/cassie_description/robots/cassie.sdf", false, "gearbox",
   "SDF-010: gearbox joints are not supported (libsdformat stopped earlier at the foot-reference"
   " links' invalid inertia, a warning for Drake)"},
  {"gazebo_models/camera/model-1_2.sdf", false, "<sdf> root element",
   "COMMON-006: a Gazebo-era file with a <gazebo> root, not <sdf>"},
  {"gazebo_models/create/model-1_2.sdf", false, "<sdf> root element",
   "COMMON-006: a Gazebo-era file with a <gazebo> root, not <sdf>"},
  {"gazebo_models/create/model-1_3.sdf", true, "",
   "COMMON-040: non-physical inertia is a warning and the inertia is replaced, as Drake's own "
   "check does (link 'base')"},
  {"gazebo_models/create/model-1_4.sdf", true, "",
   "COMMON-040: non-physical inertia is a warning and the inertia is replaced, as Drake's own "
   "check does (link 'base')"},
  {"gazebo_models/create/model.sdf", true, "",
   "COMMON-040: non-physical inertia is a warning and the inertia is replaced, as Drake's own "
   "check does (link 'base')"},
  {"gazebo_models/demo_joint_types/model.sdf", false, "axis2",
   "SDF-010: universal joint 'universal_demo' has no <axis2> (libsdformat stopped earlier at "
   "invalid inertia, a warning for Drake)"},
  {"gazebo_models/ground_plane/model-1_2.sdf", false, "<sdf> root element",
   "COMMON-006: a Gazebo-era file with a <gazebo> root, not <sdf>"},
  {"gazebo_models/hokuyo/model-1_2.sdf", false, "<sdf> root element",
   "COMMON-006: a Gazebo-era file with a <gazebo> root, not <sdf>"},
  {"gazebo_models/kinect/model-1_2.sdf", false, "<sdf> root element",
   "COMMON-006: a Gazebo-era file with a <gazebo> root, not <sdf>"},
  {"gazebo_models/mpl_right_forearm/model.sdf", false, "malformed XML",
   "COMMON-004: an XML declaration in the middle of the document is not well-formed XML"},
  {"gazebo_models/pioneer2dx/model-1_2.sdf", false, "<sdf> root element",
   "COMMON-006: a Gazebo-era file with a <gazebo> root, not <sdf>"},
  {"gazebo_models/pr2_gripper/model-1_2.sdf", false, "<sdf> root element",
   "COMMON-006: a Gazebo-era file with a <gazebo> root, not <sdf>"},
  {"gazebo_models/pr2_gripper/model-1_3.sdf", false, "friction coefficient",
   "SDF-041: <mu> is -1; a negative friction coefficient is an error (libsdformat 12 also "
   "rejects the <mu>)"},
  {"gazebo_models/pr2_gripper/model-1_4.sdf", false, "friction coefficient",
   "SDF-041: <mu> is -1; a negative friction coefficient is an error (libsdformat 12 also "
   "rejects the <mu>)"},
  {"gazebo_models/pr2_gripper/model.sdf", false, "friction coefficient",
   "SDF-041: <mu> is -1; a negative friction coefficient is an error (libsdformat 12 also "
   "rejects the <mu>)"},
  {"gazebo_models/ragdoll/model-1_4.sdf", false, "friction coefficient",
   "SDF-041: <mu> is -1; a negative friction coefficient is an error (libsdformat 12 also "
   "rejects the <mu>)"},
  {"gazebo_models/ragdoll/model.sdf", false, "friction coefficient",
   "SDF-041: <mu> is -1; a negative friction coefficient is an error (libsdformat 12 also "
   "rejects the <mu>)"},
  {"gazebo_models/simple_arm/model-1_2.sdf", false, "<sdf> root element",
   "COMMON-006: a Gazebo-era file with a <gazebo> root, not <sdf>"},
  {"gazebo_models/simple_arm/model-1_3.sdf", true, "",
   "COMMON-040: non-physical inertia is a warning and the inertia is replaced, as Drake's own "
   "check does (link 'arm_base')"},
  {"gazebo_models/simple_arm/model-1_4.sdf", true, "",
   "COMMON-040: non-physical inertia is a warning and the inertia is replaced, as Drake's own "
   "check does (link 'arm_base')"},
  {"gazebo_models/simple_arm/model.sdf", true, "",
   "COMMON-040: non-physical inertia is a warning and the inertia is replaced, as Drake's own "
   "check does (link 'arm_base')"},
  {"gazebo_models/simple_arm_gripper/model-1_2.sdf", false, "<sdf> root element",
   "COMMON-006: a Gazebo-era file with a <gazebo> root, not <sdf>"},
  {"gazebo_models/simple_arm_gripper/model-1_3.sdf", true, "",
   "COMMON-040: non-physical inertia is a warning and the inertia is replaced, as Drake's own "
   "check does (link 'arm_base' of the included simple_arm); model://simple_arm resolves to the "
   "Gazebo model folder"},
  {"gazebo_models/simple_arm_gripper/model-1_4.sdf", true, "",
   "COMMON-040: non-physical inertia is a warning and the inertia is replaced, as Drake's own "
   "check does (link 'arm_base' of the included simple_arm); model://simple_arm resolves to the "
   "Gazebo model folder"},
  {"gazebo_models/simple_arm_gripper/model.sdf", true, "",
   "COMMON-040: non-physical inertia is a warning and the inertia is replaced, as Drake's own "
   "check does (link 'arm_base' of the included simple_arm); model://simple_arm resolves to the "
   "Gazebo model folder"},
  {"gazebo_models/simple_gripper/model-1_2.sdf", false, "<sdf> root element",
   "COMMON-006: a Gazebo-era file with a <gazebo> root, not <sdf>"},
  {"gazebo_models/sun/model-1_2.sdf", false, "<sdf> root element",
   "COMMON-006: a Gazebo-era file with a <gazebo> root, not <sdf>"},
  {"gazebo_models/turtlebot/model-1_2.sdf", false, "<sdf> root element",
   "COMMON-006: a Gazebo-era file with a <gazebo> root, not <sdf>"},
  {"gazebo_models/turtlebot/model-1_3.sdf", false, "loops are not supported",
   "URDF-017 (the same plant rule for SDF): link 'rack' has two parent joints, a kinematic loop "
   "(libsdformat stopped earlier at invalid inertia, a warning for Drake)"},
  {"gazebo_models/turtlebot/model-1_4.sdf", false, "loops are not supported",
   "URDF-017 (the same plant rule for SDF): link 'rack' has two parent joints, a kinematic loop "
   "(libsdformat stopped earlier at invalid inertia, a warning for Drake)"},
  {"gazebo_models/turtlebot/model.sdf", false, "loops are not supported",
   "URDF-017 (the same plant rule for SDF): link 'rack' has two parent joints, a kinematic loop "
   "(libsdformat stopped earlier at invalid inertia, a warning for Drake)"},
  {"gazebo_models/utility_cart/model-1_2.sdf", false, "<sdf> root element",
   "COMMON-006: a Gazebo-era file with a <gazebo> root, not <sdf>"},
  {"sdformat/test/integration/cfm_damping_implicit_spring_damper.sdf", false, "reserved",
   "SDF-034: 'world' is a reserved name and may not name a link"},
  {"sdformat/test/integration/custom_elems_attrs.sdf", false, "<axis> must be specified",
   "SDF-014: revolute joint J1 has no <axis> (libsdformat 12 complained first about the custom "
   "attribute mysim:empty_attr, which Drake ignores)"},
  {"sdformat/test/integration/deprecated_sdf_1-0.sdf", false, "<sdf> root element",
   "COMMON-006: a Gazebo-era file with a <gazebo> root, not <sdf>"},
  {"sdformat/test/integration/deprecated_sdf_1-2.sdf", false, "<sdf> root element",
   "COMMON-006: a Gazebo-era file with a <gazebo> root, not <sdf>"},
  {"sdformat/test/integration/fixed_joint_reduction_collision_visual_extension.sdf", true, "",
   "TOLERATED: SDF-041: libsdformat's material rule (Material::Load) wants a non-empty <uri> and "
   "<name> in a <script>, and this one has '__default__' for both; a material script cannot "
   "affect the plant, so mdlc warns (-Wmaterial) and ignores it"},
  {"sdformat/test/integration/include_custom_model.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'robot' is a path relative to the file, where it "
   "does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/integration/include_description.sdf", false, "<sdf> root element",
   "COMMON-006: an element-description file (<element> root), not an SDFormat model"},
  {"sdformat/test/integration/include_invalid_custom_model.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'robot' is a path relative to the file, where it "
   "does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/integration/include_model.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'robot' is a path relative to the file, where it "
   "does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/integration/merge_include_model.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'merge_robot' is a path relative to the file, "
   "where it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/integration/model/cococan/model-100.sdf", false, "unsupported SDFormat version",
   "SDF-001: version '100' is unknown"},
  {"sdformat/test/integration/model/cococan/model-1_2.sdf", true, "",
   "TOLERATED: SDF-041: a Gazebo-classic <script>Gazebo/WoodPallet</script>, with no <uri> or "
   "<name>, which libsdformat's material rule (Material::Load) rejects; a material script "
   "cannot affect the plant, so mdlc warns (-Wmaterial) and ignores it"},
  {"sdformat/test/integration/model/cococan/model-1_4.sdf", true, "",
   "TOLERATED: SDF-041: a Gazebo-classic <script>Gazebo/WoodPallet</script>, with no <uri> or "
   "<name>, which libsdformat's material rule (Material::Load) rejects; a material script "
   "cannot affect the plant, so mdlc warns (-Wmaterial) and ignores it"},
  {"sdformat/test/integration/model/cococan_noversiontag/model-1_2.sdf", true, "",
   "TOLERATED: SDF-041: a Gazebo-classic <script>Gazebo/WoodPallet</script>, with no <uri> or "
   "<name>, which libsdformat's material rule (Material::Load) rejects; a material script "
   "cannot affect the plant, so mdlc warns (-Wmaterial) and ignores it"},
  {"sdformat/test/integration/model/cococan_noversiontag/model-1_4.sdf", true, "",
   "TOLERATED: SDF-041: a Gazebo-classic <script>Gazebo/WoodPallet</script>, with no <uri> or "
   "<name>, which libsdformat's material rule (Material::Load) rejects; a material script "
   "cannot affect the plant, so mdlc warns (-Wmaterial) and ignores it"},
  {"sdformat/test/integration/model/double_pendulum.toml", false, "unknown file extension",
   "COMMON-005: a .toml file is no model format; the error is about the file name, so it has no "
   "line", false},
  {"sdformat/test/integration/model/intermediate_model_with_interface_api_1.sdf", false, "only SDFormat (.sdf) and URDF (.urdf)",
   "SDF-031: an include of a .toml file (libsdformat's test used a custom parser for it)"},
  {"sdformat/test/integration/model/intermediate_model_with_interface_api_2.sdf", false, "only SDFormat (.sdf) and URDF (.urdf)",
   "SDF-031: an include of a .toml file (libsdformat's test used a custom parser for it)"},
  {"sdformat/test/integration/model/merge_robot/model.sdf", false, "not an SDFormat element",
   "SDF-001: <unknown_element> in the SDF namespace is an error; without it mdlc also rejects "
   "the joints naming __model__ (SDF-034), libsdformat's complaint"},
  {"sdformat/test/integration/model/model_actor_light/model.sdf", false, "only one of <model>, <light> or <actor>",
   "SDF-002: the <sdf> root holds one model, light or actor, not two kinds"},
  {"sdformat/test/integration/model/model_for_world_merge_include.sdf", false, "does not exist",
   "COMMON-011: the included test_model's meshes/mesh.dae is not in the corpus (libsdformat "
   "failed earlier on the bare URI 'test_model')"},
  {"sdformat/test/integration/model/multiple_actors/model.sdf", false, "no <model> and no <world>",
   "SDF-002: a file of <actor>s only has no model to load"},
  {"sdformat/test/integration/model/multiple_lights/model.sdf", false, "no <model> and no <world>",
   "SDF-002: a file of <light>s only has no model to load"},
  {"sdformat/test/integration/model/multiple_models/model.sdf", false, "exactly one top-level <model>",
   "SDF-002: several top-level models in a model file"},
  {"sdformat/test/integration/model/nested_include/base/base.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'top_model' is a path relative to the file, where "
   "it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/integration/model/nested_include/test_nested_include.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'base' is a path relative to the file, where it "
   "does not exist (libsdformat's own test finds it through SDF_PATH); mdlc finds base/ but "
   "base.sdf's own includes fail"},
  {"sdformat/test/integration/model/nested_include/top_model/top_model.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'top_camera' is a path relative to the file, where"
   " it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/integration/model/nested_multiple_actors_error/model.sdf", false, "not an SDFormat element of <sdf>",
   "SDF-001, SDF-002: <include> directly under <sdf> is not a model or world"},
  {"sdformat/test/integration/model/nested_multiple_elements_error/model.sdf", false, "not an SDFormat element of <sdf>",
   "SDF-001, SDF-002: <include> directly under <sdf> is not a model or world"},
  {"sdformat/test/integration/model/nested_multiple_lights_error/model.sdf", false, "not an SDFormat element of <sdf>",
   "SDF-001, SDF-002: <include> directly under <sdf> is not a model or world"},
  {"sdformat/test/integration/model/nested_multiple_models_error/model.sdf", false, "not an SDFormat element of <sdf>",
   "SDF-001, SDF-002: <include> directly under <sdf> is not a model or world"},
  {"sdformat/test/integration/model/pr2.sdf", false, "loops are not supported",
   "URDF-017 (the same plant rule for SDF): links with two parent joints, kinematic loops "
   "(libsdformat stopped earlier at its Gazebo-classic <script>s without <uri>, which mdlc only "
   "warns about: SDF-041)"},
  {"sdformat/test/integration/model/sub_nested/model.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'simple_model' is a path relative to the file, "
   "where it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/integration/model/test_nested_model_with_frames/model.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'test_model_with_frames_no_rotations' is a path "
   "relative to the file, where it does not exist (libsdformat's own test finds it through "
   "SDF_PATH)"},
  {"sdformat/test/integration/model/top_nested/model.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'sub_nested' is a path relative to the file, where"
   " it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/integration/model/turtlebot.sdf", false, "unknown package",
   "COMMON-011: model://create and model://kinect name no package on the package path "
   "(libsdformat stopped earlier at invalid inertia, a warning for Drake)"},
  {"sdformat/test/sdf/bad_syntax_double.sdf", false, "must hold a number",
   "COMMON-007: <velocity_decay><linear>bad</linear> is not a number (the element is unsupported, its values still checked)"},
  {"sdformat/test/sdf/bad_syntax_pose.sdf", false, "<pose> must hold 6 numbers",
   "COMMON-007: 'bad' in a pose is no number"},
  {"sdformat/test/sdf/bad_syntax_vector.sdf", false, "<gravity> must hold 3 numbers",
   "COMMON-007: 'bad' in <gravity> is no number"},
  {"sdformat/test/sdf/box_bad_test.world", false, "missing required attribute 'name'",
   "SDF-002: <link> without name (a .world file is SDFormat for mdlc, where Drake refuses the "
   "extension: README, deliberate differences)"},
  {"sdformat/test/sdf/empty_invalid.sdf", false, "<sdf> root element",
   "COMMON-006: the root is <sdfgarbage>"},
  {"sdformat/test/sdf/empty_noversion.sdf", false, "missing required attribute 'version'",
   "SDF-001: <sdf> without version"},
  {"sdformat/test/sdf/include_model_with_plugin.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'test_model_with_plugin' is a path relative to the"
   " file, where it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/sdf/include_pose_1_9.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'box' is a path relative to the file, where it "
   "does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/sdf/include_with_interface_api_frame_semantics.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'double_pendulum.toml' is a path relative to the "
   "file, where it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/sdf/include_with_interface_api_reposture.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the include names a file that exists nowhere "
   "(nonexistent_reposture_test_file.nonce_1)"},
  {"sdformat/test/sdf/includes.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'test_model' is a path relative to the file, where"
   " it does not exist (libsdformat's own test finds it through SDF_PATH); <namespace> in "
   "<include> is also no SDFormat element"},
  {"sdformat/test/sdf/includes_1.5.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'test_model' is a path relative to the file, where"
   " it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/sdf/includes_missing_model.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the include names missing_model, which exists nowhere"},
  {"sdformat/test/sdf/includes_missing_uri.sdf", false, "missing 'uri'",
   "SDF-031: <include> without <uri>"},
  {"sdformat/test/sdf/includes_model_without_sdf.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'box_missing_config' is a path relative to the "
   "file, where it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/sdf/includes_rotations_in_degrees.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'test_model' is a path relative to the file, where"
   " it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/sdf/includes_rotations_in_quaternions.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'test_model' is a path relative to the file, where"
   " it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/sdf/includes_rotations_in_radians.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'test_model' is a path relative to the file, where"
   " it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/sdf/includes_without_top_level.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'model_without_top_level' is a path relative to "
   "the file, where it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/sdf/inertial_invalid.sdf", true, "",
   "COMMON-041: a negative mass is a warning and the inertia is replaced, as Drake's own check "
   "does"},
  {"sdformat/test/sdf/invalid_xml_syntax.sdf", false, "malformed XML",
   "COMMON-004: mismatched tags, not well-formed XML"},
  {"sdformat/test/sdf/joint_axis_xyz_normalization.sdf", false, "must not be zero",
   "SDF-012: a zero <xyz> axis cannot be normalised"},
  {"sdformat/test/sdf/joint_child_model_frame.sdf", false, "names __model__ as its child",
   "SDF-034: a joint may not name __model__ as its child"},
  {"sdformat/test/sdf/joint_child_world.sdf", false, "the world can only be a parent",
   "SDF-011: world may only be a joint's parent, not its child"},
  {"sdformat/test/sdf/joint_invalid_child.sdf", false, "child frame 'invalid'",
   "SDF-004: the joint's child names no frame"},
  {"sdformat/test/sdf/joint_invalid_parent.sdf", false, "parent frame 'invalid'",
   "SDF-004: the joint's parent names no frame"},
  {"sdformat/test/sdf/joint_invalid_parent_same_as_child.sdf", false, "different frames for parent and child",
   "SDF-011: parent and child are the same link"},
  {"sdformat/test/sdf/joint_invalid_resolved_parent_same_as_child.sdf", false, "both fixed to link",
   "SDF-011: parent frame J1 and child L2 resolve to the same link"},
  {"sdformat/test/sdf/joint_invalid_self_child.sdf", false, "attached to itself",
   "SDF-004: the joint names itself as child, an attached_to cycle"},
  {"sdformat/test/sdf/joint_invalid_self_parent.sdf", false, "both fixed to link",
   "SDF-011: the joint names itself as parent, which resolves to its own child link"},
  {"sdformat/test/sdf/joint_nested_parent_child.sdf", false, "M1::__model__",
   "SDF-034: a joint may not name a nested model's __model__ as parent or child"},
  {"sdformat/test/sdf/joint_parent_model_frame.sdf", false, "names __model__ as its parent",
   "SDF-034: a joint may not name __model__ as its parent"},
  {"sdformat/test/sdf/link_duplicate_sibling_collisions.sdf", false, "already used",
   "COMMON-023: two collisions named 'collision' in one link"},
  {"sdformat/test/sdf/link_duplicate_sibling_visuals.sdf", false, "already used",
   "COMMON-023: two visuals named 'visual' in one link"},
  {"sdformat/test/sdf/material_invalid.sdf", false, "color",
   "SDF-041: material colors are 3 or 4 values in [0, 1]; checked even on a visual without geometry"},
  {"sdformat/test/sdf/material_normal_map_missing.sdf", false, "normal map",
   "SDFormat material rule: a normal_map shader type needs a <normal_map>"},
  {"sdformat/test/sdf/material_script_no_uri.sdf", true, "",
   "TOLERATED: SDF-041: a <script> without <uri>, which libsdformat's material rule "
   "(Material::Load) rejects; a material script cannot affect the plant, so mdlc warns "
   "(-Wmaterial) and ignores it"},
  {"sdformat/test/sdf/merge_include_with_interface_api_frame_semantics.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'double_pendulum.toml' is a path relative to the "
   "file, where it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/sdf/merge_include_with_interface_api_reposture.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the include names a file that exists nowhere "
   "(nonexistent_reposture_test_file.nonce_1)"},
  {"sdformat/test/sdf/model_duplicate_joints.sdf", false, "already used",
   "COMMON-023: two joints named 'joint'"},
  {"sdformat/test/sdf/model_duplicate_links.sdf", false, "already used",
   "COMMON-023: two links named 'link'"},
  {"sdformat/test/sdf/model_frame_invalid_attached_to.sdf", false, "attached_to name 'A'",
   "SDF-004: frame F3 is attached to an undefined frame"},
  {"sdformat/test/sdf/model_frame_invalid_attached_to_cycle.sdf", false, "attached_to cycle",
   "SDF-004: attached_to cycle F1 -> F2 -> F1"},
  {"sdformat/test/sdf/model_include_with_interface_api.sdf", false, "not an SDFormat element of <include>",
   "SDF-001: <extra> in <include> (libsdformat's test used a custom parser for the .toml "
   "include, which is missing too)"},
  {"sdformat/test/sdf/model_invalid_canonical_link.sdf", false, "canonical_link 'link3'",
   "SDF-005: canonical_link names no link"},
  {"sdformat/test/sdf/model_invalid_frame_only.sdf", false, "at least one link",
   "SDF-005: a model of frames only has no canonical link"},
  {"sdformat/test/sdf/model_invalid_frame_relative_to.sdf", false, "relative_to name 'A'",
   "SDF-004: relative_to names no frame; a frame relative to itself is a cycle"},
  {"sdformat/test/sdf/model_invalid_frame_relative_to_cycle.sdf", false, "relative_to cycle",
   "SDF-004: relative_to cycle F1 -> F2 -> F1"},
  {"sdformat/test/sdf/model_invalid_joint_relative_to.sdf", false, "graph cycle",
   "SDF-004: joint pose relative_to itself is a cycle; relative_to 'A' names no frame"},
  {"sdformat/test/sdf/model_invalid_link_relative_to.sdf", false, "relative_to name 'A'",
   "SDF-004: link pose relative_to names no frame; a link relative to itself is a cycle"},
  {"sdformat/test/sdf/model_invalid_placement_frame.sdf", false, "placement_frame 'link3'",
   "SDF-005: placement_frame names no frame"},
  {"sdformat/test/sdf/model_invalid_reserved_names.sdf", false, "reserved",
   "SDF-034: world, __link__, __frame__, __joint__, ... are reserved names"},
  {"sdformat/test/sdf/model_invalid_root_reference.sdf", false, "__root__",
   "SDF-004, SDF-034: __root__ is no frame a model may refer to"},
  {"sdformat/test/sdf/model_invalid_top_level_frame.sdf", false, "top-level model",
   "SDF-003: the pose of a top-level model cannot be relative_to anything"},
  {"sdformat/test/sdf/model_without_links.sdf", false, "at least one link",
   "SDF-005: a model without links has no canonical link"},
  {"sdformat/test/sdf/nested_multiple_elements_error_world.sdf", false, "malformed XML",
   "COMMON-004: a stray </sdf> after the root element, not well-formed XML"},
  {"sdformat/test/sdf/nested_without_links_invalid.sdf", false, "at least one link",
   "SDF-005: nested model without links has no canonical link"},
  {"sdformat/test/sdf/placement_frame.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'test_model_with_frames' is a path relative to the"
   " file, where it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/sdf/placement_frame_missing_pose.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'test_model_with_frames' is a path relative to the"
   " file, where it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/sdf/resolve_uris.sdf", false, "unsupported scheme",
   "COMMON-010: shapes.sdf (which it includes) names an https:// mesh; libsdformat 12 could not find shapes.sdf"},
  {"sdformat/test/sdf/root_duplicate_models.sdf", false, "exactly one top-level <model>",
   "SDF-002: two top-level models (both named robot1)"},
  {"sdformat/test/sdf/root_multiple_models.sdf", false, "exactly one top-level <model>",
   "SDF-002: several top-level models in a model file"},
  {"sdformat/test/sdf/sensors.sdf", true, "",
   "SDF-043/044: libsdformat 12 rejects a sensor type newer than itself; mdlc, like Drake's newer libsdformat, reads the cameras and warns on the other sensors"},
  {"sdformat/test/sdf/stricter_semantics_desc.sdf", false, "<sdf> root element",
   "COMMON-006: an element-description file (<element> root), not an SDFormat model"},
  {"sdformat/test/sdf/whitespace.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'test_model' is a path relative to the file, where"
   " it does not exist (libsdformat's own test finds it through SDF_PATH)"},
  {"sdformat/test/sdf/world_duplicate.sdf", false, "only one <world>",
   "SDF-002: two worlds in one file"},
  {"sdformat/test/sdf/world_frame_invalid_attached_to.sdf", false, "attached_to name 'A'",
   "SDF-004, SDF-035: a world frame attached to an undefined frame; another attached to itself"},
  {"sdformat/test/sdf/world_frame_invalid_attached_to_scope.sdf", false, "M2::M1::L1",
   "SDF-034: scoped names go only downward from the frame's own scope"},
  {"sdformat/test/sdf/world_frame_invalid_relative_to.sdf", false, "relative_to name 'A'",
   "SDF-004, SDF-035: a world model placed relative_to an undefined frame"},
  {"sdformat/test/sdf/world_include_with_interface_api.sdf", false, "not an SDFormat element of <include>",
   "SDF-001: <extra> in <include> (libsdformat's test used a custom parser for the .toml "
   "include, which is missing too)"},
  {"sdformat/test/sdf/world_invalid_root_reference.sdf", false, "does not exist",
   "SDF-031, COMMON-011: the bare include URI 'test_model_with_frames' is a path relative to the"
   " file, where it does not exist (libsdformat's own test finds it through SDF_PATH); without "
   "it mdlc rejects every __root__ reference (SDF-004), libsdformat's complaint"},
  {"sdformat/test/sdf/world_merge_include.sdf", false, "merge-include is not allowed",
   "SDF-032: merge-include directly in a <world> is an error"},
  {"sdformat/test/sdf/world_noname.sdf", false, "missing required attribute 'name'",
   "SDF-002: <world> without name"},
};
// clang-format on

std::span<const Expectation> SdfReferenceRejects() { return kSdf; }

}  // namespace mdlc::corpus
