#!/usr/bin/env python3
"""view_test.py - `mdlc view` in a real browser (headless Chromium).

    view_test.py MDLC MODEL [MODEL...]

For each model: write the page, open it (file://, no network) and check
- the page meets no error (uncaught exceptions, rejected promises,
  console.error), and finishes building its scene;
- a screenshot of it is not blank: the 3D view holds many colours;
- its forward kinematics are the plant's: window.mdlcBodyPoses(q) equals
  `mdlc compile --emit=plant-json --q JOINT=VALUE ...` X_WB to 1e-9 at
  several q;
- where the Python module mdlc is importable, the same at random q that set
  every coordinate, multi-dof joints (ball, universal, planar, floating)
  included, against Model.body_poses(q);
- moving one joint's slider (a real input event) moves exactly the bodies
  downstream of that joint, as the scene shows them;
- the page holds no absolute path of this machine (issue 58).
Then, for the models it is given (issue 58):
- mesh_colors.urdf: the mesh files' own colours (OBJ .mtl, COLLADA, glTF)
  reach the page and its pixels;
- free_ball.xml: `mdlc view --q` sets the configuration shown (equal to
  plant-json's at the same --q), a value past a joint's limit is clamped in
  the slider, its label and the bodies alike; a floating body's sliders are
  x, y, z, roll, pitch, yaw, and dragging them sets q's quaternion; the
  selected body's panel lies inside a 1280x800 window.
Screenshots are kept in $MDLC_VIEW_SCREENSHOTS when it is set.
The page runs the checks itself when opened as page.html#selftest=JSON and
writes the results into <pre id="mdlc-selftest">, read from its DOM. One
Chromium (headless_browser.py) opens every page in turn.

Exit status 0: passed; 77: skipped (no Chromium, or an mdlc built without the
viewer), with the reason on stdout; 1: failed.
"""
import html
import json
import math
import os
import random
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import urllib.parse
import zlib

from headless_browser import Browser

TOLERANCE = 1e-9
SKIP = 77


def chromium():
    for name in (os.environ.get("MDLC_CHROMIUM", ""), "chromium", "chromium-browser",
                 "google-chrome"):
        if name and shutil.which(name):
            return shutil.which(name)
    return None


def png_pixels(path):
    """(width, height, rows of RGBA bytes) of an 8-bit RGB or RGBA PNG."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color = struct.unpack(">IIBB", body[:10])
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    assert depth == 8 and color in (2, 6), f"unexpected PNG format {depth}/{color}"
    channels = 4 if color == 6 else 3
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        line = raw[y * (stride + 1):(y + 1) * (stride + 1)]
        kind, row = line[0], bytearray(line[1:])
        for i in range(stride):  # undo the PNG row filter
            a = row[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                row[i] = (row[i] + a) & 255
            elif kind == 2:
                row[i] = (row[i] + b) & 255
            elif kind == 3:
                row[i] = (row[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(row))
        previous = row
    return width, height, channels, rows


def rotation_of(quat):
    w, x, y, z = quat
    return [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
            2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
            2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]


def embedded_model(page):
    match = re.search(r'<script type="application/json" id="mdlc-model">(.*?)</script>', page, re.S)
    return json.loads(match.group(1))


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


REPOSITORY = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def write_page(mdlc, model_path, page_path, *flags):
    """`mdlc view` of the model into page_path: the page's text."""
    done = subprocess.run([mdlc, "view", model_path, "-o", page_path, *flags],
                          capture_output=True, text=True)
    if done.returncode != 0 and "without the viewer" in done.stderr:
        print(f"skipped: {done.stderr.strip()}")
        sys.exit(SKIP)
    check(done.returncode == 0, f"mdlc view {model_path} failed: {done.stderr}")
    page = open(page_path, encoding="utf-8").read()
    # a page is passed around: it names files relative to the model's folder
    for local in {os.path.dirname(os.path.abspath(model_path)), REPOSITORY, os.getcwd()}:
        check(local not in page, f"{page_path} holds the local path {local}")
    return page


