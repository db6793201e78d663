#!/usr/bin/env python3
"""robot_meshes_test.py - real robots' meshes drawn where they belong (issue 55).

    robot_meshes_test.py MDLC THIRD_PARTY_DIR SCREENSHOT_DIR

Two published robots (tests/models/third_party) whose meshes are not Z-up
as written:
- Drake's Kinova Jaco (j2s7s300.urdf), with glTF meshes: glTF is Y-up, and
  mdlc turns it Z-up as Drake does. Checked: the base spans z in [0, 0.157]
  as its OBJ twin does; every revolute joint sits inside its parent link's
  mesh; a glTF mesh and its OBJ twin, on two links of one model, have the
  same bounds.
- iCub (iCubGenova03), with COLLADA meshes that declare Y_UP and are meant
  as written (as RViz and Gazebo show them). Checked: each thigh spans its
  link's y in [-0.2555, 0] and holds the knee, each shank holds the ankle,
  and the page says what was done; with --collada-up-axis=apply the
  page says the files were turned and the knees leave the thighs.
The numbers come from the page `mdlc view` writes (the vertices the viewer
draws), each geometry placed on its body. Each page is also opened in
headless Chromium (one browser for all, headless_browser.py): it must build
its scene without an error, and its screenshot, kept in SCREENSHOT_DIR, must
not be blank. With MDLC_VIEW_BROWSER=off (the sanitizer suite) the pages are
checked without the browser.

Exit status 0: passed; 77: skipped (no Chromium, or an mdlc built without
the viewer); 1: failed.
"""
import base64
import contextlib
import os
import re
import struct
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from headless_browser import Browser  # noqa: E402
from view_test import SKIP, Failure, check, chromium, embedded_model, png_pixels  # noqa: E402

MARGIN = 0.01  # m: how far outside a mesh's bounds a joint may sit and still be "in" it


def view(mdlc, model, page, *flags):
    done = subprocess.run([mdlc, "view", model, "-o", page, *flags], capture_output=True, text=True)
    if done.returncode != 0 and "without the viewer" in done.stderr:
        print(f"skipped: {done.stderr.strip()}")
        sys.exit(SKIP)
    check(done.returncode == 0, f"mdlc view {model} {' '.join(flags)} failed: {done.stderr}")
    return embedded_model(open(page, encoding="utf-8").read())


def mesh_bounds(model):
    """{(body name, mesh file name): (lo, hi)} of each illustration mesh,
    in its body's frame (scale, then the geometry's pose)."""
    out = {}
    for g in model["geometries"]:
        shape = g["shape"]
        if shape["type"] != "mesh" or shape.get("mesh", -1) < 0 or "illustration" not in g["roles"]:
            continue
        mesh = model["meshes"][shape["mesh"]]
        raw = base64.b64decode(mesh["vertices"])
        xyz = struct.unpack(f"<{len(raw) // 4}f", raw)
        R, p, s = g["X_BG"]["R"], g["X_BG"]["p"], shape["scale"]
        lo, hi = [float("inf")] * 3, [float("-inf")] * 3
        for i in range(0, len(xyz), 3):
            v = [xyz[i] * s[0], xyz[i + 1] * s[1], xyz[i + 2] * s[2]]
            for r in range(3):
                w = R[3 * r] * v[0] + R[3 * r + 1] * v[1] + R[3 * r + 2] * v[2] + p[r]
                lo[r], hi[r] = min(lo[r], w), max(hi[r], w)
        body = model["bodies"][g["body"]]["name"]
        out[(body, os.path.basename(mesh["path"]))] = (lo, hi)
    return out


def body_bounds(bounds, body):
    """The bounds of all of `body`'s illustration meshes together."""
    boxes = [b for (name, _), b in bounds.items() if name == body]
    check(boxes, f"body {body} shows no mesh")
    return ([min(b[0][k] for b in boxes) for k in range(3)],
            [max(b[1][k] for b in boxes) for k in range(3)])


