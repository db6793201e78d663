#!/usr/bin/env bash
# mdlc in a ROS 2 colcon workspace (package.xml at the repository root): a
# scratch workspace whose src/ holds a link to this source tree and a copy of
# tests/install/colcon/tiny_description (a description package as
# ament_cmake installs one: xacro, an STL mesh, the ament index marker and
# the AMENT_PREFIX_PATH hooks), then
#   - package.xml's version is the project's; colcon finds mdlc as a
#     (ROS) cmake package and tiny_description as an ament_cmake one;
#   - colcon build, without tests or the Python module, at -O0 (no
#     optimization, no debug information: the cheapest build that runs);
#   - in a fresh bash that sources install/setup.bash: mdlc is the
#     workspace's, prints the version, and compiles the package's xacro,
#     finding $(find tiny_description) and its package:// mesh through the
#     ament index of AMENT_PREFIX_PATH (the links and joints in plant-json,
#     the mesh resolved under install/ and read by the installed mesh reader);
#   - without the setup sourced (no AMENT_PREFIX_PATH), the same compile
#     fails with an error at the $(find ...) that names the package.
# Exit 77 (ctest: skipped) only when colcon, or its CMake and ROS support
# (colcon-cmake, colcon-ros), is not installed.
#   colcon_workspace_test.sh SOURCE_DIR VERSION [SCRATCH_PARENT]
# (SCRATCH_PARENT: where the workspace is made, e.g. a folder of the build
# tree; a temporary folder when not given. The workspace is removed after.)
set -euo pipefail
source_dir=$1 version=$2 scratch_parent=${3:-}

if ! command -v colcon >/dev/null; then
  echo "skipped: colcon not found (python3-colcon-common-extensions, or Debian's" \
       "colcon with python3-colcon-cmake, -ros and -bash)"
  exit 77
fi
colcon_help=$(colcon build --help 2>/dev/null || true)
if [[ "$colcon_help" != *--cmake-args* || "$colcon_help" != *--ament-cmake-args* ]]; then
  echo "skipped: colcon builds no CMake or ROS packages here (it needs colcon-cmake and colcon-ros)"
  exit 77
fi

if [ -n "$scratch_parent" ]; then
  mkdir -p "$scratch_parent"
  ws=$(mktemp -d "$scratch_parent/colcon_workspace.XXXXXX")
else
  ws=$(mktemp -d)
fi
cleanup() {
  status=$?
  rm -rf "$ws"
  exit $status
}
trap cleanup EXIT
source "$(dirname "${BASH_SOURCE[0]}")/install_test_lib.sh"

# -- the workspace --------------------------------------------------------
mkdir -p "$ws/src"
ln -s "$(realpath "$source_dir")" "$ws/src/mdlc"
cp -R "$source_dir/tests/install/colcon/tiny_description" "$ws/src/"
cd "$ws"
# nothing of the caller's colcon settings (~/.colcon: defaults, mixins), of
# a sourced ROS or workspace, or of the build tree may help or change what
# follows
export COLCON_HOME=$ws/.colcon
unset AMENT_PREFIX_PATH COLCON_PREFIX_PATH ROS_PACKAGE_PATH CMAKE_PREFIX_PATH \
      MDLC_MESH_READER MDLC_MESH_MODULE COLCON_DEFAULTS_FILE
export MDLC_CACHE_DIR=$ws/cache

manifest_version=$(sed -n 's|^[[:space:]]*<version>\([^<]*\)</version>.*|\1|p' "$source_dir/package.xml")
[ "$manifest_version" = "$version" ] ||
  fail "package.xml gives version '$manifest_version', the project (CMakeLists.txt) $version"

