#!/usr/bin/env bash
# sanitize.sh - the test suite under AddressSanitizer and UndefinedBehavior-
# Sanitizer, then each libFuzzer harness for a fixed time (issue 16).
#
#   tools/sanitize.sh [SECONDS]   SECONDS per fuzzer (default 60)
#   FUZZERS="urdf sdf"            only these fuzzers (default: all six)
#   FUZZ_ONLY=1                   skip the test suite (a longer hunt)
#
# Builds with clang in BUILD_DIR (default: build-sanitize), every library
# instrumented for the sanitizers and for coverage; runs the unit,
# diagnostics, golden, command-line and convert tests there (the oracle and
# corpus suites run in the ordinary build: under the sanitizers they would
# only repeat the same code paths, slower); then runs fuzz_urdf, fuzz_sdf,
# fuzz_mjcf, fuzz_directives, fuzz_mesh and fuzz_xacro, each seeded from the
# project's models and diagnostics files (fuzz_xacro: from its seeds in
# tests/fuzz/seeds/xacro and the xacro test cases, with the token dictionary
# tests/fuzz/xacro.dict) and, when present, the shared corpus. Any
# sanitizer report, crash, leak or timeout fails the script; a fuzzer's
# failing input is kept as BUILD_DIR/fuzz/<fuzzer>/crash-* for the
# regression suite (tests/fuzz/regressions/).
set -euo pipefail

seconds=${1:-60}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$root/build-sanitize}
jobs=${JOBS:-$(nproc)}
shared=${MDLC_SHARED_DIR:-$root/../shared}

if ! command -v clang++ >/dev/null 2>&1; then
  echo "sanitize.sh: clang++ is missing (Debian: clang libclang-rt-14-dev)" >&2
  exit 1
fi

flags="-fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=undefined"
# line tables are all a sanitizer report needs to name function, file and
# line; full debug information would only make every object slower to build
flags+=" -fno-omit-frame-pointer -gline-tables-only -O1"
echo "==> configuring the sanitizer build in $build_dir"
# a Debug build (assertions on) whose own flags, a full -g, give way to those
cmake -S "$root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS_DEBUG= -DCMAKE_C_FLAGS_DEBUG= \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_MODULE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DMDLC_BUILD_TESTS=ON -DMDLC_BUILD_FUZZERS=ON \
  -DMDLC_BUILD_BENCHMARKS=OFF -DMDLC_BUILD_PYTHON=OFF >/dev/null
targets=(mdlc mdlc_unit_tests mdlc_cli_test mdlc_convert_test
         fuzz_urdf fuzz_sdf fuzz_mjcf fuzz_directives fuzz_mesh fuzz_xacro)
cmake --build "$build_dir" -j "$jobs" --target "${targets[@]}"

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# leaks inside third-party libraries, each one explained in the file
export LSAN_OPTIONS=suppressions=$root/tests/fuzz/lsan_suppressions.txt
# the targets built above discover their own tests; the script-driven ones
# that need other targets (oracles, Python, the embed examples, corpus runs,
# the install packages) are left to the ordinary build
# cli/robot_meshes checks the pages mdlc view writes without opening them in
# Chromium (MDLC_VIEW_BROWSER=off): the browser is none of mdlc's memory, and
# the ordinary build's run of the same test opens and screenshots each page
if [ -z "${FUZZ_ONLY:-}" ]; then
  echo "==> the test suite under ASan and UBSan"
  (cd "$build_dir" && MDLC_VIEW_BROWSER=off ctest --output-on-failure -j "$jobs" --timeout 900 \
     -E 'oracle|Oracle|python|embed|corpus|Corpus|convert/|layers/|[Dd]eterminism|ReferenceRejects|view_in_browser|readme|install/')
fi

