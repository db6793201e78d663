"""Every entity kind the plant holds, in all three of mdlc's full views of a
model: `mdlc compile --emit=ir`, plant-json and the Python model; and the
shapes and roles `mdlc view` draws.

tests/models/every_entity/ holds one of each kind (each joint type, shape,
role, constraint, force element; frames, actuators, cameras, collision
filters). A kind or field one view shows and another leaves out fails here:
that is how the views, kept in step by hand, stay in step. When the plant
gains a kind or a field, add it to the model (the checklists in
ir/entities.h and backend/plant.h) and, where a view names it differently,
to the tables below.

Run by ctest (python/every_entity) with the built package on PYTHONPATH and
the command line in MDLC_BINARY.
"""

import json
import os
import pathlib
import re
import subprocess
import tempfile
import unittest

import numpy as np

import mdlc

ROOT = pathlib.Path(__file__).resolve().parents[2]
MODEL_DIR = ROOT / "tests/models/every_entity"
MODEL = MODEL_DIR / "every_entity.dmd.yaml"

# What the model must hold: every kind a reader can give the plant.
# (rpy_floating is a joint type no reader makes.)
JOINT_TYPES = {"weld", "revolute", "prismatic", "ball", "universal", "planar", "screw",
               "curvilinear", "quaternion_floating"}
SHAPES = {"box", "sphere", "cylinder", "capsule", "ellipsoid", "half_space", "mesh", "convex"}
ROLES = {"proximity", "illustration", "perception"}
CONSTRAINTS = {"coupler", "ball", "distance", "weld", "tendon"}
FORCE_ELEMENTS = {"linear_bushing_rpy", "linear_spring_damper", "revolute_spring",
                  "prismatic_spring"}

# plant-json keys the Python object spells differently, per list
PYTHON_NAME = {
    "joints": {"velocity_limit": "velocity_upper", "effort_limit": "effort",
               "acceleration_limit": "acceleration_upper"},
}
# plant-json keys with no Python attribute: world-frame values at q, which
# Python gives through body_poses(q)
PLANT_JSON_ONLY = {"X_WB", "X_WG", "axis_W"}
# Python attributes with no plant-json key: plant-json gives poses in the
# world, Python in the parent; the q layout; links in the tree
PYTHON_ONLY = {
    "bodies": {"scoped_name", "is_world", "parent", "joint", "index"},
    "joints": {"scoped_name", "X_PF", "X_CM", "axis", "velocity_lower", "acceleration_lower",
               "q_start", "nq", "v_start", "nv"},
    "geometries": {"X_BG", "shape_parameters"},
}
# plant-json keys written only where they say something (a screw joint's
# pitch, a finite acceleration limit, a body's surface velocity axis, a
# compiler-named entity's flag); Python
# always has the attribute
PLANT_JSON_WHEN_SET = {"unnamed", "screw_thread_pitch", "acceleration_upper",
                       "surface_velocity_axis", "deformable"}
IR_SHAPE_KEY = {"a": "abc", "b": "abc", "c": "abc"}
# the IR's name of a force element kind
IR_FORCE_ELEMENT = {"revolute_spring": "joint_spring", "prismatic_spring": "joint_spring"}


def run_mdlc(emit):
    result = subprocess.run(
        [os.environ["MDLC_BINARY"], "compile", str(MODEL), "--package-path", str(MODEL_DIR),
         "--emit=" + emit], capture_output=True, text=True, check=True)
    return result.stdout


def python_attributes(obj):
    return {name for name in dir(obj)
            if not name.startswith("_") and not callable(getattr(obj, name))}


