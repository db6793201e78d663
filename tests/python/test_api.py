"""The Python module mdlc (issue 13): compile from paths and text, the model's
objects as numpy arrays, evaluation at q, and diagnostics as exceptions.

Run by ctest (python/api) with the built package on PYTHONPATH; models come
from examples/ and from text written here, so nothing outside the repository
is needed.
"""

import json
import math
import os
import pathlib
import tempfile
import unittest

import numpy as np

import mdlc

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"

PENDULUM = """<?xml version="1.0"?>
<robot name="pendulum">
  <link name="world"/>
  <link name="arm">
    <inertial><origin xyz="0 0 -0.5"/><mass value="2"/>
      <inertia ixx="0.1" iyy="0.1" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.1 0.1 1"/></geometry></collision>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="world"/><child link="arm"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="10" velocity="5"/>
  </joint>
</robot>
"""


class CompileFromPathAndText(unittest.TestCase):
    def test_path_gives_bodies_joints_and_numpy_values(self):
        model = mdlc.compile(str(EXAMPLES / "urdf/double_pendulum.urdf"))
        self.assertEqual(model.bodies[0].name, "world")
        self.assertTrue(model.bodies[0].is_world)
        names = [b.name for b in model.bodies[1:]]
        self.assertEqual(len(names), 3)
        for body in model.bodies:
            self.assertIsInstance(body.com, np.ndarray)
            self.assertEqual(body.com.shape, (3,))
            self.assertEqual(body.inertia.shape, (3, 3))
            np.testing.assert_array_equal(body.inertia, body.inertia.T)
        self.assertEqual(model.num_velocities, 2)
        self.assertEqual({j.type for j in model.joints} & {"revolute"}, {"revolute"})

    def test_pathlike_is_a_path(self):
        model = mdlc.compile(EXAMPLES / "urdf/double_pendulum.urdf")
        self.assertEqual(model.num_positions, 2)

    def test_text_needs_a_format_or_a_name(self):
        with self.assertRaises(ValueError):
            mdlc.compile(PENDULUM)
        by_format = mdlc.compile(PENDULUM, format="urdf")
        by_name = mdlc.compile(PENDULUM, name="pendulum.urdf")
        self.assertEqual(by_format.to_json(), by_name.to_json())

    def test_text_and_file_give_byte_identical_plant_json(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "pendulum.urdf")
            with open(path, "w") as f:
                f.write(PENDULUM)
            from_file = mdlc.compile(path)
            from_text = mdlc.compile(PENDULUM, name=path)
            self.assertEqual(from_file.to_json(), from_text.to_json())

    def test_several_inputs_make_one_plant(self):
        model = mdlc.compile([PENDULUM], format="urdf")
        two = mdlc.compile([str(EXAMPLES / "urdf/double_pendulum.urdf"),
                            str(EXAMPLES / "urdf/scara_arm.urdf")])
        self.assertEqual(len(two.model_instances), 4)
        self.assertGreater(len(two.bodies), len(model.bodies))

    def test_a_non_model_argument_is_a_type_error(self):
        with self.assertRaises(TypeError):
            mdlc.compile(42)


