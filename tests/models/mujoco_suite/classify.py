#!/usr/bin/env python3
"""Classifies MuJoCo's own model files for mdlc's MuJoCo suite test.

The files are the MJCF models of MuJoCo's test/ and model/ folders at the
commit the oracle's MuJoCo 3.3.8 comes from (PINNED_COMMIT below). They are
not kept in this repository (README.md says why); a copy of those folders is
found through --suite DIR or the environment variable MDLC_MUJOCO_SUITE_DIR,
and `classify.py extract` makes one from a clone of MuJoCo's repository.

For every .xml file below test/ and model/ this script
  * asks MuJoCo 3.3.8 (tests/oracle/mujoco_js/mujoco_dump.mjs --brief, run by
    Node.js) whether it loads the file, and the size of the model it builds,
  * runs `mdlc compile FILE --emit=plant-json` and records its exit status,
    its first error and how many warnings it gave,
  * reads the file (and the files it includes) for the constructs the plant
    cannot hold or that mdlc does not read yet,
and from that writes one row of manifest.tsv with the expected outcome:

  agree                  MuJoCo loads it, nothing in it is outside the plant:
                         mdlc must compile it and agree body by body
  mujoco-rejects         MuJoCo 3.3.8 refuses it: mdlc must refuse it with a
                         located error, or the note says why mdlc accepts it
  not-held:<construct>   MuJoCo builds something the plant cannot hold (flex,
                         spatial tendon, plugin, sdf geom, skin, composite):
                         mdlc must not crash and must warn about it
  pending:<construct>    a construct mdlc does not read yet but is meant to
                         (the keyframes of an attached model, builtin
                         meshes): the test compares and reports these
                         without failing

Several constructs are joined with '+'. Usage:

  classify.py [--suite DIR] [--mdlc PATH] [--node PATH] --write   rewrite manifest.tsv
  classify.py [--suite DIR] [--mdlc PATH] [--node PATH] --check   exit 1 if it differs
  classify.py extract --git-dir DIR --out DIR   the suite from a MuJoCo clone

The mdlc column (exit status, warnings, first error) describes today's mdlc;
--check compares only the path, outcome and MuJoCo columns, so a change in
mdlc's warnings does not make the manifest stale, while a change of outcome
does.
"""

import argparse
import json
import os
import re
import subprocess
import sys
import tarfile
import io
import xml.etree.ElementTree as ET

PINNED_COMMIT = "6e59f61c70d26a9dc089cdf1b8a3ff6980e5b198"
HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
MANIFEST = os.path.join(HERE, "manifest.tsv")
DUMP_SCRIPT = os.path.join(REPO, "tests", "oracle", "mujoco_js", "mujoco_dump.mjs")
COLUMNS = ["path", "outcome", "mujoco", "mdlc", "note"]

# Constructs whose entities the plant cannot hold: mdlc warns and leaves them
# out. (Order: the first found names the outcome first.)
NOT_HELD = ["flex", "spatial-tendon", "plugin", "sdf-geom", "skin", "composite"]
# Constructs mdlc is being taught to read (issue 62). Meshes written in the
# file ("inline-mesh"), meshes without faces ("point-cloud-mesh") and
# <freejoint align> ("freejoint-align") were here until mdlc read them as
# MuJoCo does, and so were <replicate>, <attach> and keyframes shorter than
# qpos (which mdlc pads as MuJoCo does) until mdlc expanded and read them:
# their files are `agree` now; so were the keyframes of an attached model
# ("attach-keyframe"), which mdlc now attaches with it as MuJoCo does.
# Meshes MuJoCo builds from a builtin shape (<mesh builtin="sphere">) are
# here too: mdlc leaves them out with a warning, though nothing keeps the
# plant from holding them, and no one is teaching mdlc them yet.
PENDING = ["builtin-mesh"]

