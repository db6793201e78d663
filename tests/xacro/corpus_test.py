#!/usr/bin/env python3
"""Checks `mdlc xacro` and `mdlc compile` of .xacro files against the xacro
corpus: SHARED_DIR/corpus/xacro (its README.md describes it).

usage: corpus_test.py MDLC_BINARY SHARED_DIR [--only SUBSTRING] [--keep DIR]
                      [--expand-only] [--timeout S]

For every row of manifest.tsv (path, args, packages, expanded, ...):

1. Expansion: from the corpus folder, runs
       mdlc xacro ABS_PATH ARGS... --package NAME=ABS_DIR ... -o OUT
   (ABS_PATH and ABS_DIR: the manifest's paths made absolute under the
   symlink-resolved corpus folder). The reference expansion was made with the
   corpus folder seen as /media/xacro-corpus and the top-level file given by
   its absolute path there; its line 2 is a comment the corpus added. The
   test replaces /media/xacro-corpus by the corpus folder in the reference,
   drops line 2, and compares with xml_compare.py.
2. Plant: compiles the .xacro (mdlc compile ABS_PATH ARGS... --package ...
   --emit=plant-json -o A.json) and the fixed reference (written to a
   temporary .urdf file, compiled with the same --package flags) and requires
   identical plant-json bytes. When both compiles fail with the same error
   messages (locations aside: one points into .xacro files, the other into
   the expansion), the entry passes as "same-error": some corpus robots do
   not compile whatever reads them (the corpus leaves out meshes over 500 kB,
   see meshes_skipped.tsv; one robot names an undefined material). --expand-only skips this half.

Prints one line per entry and summary counts; exits 0 only when every entry
passes, 77 (ctest's skip code) when the corpus is absent.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import xml_compare  # noqa: E402

VIRTUAL_ROOT = b'/media/xacro-corpus'
SKIP = 77


def read_manifest(path):
    with open(path, encoding='utf-8') as f:
        header = f.readline().rstrip('\n').split('\t')
        need = ['path', 'args', 'packages', 'expanded']
        missing = [c for c in need if c not in header]
        if missing:
            raise SystemExit('%s: no column(s) %s' % (path, ', '.join(missing)))
        rows = []
        for line in f:
            line = line.rstrip('\n')
            if not line.strip():
                continue
            cols = line.split('\t')
            cols += [''] * (len(header) - len(cols))
            rows.append(dict(zip(header, cols)))
    return rows


def fix_reference(data, corpus_dir):
    """The reference as xacro would write it here: real root, no line 2."""
    return xml_compare.drop_line2_comment(data).replace(VIRTUAL_ROOT, corpus_dir.encode())


ERROR_LINE = re.compile(r'^\S.*?:\d+:\d+: error: (.*)$')


def error_messages(stderr):
    """The messages of the located errors, without their locations (which
    differ: one points into .xacro files, the other into the expansion)."""
    return [m.group(1) for m in map(ERROR_LINE.match, stderr.splitlines()) if m]


def run(cmd, cwd, timeout):
    """Returns (exit status or None, a one-line message, the error messages)."""
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, errors='replace',
                           timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, 'timed out after %d s' % timeout, []
    if p.returncode != 0:
        lines = [l for l in p.stderr.splitlines() if l.strip()]
        errors = [l for l in lines if 'error' in l] or lines
        return p.returncode, 'exit %d: %s' % (p.returncode, errors[0] if errors else '(no message)'), \
            error_messages(p.stderr)
    return 0, '', []


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('mdlc')
    ap.add_argument('shared_dir')
    ap.add_argument('--only', metavar='SUBSTRING', help='check only the entries whose path or expansion contains this')
    ap.add_argument('--keep', metavar='DIR', help='write the outputs here and keep them')
    ap.add_argument('--expand-only', action='store_true', help='skip the plant-json half')
    ap.add_argument('--timeout', type=int, default=300, help='seconds per mdlc run')
    args = ap.parse_args()

    corpus_dir = os.path.join(args.shared_dir, 'corpus', 'xacro')
    manifest = os.path.join(corpus_dir, 'manifest.tsv')
    if not os.path.isfile(manifest):
        print('skipped: no xacro corpus (%s not found)' % manifest)
        return SKIP
    corpus_dir = os.path.realpath(corpus_dir)
    mdlc = os.path.abspath(args.mdlc) if os.sep in args.mdlc else args.mdlc
    rows = read_manifest(manifest)
    if args.only:
        rows = [r for r in rows if args.only in r['path'] or args.only in r['expanded']]
    if not rows:
        print('no entries to check')
        return 1

    if args.keep:
        out_dir = os.path.abspath(args.keep)
        os.makedirs(out_dir, exist_ok=True)
    else:
        out_dir = tempfile.mkdtemp(prefix='mdlc-xacro-corpus-')

    counts = dict(expand_same=0, expand_different=0, expand_failed=0,
                  plant_same=0, plant_same_error=0, plant_different=0, plant_failed=0)
    failed = []
    try:
        for row in rows:
            ok = True
            src = os.path.join(corpus_dir, row['path'])
            ref = os.path.join(corpus_dir, row['expanded'])
            xargs = row['args'].split()
            pkgs = []
            for p in filter(None, row['packages'].split(';')):
                name, _, d = p.partition('=')
                pkgs += ['--package', '%s=%s' % (name, os.path.join(corpus_dir, d))]
            # one name per entry: the reference's own, which is unique
            stem = row['expanded'].replace('/', '__')
            if stem.endswith('.expanded.urdf'):
                stem = stem[:-len('.expanded.urdf')]
            out = os.path.join(out_dir, stem + '.xacro-out.urdf')
            fixed_ref = os.path.join(out_dir, stem + '.reference.urdf')

            rc, msg, _ = run([mdlc, 'xacro', src] + xargs + pkgs + ['-o', out], corpus_dir, args.timeout)
            if rc != 0:
                expand = 'expand failed (%s)' % msg
                counts['expand_failed'] += 1
                ok = False
            else:
                try:
                    diff = xml_compare.compare_files(
                        ref, out, expected_filter=lambda d: fix_reference(d, corpus_dir))
                except xml_compare.XmlError as e:
                    diff = (str(e), '', '')
                if diff:
                    expand = 'expand different at ' + xml_compare.format_diff(diff)
                    counts['expand_different'] += 1
                    ok = False
                else:
                    expand = 'expand same'
                    counts['expand_same'] += 1

            plant = ''
            if not args.expand_only:
                with open(ref, 'rb') as f:
                    data = fix_reference(f.read(), corpus_dir)
                with open(fixed_ref, 'wb') as f:
                    f.write(data)
                a_json = os.path.join(out_dir, stem + '.xacro.plant.json')
                b_json = os.path.join(out_dir, stem + '.reference.plant.json')
                ra, ma, ea = run([mdlc, 'compile', src] + xargs + pkgs + ['--emit=plant-json', '-o', a_json],
                             corpus_dir, args.timeout)
                rb, mb, eb = run([mdlc, 'compile', fixed_ref] + pkgs + ['--emit=plant-json', '-o', b_json],
                             corpus_dir, args.timeout)
                if ra is not None and rb is not None and ra > 0 and rb > 0 and ea and ea == eb:
                    # both refuse the model with the same errors
                    plant = 'plant same-error (both fail: %s)' % ea[0]
                    counts['plant_same_error'] += 1
                elif ra != 0 or rb != 0:
                    plant = 'plant compile-failed (%s)' % '; '.join(
                        w + ': ' + m for w, r, m in (('xacro', ra, ma), ('reference', rb, mb)) if r != 0)
                    counts['plant_failed'] += 1
                    ok = False
                else:
                    with open(a_json, 'rb') as fa, open(b_json, 'rb') as fb:
                        same = fa.read() == fb.read()
                    plant = 'plant same' if same else 'plant different (%s vs %s)' % (a_json, b_json)
                    counts['plant_same' if same else 'plant_different'] += 1
                    ok = ok and same
            print('%s %s: %s%s' % ('PASS' if ok else 'FAIL', row['path'] + (' ' + row['args'] if row['args'] else ''),
                                   expand, ', ' + plant if plant else ''), flush=True)
            if not ok:
                failed.append(row['expanded'])
    finally:
        if not args.keep:
            shutil.rmtree(out_dir, ignore_errors=True)

    print('xacro corpus: %d entries; expansion: %d same, %d different, %d failed'
          % (len(rows), counts['expand_same'], counts['expand_different'], counts['expand_failed']))
    if not args.expand_only:
        print('plant-json: %d same, %d same-error, %d different, %d compile-failed'
              % (counts['plant_same'], counts['plant_same_error'], counts['plant_different'],
                 counts['plant_failed']))
    print('%d passed, %d failed' % (len(rows) - len(failed), len(failed)))
    return 0 if not failed else 1


if __name__ == '__main__':
    sys.exit(main())