def inside(point, box, margin=MARGIN):
    lo, hi = box
    return all(lo[k] - margin <= point[k] <= hi[k] + margin for k in range(3))


def joint(model, name):
    for j in model["joints"]:
        if j["name"] == name:
            return j
    raise Failure(f"no joint {name}")


def near(actual, expected, tol, what):
    check(all(abs(a - e) <= tol for a, e in zip(actual, expected)),
          f"{what}: {[round(a, 4) for a in actual]}, expected {expected} within {tol}")


def screenshot(browser, page, png):
    """The page in Chromium: its scene built without an error, and a
    screenshot that is not blank, kept at `png` (both of one opening: the
    page is the same file either way)."""
    if browser is None:  # MDLC_VIEW_BROWSER=off
        return "not taken (MDLC_VIEW_BROWSER=off)"
    browser.open("file://" + page, for_screenshot=True)
    dom = browser.dom()
    errors = re.search(r'<pre id="mdlc-errors"[^>]*>(.*?)</pre>', dom, re.S)
    check(not errors or not errors.group(1).strip(), f"{page}: the page reported errors")
    check('data-ready="true"' in dom, f"{page}: the page did not finish building its scene")
    browser.screenshot(png)
    check(os.path.exists(png), f"no screenshot of {page}")
    width, height, channels, rows = png_pixels(png)
    colours = {row[x * channels:x * channels + 3] for row in rows[::4] for x in range(400, width, 4)}
    check(len(colours) >= 20, f"{png}: the 3D view looks blank ({len(colours)} colours)")
    return f"{png} ({len(colours)} colours)"


def test_jaco(mdlc, browser, third_party, shots, work):
    root = os.path.join(third_party, "drake_models")
    urdf = os.path.join(root, "jaco_description", "urdf", "j2s7s300.urdf")
    page = os.path.join(work, "jaco.html")
    model = view(mdlc, urdf, page, "--package-path", root)
    check(not any("not shown" in n for n in model["notes"]), f"jaco: meshes not shown: {model['notes']}")
    bounds = mesh_bounds(model)
    # the base stands on its link's frame, as base.obj does: z in [0, 0.1567]
    lo, hi = bounds[("j2s7s300_link_base", "base.gltf")]
    near([lo[2], hi[2]], [0.0, 0.1567], 1e-3, "jaco base.gltf z range")
    near([lo[0], hi[0], lo[1], hi[1]], [-0.0413, 0.0413, -0.0413, 0.0413], 1e-3, "jaco base x, y")
    # every revolute joint sits on its parent link's mesh
    revolute = [j for j in model["joints"] if j["type"] == "revolute"]
    check(len(revolute) == 10, f"jaco: {len(revolute)} revolute joints, expected 10")
    for j in revolute:
        parent = model["bodies"][j["parent"]]["name"]
        check(inside(j["X_PF"]["p"], body_bounds(bounds, parent)),
              f"jaco: joint {j['name']} at {j['X_PF']['p']} is off its parent {parent}'s mesh "
              f"{body_bounds(bounds, parent)}")

    # glTF and OBJ twins, side by side in one model, agree
    meshes = os.path.join(root, "jaco_description", "meshes")
    twins = os.path.join(work, "twins.urdf")
    links = "".join(
        f'<link name="{n}_{ext}"><visual><geometry><mesh filename="{meshes}/{n}.{ext}"/>'
        f'</geometry></visual><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" '
        f'ixy="0" ixz="0" iyz="0"/></inertial></link>'
        for n in ("finger_distal", "finger_proximal") for ext in ("gltf", "obj"))
    with open(twins, "w") as f:
        f.write(f'<robot name="twins">{links}</robot>\n')
    twin_bounds = mesh_bounds(view(mdlc, twins, os.path.join(work, "twins.html")))
    for n in ("finger_distal", "finger_proximal"):
        (glo, ghi), (olo, ohi) = twin_bounds[(f"{n}_gltf", f"{n}.gltf")], twin_bounds[(f"{n}_obj", f"{n}.obj")]
        near(glo + ghi, olo + ohi, 1e-5, f"{n}.gltf against {n}.obj")
    shot = screenshot(browser, page, os.path.join(shots, "jaco_j2s7s300.png"))
    print(f"ok jaco: base z [{lo[2]:.4f}, {hi[2]:.4f}]; {len(revolute)} revolute joints on their "
          f"parents' meshes; 2 glTF/OBJ twins agree; screenshot {shot}")


