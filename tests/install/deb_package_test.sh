#!/usr/bin/env bash
# The Debian package (tools/packaging/cpack.cmake): `cpack -G DEB` of the
# build tree into a scratch folder, then
#   - its contents (dpkg-deb -c): the command, the mesh reader, the static
#     libraries, the headers, mdlcConfig.cmake, mdlc.pc, the Python package,
#     and nothing outside /usr;
#   - its control fields (dpkg-deb -f): Depends computed by dpkg-shlibdeps,
#     the maintainer, the description, section and priority;
#   - only as root with MDLC_TEST_SYSTEM_INSTALL=1 (it changes the machine;
#     CI sets it on its throwaway one): dpkg -i, then mdlc from /usr (version,
#     a compile, meshes read by the installed reader), `import mdlc` with
#     /usr/bin/python3, a CMake project's find_package(mdlc) without a prefix,
#     pkg-config, and dpkg -r, after which no file of the package may remain.
# Exit 77 (ctest: skipped) only when nothing could be checked.
#   deb_package_test.sh BUILD_DIR SOURCE_DIR VERSION LIBDIR PYTHON_DIR CMAKE CPACK
# (PYTHON_DIR empty: the build has no Python module)
set -euo pipefail
build_dir=$1 source_dir=$2 version=$3 libdir=$4 python_dir=$5 cmake=$6 cpack=$7

for tool in dpkg-deb dpkg-shlibdeps "$cpack"; do
  if ! command -v "$tool" >/dev/null; then
    echo "skipped: $tool not found (dpkg-dev and cmake build the package)"
    exit 77
  fi
done

scratch=$(mktemp -d)
installed=0
cleanup() {
  status=$?
  if [ "$installed" = 1 ]; then
    echo "failed with mdlc installed: removing it (dpkg --purge mdlc)" >&2
    dpkg --purge mdlc >/dev/null 2>&1 || true
  fi
  rm -rf "$scratch"
  exit $status
}
trap cleanup EXIT
source "$(dirname "${BASH_SOURCE[0]}")/install_test_lib.sh"

# -- the package ---------------------------------------------------------
start=$(seconds)
if ! "$cpack" -G DEB --config "$build_dir/CPackConfig.cmake" -B "$scratch/out" \
     >"$scratch/cpack.log" 2>&1; then
  cat "$scratch/cpack.log" >&2
  fail "cpack -G DEB failed"
fi
echo "cpack -G DEB: $(elapsed "$start") s"
arch=$(dpkg --print-architecture)
deb=$scratch/out/mdlc_${version}_${arch}.deb
[ -f "$deb" ] || fail "no mdlc_${version}_${arch}.deb; cpack made: $(ls "$scratch/out")"
echo "package: $(basename "$deb"), $(du -k "$deb" | cut -f1) KiB"

# the paths, without dpkg-deb's leading "./"; folders end in /
dpkg-deb -c "$deb" | awk '{ print $6 }' | sed 's|^\./|/|' >"$scratch/contents"
expected=(
  /usr/bin/mdlc
  /usr/libexec/mdlc/mdlc-mesh-reader
  "/usr/$libdir/mdlc/mdlc-mesh-import.so"
  "/usr/$libdir/libmdlc_driver.a"
  "/usr/$libdir/libmdlc_ir.a"
  /usr/include/mdlc/mdlc.h
  /usr/include/mdlc/version.h
  "/usr/$libdir/cmake/mdlc/mdlcConfig.cmake"
  "/usr/$libdir/cmake/mdlc/mdlcConfigVersion.cmake"
  "/usr/$libdir/cmake/mdlc/mdlcTargets.cmake"
  "/usr/$libdir/pkgconfig/mdlc.pc"
)
if [ -n "$python_dir" ]; then
  expected+=("/usr/$python_dir/mdlc/__init__.py")
fi
for path in "${expected[@]}"; do
  grep -qxF "$path" "$scratch/contents" || fail "the package has no $path"