# -O0 without debug information (CMAKE_BUILD_TYPE None: no flags of a build
# type), the cheapest build that makes a working install: its compiles take
# about 660 s of CPU, 6 min on 2 idle cores; -O1's no less, the default
# RelWithDebInfo's about 1.8 times as much. Ninja when there is one (both
# builds below get the same arguments: a changed generator would fail the
# second configure of tiny_description).
cmake_args=(-DBUILD_TESTING=OFF -DMDLC_BUILD_PYTHON=OFF -DCMAKE_BUILD_TYPE=None)
if command -v ninja >/dev/null; then cmake_args+=(-G Ninja); fi
colcon_build() {
  local name=$1; shift
  if ! colcon --log-base "$ws/log" build --base-paths src \
         --event-handlers console_direct- console_cohesion- "$@" >"$ws/$name.txt" 2>&1; then
    cat "$ws/$name.txt" >&2
    for log in "$ws"/log/latest_build/*/stdout_stderr.log; do
      [ -f "$log" ] || continue
      echo "--- last lines of $log" >&2
      tail -40 "$log" >&2
    done
    fail "colcon build $* failed"
  fi
}

# what colcon sees (Debian's colcon has no `colcon list`: its log says),
# from building the description package alone (a second)
start=$(seconds)
colcon_build description --packages-select tiny_description --cmake-args "${cmake_args[@]}"
grep -oE "Package '[^']*' with type '[^']*' and name '[^']*'" \
  "$ws/log/latest_build/logger_all.log" | sort >"$ws/packages.txt"
expected="Package 'src/mdlc' with type 'ros.cmake' and name 'mdlc'
Package 'src/tiny_description' with type 'ros.ament_cmake' and name 'tiny_description'"
[ "$(cat "$ws/packages.txt")" = "$expected" ] ||
  fail "colcon found$(printf '\n')$(cat "$ws/packages.txt")$(printf '\n')not$(printf '\n')$expected" \
       "$(printf '\n')(is colcon-ros installed?)"
echo "colcon finds mdlc (ros.cmake, package.xml version $version) and tiny_description" \
     "(ros.ament_cmake); tiny_description built ($(elapsed "$start") s)"

# -- colcon build ---------------------------------------------------------
start=$(seconds)
colcon_build build --cmake-args "${cmake_args[@]}"
echo "colcon build (${cmake_args[*]}): $(elapsed "$start") s"
[ -x "$ws/install/mdlc/bin/mdlc" ] || fail "colcon build installed no install/mdlc/bin/mdlc"
[ -f "$ws/install/tiny_description/share/ament_index/resource_index/packages/tiny_description" ] ||
  fail "tiny_description installed no ament index marker"

# -- with install/setup.bash sourced ---------------------------------------
model=src/tiny_description/urdf/robot.urdf.xacro
sourced() { bash -c 'source install/setup.bash && '"$1"; }

out=$(sourced 'echo "$AMENT_PREFIX_PATH"') || fail "sourcing install/setup.bash failed: $out"
[[ ":$out:" == *":$ws/install/tiny_description:"* ]] ||
  fail "install/setup.bash put no install/tiny_description on AMENT_PREFIX_PATH ('$out'):" \
       "the package's local_setup.dsv hook did not run"
# the package's own shell hooks (local_setup.sh and .bash), which its
# package.bash sources, do the same
out=$(bash -c 'source install/tiny_description/share/tiny_description/package.bash; echo "$AMENT_PREFIX_PATH"')
[ "$out" = "$ws/install/tiny_description" ] ||
  fail "share/tiny_description/package.bash set AMENT_PREFIX_PATH to '$out'"

out=$(sourced 'command -v mdlc')
[ "$out" = "$ws/install/mdlc/bin/mdlc" ] || fail "after install/setup.bash, mdlc is '$out', not the workspace's"
out=$(sourced 'mdlc --version')
[[ "$out" == *"$version"* ]] || fail "mdlc --version printed '$out', not $version"
echo "after source install/setup.bash: mdlc is install/mdlc/bin/mdlc, $out"

start=$(seconds)
out=$(sourced "mdlc compile $model") || fail "mdlc compile $model failed: $out"
[[ "$out" == *"tiny_arm: 3 bodies, 3 joints"* ]] || fail "mdlc compile $model printed: $out"
out=$(sourced "mdlc compile --emit=plant-json $model" | python3 -c '
import json, sys
plant = json.load(sys.stdin)
print(" ".join(sorted(b["name"] for b in plant["bodies"])))
print(" ".join(sorted(j["name"] for j in plant["joints"] if j["type"] == "revolute")))
print(" ".join(g["shape"]["uri"] for g in plant["geometries"] if g["shape"]["type"] == "mesh"))
') || fail "mdlc compile --emit=plant-json $model failed or printed no plant: $out"
expected="base_link forearm upper_arm
elbow shoulder
package://tiny_description/meshes/base.stl package://tiny_description/meshes/base.stl"
[ "$out" = "$expected" ] ||
  fail "plant-json of $model: bodies, revolute joints, mesh URIs are$(printf '\n')$out$(printf '\n')not$(printf '\n')$expected"
# the URI resolved through the ament index to the installed package, and the
# file read by the installed mesh reader
mesh=$ws/install/tiny_description/share/tiny_description/meshes/base.stl
out=$(sourced "mdlc assets $model") || fail "mdlc assets $model failed: $out"
[[ "$out" == *"package://tiny_description/meshes/base.stl -> $mesh [stl,"* ]] ||
  fail "mdlc assets did not resolve the mesh to $mesh: $out"
out=$(sourced "mdlc stats --no-cache $model") || fail "mdlc stats $model failed: $out"
[[ "$out" == *"$mesh: 4 vertices, 4 triangles"* ]] || fail "mdlc stats read no mesh: $out"
echo "mdlc compile $model: 3 bodies, joints shoulder and elbow, the mesh found in" \
     "install/tiny_description and read ($(elapsed "$start") s)"

# -- without it ------------------------------------------------------------
if out=$("$ws/install/mdlc/bin/mdlc" compile "$model" 2>&1); then
  fail "without install/setup.bash (no AMENT_PREFIX_PATH), mdlc compile $model succeeded: $out"
fi
grep -qE "robot\.urdf\.xacro:[0-9]+:[0-9]+: error: .*'tiny_description'" <<<"$out" ||
  fail "without AMENT_PREFIX_PATH, mdlc compile failed without a located error naming tiny_description: $out"
echo "without install/setup.bash: $(grep -m1 'error:' <<<"$out")"
echo "total: $(elapsed "$test_start") s"