def selftest(browser, page_path, request, name):
    """Opens the page with #selftest=request: the report it writes."""
    url = "file://" + page_path + "#selftest=" + urllib.parse.quote(json.dumps(request))
    browser.open(url)
    dom = browser.dom()
    errors = re.search(r'<pre id="mdlc-errors"[^>]*>(.*?)</pre>', dom, re.S)
    check(not errors or not errors.group(1).strip(), f"{name}: the page reported errors: "
          f"{errors.group(1) if errors else ''}")
    # the last match: the viewer script's own text names the element too
    matches = re.findall(r'<pre id="mdlc-selftest">([^<]*)</pre>', dom)
    check(matches, f"{name}: the page did not finish its self-test (it never got to run?)")
    try:
        report = json.loads(html.unescape(matches[-1]))
    except ValueError:
        raise Failure(f"{name}: the self-test wrote no JSON: {matches[-1][:300]}")
    check(report["errors"] == [], f"{name}: errors in the page: {report['errors']}")
    check('data-ready="true"' in dom, f"{name}: the page did not finish building its scene")
    return report


def screenshot(browser, url, png, name):
    """A screenshot of the page at url, kept at png: (width, height, channels, rows)."""
    browser.open(url, for_screenshot=True)
    browser.screenshot(png)
    check(os.path.exists(png), f"{name}: no screenshot")
    return png_pixels(png)


# what a model's page is opened with beyond the common checks (issue 58), so
# that they cost no browser run of their own: free_ball.xml opens at a --q
# (jaw_hinge's range is [-10, 30] degrees: 1 rad is past it), drags its free
# body's sliders (free joints are named after their bodies, as in Drake) and
# selects a body
EXTRAS = {
    "free_ball": {
        "flags": ["--q", "jaw_hinge=1.0", "--q", "shoulder_slide=0.03"],
        "request": {"drag": [["box", "x", 0.3], ["box", "roll", 0.5], ["box", "pitch", 0.2],
                             ["box", "yaw", -0.4]], "select": "lid"},
        "hash": "#select=lid",
    },
}


def test_model(mdlc, browser, model_path, work, shots):
    name = os.path.splitext(os.path.basename(model_path))[0]
    extras = EXTRAS.get(name, {})
    page_path = os.path.join(work, name + ".html")
    page = write_page(mdlc, model_path, page_path, *extras.get("flags", []))
    model = embedded_model(page)
    bodies, joints = model["bodies"], model["joints"]
    movable = [j for j in (joints[i] for i in model["joint_order"]) if j["nq"] == 1]
    # a joint whose first coordinate moves its child: a 1-dof one where there
    # is one (a quaternion's w alone would not turn anything)
    sliding = movable or [j for j in joints if j["nq"] > 0 and j["type"] != "quaternion_floating"]
    check(sliding, f"{name}: no joint to move")

    # q: the defaults, then each 1-dof joint set away from zero within its limits
    def q_with(values):
        q = [0.0] * model["num_positions"]
        for joint in joints:
            for k in range(joint["nq"]):
                q[joint["q_start"] + k] = joint["default"][k] if k < len(joint["default"]) else 0.0
        for joint in movable:
            if joint["scoped_name"] in values:
                q[joint["q_start"]] = values[joint["scoped_name"]]
        return q

    def inside(joint, x):
        lo, hi = joint["lower"][0], joint["upper"][0]
        lo = lo if lo is not None else -math.pi
        hi = hi if hi is not None else math.pi
        return lo + (hi - lo) * x

    settings = [{}]
    for fraction in (0.3, 0.8, 0.55):
        settings.append({j["scoped_name"]: inside(j, (fraction + 0.17 * i) % 1)
                         for i, j in enumerate(movable)})
    qs = [q_with(setting) for setting in settings]

    # the slider: the first movable joint with the most bodies below it
    children = {}
    for joint in joints:
        children.setdefault(joint["parent"], []).append(joint["child"])

    def downstream(body):
        out = {body}
        for child in children.get(body, []):
            out |= downstream(child)
        return out

    slider = max(sliding, key=lambda j: len(downstream(j["child"])))
    expected_moved = sorted(bodies[b]["scoped_name"] for b in downstream(slider["child"]))
    slider_value = inside(slider, 0.9) if slider["nq"] == 1 else 0.7

    # random q over every coordinate, for the Python module's body_poses
    try:
        import mdlc as mdlc_python
    except ImportError:
        mdlc_python = None
    generator = random.Random(15)
    random_qs = [[generator.uniform(-1.5, 1.5) for _ in range(model["num_positions"])]
                 for _ in range(3)] if mdlc_python else []

    request = {"qs": qs + random_qs, "slider": slider["scoped_name"], "value": slider_value,
               **extras.get("request", {})}
    report = selftest(browser, page_path, request, name)

    # the page's poses against plant-json's, body by body
    worst = 0.0
    for setting, q, poses in zip(settings, qs, report["poses"]):
        command = [mdlc, "compile", model_path, "--emit=plant-json"]
        for key, value in setting.items():
            command += ["--q", f"{key}={value!r}"]
        plant = json.loads(subprocess.run(command, capture_output=True, text=True,
                                          check=True).stdout)
        check(len(plant["bodies"]) == len(bodies) - 1, f"{name}: body counts differ")
        for b, expected in enumerate(plant["bodies"], start=1):
            check(bodies[b]["name"] == expected["name"], f"{name}: body {b} is named differently")
            R = rotation_of(expected["X_WB"]["q"])
            got = poses[b]
            error = max([abs(x - y) for x, y in zip(got["R"], R)] +
                        [abs(x - y) for x, y in zip(got["p"], expected["X_WB"]["p"])])
            worst = max(worst, error)
            check(error <= TOLERANCE, f"{name}: body {bodies[b]['scoped_name']} at q={q}: "
                  f"page {got} vs plant {expected['X_WB']} (error {error:g})")
    if mdlc_python:
        compiled = mdlc_python.compile(model_path)
        for q, poses in zip(random_qs, report["poses"][len(qs):]):
            for b, expected in enumerate(compiled.body_poses(q)):
                R = [float(x) for row in expected.R for x in row]
                error = max([abs(x - y) for x, y in zip(poses[b]["R"], R)] +
                            [abs(x - float(y)) for x, y in zip(poses[b]["p"], expected.p)])
                worst = max(worst, error)
                check(error <= TOLERANCE, f"{name}: body {bodies[b]['scoped_name']} at random "
                      f"q={q}: page {poses[b]} vs body_poses (error {error:g})")
    check(sorted(report["moved"]) == expected_moved,
          f"{name}: moving {slider['scoped_name']} moved {report['moved']}, expected {expected_moved}")

    # a screenshot: the 3D view (right of the side panel) is not one colour
    png = os.path.join(shots, name + ".png")
    width, height, channels, rows = screenshot(browser, "file://" + page_path +
                                               extras.get("hash", ""), png, name)
    colours = set()
    for row in rows[::4]:
        for x in range(400, width, 4):
            colours.add(row[x * channels:x * channels + 3])
    check(len(colours) >= 20, f"{name}: the 3D view looks blank ({len(colours)} colours)")

    print(f"ok {name}: {len(bodies) - 1} bodies, {len(qs)} configurations against plant-json and "
          f"{len(random_qs)} random ones against body_poses, worst pose error "
          f"{worst:.1e}; slider {slider['scoped_name']} moved {len(report['moved'])} bodies; "
          f"screenshot {width}x{height} with {len(colours)} colours in the 3D view")
    if name == "mesh_colors":
        check_mesh_colors(model, channels, rows)
    if name == "free_ball":
        check_configuration(mdlc, model_path, model, report, png)