done
if [ -n "$python_dir" ]; then
  grep -qx "/usr/$python_dir/mdlc/_mdlc\..*\.so" "$scratch/contents" ||
    fail "the package has no Python extension module in /usr/$python_dir/mdlc"
else
  echo "note: this build has no Python module; the package has none"
fi
if grep -v '^/usr/' "$scratch/contents" | grep -vx '/'; then
  fail "the package installs the paths above outside /usr"
fi
if grep -q '_detail\.h$' "$scratch/contents"; then fail "the package holds internal headers"; fi
files=$(grep -vc '/$' "$scratch/contents")
echo "contents: $files files, among them ${#expected[@]} checked by name"

field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = mdlc ] || fail "Package is '$(field Package)'"
[ "$(field Version)" = "$version" ] || fail "Version is '$(field Version)', not $version"
[ "$(field Architecture)" = "$arch" ] || fail "Architecture is '$(field Architecture)'"
for name in Maintainer Section Priority Description; do
  [ -n "$(field $name)" ] || fail "no $name field"
done
depends=$(field Depends)
echo "Depends: $depends"
# computed from what the binaries link: the C and C++ runtimes, and assimp
# (the mesh reader's alone)
for library in libc6 libstdc++6 libassimp; do
  [[ "$depends" == *"$library"* ]] || fail "Depends lacks $library"
done

# -- installed in /usr ----------------------------------------------------
if [ "$(id -u)" != 0 ] || [ "${MDLC_TEST_SYSTEM_INSTALL:-}" != 1 ]; then
  echo "system install skipped: it runs dpkg -i on this machine, so only as root with" \
       "MDLC_TEST_SYSTEM_INSTALL=1 (CI sets it); the package itself is checked above"
  echo "total: $(elapsed "$test_start") s"
  exit 0
fi
if dpkg-query -W -f='${Status}' mdlc 2>/dev/null | grep -q installed; then
  fail "a package mdlc is installed already; remove it first (dpkg -r mdlc), the test removes its own"
fi

start=$(seconds)
installed=1
dpkg -i "$deb" >"$scratch/dpkg.log" 2>&1 || { cat "$scratch/dpkg.log" >&2; fail "dpkg -i failed"; }
dpkg-query -L mdlc | sort >"$scratch/listed"
echo "dpkg -i: $(elapsed "$start") s"

# none of the build tree's settings may help what follows
# (and Python writes its bytecode beside the package, as it does for a user
# importing as root, which dpkg -r must not leave behind)
run() { env -u MDLC_MESH_READER -u MDLC_MESH_MODULE -u PYTHONPATH -u CMAKE_PREFIX_PATH \
            -u PKG_CONFIG_PATH -u PYTHONDONTWRITEBYTECODE MDLC_CACHE_DIR="$scratch/cache" "$@"; }
out=$(run /usr/bin/mdlc --version)
[[ "$out" == *"$version"* ]] || fail "/usr/bin/mdlc --version printed '$out', not $version"
out=$(run /usr/bin/mdlc compile "$source_dir/examples/urdf/double_pendulum.urdf") ||
  fail "/usr/bin/mdlc compile double_pendulum.urdf failed: $out"
[[ "$out" == *"bodies: 3 (plus world)"* ]] || fail "/usr/bin/mdlc compile printed: $out"
# meshes, read by the installed mesh reader (found from /usr, not the build)
out=$(run /usr/bin/mdlc stats --no-cache "$source_dir/examples/urdf/pan_tilt.urdf")
[[ "$out" == *"pan_tilt_base.stl: 18 vertices, 32 triangles"* ]] ||
  fail "/usr/bin/mdlc stats pan_tilt.urdf read no meshes: $out"
echo "/usr/bin/mdlc: --version, compile and stats with meshes work"