echo "==> fuzzing, ${seconds}s per harness"
fuzz_root="$build_dir/fuzz"
status=0
for fuzzer in ${FUZZERS:-urdf sdf mjcf directives mesh xacro}; do
  options=()
  names=(-name '*.urdf' -o -name '*.sdf' -o -name '*.xml' -o -name '*.yaml')
  case $fuzzer in
    urdf) seeds=("$root/tests/models/urdf" "$root/tests/diag/urdf" "$root/examples/urdf")
          format=urdf ;;
    sdf) seeds=("$root/tests/models/sdf" "$root/tests/diag/sdf" "$root/examples/sdf")
         format=sdf ;;
    mjcf) seeds=("$root/tests/models/mjcf" "$root/tests/diag/mjcf" "$root/examples/mjcf")
          format=mjcf ;;
    directives) seeds=("$root/tests/models/dmd" "$root/tests/diag/dmd" "$root/examples/directives")
                format=dmd ;;
    mesh) seeds=() format=mesh ;;
    xacro) seeds=("$root/tests/fuzz/seeds/xacro" "$root/tests/xacro/cases")
           format=xacro names=(-name '*.xacro') options=(-dict="$root/tests/fuzz/xacro.dict") ;;
  esac
  work="$fuzz_root/$fuzzer"
  rm -rf "$work/corpus"
  mkdir -p "$work/corpus"
  # seed files: the format's own files (the mesh fuzzer's first byte picks
  # the file type, so its seeds are prefixed with it)
  if [ "$fuzzer" = mesh ]; then
    i=0
    for ext in obj stl dae gltf ply; do
      for f in "$root"/tests/models/meshes/*."$ext"; do
        [ -f "$f" ] || continue
        { printf "\\x$(printf %02x $i)"; cat "$f"; } > "$work/corpus/$(basename "$f")"
      done
      i=$((i + 1))
    done
  else
    for dir in "${seeds[@]}"; do
      [ -d "$dir" ] && find "$dir" -type f \( "${names[@]}" \) -size -64k \
        -exec cp -t "$work/corpus" {} + 2>/dev/null || true
    done
  fi
  # the shared corpus, when present: real models of the fuzzer's format (the
  # manifest's format column) and real meshes, each small enough for
  # -max_len; for fuzz_xacro, the real robots' xacro files
  if [ "$fuzzer" = xacro ]; then
    if [ -d "$shared/corpus/xacro" ]; then
      while IFS= read -r -d '' f; do
        cp "$f" "$work/corpus/corpus_$(printf '%s' "${f#"$shared/corpus/xacro/"}" | tr '/' '_')"
      done < <(find "$shared/corpus/xacro" -type f -name '*.xacro' -size -64k -print0)
    fi
  elif [ -f "$shared/corpus/manifest.tsv" ]; then
    while IFS= read -r path; do
      f="$shared/corpus/$path"
      [ -f "$f" ] && [ "$(stat -L -c %s "$f")" -lt 65536 ] || continue
      name="corpus_$(printf '%s' "$path" | tr '/' '_')"
      if [ "$fuzzer" = mesh ]; then
        case ${path,,} in
          *.obj) i=0 ;; *.stl) i=1 ;; *.dae) i=2 ;; *.gltf) i=3 ;; *.ply) i=4 ;; *) continue ;;
        esac
        { printf "\\x$(printf %02x $i)"; cat "$f"; } > "$work/corpus/$name"
      else
        cp "$f" "$work/corpus/$name"
      fi
    done < <(awk -F'\t' -v format="$format" '$1 == format { print $2 }' "$shared/corpus/manifest.tsv")
  fi
  if [ -d "$root/tests/fuzz/regressions/$fuzzer" ]; then
    cp "$root/tests/fuzz/regressions/$fuzzer"/* "$work/corpus/" 2>/dev/null || true
  fi
  echo "--> fuzz_$fuzzer: $(ls "$work/corpus" | wc -l) seeds"
  if ! (cd "$work" && "$build_dir/tests/fuzz/fuzz_$fuzzer" -max_total_time="$seconds" \
          -timeout=20 -rss_limit_mb=2560 -max_len=65536 -print_final_stats=1 \
          "${options[@]}" -artifact_prefix="$work/" corpus >"$work/log.txt" 2>&1); then
    echo "fuzz_$fuzzer FAILED; its input and log:" >&2
    ls "$work"/crash-* "$work"/leak-* "$work"/timeout-* "$work"/oom-* 2>/dev/null >&2 || true
    tail -40 "$work/log.txt" >&2
    status=1
  else
    grep -E "^stat::number_of_executed_units|^stat::average_exec_per_sec|^stat::peak_rss_mb" \
      "$work/log.txt" |
      sed "s/^/    fuzz_$fuzzer /"
  fi
done
exit $status