# Why mdlc may accept a file MuJoCo 3.3.8 refuses, by MuJoCo's error text:
# the refusal is not about anything the plant holds. (A mujoco-rejects file mdlc
# accepts and no entry here explains is reported by the test as a failure.)
ACCEPTED_REJECTIONS = [
    (r"unrecognized attribute: 'sleep(_tolerance)?'",
     "the file is newer than MuJoCo 3.3.8's release (the sleep option came after it, at this "
     "commit still versioned 3.3.8); mdlc ignores <option> settings it does not model"),
    (r"plugin \S+ not found",
     "the oracle's WebAssembly build has no plugins; the plugin is outside the plant, mdlc warns "
     "and leaves it out"),
    (r"not found in (wrap|bodypair)",
     "the file names entities that a replicate or composite of a newer MuJoCo generates (names "
     "MuJoCo 3.3.8's release spells differently): a spatial tendon, outside the plant, which mdlc "
     "leaves out with a warning, or a contact exclusion of an attached model, which mdlc reads "
     "with the names its expansion of the replicate and attach gives the bodies"),
    (r"unknown body '[^']*' in flex",
     "the flex names a body a newer MuJoCo's replicate generates; flex is outside the plant and "
     "mdlc leaves it out with a warning"),
    (r"unrecognized name '[^']*' of sensorized",
     "a fromto sensor between bodies, newer than MuJoCo 3.3.8's release; mdlc does not read "
     "sensors and warns that <sensor> is ignored"),
    (r"invalid keyword: 'quadratic'",
     "a flexcomp option newer than MuJoCo 3.3.8's release; flex is outside the plant and mdlc "
     "leaves it out with a warning"),
    (r"Error reading Nodes header|Invalid node header|Maximum number of nodes|Error reading Elements|"
     r"must be in single block|Node tags must be sequential|Vertex and face data required",
     "the refused part is a flex's gmsh or vertex data, which the plant does not hold: mdlc "
     "leaves the flexcomp out with a warning and never reads the file"),
]


def fail(msg):
    sys.stderr.write("classify.py: " + msg + "\n")
    sys.exit(2)


# --------------------------------------------------------------------- files
def suite_files(suite):
    out = []
    for top in ("test", "model"):
        for dirpath, dirnames, filenames in os.walk(os.path.join(suite, top)):
            dirnames.sort()
            for f in sorted(filenames):
                if f.endswith(".xml"):
                    out.append(os.path.relpath(os.path.join(dirpath, f), suite))
    return sorted(out)


def read_tree(path, seen=None):
    """The file's root element and those of the files it includes or attaches
    models from (paths relative to the file's folder)."""
    seen = set() if seen is None else seen
    if path in seen or not os.path.isfile(path):
        return []
    seen.add(path)
    try:
        root = ET.parse(path).getroot()
    except (ET.ParseError, UnicodeDecodeError):
        return []
    roots = [(path, root)]
    # <include file> and the models <attach> takes (<asset><model file>)
    linked = list(root.iter("include")) + [m for a in root.iter("asset") for m in a.iter("model")]
    for el in linked:
        f = el.get("file", "")
        if f:
            roots.extend(read_tree(os.path.normpath(os.path.join(os.path.dirname(path), f)), seen))
    return roots


def obj_has_faces(path):
    try:
        with open(path, "rb") as f:
            for line in f:
                if line.startswith(b"f "):
                    return True
    except OSError:
        return True  # unreadable: not a point cloud we can tell
    return False


def constructs(path):
    """The NOT_HELD and PENDING constructs the file uses."""
    found = set()
    roots = read_tree(path)
    main_dir = os.path.dirname(path)
    meshdir = ""
    for _, root in roots:
        for c in root.iter("compiler"):
            meshdir = c.get("meshdir", c.get("assetdir", meshdir))
            if c.get("alignfree", "false") == "true":
                found.add("freejoint-align")
    for fpath, root in roots:
        for el in root.iter():
            tag = el.tag if isinstance(el.tag, str) else ""
            if tag in ("flex", "flexcomp") or tag == "deformable" and len(el):
                found.add("flex")
            elif tag == "spatial":
                found.add("spatial-tendon")
            elif tag in ("plugin", "instance") or tag == "extension" and len(el):
                found.add("plugin")
            elif tag == "skin":
                found.add("skin")
            elif tag == "composite":
                found.add("composite")
            elif tag == "geom" and el.get("type") == "sdf":
                found.add("sdf-geom")
            elif tag == "freejoint" and el.get("align") is not None:
                found.add("freejoint-align")
            elif tag == "joint" and el.get("type") == "free" and el.get("align") is not None:
                found.add("freejoint-align")
            elif tag == "mesh" and el.get("builtin") is not None:
                found.add("builtin-mesh")
            elif tag == "mesh" and el.get("vertex") is not None:
                found.add("inline-mesh" if el.get("face") is not None else "point-cloud-mesh")
            elif tag == "mesh" and el.get("file", "").lower().endswith(".obj"):
                f = os.path.join(main_dir, meshdir, el.get("file"))
                if not obj_has_faces(f):
                    found.add("point-cloud-mesh")
    return found


