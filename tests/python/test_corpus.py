"""The Python module against plant-json, bit for bit, on the shared corpus
(issue 13): for every model of a format that the reference tools load, the
values Python sees (masses, centers of mass, inertias, body and frame poses,
joint limits, the mass matrix) are the very doubles plant-json prints.

One test class per format, so ctest runs them as separate tests. The corpus is
../shared/corpus (or MDLC_SHARED_DIR); without it every test reports itself
skipped.
"""

import json
import math
import os
import pathlib
import subprocess
import unittest

import mdlc

ROOT = pathlib.Path(__file__).resolve().parents[2]
SHARED = pathlib.Path(os.environ.get("MDLC_SHARED_DIR", ROOT.parent / "shared"))
CORPUS = SHARED / "corpus"
MDLC = os.environ.get("MDLC_BINARY")  # the command line, to compare verdicts with


def manifest_rows(fmt):
    """(path, loads_in_reference) of the manifest's rows of a format."""
    rows = []
    with open(CORPUS / "manifest.tsv") as f:
        header = f.readline().rstrip("\n").split("\t")
        for line in f:
            row = dict(zip(header, line.rstrip("\n").split("\t")))
            if row["format"] == fmt:
                rows.append((row["path"], row["loads_in_reference"]))
    return rows


def bound(x, unbounded):
    return unbounded if x is None else x  # plant-json writes an unbounded limit as null


def inertia6(I):
    return [I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[0, 2], I[1, 2]]


class CorpusAgreement:
    """Mixed into one TestCase per format."""

    FORMAT = None
    # as the corpus tests of the command line compile them
    PACKAGE_PATHS = [CORPUS]

    def setUp(self):
        if not (CORPUS / "manifest.tsv").is_file():
            self.skipTest(f"the shared corpus is absent ({CORPUS})")

    def models(self):
        rows = manifest_rows(self.FORMAT)
        if self.FORMAT == "dmd":
            return [path for path, _ in rows]
        return [path for path, loads in rows if loads.startswith("yes")]

    def test_python_values_are_plant_json_values(self):
        compared, rejected = 0, 0
        for path in self.models():
            with self.subTest(model=path):
                try:
                    model = mdlc.compile(str(CORPUS / path), package_paths=self.PACKAGE_PATHS)
                except mdlc.CompileError as e:
                    # which models mdlc rejects is pinned by the corpus and
                    # oracle tests; here Python must only agree with the CLI
                    self.assertTrue(any(d.severity == "error" for d in e.diagnostics))
                    self.assert_command_line_rejects(path)
                    rejected += 1
                    continue
                self.check_model(model)
                compared += 1
        print(f"\n{self.FORMAT}: {compared} models agree bit for bit; "
              f"{rejected} rejected, as by the command line")
        self.assertGreater(compared, rejected)

    def assert_command_line_rejects(self, path):
        if not MDLC:
            return
        args = [MDLC, "compile", "--emit=none", str(CORPUS / path)]
        for p in self.PACKAGE_PATHS:
            args += ["--package-path", str(p)]
        status = subprocess.run(args, capture_output=True, env={}).returncode
        self.assertEqual(status, 1, f"the command line compiles {path}; Python did not")

    def check_model(self, model):
        q = model.default_positions()
        dump = json.loads(model.to_json(q))
        poses = model.body_poses(q)

        bodies = {(b.model_instance, b.name): b for b in model.bodies}
        self.assertEqual(len(dump["bodies"]), len(model.bodies) - 1)  # the dump has no world
        for entry in dump["bodies"]:
            body = bodies[(entry["model_instance"], entry["name"])]
            self.assertEqual(body.mass, entry["mass"])
            self.assertEqual(list(body.com), entry["com"])
            self.assertEqual(inertia6(body.inertia), entry["inertia"])
            self.assertEqual(list(poses[body.index].p), entry["X_WB"]["p"])
            self.assertEqual(list(poses[body.index].q), entry["X_WB"]["q"])
            self.assertEqual(body.unnamed, entry.get("unnamed", False))

        joints = {(j.model_instance, j.name): j for j in model.joints}
        self.assertEqual(len(dump["joints"]), len(model.joints))
        for entry in dump["joints"]:
            joint = joints[(entry["model_instance"], entry["name"])]
            self.assertEqual(joint.type, entry["type"])
            self.assertEqual((joint.parent, joint.child), (entry["parent"], entry["child"]))
            self.assertEqual(list(joint.lower), [bound(x, -math.inf) for x in entry["lower"]])
            self.assertEqual(list(joint.upper), [bound(x, math.inf) for x in entry["upper"]])
            self.assertEqual(list(joint.damping), entry["damping"])

        frames = {(f.model_instance, f.name): f for f in model.frames}
        for entry in dump["frames"]:
            frame = frames[(entry["model_instance"], entry["name"])]
            self.assertEqual(frame.body, entry["body"])
            self.assertEqual(list(frame.X_BF.p), entry["X_BF"]["p"])
            self.assertEqual(list(frame.X_BF.q), entry["X_BF"]["q"])

        self.assertEqual(len(dump["geometries"]), len(model.geometries))
        self.assertEqual(len(dump["actuators"]), len(model.actuators))
        self.assertEqual(len(dump["constraints"]), len(model.constraints))
        self.assertEqual(len(dump["cameras"]), len(model.cameras))

        if "mass_matrix" in dump:
            by_name = {j.scoped_name: j for j in model.joints}
            rows = [by_name[name].v_start for name in dump["dofs"]]
            M = model.mass_matrix(q)
            for i, row in enumerate(rows):
                self.assertEqual([M[row, col] for col in rows], dump["mass_matrix"][i])


class CorpusUrdf(CorpusAgreement, unittest.TestCase):
    FORMAT = "urdf"


class CorpusSdf(CorpusAgreement, unittest.TestCase):
    FORMAT = "sdf"


class CorpusMjcf(CorpusAgreement, unittest.TestCase):
    FORMAT = "mjcf"


class CorpusDirectives(CorpusAgreement, unittest.TestCase):
    FORMAT = "dmd"


if __name__ == "__main__":
    unittest.main()