class EvaluateThePlant(unittest.TestCase):
    def setUp(self):
        self.model = mdlc.compile(PENDULUM, format="urdf")

    def test_mass_matrix_is_the_pendulum_inertia_about_the_axis(self):
        M = self.model.mass_matrix()
        self.assertEqual(M.shape, (1, 1))
        # iyy about the center of mass plus m d^2 (parallel axes): 0.1 + 2 * 0.5^2
        self.assertAlmostEqual(M[0, 0], 0.1 + 2 * 0.25, places=12)
        np.testing.assert_array_equal(M, self.model.mass_matrix(self.model.default_positions()))

    def test_body_poses_follow_q(self):
        arm = next(b for b in self.model.bodies if b.name == "arm")
        at_zero = self.model.body_poses()[arm.index]
        turned = self.model.body_poses(np.array([math.pi / 2]))[arm.index]
        np.testing.assert_allclose(at_zero.R, np.eye(3), atol=0)
        np.testing.assert_allclose(turned.R @ np.array([1.0, 0, 0]), [0, 0, -1], atol=1e-15)
        self.assertEqual(turned.matrix.shape, (4, 4))
        np.testing.assert_array_equal(turned.matrix[:3, :3], turned.R)

    def test_poses_agree_with_plant_json_at_the_same_q(self):
        q = np.array([0.3])
        dump = json.loads(self.model.to_json(q))
        poses = self.model.body_poses(q)
        for entry in dump["bodies"]:
            body = next(b for b in self.model.bodies if b.name == entry["name"])
            self.assertEqual(list(poses[body.index].p), entry["X_WB"]["p"])
            self.assertEqual(list(poses[body.index].q), entry["X_WB"]["q"])

    def test_wrong_q_size_is_a_value_error(self):
        with self.assertRaises(ValueError):
            self.model.mass_matrix(np.zeros(3))

    def test_joint_positions_set_the_default_configuration(self):
        model = mdlc.compile(PENDULUM, format="urdf", joint_positions={"shoulder": 0.25})
        np.testing.assert_array_equal(model.default_positions(), [0.25])
        with self.assertRaises(mdlc.CompileError):
            mdlc.compile(PENDULUM, format="urdf", joint_positions={"elbow": 1})

    def test_geometry_and_joint_details(self):
        (geometry,) = self.model.geometries
        self.assertEqual(geometry.shape, "box")
        np.testing.assert_array_equal(geometry.shape_parameters["size"], [0.1, 0.1, 1])
        self.assertEqual(geometry.roles, ["proximity"])
        self.assertEqual(geometry.body, "pendulum::arm")
        (joint,) = self.model.joints
        self.assertEqual((joint.parent, joint.child), ("world", "pendulum::arm"))
        np.testing.assert_array_equal(joint.axis, [0, 1, 0])
        np.testing.assert_array_equal(joint.lower, [-2])


WELDED_IN_A_GROUP = """<?xml version="1.0"?>
<robot name="r" xmlns:drake="http://drake.mit.edu">
  <link name="base"><collision><geometry><box size="1 1 1"/></geometry></collision></link>
  <link name="arm"><collision><geometry><box size="1 1 1"/></geometry></collision></link>
  <link name="hand"><collision><geometry><box size="1 1 1"/></geometry></collision></link>
  <link name="tool"><collision><geometry><box size="1 1 1"/></geometry></collision></link>
  <link name="ghost"/>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
  <joint name="wrist" type="fixed"><parent link="arm"/><child link="hand"/></joint>
  <joint name="mount" type="fixed"><parent link="hand"/><child link="ghost"/></joint>
  <joint name="slide" type="prismatic">
    <parent link="hand"/><child link="tool"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="1" effort="1" velocity="1"/>
  </joint>
  <drake:collision_filter_group name="ends">
    <drake:member link="base"/><drake:member link="tool"/>
    <drake:ignored_collision_filter_group name="ends"/>
  </drake:collision_filter_group>
</robot>
"""


class CollisionFilters(unittest.TestCase):  # issue 16, COMMON-051, COMMON-054
    def test_filtered_pairs_by_name_and_by_index_agree_with_plant_json(self):
        model = mdlc.compile(WELDED_IN_A_GROUP, format="urdf")
        pairs = model.collision_filters()
        listed = [tuple(p) for p in json.loads(model.to_json())["collision_filters"]]
        self.assertEqual(pairs, listed)
        # adjacent (base-arm, hand-tool), welded (arm-hand), the group (base-tool)
        self.assertEqual(pairs, [("r::arm", "r::base"), ("r::arm", "r::hand"),
                                 ("r::base", "r::tool"), ("r::hand", "r::tool")])
        named = {frozenset(p) for p in pairs}
        for a in model.bodies:
            for b in model.bodies:
                self.assertEqual(
                    model.collision_filtered(a.index, b.index),
                    frozenset((a.scoped_name, b.scoped_name)) in named and a.index != b.index,
                    (a.scoped_name, b.scoped_name))

    def test_a_body_index_out_of_range_is_an_index_error(self):
        model = mdlc.compile(WELDED_IN_A_GROUP, format="urdf")
        with self.assertRaises(IndexError):
            model.collision_filtered(0, len(model.bodies))