# ------------------------------------------------------------------- running
def mujoco_brief(node, suite, files):
    """MuJoCo 3.3.8's brief dump of every file, by relative path."""
    paths = [os.path.join(os.path.abspath(suite), f) for f in files]
    r = subprocess.run([node, DUMP_SCRIPT, "--brief", "--serve"], input="\n".join(paths) + "\n",
                       capture_output=True, text=True, timeout=1800)
    if r.returncode != 0:
        fail("mujoco_dump.mjs failed: " + r.stderr[:2000])
    lines = r.stdout.splitlines()
    if len(lines) != len(files):
        fail("mujoco_dump.mjs answered %d of %d files" % (len(lines), len(files)))
    return {f: json.loads(line) for f, line in zip(files, lines)}


def run_mdlc(mdlc, suite, rel):
    try:
        r = subprocess.run([mdlc, "compile", rel, "--emit=plant-json"], cwd=suite,
                           capture_output=True, text=True, timeout=300)
    except subprocess.TimeoutExpired:
        return None, "", "timed out"
    return r.returncode, r.stderr, ""


def one_line(s, n=160):
    s = " ".join(s.split())
    return s if len(s) <= n else s[: n - 3] + "..."


def classify(suite, mdlc, node):
    files = suite_files(suite)
    if not files:
        fail("no test/ or model/ .xml files below " + suite)
    mj = mujoco_brief(node, suite, files)
    rows = []
    for rel in files:
        d = mj[rel]
        if d.get("ok"):
            mj_col = "loads: nbody=%d njnt=%d nv=%d" % (d["nbody"], d["njnt"], d["nv"])
        else:
            mj_col = "rejects: " + one_line(d.get("error", "?").replace("\t", " "))
        found = constructs(os.path.join(suite, rel))
        code, err, why = run_mdlc(mdlc, suite, rel)
        if code is None:
            mdlc_col = "timed out"
        else:
            warnings = len(re.findall(r": warning: ", err))
            errors = [l.split(": error: ", 1)[1] for l in err.splitlines() if ": error: " in l]
            mdlc_col = "exit %d, %d warnings" % (code, warnings)
            if code < 0 or code > 1:
                mdlc_col = "CRASH " + mdlc_col
            if errors:
                mdlc_col += ", error: " + one_line(errors[0], 120)
        not_held = [c for c in NOT_HELD if c in found]
        pending = [c for c in PENDING if c in found]
        note = ""
        if not d.get("ok") and re.search(r"plugin \S+ not found", d.get("error", "")):
            not_held = not_held or ["plugin"]
        if not_held:
            outcome = "not-held:" + "+".join(not_held)
        elif not d.get("ok"):
            outcome = "mujoco-rejects"
        elif pending:
            outcome = "pending:" + "+".join(pending)
        else:
            outcome = "agree"
        if not d.get("ok"):
            for pattern, why_accepts in ACCEPTED_REJECTIONS:
                if re.search(pattern, d.get("error", "")):
                    note = "mdlc may accept it: " + why_accepts
                    break
        if outcome.startswith("not-held") and pending:
            note = (note + "; " if note else "") + "also uses " + "+".join(pending)
        rows.append([rel, outcome, mj_col, mdlc_col, note])
    return rows