def test_icub(mdlc, browser, third_party, shots, work):
    root = os.path.join(third_party, "icub-models", "iCub")
    urdf = os.path.join(root, "robots", "iCubGenova03", "model.urdf")
    page = os.path.join(work, "icub.html")
    model = view(mdlc, urdf, page, "--package", f"iCub={root}")
    note = [n for n in model["notes"] if n.startswith("COLLADA mesh")]
    check(len(note) == 1 and "declares Y_UP" in note[0] and "read as written" in note[0],
          f"icub: the page's note on COLLADA axes: {model['notes']}")
    bounds = mesh_bounds(model)
    for side in ("l", "r"):
        thigh = bounds[(f"{side}_upper_leg", f"icub_{side}_thigh.dae")]
        near([thigh[0][1], thigh[1][1]], [-0.2555, 0.0], 1e-3, f"icub {side} thigh y range")
        knee = joint(model, f"{side}_knee")["X_PF"]["p"]
        check(inside(knee, thigh), f"icub: the {side} knee {knee} is off the thigh {thigh}")
        ankle = joint(model, f"{side}_ankle_pitch")["X_PF"]["p"]
        shank = bounds[(f"{side}_lower_leg", f"icub_{side}_shank.dae")]
        check(inside(ankle, shank), f"icub: the {side} ankle {ankle} is off the shank {shank}")
    shot = screenshot(browser, page, os.path.join(shots, "icub_genova03.png"))

    # the switch: applied, the declared Y_UP turns the thighs away from the knees
    applied_page = os.path.join(work, "icub_applied.html")
    applied = view(mdlc, urdf, applied_page, "--package", f"iCub={root}", "--collada-up-axis=apply")
    check(any("turned to Z-up" in n for n in applied["notes"]),
          f"icub, applied: the page's notes {applied['notes']}")
    applied_bounds = mesh_bounds(applied)
    for side in ("l", "r"):
        thigh = applied_bounds[(f"{side}_upper_leg", f"icub_{side}_thigh.dae")]
        knee = joint(applied, f"{side}_knee")["X_PF"]["p"]
        check(not inside(knee, thigh), f"icub, applied: the {side} knee is still on the thigh")
    applied_shot = screenshot(browser, applied_page, os.path.join(shots, "icub_genova03_applied.png"))
    print(f"ok icub: thighs span y [-0.2555, 0] and hold the knees, shanks hold the ankles, read "
          f"as written; applied, the knees leave the thighs; screenshots {shot}, {applied_shot}")


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    mdlc, third_party, shots = (os.path.abspath(a) for a in sys.argv[1:])
    # the sanitizer suite (tools/sanitize.sh) looks for memory errors in mdlc:
    # it checks what mdlc writes and leaves the drawing to the ordinary build
    with_browser = os.environ.get("MDLC_VIEW_BROWSER", "on") != "off"
    chromium_path = chromium()
    if with_browser and not chromium_path:
        print("skipped: no Chromium on the PATH (Debian: apt-get install chromium)")
        return SKIP
    os.makedirs(shots, exist_ok=True)
    failures = 0
    # one browser opens every page in turn (headless_browser.py says why)
    with tempfile.TemporaryDirectory() as work, \
            (Browser(chromium_path) if with_browser else contextlib.nullcontext()) as browser:
        for test in (test_jaco, test_icub):
            try:
                test(mdlc, browser, third_party, shots, work)
            except Failure as failure:
                print(f"FAIL {failure}")
                failures += 1
    print(f"{2 - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