class Diagnostics(unittest.TestCase):
    def test_errors_raise_with_every_located_diagnostic(self):
        broken = PENDULUM.replace('<child link="arm"/>', '<child link="hand"/>')
        with self.assertRaises(mdlc.CompileError) as caught:
            mdlc.compile(broken, name="broken.urdf")
        errors = [d for d in caught.exception.diagnostics if d.severity == "error"]
        self.assertTrue(errors)
        first = errors[0]
        self.assertEqual(first.file, "broken.urdf")
        self.assertEqual(first.line, 10)  # the <child> naming it
        self.assertGreater(first.column, 0)
        self.assertIn("hand", first.message)
        self.assertTrue(first.group)
        self.assertIn("broken.urdf:10:", str(caught.exception))

    def test_warnings_are_returned_or_raised_when_strict(self):
        noisy = PENDULUM.replace("<link name=\"arm\">", "<link name=\"arm\"><bogus/>")
        model = mdlc.compile(noisy, format="urdf")
        warnings = [d for d in model.diagnostics if d.severity == "warning"]
        self.assertEqual(len(warnings), 1)
        self.assertIn("bogus", warnings[0].message)
        group = warnings[0].group
        with self.assertRaises(mdlc.CompileError) as caught:
            mdlc.compile(noisy, format="urdf", strict=True)
        self.assertEqual(caught.exception.diagnostics[0].severity, "error")
        quiet = mdlc.compile(noisy, format="urdf", disabled_warnings=[group])
        self.assertEqual(list(quiet.diagnostics), [])
        with self.assertRaises(mdlc.CompileError):
            mdlc.compile(noisy, format="urdf", error_warnings=[group])

    def test_limits_bound_the_input(self):  # issue 16
        with self.assertRaises(mdlc.CompileError) as caught:
            mdlc.compile(PENDULUM, name="p.urdf", limits={"depth": 2})
        error = caught.exception.diagnostics[0]
        self.assertEqual(error.severity, "error")
        self.assertEqual(error.group, "limits")
        self.assertIn("over the depth limit of 2", error.message)
        self.assertEqual(error.line, PENDULUM.splitlines().index("  <link name=\"arm\">") + 2)
        deep_enough = mdlc.compile(PENDULUM, name="p.urdf", limits={"depth": 5, "file_size": "1K"})
        self.assertEqual(deep_enough.num_positions, 1)
        with self.assertRaises(ValueError):
            mdlc.compile(PENDULUM, name="p.urdf", limits={"dept": 4})
        with self.assertRaises(ValueError):
            mdlc.compile(PENDULUM, name="p.urdf", limits={"depth": "deep"})

    def test_mesh_reader_choices_give_the_same_plant(self):  # issue 16
        model = ROOT / "tests/models/mjcf/oracle/mesh_geoms.xml"
        child = mdlc.compile(model)  # mesh files read in a child process
        here = mdlc.compile(model, mesh_reader="in-process")
        self.assertEqual(child.to_json(), here.to_json())
        self.assertGreater(child.num_positions, 0)
        with self.assertRaises(ValueError):
            mdlc.compile(model, mesh_reader="thread")

    def test_a_crashing_mesh_reader_is_a_compile_error(self):  # issue 16
        with tempfile.TemporaryDirectory() as folder:
            reader = pathlib.Path(folder) / "reader.sh"
            reader.write_text("#!/bin/sh\nkill -SEGV $$\n")
            reader.chmod(0o755)
            os.environ["MDLC_MESH_READER"] = str(reader)
            try:
                with self.assertRaises(mdlc.CompileError) as caught:
                    mdlc.compile(ROOT / "tests/models/mjcf/oracle/mesh_geoms.xml")
            finally:
                del os.environ["MDLC_MESH_READER"]
        error = caught.exception.diagnostics[0]
        self.assertEqual(error.kind, "bad-mesh")
        self.assertIn("the mesh reader crashed (signal 11, SIGSEGV)", error.message)
        self.assertTrue(error.file.endswith("mesh_geoms.xml"))

    def test_missing_file_is_a_file_not_found_error(self):  # issue 58
        # as open() reports it: errno, strerror and the file name, not a model error
        for path in ("no/such/robot.urdf", pathlib.Path("no/such/robot.sdf")):
            with self.assertRaises(FileNotFoundError) as caught:
                mdlc.compile(path)
            self.assertEqual(caught.exception.filename, os.fspath(path))
            self.assertNotIsInstance(caught.exception, mdlc.CompileError)
        with self.assertRaises(FileNotFoundError):
            mdlc.compile([str(EXAMPLES / "urdf/scara_arm.urdf"), "missing.urdf"])