if [ -n "$python_dir" ]; then
  out=$(cd "$scratch" && run /usr/bin/python3 -c \
    'import mdlc, sys; m = mdlc.compile(sys.argv[1]); print(mdlc.__file__, m.num_positions)' \
    "$source_dir/examples/urdf/double_pendulum.urdf") || fail "import mdlc failed: $out"
  [ "$out" = "/usr/$python_dir/mdlc/__init__.py 2" ] ||
    fail "/usr/bin/python3 imported mdlc from elsewhere: $out"
  [ -d "/usr/$python_dir/mdlc/__pycache__" ] || fail "import mdlc as root wrote no __pycache__"
  echo "/usr/bin/python3: import mdlc from /usr/$python_dir, compiled a model, wrote __pycache__"
fi

# a project of its own: find_package(mdlc) with no prefix given
start=$(seconds)
cp "$source_dir/examples/embed_cmake/CMakeLists.txt" "$source_dir/examples/embed_cmake/embed.cc" "$scratch/"
if ! { run "$cmake" -S "$scratch" -B "$scratch/embed" -DCMAKE_BUILD_TYPE=Release &&
       run "$cmake" --build "$scratch/embed" -j2; } >"$scratch/embed.log" 2>&1; then
  cat "$scratch/embed.log" >&2
  fail "the find_package(mdlc) project did not configure and build"
fi
grep -q "mdlc_DIR:PATH=/usr/$libdir/cmake/mdlc" "$scratch/embed/CMakeCache.txt" ||
  fail "find_package(mdlc) found $(grep mdlc_DIR "$scratch/embed/CMakeCache.txt")"
run "$scratch/embed/embed" "$source_dir/examples/urdf/double_pendulum.urdf" >/dev/null ||
  fail "the program built with find_package(mdlc) failed"
echo "find_package(mdlc) without a prefix: configured, built and ran ($(elapsed "$start") s)"

cflags=$(run pkg-config --cflags mdlc) || fail "pkg-config --cflags mdlc failed"
# mdlc.pc is relocatable (${pcfiledir}/../..): its -I folders are spelled
# through /usr/lib/pkgconfig, and must lead to /usr/include/mdlc
found=0
for flag in $cflags; do
  if [[ "$flag" == -I* ]] && [ "$(realpath -m "${flag#-I}")" = /usr/include/mdlc ]; then found=1; fi
done
[ "$found" = 1 ] || fail "pkg-config --cflags mdlc names no -I of /usr/include/mdlc: $cflags"
echo "pkg-config --cflags mdlc: $cflags"

# -- removed --------------------------------------------------------------
dpkg -r mdlc >"$scratch/dpkg.log" 2>&1 || { cat "$scratch/dpkg.log" >&2; fail "dpkg -r mdlc failed"; }
installed=0
if dpkg-query -W -f='${Status}' mdlc 2>/dev/null | grep -q 'ok installed'; then
  fail "mdlc is still installed after dpkg -r"
fi
left=0
while read -r path; do
  # the folders dpkg shares with other packages (/usr, /usr/lib, ...) stay
  if [ -d "$path" ] && ! dpkg -S "$path" >/dev/null 2>&1; then
    echo "left behind: $path/ holding $(find "$path" -mindepth 1 | head -3 | tr '\n' ' ')" >&2; left=1
  elif [ ! -d "$path" ] && [ -e "$path" ]; then
    echo "left behind: $path" >&2; left=1
  fi
done <"$scratch/listed"
[ "$left" = 0 ] || fail "dpkg -r mdlc left the paths above"
# dpkg -r keeps the package's record and postrm ("rc"); the machine is left
# as it was found
dpkg --purge mdlc >/dev/null 2>&1 || fail "dpkg --purge mdlc failed"
if dpkg-query -W mdlc >/dev/null 2>&1; then fail "dpkg still knows mdlc after --purge"; fi
echo "dpkg -r mdlc: all $(wc -l <"$scratch/listed") listed paths gone (but folders other packages own); purged"
echo "total: $(elapsed "$test_start") s"