def format_rows(rows):
    head = ("# MuJoCo's own test/ and model/ MJCF files at google-deepmind/mujoco@%s\n"
            "# (MuJoCo 3.3.8), with the outcome mdlc's suite test expects; written by classify.py,\n"
            "# do not edit by hand. Columns: path (below the MuJoCo tree), outcome, what MuJoCo\n"
            "# 3.3.8 makes of it, what mdlc made of it when the manifest was written, note.\n"
            % PINNED_COMMIT)
    out = head + "\t".join(COLUMNS) + "\n"
    for r in rows:
        out += "\t".join(c.replace("\t", " ") for c in r) + "\n"
    return out


def read_manifest():
    rows = []
    with open(MANIFEST, encoding="utf-8") as f:
        for line in f:
            if line.startswith("#") or line.startswith("path\t"):
                continue
            rows.append(line.rstrip("\n").split("\t"))
    return rows


# ------------------------------------------------------------------- extract
SKIP_EXT = (".cc", ".h", ".py", ".sh", ".bzl", ".bazel", ".txt", ".md", ".usda")


def extract(git_dir, out):
    """test/ and model/ at PINNED_COMMIT with MuJoCo's LICENSE, less the
    C++, Python and build sources: the models and the assets they load."""
    r = subprocess.run(["git", "--git-dir", git_dir, "archive", "--format=tar", PINNED_COMMIT,
                        "LICENSE", "test", "model"], capture_output=True)
    if r.returncode != 0:
        fail("git archive failed: " + r.stderr.decode(errors="replace")[:500])
    n = 0
    with tarfile.open(fileobj=io.BytesIO(r.stdout)) as tar:
        members = [m for m in tar.getmembers()
                   if m.isdir() or (m.isfile() and not m.name.endswith(SKIP_EXT))]
        tar.extractall(out, members=members)
        n = sum(1 for m in members if m.isfile())
    print("extracted %d files of google-deepmind/mujoco@%s into %s" % (n, PINNED_COMMIT, out))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("command", nargs="?", choices=["extract"])
    ap.add_argument("--git-dir")
    ap.add_argument("--out")
    ap.add_argument("--suite", default=os.environ.get("MDLC_MUJOCO_SUITE_DIR", ""))
    ap.add_argument("--mdlc", default=os.environ.get("MDLC_BINARY",
                                                     os.path.join(REPO, "build", "tools", "mdlc", "mdlc")))
    ap.add_argument("--node", default=os.environ.get("MDLC_NODE", "node"))
    ap.add_argument("--write", action="store_true")
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()
    if a.command == "extract":
        if not a.git_dir or not a.out:
            fail("extract needs --git-dir and --out")
        extract(a.git_dir, a.out)
        return 0
    if not a.suite or not os.path.isdir(os.path.join(a.suite, "model")):
        fail("no MuJoCo tree: give --suite DIR or MDLC_MUJOCO_SUITE_DIR (see README.md)")
    if a.write == a.check:
        fail("give exactly one of --write and --check")
    rows = classify(os.path.abspath(a.suite), os.path.abspath(a.mdlc), a.node)
    if a.write:
        with open(MANIFEST, "w", encoding="utf-8") as f:
            f.write(format_rows(rows))
        counts = {}
        for r in rows:
            key = r[1].split(":")[0]
            counts[key] = counts.get(key, 0) + 1
        print("wrote %d rows: %s" % (len(rows), ", ".join("%s %d" % kv for kv in sorted(counts.items()))))
        return 0
    old = {r[0]: r for r in read_manifest()}
    new = {r[0]: r for r in rows}
    diffs = []
    for path in sorted(set(old) | set(new)):
        o, n = old.get(path), new.get(path)
        if o is None or n is None:
            diffs.append("%s: %s" % (path, "not in the manifest" if o is None else "no longer in the suite"))
        elif o[1:3] != n[1:3]:
            diffs.append("%s: manifest says %s | %s, now %s | %s" % (path, o[1], o[2], n[1], n[2]))
    for d in diffs:
        print(d)
    print("%d files, %d differ from manifest.tsv" % (len(new), len(diffs)))
    return 1 if diffs else 0


if __name__ == "__main__":
    sys.exit(main())
