#!/usr/bin/env bash
# `pip install --no-build-isolation .` (pyproject.toml,
# tools/packaging/pip_backend.py) into a fresh virtual environment that sees
# Debian's NumPy (--system-site-packages), offline (--no-index, no pip
# configuration of the machine), from this build tree (MDLC_BUILD_DIR: the
# wheel is packed from what it built, nothing is compiled again). Then
#   - the wheel's files: the command in the environment's bin/, the mesh
#     reader under its libexec/mdlc and <libdir>/mdlc, the package in
#     site-packages, the version the project's;
#   - the environment's mdlc: --version, a compile, meshes read by the
#     environment's reader (in a child process and in its own);
#   - its Python: import mdlc from site-packages, plant-json of a bundled
#     model (and of a corpus model, when the shared corpus is there) equal
#     to the command's, meshes read in-process with the environment's module;
#   - pip uninstall mdlc removes every file it installed.
# Exit 77 (ctest: skipped) when this build has no Python module or the
# interpreter it was built for lacks venv, pip or Debian's python3-wheel.
#   pip_wheel_test.sh BUILD_DIR SOURCE_DIR VERSION PYTHON SHARED_DIR
# (PYTHON empty: the build has no Python module)
set -euo pipefail
build_dir=$1 source_dir=$2 version=$3 python=$4 shared_dir=$5

if [ -z "$python" ]; then
  echo "skipped: this build has no Python module (python3-dev, python3-numpy, pybind11-dev)"
  exit 77
fi
for module in venv ensurepip wheel.wheelfile numpy; do
  if ! "$python" -c "import $module" 2>/dev/null; then
    echo "skipped: $python cannot import $module (Debian: python3-venv, python3-wheel, python3-numpy)"
    exit 77
  fi
done

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
source "$(dirname "${BASH_SOURCE[0]}")/install_test_lib.sh"

# none of the build tree's settings may help what the environment does, and
# pip reads no configuration of this machine (no index, no extra links)
run() { env -u MDLC_MESH_READER -u MDLC_MESH_MODULE -u PYTHONPATH -u PYTHONHOME \
            -u PIP_FIND_LINKS -u PIP_INDEX_URL -u PIP_EXTRA_INDEX_URL \
            PIP_CONFIG_FILE=/dev/null PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1 \
            MDLC_CACHE_DIR="$scratch/cache" "$@"; }

start=$(seconds)
run "$python" -m venv --system-site-packages "$scratch/venv" || fail "python3 -m venv failed"
venv=$scratch/venv
echo "venv: $(elapsed "$start") s"

# pip builds in the source tree: no bytecode may be left there
start=$(seconds)
if ! (cd "$scratch" && run env PYTHONDONTWRITEBYTECODE=1 MDLC_BUILD_DIR="$build_dir" \
        "$venv/bin/pip" install --no-build-isolation "$source_dir") >"$scratch/pip.log" 2>&1; then
  cat "$scratch/pip.log" >&2
  fail "pip install --no-build-isolation failed"
fi
echo "pip install --no-build-isolation (wheel packed from the build tree, installed): $(elapsed "$start") s"
[ ! -e "$source_dir/tools/packaging/__pycache__" ] || fail "the build left bytecode in the source tree"

# -- what the wheel installed ----------------------------------------------
run "$venv/bin/pip" show -f mdlc >"$scratch/show" || fail "pip show mdlc failed"
grep -qx "Version: $version" "$scratch/show" || fail "pip show mdlc: $(grep Version "$scratch/show"), not $version"
grep -qx "Requires: numpy" "$scratch/show" || fail "the wheel does not require numpy: $(grep Requires "$scratch/show")"
site=$("$venv/bin/python" -c 'import sysconfig; print(sysconfig.get_path("platlib"))')
location=$(sed -n 's/^Location: //p' "$scratch/show")
# the listed files, as absolute paths (pip lists them relative to site-packages)
sed -n '/^Files:/,$p' "$scratch/show" | tail -n +2 | sed 's/^ *//' | while read -r file; do
  realpath -m "$location/$file"
done | sort >"$scratch/installed"
for path in "$venv/bin/mdlc" "$venv/libexec/mdlc/mdlc-mesh-reader" "$site/mdlc/__init__.py"; do
  grep -qxF "$(realpath -m "$path")" "$scratch/installed" || fail "the wheel installed no $path"
done
module_file=$(grep '/mdlc-mesh-import\.so$' "$scratch/installed") ||
  fail "the wheel installed no mdlc-mesh-import.so"
grep -q "^$(realpath -m "$site")/mdlc/_mdlc\..*\.so$" "$scratch/installed" ||
  fail "the wheel installed no extension module in $site/mdlc"