def check_mesh_colors(model, channels, rows):
    """The files' material colours in the page's data and on screen."""
    runs = {os.path.basename(m["path"]): [[round(x, 6) for x in run] for run in m["colors"]]
            for m in model["meshes"]}
    expected = {"two_colors.obj": [[0, 0.9, 0.1, 0.1, 1], [6, 0.1, 0.8, 0.2, 1]],
                "blue.dae": [[0, 0.1, 0.2, 0.9, 1]], "yellow.gltf": [[0, 0.9, 0.8, 0.1, 1]]}
    check(runs == expected, f"mesh_colors: the page's colour runs are {runs}, not {expected}")
    # lit, the faces keep their hue: count the pixels of each in the 3D view
    hues = {"red": 0, "green": 0, "blue": 0, "yellow": 0}
    for row in rows:
        for x in range(400, len(row) // channels):
            r, g, b = row[x * channels:x * channels + 3]
            if r > 140 and g < 90 and b < 90:
                hues["red"] += 1
            elif g > 110 and r < 100 and b < 110:
                hues["green"] += 1
            elif b > 140 and r < 100 and g < 130:
                hues["blue"] += 1
            elif r > 140 and g > 120 and b < 80:
                hues["yellow"] += 1
    check(min(hues.values()) >= 100, f"mesh_colors: pixels by hue {hues}: a file's colour "
          "is missing from the screenshot")
    print(f"ok mesh_colors: the files' colours reach the page; pixels by hue {hues}")


def rpy_quaternion(roll, pitch, yaw):
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return [cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy,
            cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy]


def check_configuration(mdlc, model_path, model, report, png):
    """--q, clamping, floating sliders and the selection panel (free_ball.xml,
    opened and driven as EXTRAS says)."""
    name = "free_ball --q"
    opened = report["opened"]
    sliders = {(s["joint"].split("::")[-1], s["coordinate"]): s for s in opened["sliders"]}
    for joint in ("box", "torso"):  # <joint type="free"> and <freejoint/>
        coordinates = [c for j, c in sliders if j == joint]
        check(coordinates == ["x", "y", "z", "roll", "pitch", "yaw"],
              f"{name}: the floating joint's sliders are {coordinates}")
    check(not any(c.startswith("q") for _, c in sliders), f"{name}: quaternion sliders shown")

    joints = {j["name"]: j for j in model["joints"]}
    jaw, upper = joints["jaw_hinge"], math.radians(30)
    jaw_slider = sliders[("jaw_hinge", "")]
    check(abs(jaw_slider["value"] - upper) < 1e-12 and jaw_slider["label"] == f"{upper:.3f}"
          and jaw_slider["clamped"] and abs(opened["q"][jaw["q_start"]] - upper) < 1e-12,
          f"{name}: jaw_hinge=1.0 past its limit {upper} shows {jaw_slider}, q "
          f"{opened['q'][jaw['q_start']]}")
    others = [k for k, s in sliders.items() if s["clamped"] and k != ("jaw_hinge", "")]
    check(not others, f"{name}: sliders within their ranges are marked clamped: {others}")
    slide = sliders[("shoulder_slide", "")]
    check(slide["label"] == "0.030" and not slide["clamped"] and
          opened["q"][joints["shoulder_slide"]["q_start"]] == 0.03,
          f"{name}: shoulder_slide=0.03 shows {slide}")
    # the bodies shown on opening are plant-json's at the same (clamped) --q
    plant = json.loads(subprocess.run(
        [mdlc, "compile", model_path, "--emit=plant-json", "--q", f"jaw_hinge={upper!r}",
         "--q", "shoulder_slide=0.03"], capture_output=True, text=True, check=True).stdout)
    worst = 0.0
    for b, expected in enumerate(plant["bodies"], start=1):
        R = rotation_of(expected["X_WB"]["q"])
        got = opened["shown"][b]
        worst = max([worst] + [abs(x - y) for x, y in zip(got["R"], R)] +
                    [abs(x - y) for x, y in zip(got["p"], expected["X_WB"]["p"])])
    check(worst <= TOLERANCE, f"{name}: the opened page differs from plant-json by {worst:g}")

    # dragging x, roll, pitch, yaw sets q's translation and quaternion
    box = joints["box"]
    dragged = report["dragged"]["q"][box["q_start"]:box["q_start"] + 7]
    wanted = rpy_quaternion(0.5, 0.2, -0.4)
    sign = 1 if sum(a * b for a, b in zip(dragged[:4], wanted)) > 0 else -1
    error = max(abs(sign * a - b) for a, b in zip(dragged[:4], wanted))
    check(error < 1e-12 and dragged[4] == 0.3, f"{name}: dragged box to q {dragged}, "
          f"expected quaternion {wanted} and x 0.3")

    selection = report["selection"]
    # a 1280x800 window (its viewport a little shorter: the browser's own bars)
    check(selection["width"] == 1280 and selection["left"] >= 0 and
          selection["top"] >= 0 and selection["right"] <= selection["width"] and
          selection["bottom"] <= selection["height"] and "lid" in selection["text"],
          f"{name}: the selected body's panel is not inside the window: {selection}")
    print(f"ok {name}: opened as plant-json at --q (error {worst:.1e}), jaw_hinge clamped to "
          f"{upper:.4f}; box dragged by x, roll, pitch, yaw; selection panel at "
          f"({selection['left']:.0f}, {selection['top']:.0f})-({selection['right']:.0f}, "
          f"{selection['bottom']:.0f}); screenshot {png}")


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    mdlc, models = sys.argv[1], sys.argv[2:]
    chromium_path = chromium()
    if not chromium_path:
        print("skipped: no Chromium on the PATH (Debian: apt-get install chromium)")
        return SKIP
    failures = 0
    # one browser opens every page in turn (headless_browser.py says why)
    with tempfile.TemporaryDirectory() as work, Browser(chromium_path) as browser:
        shots = os.environ.get("MDLC_VIEW_SCREENSHOTS") or work
        os.makedirs(shots, exist_ok=True)
        for model in models:
            try:
                test_model(mdlc, browser, model, work, shots)
            except Failure as failure:
                print(f"FAIL {failure}")
                failures += 1
    print(f"{len(models) - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
