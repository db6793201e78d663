#!/bin/sh
# check_parallel.sh - how much faster `mdlc check -j N` is than a serial
# check of the same folder (issue 15). Runs each REPS times, alternating
# serial and parallel so machine load hits both alike, and prints the median
# wall time and the median CPU time (user + sys) of each, and the speedup.
# Needs GNU time (/usr/bin/time). A timing, so a benchmark: never run as a
# test.
#
#   tests/bench/check_parallel.sh MDLC DIR [JOBS [REPS]] [-- EXTRA CHECK FLAGS]
#   tests/bench/check_parallel.sh build/tools/mdlc/mdlc ../shared/corpus 2 5 \
#       -- --package-path ../shared/corpus
set -eu

if [ $# -lt 2 ]; then
  sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
fi
mdlc=$1
dir=$2
jobs=${3:-2}
reps=${4:-5}
shift $(( $# < 4 ? $# : 4 ))
[ "${1:-}" = "--" ] && shift

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# one run: "wall cpu" in seconds (GNU time: elapsed, user + system)
run() {
  /usr/bin/time -f '%e %U %S' -o "$tmp/time" "$@" >/dev/null 2>&1 || true
  tail -n 1 "$tmp/time" | awk '{ printf "%.3f %.3f\n", $1, $2 + $3 }'
}

median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

files=$("$mdlc" check "$dir" --format json -j "$jobs" "$@" 2>/dev/null | wc -l)
i=0
while [ $i -lt "$reps" ]; do
  run "$mdlc" check "$dir" --format json -j 1 "$@" >>"$tmp/serial"
  run "$mdlc" check "$dir" --format json -j "$jobs" "$@" >>"$tmp/parallel"
  i=$((i + 1))
done

serial_wall=$(cut -d' ' -f1 "$tmp/serial" | median)
serial_cpu=$(cut -d' ' -f2 "$tmp/serial" | median)
parallel_wall=$(cut -d' ' -f1 "$tmp/parallel" | median)
parallel_cpu=$(cut -d' ' -f2 "$tmp/parallel" | median)
echo "mdlc check $dir: $files files, $reps runs each, medians"
printf '  -j 1:  wall %6.3f s   user+sys %6.3f s\n' "$serial_wall" "$serial_cpu"
printf '  -j %s:  wall %6.3f s   user+sys %6.3f s\n' "$jobs" "$parallel_wall" "$parallel_cpu"
awk -v s="$serial_wall" -v p="$parallel_wall" -v n="$(nproc)" -v l="$(cut -d' ' -f1 /proc/loadavg)" \
  'BEGIN { printf "  speedup (wall): %.2fx   (%s cores, load average %s)\n", s / p, n, l }'