class Packages(unittest.TestCase):
    def test_package_paths_resolve_a_directives_scene(self):
        scene = EXAMPLES / "directives/handover_cell.dmd.yaml"
        with self.assertRaises(mdlc.CompileError):
            mdlc.compile(scene)
        model = mdlc.compile(scene, package_paths=[EXAMPLES], strict=True)
        self.assertGreater(len(model.model_instances), 3)
        by_map = mdlc.compile(scene, packages={"mdlc_examples": str(EXAMPLES)})
        self.assertEqual(model.to_json(), by_map.to_json())


class ResolveUri(unittest.TestCase):  # COMMON-010, COMMON-011
    def test_a_package_uri_resolves_as_a_models_mesh_does(self):
        mesh = next((EXAMPLES / "urdf/meshes").iterdir())
        uri = f"package://mdlc_examples/urdf/meshes/{mesh.name}"
        path = mdlc.resolve_uri(uri, package_paths=[EXAMPLES])
        self.assertEqual(pathlib.Path(path).resolve(), mesh.resolve())
        by_map = mdlc.resolve_uri(uri, packages={"mdlc_examples": str(EXAMPLES)})
        self.assertEqual(pathlib.Path(by_map).resolve(), mesh.resolve())
        relative = mdlc.resolve_uri(f"meshes/{mesh.name}", relative_to=EXAMPLES / "urdf")
        self.assertEqual(pathlib.Path(relative).resolve(), mesh.resolve())

    def test_what_names_no_file_raises_with_the_reason(self):
        with self.assertRaises(FileNotFoundError) as caught:
            mdlc.resolve_uri("package://no_such_package/a.obj", package_paths=[EXAMPLES])
        self.assertIn("unknown package 'no_such_package'", str(caught.exception))
        self.assertIn(f"searched '{EXAMPLES}'", str(caught.exception))
        with self.assertRaises(FileNotFoundError) as caught:
            mdlc.resolve_uri("package://mdlc_examples/missing.obj", package_paths=[EXAMPLES])
        self.assertIn("which does not exist", str(caught.exception))


TWO_ARMS = PENDULUM.replace('<robot name="pendulum">', '<robot name="left">')


