#!/usr/bin/env python3
"""plant-json's reference page names every key the writer prints (issue 58).

Compiles every model under the given folders with --emit=plant-json, gathers
each key that appears (outside geometry `properties`, whose keys are the
source's own Drake property names), and fails when backend/plant_json.md does
not name one of them as `key`. Also checks that the page's table of top-level
keys is in the order the writer prints them.

usage: plant_json_doc_test.py MDLC PLANT_JSON_MD FOLDER...
"""
import json
import os
import re
import subprocess
import sys

MODEL_SUFFIXES = (".urdf", ".sdf", ".xml", ".dmd.yaml")


def model_files(folders):
    for folder in folders:
        for root, _, names in sorted(os.walk(folder)):
            for name in sorted(names):
                if name.endswith(MODEL_SUFFIXES):
                    yield os.path.join(root, name)


def keys_in(value, found, path=""):
    """Adds every object key under `value` to found[key] = first path seen."""
    if isinstance(value, dict):
        for key, child in value.items():
            found.setdefault(key, path or "top level")
            if key != "properties":
                keys_in(child, found, f"{path}.{key}" if path else key)
    elif isinstance(value, list):
        for child in value:
            keys_in(child, found, path)


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    mdlc, page_path, folders = sys.argv[1], sys.argv[2], sys.argv[3:]
    with open(page_path, encoding="utf-8") as f:
        page = f.read()
    # a key is named as `key`, or quoted inside a code span: `{"p": [x, y, z]}`
    spans = re.findall(r"`([^`]+)`", page)
    named = {s for s in spans if re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", s)}
    for span in spans:
        named.update(re.findall(r'"([A-Za-z_][A-Za-z0-9_]*)"\s*:', span))

    found = {}
    top_level_orders = []
    compiled = 0
    for model in model_files(folders):
        run = subprocess.run([mdlc, "compile", model, "--emit=plant-json", "--no-cache"],
                             capture_output=True, text=True, timeout=60)
        if run.returncode != 0:
            continue  # models that need packages or are meant to fail
        dump = json.loads(run.stdout)
        compiled += 1
        keys_in(dump, found)
        top_level_orders.append(list(dump.keys()))

    failures = []
    if compiled < 20:
        failures.append(f"only {compiled} models compiled; the check needs a broad sample")
    for key, where in sorted(found.items()):
        if key not in named:
            failures.append(f"plant-json prints `{key}` (in {where}) but {os.path.basename(page_path)} "
                            "does not name it")

    # the table of top-level keys lists them in the order the writer prints them
    table = re.search(r"## Top level, in the order printed\n(.*?)\n## ", page, re.S)
    documented = re.findall(r"^\| `([a-z_]+)` \|", table.group(1), re.M) if table else []
    if not documented:
        failures.append("the page has no table of top-level keys")
    for order in top_level_orders:
        printed = [k for k in order if k in documented]
        expected = [k for k in documented if k in order]
        if printed != expected:
            failures.append(f"top-level keys printed as {printed}, documented as {expected}")
            break
        unlisted = [k for k in order if k not in documented]
        if unlisted:
            failures.append(f"top-level keys missing from the table: {unlisted}")
            break

    print(f"{compiled} models compiled, {len(found)} distinct keys, "
          f"{len(documented)} top-level keys documented")
    for failure in failures:
        print("FAIL:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
