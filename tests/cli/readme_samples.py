#!/usr/bin/env python3
"""The README's sample outputs are real (issue 15): each block that follows a
`<!-- sample: ARGS -->` line is what `mdlc ARGS` prints, run from the
repository root. Fails with a diff when one is not; with --write, rewrites
the blocks (and renders the kinematic graph image) instead.

    readme_samples.py MDLC REPOSITORY [--write]
"""
import difflib
import os
import re
import shlex
import shutil
import subprocess
import sys

MARKER = re.compile(r"^<!-- sample: (.*) -->$")
# the rendered graph in the README, and the example it shows
GRAPH_IMAGE = "examples/graph_scara_arm.svg"
GRAPH_ARGS = ["graph", "examples/urdf/scara_arm.urdf"]


def run(mdlc, repo, args):
    out = subprocess.run([mdlc] + args, cwd=repo, capture_output=True, text=True, check=True)
    return out.stdout.splitlines()


def blocks(lines):
    """(marker index, first block line, end) of each sample: the indented
    block after the marker, blank lines inside it included."""
    for i, line in enumerate(lines):
        match = MARKER.match(line)
        if not match:
            continue
        start = i + 1
        while start < len(lines) and not lines[start].strip():
            start += 1
        end = start
        while end < len(lines) and (lines[end].startswith("    ") or not lines[end].strip()):
            end += 1
        while end > start and not lines[end - 1].strip():
            end -= 1
        yield match.group(1), start, end


def main():
    mdlc, repo = sys.argv[1], sys.argv[2]
    write = "--write" in sys.argv[3:]
    readme_path = os.path.join(repo, "README.md")
    with open(readme_path, encoding="utf-8") as f:
        lines = f.read().split("\n")

    failures, samples = [], list(blocks(lines))
    if not samples:
        print("README.md has no <!-- sample: ... --> blocks")
        return 1
    for args, start, end in reversed(samples):  # from the end: edits keep earlier indices
        expected = [("    " + l).rstrip() for l in run(mdlc, repo, shlex.split(args))]
        shown = [l.rstrip() for l in lines[start:end]]
        if shown == expected:
            continue
        if write:
            lines[start:end] = expected
        else:
            failures.append(f"README sample 'mdlc {args}' differs from the real output:\n" +
                            "\n".join(difflib.unified_diff(shown, expected, "README.md",
                                                           f"mdlc {args}", lineterm="")))

    image = os.path.join(repo, GRAPH_IMAGE)
    if write:
        with open(readme_path, "w", encoding="utf-8") as f:
            f.write("\n".join(lines))
        if shutil.which("dot"):
            subprocess.run([mdlc] + GRAPH_ARGS + ["-o", image], cwd=repo, check=True)
        print(f"rewrote {len(samples)} samples" + (f" and {GRAPH_IMAGE}" if shutil.which("dot") else ""))
        return 0

    # the image shows the graph of today's example: each body is in it
    with open(image, encoding="utf-8") as f:
        svg = f.read()
    for line in run(mdlc, repo, GRAPH_ARGS):
        node = re.match(r'^  "([^"]+)" \[label=', line)
        if node and f">{node.group(1)}</text>" not in svg:
            failures.append(f"{GRAPH_IMAGE} has no node '{node.group(1)}': rerun with --write")
    for failure in failures:
        print(failure)
    print(f"{len(samples)} README samples checked, {len(failures)} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
