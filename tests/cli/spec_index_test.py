#!/usr/bin/env python3
"""The feature IDs the sources cite are the ones tests/spec_index.md lists.

Sources and tests cite the feature checklist by ID (`URDF-012`, `EXT-060`).
The checklist itself lives outside the repository, so the repository ships an
index of the IDs. This fails when a source cites an ID the index does not
list (a typo, or a feature added without its index line), when the index
lists an ID no test cites (a feature nothing pins), and, when the checklist
is at hand (SPEC given and present), when the index and the checklist do not
hold the same IDs.

usage: spec_index_test.py SOURCE_DIR [SPEC]
"""
import os
import re
import sys

ID = re.compile(r"\b(COMMON|URDF|SDF|MJCF|DMD|EXT|BEYOND)-\d{3}\b")
SOURCE_FOLDERS = ("frontend", "ir", "passes", "backend", "tools", "tests", "examples")
SUFFIXES = (".h", ".cc", ".py", ".cmake", ".txt", ".urdf", ".sdf", ".xml", ".yaml",
            ".xacro", ".md", ".js")


def cited_ids(root, folder, skip):
    """{id: first file citing it} for the files under root/folder."""
    found = {}
    for here, dirs, names in os.walk(os.path.join(root, folder)):
        dirs[:] = sorted(d for d in dirs if d != "node_modules")
        for name in sorted(names):
            path = os.path.join(here, name)
            if not name.endswith(SUFFIXES) or os.path.samefile(path, skip):
                continue
            with open(path, encoding="utf-8", errors="replace") as f:
                for match in ID.finditer(f.read()):
                    found.setdefault(match.group(0), os.path.relpath(path, root))
    return found


def main():
    root = sys.argv[1]
    index_path = os.path.join(root, "tests", "spec_index.md")
    with open(index_path, encoding="utf-8") as f:
        listed = re.findall(r"^- ((?:[A-Z]+)-\d{3}):", f.read(), re.M)
    problems = []
    if len(listed) != len(set(listed)):
        problems.append("the index lists an ID twice")
    listed = set(listed)
    cited = {}
    for folder in SOURCE_FOLDERS:
        for id_, where in cited_ids(root, folder, index_path).items():
            cited.setdefault(id_, where)
    cited_by_tests = cited_ids(root, "tests", index_path)
    for id_ in sorted(set(cited) - listed):
        problems.append(f"{cited[id_]} cites {id_}, which tests/spec_index.md does not list")
    for id_ in sorted(listed - set(cited_by_tests)):
        problems.append(f"tests/spec_index.md lists {id_}, which no test cites")
    if len(sys.argv) > 2 and os.path.exists(sys.argv[2]):
        with open(sys.argv[2], encoding="utf-8") as f:
            spec = set(re.findall(r"^- \*\*([A-Z]+-\d{3})\*\*", f.read(), re.M))
        for id_ in sorted(spec - listed):
            problems.append(f"the checklist has {id_}, which the index does not list")
        for id_ in sorted(listed - spec):
            problems.append(f"the index lists {id_}, which the checklist does not have")
    if not listed or not cited:
        problems.append("found no IDs: the index or the sources were not read")
    for problem in problems:
        print(f"spec_index_test: {problem}")
    print(f"{len(listed)} IDs listed, {len(cited)} cited, {len(cited_by_tests)} by tests")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
