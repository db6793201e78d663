#!/usr/bin/env bash
# setup.sh - one command from a fresh Debian 12 machine to a working mdlc.
#
#   tools/setup.sh example   install what is missing, build the mdlc command only,
#                            compile a bundled example
#   tools/setup.sh test      install what is missing, build everything (libraries,
#                            command, Python module, tests), run the whole test suite,
#                            then the sanitizer suite and each fuzzer for
#                            FUZZ_SECONDS (default 30; tools/sanitize.sh)
#
# Installing needs root (apt-get); as another user the script prints the exact
# apt-get line to run and stops. BUILD_DIR (default: build) and JOBS (default:
# the number of cores) may be set in the environment.
set -euo pipefail

mode=${1:-example}
case "$mode" in
  example|test) ;;
  *) echo "usage: $0 example|test" >&2; exit 2 ;;
esac

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$root/build}
jobs=${JOBS:-$(nproc)}

# what mdlc needs to build and run
runtime_packages=(cmake ninja-build g++ pkg-config libeigen3-dev libxml2-dev libyaml-cpp-dev
                  libfmt-dev libassimp-dev libqhull-dev libcli11-dev libabsl-dev libxxhash-dev)
# the Python module (built and tested by `test`)
python_packages=(python3-dev python3-numpy pybind11-dev)
# what its tests need besides: GoogleTest, Google Benchmark, and the reference
# implementations the differential tests compare against (DART 6.12 with its
# URDF and SDFormat readers for the dynamics oracle), Graphviz to
# check that `mdlc graph -o x.svg` renders, and Chromium to open the pages
# `mdlc view` writes, and clang with its sanitizer and libFuzzer runtimes for
# the sanitizer suite and the fuzzers, and dpkg-dev, whose dpkg-shlibdeps
# computes the Debian package's Depends, python3-venv and python3-wheel, with
# which the wheel is built and installed in a virtual environment, and colcon
# with its CMake, ROS and bash extensions, which build a ROS 2 workspace
# holding mdlc (the install tests, tests/install; test-only)
test_packages=(libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev
               liburdfdom-dev libsdformat-dev libmujoco-dev graphviz chromium
               libdart-dev libdart-utils-dev libdart-utils-urdf-dev
               clang libclang-rt-14-dev dpkg-dev python3-venv python3-wheel
               colcon python3-colcon-cmake python3-colcon-ros python3-colcon-bash
               python3-colcon-recursive-crawl python3-colcon-package-selection
               python3-colcon-output)

packages=("${runtime_packages[@]}")
if [ "$mode" = test ]; then
  packages+=("${python_packages[@]}" "${test_packages[@]}")
fi
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if ((${#missing[@]})); then
  install_line="apt-get install -y --no-install-recommends ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then
    echo "mdlc needs these Debian packages. Run, as root:" >&2
    echo "  apt-get update && $install_line" >&2
    exit 1
  fi
  echo "==> installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The MuJoCo 3.3.8 oracle (tests/oracle/mujoco_js, test-only) runs MuJoCo's
# official WebAssembly build under Node.js. Debian's nodejs and npm are
# installed only when no `node` is on the PATH (a newer Node.js may be there
# already); the npm package is pinned by package-lock.json and installed with
# `npm ci`. Without either, the MuJoCo oracle tests report themselves skipped.
if [ "$mode" = test ]; then
  if ! command -v node >/dev/null 2>&1; then
    if [ "$(id -u)" -ne 0 ]; then
      echo "note: no node on the PATH; the MuJoCo 3.3.8 oracle tests will be skipped." >&2
      echo "  To run them, as root: apt-get update && apt-get install -y --no-install-recommends nodejs npm" >&2
    else
      echo "==> installing: nodejs npm"
      export DEBIAN_FRONTEND=noninteractive
      apt-get update -qq
      apt-get install -y -qq --no-install-recommends nodejs npm >/dev/null ||
        echo "note: could not install nodejs/npm; the MuJoCo 3.3.8 oracle tests will be skipped" >&2
    fi
  fi
  mujoco_js="$root/tests/oracle/mujoco_js"
  if command -v npm >/dev/null 2>&1; then
    echo "==> npm ci in tests/oracle/mujoco_js (MuJoCo 3.3.8 oracle)"
    if ! (cd "$mujoco_js" && timeout 300 npm ci --prefer-offline --fetch-retries=1 --fetch-timeout=60000 --no-audit --no-fund --loglevel=error); then
      echo "note: npm ci failed (registry unreachable?); the MuJoCo 3.3.8 oracle tests will be skipped" >&2
    fi
  else
    echo "note: npm not found; the MuJoCo 3.3.8 oracle tests will be skipped" >&2
  fi
fi

# `mdlc view` embeds three.js, which CMake installs with npm (pinned by
# tools/mdlc/viewer/package-lock.json) when it configures; without npm, mdlc
# is built without the viewer and `mdlc view` says so.
if ! command -v npm >/dev/null 2>&1; then
  echo "note: npm not found; mdlc is built without its viewer (mdlc view)" >&2
fi

echo "==> configuring and building in $build_dir"
# optimized, with line tables and function names only (-g1): enough for
# profiles and stack traces, and about 30% less compile time than a full -g
# (the largest unit-test source: 67 s with -g, 47 s with -g1)
optimized="-O2 -g1 -DNDEBUG"
config=(-G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
        "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=$optimized" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=$optimized")
if [ "$mode" = example ]; then
  # only the command: no tests, benchmarks or Python module
  config+=(-DMDLC_BUILD_TESTS=OFF -DMDLC_BUILD_BENCHMARKS=OFF -DMDLC_BUILD_PYTHON=OFF)
  targets=(--target mdlc)
else
  config+=(-DMDLC_BUILD_TESTS=ON -DMDLC_BUILD_BENCHMARKS=ON -DMDLC_BUILD_PYTHON=ON)
  # the module is built for Debian's interpreter, the one python3-numpy serves
  if [ -x /usr/bin/python3 ]; then config+=(-DPython3_EXECUTABLE=/usr/bin/python3); fi
  targets=()
fi
cmake -S "$root" -B "$build_dir" "${config[@]}" >/dev/null
cmake --build "$build_dir" -j "$jobs" "${targets[@]}"

mdlc="$build_dir/tools/mdlc/mdlc"
if [ "$mode" = example ]; then
  example="$root/examples/urdf/double_pendulum.urdf"
  echo "==> $mdlc compile $example"
  "$mdlc" compile "$example"
  exit 0
fi

echo "==> running the test suite"
(cd "$build_dir" && ctest --output-on-failure -j "$jobs" --timeout 600)

# the same tests again under AddressSanitizer and UBSan, in a build of their
# own, then every fuzzer for a short fixed time; any report fails the run
fuzz_seconds=${FUZZ_SECONDS:-30}
# fuzz_mesh reads each input with the mesh reader in a child process, as a
# compile does, so assimp's own crashes there are errors, not failures
BUILD_DIR="${SANITIZE_BUILD_DIR:-$build_dir-sanitize}" JOBS="$jobs" \
  FUZZERS="${FUZZERS:-urdf sdf mjcf directives mesh xacro}" \
  bash "$root/tools/sanitize.sh" "$fuzz_seconds"
echo "==> passed: the test suite, the sanitizer suite and ${fuzz_seconds} s of each fuzzer"
