#!/usr/bin/env python3
"""Times the xacro stage on the real robots of the shared xacro corpus.

    tests/bench/xacro_bench.py MDLC SHARED_DIR [--xacro CMD] [--top N] [--runs K]

For the N entries with the largest reference expansions, the fastest of K runs of
  - `mdlc xacro` (expansion to XML text, as the xacro command does),
  - CMD with the same file and arguments, when --xacro names a xacro command
    (ros/xacro is not a dependency of mdlc: pass the command of one you have,
    e.g. `--xacro "xacro"`; `$(find)` must resolve for it as the corpus says),
  - `mdlc compile FILE.xacro --emit=none` against `mdlc compile` of the
    reference expansion (a .urdf): the whole compile of a .xacro against the
    compile of its expanded text.
Whole processes are timed, start-up included, as a user runs them. Timings are
reported, never asserted; the goals are in the README (xacro section).
"""
import argparse
import os
import shlex
import statistics
import subprocess
import sys
import tempfile
import time


def best_of(command, runs, cwd=None):
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        done = subprocess.run(command, cwd=cwd, stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, text=True)
        times.append(time.perf_counter() - start)
        if done.returncode != 0:
            return None, done.stderr.strip().splitlines()[:1]
    return min(times), None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('mdlc')
    parser.add_argument('shared')
    parser.add_argument('--xacro', help='a xacro command to compare with')
    parser.add_argument('--xacro-package-flags', action='store_true',
                        help='give the xacro command the packages as --package NAME=DIR too '
                             '(a wrapper that maps them for $(find))')
    parser.add_argument('--top', type=int, default=6)
    parser.add_argument('--runs', type=int, default=5)
    args = parser.parse_args()

    corpus = os.path.realpath(os.path.join(args.shared, 'corpus', 'xacro'))
    manifest = os.path.join(corpus, 'manifest.tsv')
    if not os.path.exists(manifest):
        print(f'no xacro corpus under {args.shared}; nothing to time')
        return 77
    rows = [line.rstrip('\n').split('\t') for line in open(manifest)]
    header, rows = rows[0], [dict(zip(rows[0], r)) for r in rows[1:]]
    for row in rows:
        row['size'] = os.path.getsize(os.path.join(corpus, row['expanded']))
    rows.sort(key=lambda r: -r['size'])

    print(f'{"entry":58} {"KiB":>5} {"mdlc xacro":>10} {"xacro":>8} {"x":>6} '
          f'{"compile .xacro":>14} {"compile .urdf":>13} {"ratio":>6}')
    speedups, ratios = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for row in rows[:args.top]:
            path = os.path.join(corpus, row['path'])
            xacro_args = row['args'].split()
            packages = []
            for definition in filter(None, row['packages'].split(';')):
                name, folder = definition.split('=', 1)
                packages += ['--package', f'{name}={os.path.join(corpus, folder)}']
            expand, error = best_of([args.mdlc, 'xacro', path, *xacro_args, *packages,
                                     '-o', os.devnull], args.runs)
            if expand is None:
                print(f'{row["path"]}: mdlc xacro failed: {error}')
                continue
            reference = None
            if args.xacro:
                extra = packages if args.xacro_package_flags else []
                reference, error = best_of(shlex.split(args.xacro) + extra + [path, *xacro_args],
                                           args.runs)
                if reference is None:
                    print(f'{row["path"]}: the xacro command failed: {error}')
            # the reference expansion, with the corpus's root put back
            text = open(os.path.join(corpus, row['expanded'])).read()
            urdf = os.path.join(tmp, os.path.basename(row['expanded']))
            with open(urdf, 'w') as out:
                out.write(text.replace('/media/xacro-corpus', corpus))
            compile_flags = [*packages, '--emit=none', '--no-cache']
            compile_xacro, _ = best_of([args.mdlc, 'compile', path, *xacro_args,
                                        *compile_flags], args.runs)
            compile_urdf, _ = best_of([args.mdlc, 'compile', urdf, *compile_flags], args.runs)
            speedup = reference / expand if reference else None
            ratio = (compile_xacro / compile_urdf
                     if compile_xacro is not None and compile_urdf else None)
            if speedup:
                speedups.append(speedup)
            if ratio:
                ratios.append(ratio)

            def ms(t):
                return f'{t * 1e3:.1f} ms' if t is not None else '-'
            print(f'{row["path"][:58]:58} {row["size"] // 1024:5} {ms(expand):>10} '
                  f'{ms(reference):>8} {f"{speedup:.0f}x" if speedup else "-":>6} '
                  f'{ms(compile_xacro):>14} {ms(compile_urdf):>13} '
                  f'{f"{ratio:.2f}" if ratio else "-":>6}')
    if speedups:
        print(f'mdlc xacro against the xacro command: {min(speedups):.0f}x to '
              f'{max(speedups):.0f}x faster (median {statistics.median(speedups):.0f}x)')
    if ratios:
        print(f'compile of a .xacro over compile of its expansion: {min(ratios):.2f} to '
              f'{max(ratios):.2f} (median {statistics.median(ratios):.2f})')
    return 0


if __name__ == '__main__':
    sys.exit(main())
