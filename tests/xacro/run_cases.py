#!/usr/bin/env python3
"""Runs `mdlc xacro` on every case of CASES_DIR/manifest.tsv (see README.md).

usage: run_cases.py MDLC_BINARY CASES_DIR [--only SUBSTRING] [--keep DIR] [-v]

For each row (case, args, packages, expect, note), from CASES_DIR:

    MDLC_BINARY xacro CASE [NAME:=VALUE ...] [--package NAME=DIR ...] -o OUT

- CASE is given as the relative path in the manifest, so the banner comment
  names it the way the expected output does.
- Package dirs are given absolute (CASES_DIR/DIR, with symlinks resolved).
  The expected outputs were made with the cases folder seen as the virtual
  root /xacro-cases: every absolute path xacro wrote ($(find), $(cwd)) starts
  with it. The runner replaces /xacro-cases by the real, symlink-resolved
  CASES_DIR in the expected output before comparing.
- The environment has MDLC_XACRO_TEST_ENV=from-env and no
  MDLC_XACRO_TEST_UNSET, for the $(env)/$(optenv) cases.
- expect=ok: the exit status must be 0 and OUT the same XML as
  CASE-without-.xacro + .expected.xml (xml_compare.py).
- expect=error: the exit status must not be 0 and stderr must hold a
  located diagnostic `FILE.xacro:LINE:COL: error:`. The note column holds
  xacro's own first message line, for people; mdlc's words are its own.

Prints one line per case and a summary; exits 0 only when every case passes.
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

VIRTUAL_ROOT = b'/xacro-cases'
LOCATED_ERROR = re.compile(r'\S*\.xacro:\d+:\d+: error:')


def read_manifest(path):
    rows = []
    with open(path, encoding='utf-8') as f:
        header = f.readline().rstrip('\n').split('\t')
        if header[:4] != ['case', 'args', 'packages', 'expect']:
            raise SystemExit('%s: unexpected header %r' % (path, header))
        for n, line in enumerate(f, 2):
            line = line.rstrip('\n')
            if not line.strip() or line.startswith('#'):
                continue
            cols = line.split('\t')
            cols += [''] * (5 - len(cols))
            case, args, packages, expect, note = cols[:5]
            if expect not in ('ok', 'error'):
                raise SystemExit('%s:%d: expect must be ok or error, not %r' % (path, n, expect))
            rows.append(dict(case=case, args=args.split(), packages=[p for p in packages.split(';') if p],
                             expect=expect, note=note))
    return rows


def run_case(mdlc, cases_dir, row, out_dir, env, timeout):
    case = row['case']
    out = os.path.join(out_dir, case.replace('/', '_')[:-len('.xacro')] + '.xml')
    cmd = [mdlc, 'xacro', case] + row['args']
    for p in row['packages']:
        name, _, d = p.partition('=')
        cmd += ['--package', '%s=%s' % (name, os.path.join(cases_dir, d))]
    cmd += ['-o', out]
    try:
        p = subprocess.run(cmd, cwd=cases_dir, env=env, capture_output=True, text=True,
                           errors='replace', timeout=timeout)
    except subprocess.TimeoutExpired:
        return False, 'timed out after %d s' % timeout
    if row['expect'] == 'error':
        if p.returncode == 0:
            return False, 'expected an error, mdlc succeeded'
        if p.returncode < 0:
            return False, 'mdlc died of signal %d' % -p.returncode
        if not LOCATED_ERROR.search(p.stderr):
            first = p.stderr.strip().splitlines()[:1]
            return False, 'no located "FILE.xacro:LINE:COL: error:" diagnostic (stderr: %s)' % (
                first[0] if first else 'empty')
        return True, 'error as expected'
    if p.returncode != 0:
        first = p.stderr.strip().splitlines()[:3]
        return False, 'exit %d: %s' % (p.returncode, ' | '.join(first))
    expected = os.path.join(cases_dir, case[:-len('.xacro')] + '.expected.xml')
    root = cases_dir.encode()
    try:
        diff = xml_compare.compare_files(expected, out,
                                         expected_filter=lambda data: data.replace(VIRTUAL_ROOT, root))
    except xml_compare.XmlError as e:
        return False, str(e)
    if diff:
        return False, 'different at ' + xml_compare.format_diff(diff)
    return True, 'same'


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('mdlc')
    ap.add_argument('cases_dir')
    ap.add_argument('--only', metavar='SUBSTRING', help='run only the cases whose name contains this')
    ap.add_argument('--keep', metavar='DIR', help='write the outputs here and keep them')
    ap.add_argument('--timeout', type=int, default=60)
    args = ap.parse_args()

    mdlc = os.path.abspath(args.mdlc) if os.sep in args.mdlc else args.mdlc
    cases_dir = os.path.realpath(args.cases_dir)
    rows = read_manifest(os.path.join(cases_dir, 'manifest.tsv'))
    if args.only:
        rows = [r for r in rows if args.only in r['case']]
    env = dict(os.environ, MDLC_XACRO_TEST_ENV='from-env')
    env.pop('MDLC_XACRO_TEST_UNSET', None)

    if args.keep:
        out_dir = os.path.abspath(args.keep)
        os.makedirs(out_dir, exist_ok=True)
    else:
        out_dir = tempfile.mkdtemp(prefix='mdlc-xacro-cases-')
    failed = []
    try:
        for row in rows:
            ok, what = run_case(mdlc, cases_dir, row, out_dir, env, args.timeout)
            print('%s %-40s %s' % ('PASS' if ok else 'FAIL', row['case'], what), flush=True)
            if not ok:
                failed.append(row['case'])
    finally:
        if not args.keep:
            shutil.rmtree(out_dir, ignore_errors=True)
    n_ok = sum(1 for r in rows if r['expect'] == 'ok')
    print('xacro cases: %d run (%d ok, %d error), %d passed, %d failed'
          % (len(rows), n_ok, len(rows) - n_ok, len(rows) - len(failed), len(failed)))
    if failed:
        print('failed: ' + ' '.join(failed))
    return 0 if rows and not failed else 1


if __name__ == '__main__':
    sys.exit(main())