class FirstHour(unittest.TestCase):  # issue 58: what a new user types at the prompt
    def test_every_entity_list_is_indexed_by_name(self):
        model = mdlc.compile(str(EXAMPLES / "urdf/scara_arm.urdf"))
        for entities in (model.bodies, model.joints, model.frames, model.geometries,
                         model.actuators):
            self.assertIsInstance(entities, mdlc.EntityList)
            names, scoped_names = [e.name for e in entities], entities.names()
            for entity, scoped in zip(entities, scoped_names):
                if scoped_names.count(scoped) == 1:
                    self.assertEqual(repr(entities[scoped]), repr(entity))
                if names.count(entity.name) == 1 and entity.name not in scoped_names:
                    self.assertEqual(repr(entities[entity.name]), repr(entity))
        forearm = model.bodies["forearm"]
        self.assertEqual(forearm.scoped_name, "scara_arm::forearm")
        self.assertIs(type(model.bodies["scara_arm::forearm"]), mdlc.Body)
        self.assertEqual(model.bodies["scara_arm::forearm"].index, forearm.index)
        self.assertEqual(model.joints["elbow"].child, "scara_arm::forearm")
        self.assertIn("elbow", model.joints)
        self.assertNotIn("knee", model.joints)
        self.assertIsNone(model.joints.get("knee"))
        self.assertEqual(model.bodies[0].name, "world")  # positions still index
        self.assertIsInstance(model.bodies[1:], mdlc.EntityList)
        with self.assertRaises(KeyError) as caught:
            model.joints["elbw"]
        self.assertIn("did you mean 'elbow'", str(caught.exception))
        with self.assertRaises(KeyError) as caught:
            model.constraints["anything"]
        self.assertIn("no constraint named 'anything'", str(caught.exception))

    def test_a_name_two_instances_share_needs_its_scope(self):
        model = mdlc.compile([PENDULUM, TWO_ARMS], format="urdf")
        with self.assertRaises(KeyError) as caught:
            model.bodies["arm"]
        self.assertIn("pendulum::arm", str(caught.exception))
        self.assertIn("left::arm", str(caught.exception))
        self.assertEqual(model.bodies["left::arm"].model_instance, "left")

    def test_reprs_say_what_tells_entities_apart(self):
        model = mdlc.compile(str(EXAMPLES / "urdf/scara_arm.urdf"))
        self.assertRegex(repr(model), r"^<mdlc.Model 'scara_arm': \d+ bodies, \d+ joints, "
                                      r"\d+ geometries, nq=\d+ nv=\d+>$")
        body = model.bodies["forearm"]
        self.assertEqual(repr(body), f"<mdlc.Body 'scara_arm::forearm' index={body.index} "
                                     f"mass={body.mass:.6g} joint 'scara_arm::elbow'>")
        # joints are in the plant's order, not q's: each says where its q is
        for joint in model.joints:
            where = f"q[{joint.q_start}]" if joint.nq == 1 else \
                f"q[{joint.q_start}:{joint.q_start + joint.nq}]" if joint.nq else "no q"
            self.assertEqual(repr(joint), f"<mdlc.Joint '{joint.scoped_name}' {joint.type} "
                                          f"{where} {joint.parent} -> {joint.child}>")
        self.assertIn("on 'scara_arm::", repr(model.geometries[0]))
        self.assertIn(" q=[", repr(model.body_poses()[1]))

    def test_the_namespace_holds_the_api_only(self):
        public = {name for name in dir(mdlc) if not name.startswith("_")}
        self.assertNotIn("os", public)
        self.assertEqual(public, set(mdlc.__all__))

    def test_a_zero_quaternion_is_rejected(self):
        model = mdlc.compile(ROOT / "tests/models/mjcf/oracle/free_ball.xml")
        floating = next(j for j in model.joints if j.type == "quaternion_floating")
        q = model.default_positions()
        q[floating.q_start:floating.q_start + 4] = 0
        for evaluate in (model.body_poses, model.mass_matrix, model.to_json):
            with self.assertRaises(ValueError) as caught:
                evaluate(q)
            self.assertIn(f"the quaternion [w, x, y, z] of joint '{floating.scoped_name}', "
                          f"is zero", str(caught.exception))
        # any other length is a rotation, as in Drake
        q[floating.q_start] = 2
        self.assertEqual(len(model.body_poses(q)), len(model.bodies))

    def test_collada_up_axis_is_a_keyword(self):  # issue 55, BEYOND-001
        text = f"""<mujoco model="axes">
  <asset><mesh name="m" file="{ROOT}/tests/models/meshes/box_y_up.dae"/></asset>
  <worldbody><body name="b"><freejoint/><geom type="mesh" mesh="m"/></body></worldbody>
</mujoco>"""
        # the box's center (1.5, 0.25, 1.25), written in Y_UP axes, is (x, z, -y)
        as_written = mdlc.compile(text, format="mjcf")
        np.testing.assert_allclose(as_written.bodies["b"].com, [1.5, 1.25, -0.25], atol=1e-12)
        applied = mdlc.compile(text, format="mjcf", collada_up_axis="apply")
        np.testing.assert_allclose(applied.bodies["b"].com, [1.5, 0.25, 1.25], atol=1e-12)
        with self.assertRaises(ValueError):
            mdlc.compile(text, format="mjcf", collada_up_axis="sideways")


class Version(unittest.TestCase):
    def test_version_is_the_librarys(self):
        self.assertRegex(mdlc.__version__, r"^\d+\.\d+\.\d+$")


if __name__ == "__main__":
    unittest.main()