class EveryEntity(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.model = mdlc.compile(MODEL, package_paths=[MODEL_DIR], strict=True)
        cls.plant = json.loads(run_mdlc("plant-json"))
        cls.ir = run_mdlc("ir").splitlines()

    def ir_lines(self, kind):
        return [line for line in self.ir if line.startswith(f"  {kind} #")]

    def test_the_model_holds_every_kind(self):
        p = self.plant
        self.assertEqual({j["type"] for j in p["joints"]}, JOINT_TYPES)
        self.assertEqual({g["shape"]["type"] for g in p["geometries"]}, SHAPES)
        self.assertEqual({r for g in p["geometries"] for r in g["roles"]}, ROLES)
        self.assertEqual({c["type"] for c in p["constraints"]}, CONSTRAINTS)
        self.assertEqual({f["type"] for f in p["force_elements"]}, FORCE_ELEMENTS)
        for key in ("frames", "actuators", "cameras", "collision_filters"):
            self.assertTrue(p[key], f"the model has no {key}")

    def test_python_lists_what_plant_json_lists(self):
        m = self.model
        self.assertEqual(len(m.bodies), len(self.plant["bodies"]) + 1)  # plus the world
        for key in ("joints", "frames", "geometries", "actuators", "constraints", "cameras",
                    "force_elements"):
            self.assertEqual(len(getattr(m, key)), len(self.plant[key]), key)
        self.assertEqual(sorted(map(list, m.collision_filters())),
                         sorted(self.plant["collision_filters"]))

    def test_every_plant_json_field_is_a_python_attribute_and_back(self):
        m = self.model
        lists = {"bodies": [b for b in m.bodies if not b.is_world], "joints": m.joints,
                 "frames": m.frames, "geometries": m.geometries, "actuators": m.actuators,
                 "cameras": m.cameras}
        for key, objects in lists.items():
            renames = PYTHON_NAME.get(key, {})
            for entry, obj in zip(self.plant[key], objects):
                with self.subTest(kind=key, name=entry.get("name")):
                    fields = {renames.get(k, k) for k in entry if k not in PLANT_JSON_ONLY}
                    attributes = python_attributes(obj) - PYTHON_ONLY.get(key, set())
                    self.assertEqual(fields, attributes - (PLANT_JSON_WHEN_SET - fields))
                    self.assertEqual(entry.get("name"), obj.name)

    def test_deformable_bodies_match_plant_json(self):  # EXT-070
        bodies = {(b.model_instance, b.name): b for b in self.model.bodies}
        deformable = [e for e in self.plant["bodies"] if "deformable" in e]
        self.assertTrue(deformable, "the model has no deformable body")
        for entry in self.plant["bodies"]:
            with self.subTest(body=entry["name"]):
                python = bodies[entry["model_instance"], entry["name"]].deformable
                if "deformable" not in entry:
                    self.assertIsNone(python)
                    continue
                self.assert_same_fields(entry["deformable"], python)

    def assert_same_fields(self, expected, got):
        """plant-json's value `expected` and Python's `got`: the same keys in the
        same order, lists item by item, numbers within float tolerance."""
        if isinstance(expected, dict):
            self.assertEqual(list(expected), list(got))
            for key, value in expected.items():
                self.assert_same_fields(value, got[key])
        elif isinstance(expected, list) and expected and isinstance(expected[0], dict):
            self.assertEqual(len(expected), len(got))
            for item, got_item in zip(expected, got):
                self.assert_same_fields(item, got_item)
        elif isinstance(expected, str) or expected is None:
            self.assertEqual(expected, got)
        else:
            np.testing.assert_allclose(got, expected)

    def test_parameters_match_plant_json(self):
        m = self.model
        for entry, g in zip(self.plant["geometries"], m.geometries):
            with self.subTest(geometry=entry["name"]):
                self.assertEqual(entry["shape"]["type"], g.shape)
                self.assertEqual(sorted(entry["roles"]), sorted(g.roles))
                params = {k: v for k, v in entry["shape"].items() if k != "type"}
                extras = {"path"} if g.shape in ("mesh", "convex") else set()
                self.assertEqual(set(params), set(g.shape_parameters) - extras)
                for k, v in params.items():
                    if isinstance(v, str):
                        self.assertEqual(v, g.shape_parameters[k])
                    else:
                        np.testing.assert_allclose(g.shape_parameters[k], v)
        for key in ("constraints", "force_elements"):
            for entry, obj in zip(self.plant[key], getattr(m, key)):
                with self.subTest(kind=key, type=entry["type"]):
                    self.assertEqual(entry["type"], obj.type)
                    expected = {k for k in entry if k not in ("type", "model_instance")}
                    self.assertEqual(expected, set(obj.parameters))

    def test_the_ir_shows_every_entity_and_field(self):
        named = {"body": [b for b in self.plant["bodies"]], "joint": self.plant["joints"],
                 "frame": self.plant["frames"], "geometry": self.plant["geometries"],
                 "actuator": self.plant["actuators"]}
        for kind, entries in named.items():
            names = {re.match(rf'  {kind} #\d+ "([^"]*)"', line).group(1)
                     for line in self.ir_lines(kind)}
            for entry in entries:
                self.assertIn(entry["name"], names, f"{kind} '{entry['name']}' is not in the IR")
        cameras = self.ir_lines("camera")
        self.assertEqual(len(cameras), len(self.plant["cameras"]))
        for entry, line in zip(self.plant["cameras"], cameras):
            self.assertIn(f'"{entry["name"]}"', line)
            self.assertIn(f" size={entry['width']}x{entry['height']} ", line)
            self.assertIn(" fov_y=", line)
        # parameters: each plant-json key is written in the entity's IR line
        geometry_lines = {re.match(r'  geometry #\d+ "([^"]*)".* roles=(\S+)', line).groups(): line
                          for line in self.ir_lines("geometry")}
        for entry in self.plant["geometries"]:
            line = geometry_lines[(entry["name"], ",".join(entry["roles"]))]
            self.assertIn(f" {entry['shape']['type']} ", line)
            for k in entry["shape"]:
                if k != "type":
                    self.assertIn(f" {IR_SHAPE_KEY.get(k, k)}=", line, entry["name"])
        constraint_lines = self.ir_lines("constraint")
        self.assertEqual([c["type"] for c in self.plant["constraints"]],
                         [line.split()[2] for line in constraint_lines])
        for entry, line in zip(self.plant["constraints"], constraint_lines):
            for k in entry:
                if k not in ("type", "model_instance"):
                    self.assertIn(f" {k}=", line)
        force_lines = self.ir_lines("force_element")
        self.assertEqual([IR_FORCE_ELEMENT.get(f["type"], f["type"])
                          for f in self.plant["force_elements"]],
                         [line.split()[3] for line in force_lines])
        for entry, line in zip(self.plant["force_elements"], force_lines):
            for k in entry:
                if k != "type":
                    self.assertIn(f" {k}=", line)
        self.assertTrue(self.ir_lines("collision_filter_group"))

    def test_the_viewer_draws_shapes_as_plant_json_gives_them(self):
        with tempfile.TemporaryDirectory() as work:
            page_path = pathlib.Path(work) / "page.html"
            done = subprocess.run(
                [os.environ["MDLC_BINARY"], "view", str(MODEL), "--package-path", str(MODEL_DIR),
                 "-o", str(page_path)], capture_output=True, text=True)
            if done.returncode != 0 and "without the viewer" in done.stderr:
                self.skipTest(done.stderr.strip())
            self.assertEqual(done.returncode, 0, done.stderr)
            page = page_path.read_text(encoding="utf-8")
        match = re.search(r'<script type="application/json" id="mdlc-model">(.*?)</script>', page,
                          re.S)
        view = json.loads(match.group(1))
        self.assertEqual(len(view["geometries"]), len(self.plant["geometries"]))
        for shown, entry in zip(view["geometries"], self.plant["geometries"]):
            with self.subTest(geometry=entry["name"]):
                self.assertEqual(shown["name"], entry["name"])
                self.assertEqual(set(shown["roles"]), set(entry["roles"]))
                # the page's own extra: which of its meshes draws a mesh shape
                shape = {k: v for k, v in shown["shape"].items() if k != "mesh"}
                self.assertEqual(shape, entry["shape"])


if __name__ == "__main__":
    unittest.main()