[ -x "$venv/bin/mdlc" ] && [ -x "$venv/libexec/mdlc/mdlc-mesh-reader" ] ||
  fail "the command or the mesh reader is not executable"
echo "installed: $(wc -l <"$scratch/installed") files (command, mesh reader and module, package)"

# -- the environment's command -----------------------------------------------
out=$(run "$venv/bin/mdlc" --version) || fail "mdlc --version failed"
[[ "$out" == *"$version"* ]] || fail "mdlc --version printed '$out', not $version"
example=$source_dir/examples/urdf/pan_tilt.urdf
timing=$(run "$venv/bin/mdlc" compile --emit=none --time-passes --no-cache "$example" 2>&1) ||
  fail "mdlc compile pan_tilt.urdf failed: $timing"
[[ "$timing" == *"mesh reader: $(realpath "$venv/libexec/mdlc/mdlc-mesh-reader")"* ]] ||
  fail "the environment's mdlc did not read meshes with its own reader: $timing"
timing=$(run "$venv/bin/mdlc" compile --emit=none --time-passes --no-cache \
           --mesh-reader=in-process "$example" 2>&1) || fail "mdlc compile --mesh-reader=in-process failed"
[[ "$timing" == *"in this process (asked for), with $module_file"* ]] ||
  fail "the environment's mdlc did not open its own mdlc-mesh-import.so: $timing"
echo "$venv/bin/mdlc: --version, and meshes read by the environment's reader and module"

# -- the environment's Python --------------------------------------------------
# mesh_geoms' meshes are read in any compile (its inertia comes from them):
# the Python module must open the environment's import module for them
mesh_model=$source_dir/tests/models/mjcf/oracle/mesh_geoms.xml
models=("$example" "$mesh_model")
corpus_model=$shared_dir/corpus/drake_models/franka_description/urdf/panda_arm_hand.urdf
if [ -f "$corpus_model" ]; then
  models+=("$corpus_model")
else
  echo "note: no shared corpus at $shared_dir; the corpus model is left out"
fi
for model in "${models[@]}"; do
  # the corpus model's meshes are found through its package, drake_models
  packages=""
  [[ "$model" != "$corpus_model" ]] || packages=$shared_dir/corpus/drake_models
  run "$venv/bin/mdlc" compile --emit=plant-json ${packages:+--package-path "$packages"} "$model" \
    >"$scratch/command.json" 2>"$scratch/command.err" || { cat "$scratch/command.err" >&2;
    fail "mdlc compile --emit=plant-json $model failed"; }
  ! grep -q "warning: unknown package" "$scratch/command.err" || fail "$model: a package was not found"
  (cd "$scratch" && run "$venv/bin/python" - "$model" "$site" "$module_file" "$mesh_model" "$packages" >"$scratch/python.json") <<'EOF' ||
import os, sys
import mdlc
model, site, module, mesh_model, packages = sys.argv[1:]
if os.path.realpath(mdlc.__file__) != os.path.realpath(os.path.join(site, "mdlc", "__init__.py")):
    sys.exit(f"imported mdlc from {mdlc.__file__}, not from {site}")
compiled = mdlc.compile(model, mesh_reader="in-process", package_paths=[packages] if packages else [])
opened = {line.split()[-1] for line in open("/proc/self/maps") if "mdlc-mesh-import" in line}
if opened - {os.path.realpath(module)} or (model == mesh_model and not opened):
    sys.exit(f"read meshes with {opened}, not {module}")
sys.stdout.write(compiled.to_json())
EOF
    fail "the environment's Python failed on $model"
  cmp -s "$scratch/command.json" "$scratch/python.json" ||
    fail "plant-json of $(basename "$model"): the Python module's differs from the command's
$(diff "$scratch/command.json" "$scratch/python.json" | head -5)"
  echo "plant-json of $(basename "$model") ($(wc -c <"$scratch/python.json") bytes): Python's equals the command's"
done

# -- removed -------------------------------------------------------------------
start=$(seconds)
run "$venv/bin/pip" uninstall -y mdlc >"$scratch/uninstall.log" 2>&1 ||
  { cat "$scratch/uninstall.log" >&2; fail "pip uninstall mdlc failed"; }
left=0
while read -r path; do
  if [ -e "$path" ]; then echo "left behind: $path" >&2; left=1; fi
done <"$scratch/installed"
for dir in "$venv/libexec/mdlc" "$(dirname "$module_file")" "$site/mdlc"; do
  if [ -e "$dir" ]; then echo "left behind: $dir/" >&2; left=1; fi
done
[ "$left" = 0 ] || fail "pip uninstall mdlc left the paths above"
echo "pip uninstall mdlc: all $(wc -l <"$scratch/installed") files and their folders gone ($(elapsed "$start") s)"
echo "total: $(elapsed "$test_start") s"
