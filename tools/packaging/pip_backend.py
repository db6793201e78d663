"""pip_backend.py - the build backend behind `pip install .` (PEP 517).

pyproject.toml names this module (backend-path tools/packaging). pip calls
build_wheel, which builds mdlc with CMake and packs what `cmake --install`
installs of two of its components into one wheel:

  python   the package mdlc/ (__init__.py and the _mdlc extension), at the
           wheel's root, so that it lands in site-packages;
  runtime  the mdlc command (in the wheel's scripts, installed to
           <prefix>/bin) and the mesh reader (in its data, installed to
           <prefix>/libexec/mdlc and <prefix>/<libdir>/mdlc),

so that an environment holds, under its prefix, the layout `cmake --install`
makes, and the installed command and module find their mesh reader as they
do there (passes/mesh/reader_location.h). `pip uninstall mdlc` removes every
file, the wheel's RECORD listing them all.

Nothing is downloaded: CMake, the compiler and the libraries are Debian's,
and the wheel is written with Debian's python3-wheel, which pip's isolated
build environment cannot see; hence `pip install --no-build-isolation .`.

The build tree is $MDLC_BUILD_DIR when set (an existing tree configured
with the Python module, e.g. the one the tests built: nothing is compiled
again), else build/wheel in the source tree, configured once for a Release
build of the command and the module for the interpreter running pip. The
version is the project's, from the mdlc/version.h the build generated.
"""

import io
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tarfile
import tempfile
from pathlib import Path

SOURCE_DIR = Path(__file__).resolve().parents[2]
BUILD_TARGETS = ["mdlc", "mdlc_python", "mdlc_mesh_reader", "mdlc_mesh_import_module"]
WHEEL_COMPONENTS = ["runtime", "python"]


class BuildError(RuntimeError):
    """A build step failed; the message says which and what to do."""


# -- PEP 517 hooks -------------------------------------------------------------

def get_requires_for_build_wheel(config_settings=None):
    # nothing to install when the wheel package is importable (Debian's
    # python3-wheel, seen with --no-build-isolation); otherwise pip is told
    # what is missing, and fetches it if it can
    return [] if _has_wheel_package() else ["wheel"]


def get_requires_for_build_sdist(config_settings=None):
    return []


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    if not _has_wheel_package():
        raise BuildError(
            "mdlc's wheel is written with the 'wheel' package (Debian: python3-wheel); "
            "build it with `pip install --no-build-isolation .`, which lets the build "
            "use the system's packages")
    build_dir = _build_dir(config_settings)
    _configure(build_dir)
    _log(f"building {', '.join(BUILD_TARGETS)} in {build_dir}")
    _run(["cmake", "--build", str(build_dir), "--target", *BUILD_TARGETS])
    cache = _read_cache(build_dir)
    version = _built_version(build_dir)
    with tempfile.TemporaryDirectory(prefix="mdlc-wheel-") as staging:
        staging = Path(staging)
        for component in WHEEL_COMPONENTS:
            _run(["cmake", "--install", str(build_dir), "--prefix", str(staging),
                  "--component", component, "--strip"])
        return _write_wheel(Path(wheel_directory), staging, version, cache)


def build_sdist(sdist_directory, config_settings=None):
    """The files git tracks, under mdlc-<version>/, with PKG-INFO."""
    version = _project_version()
    try:
        listed = subprocess.run(["git", "-C", str(SOURCE_DIR), "ls-files", "-z"], check=True,
                                capture_output=True).stdout.decode().split("\0")
    except (OSError, subprocess.CalledProcessError) as error:
        raise BuildError(f"a source distribution is made from a git clone: {error}") from None
    base = f"mdlc-{version}"
    name = f"{base}.tar.gz"
    with tarfile.open(Path(sdist_directory) / name, "w:gz", format=tarfile.PAX_FORMAT) as tar:
        for relative in filter(None, listed):
            if (SOURCE_DIR / relative).is_file():
                tar.add(SOURCE_DIR / relative, arcname=f"{base}/{relative}", recursive=False)
        info = tarfile.TarInfo(f"{base}/PKG-INFO")
        metadata = _metadata(version).encode()
        info.size = len(metadata)
        tar.addfile(info, io.BytesIO(metadata))
    return name


# -- the build -----------------------------------------------------------------

def _has_wheel_package():
    try:
        import wheel.wheelfile  # noqa: F401
    except ImportError:
        return False
    return True


def _log(message):
    print(f"mdlc wheel: {message}", file=sys.stderr, flush=True)


def _run(command):
    if shutil.which(command[0]) is None:
        raise BuildError(f"'{command[0]}' is not on the PATH (Debian: apt-get install cmake "
                         "ninja-build g++, and the libraries tools/setup.sh lists)")
    # the build's output goes to stderr, which pip shows with -v or on failure
    result = subprocess.run(command, stdout=sys.stderr, stderr=sys.stderr)
    if result.returncode != 0:
        raise BuildError(f"'{' '.join(command)}' failed with exit status {result.returncode}")


def _build_dir(config_settings):
    named = (config_settings or {}).get("build-dir") or os.environ.get("MDLC_BUILD_DIR")
    return Path(named).resolve() if named else SOURCE_DIR / "build" / "wheel"


def _configure(build_dir):
    if (build_dir / "CMakeCache.txt").is_file():
        return  # an existing tree, as it was configured
    command = ["cmake", "-S", str(SOURCE_DIR), "-B", str(build_dir),
               "-DCMAKE_BUILD_TYPE=Release", "-DMDLC_BUILD_TESTS=OFF",
               "-DMDLC_BUILD_BENCHMARKS=OFF", "-DMDLC_BUILD_PYTHON=ON",
               f"-DPython3_EXECUTABLE={sys.executable}"]
    if shutil.which("ninja"):
        command += ["-G", "Ninja"]
    _log(f"configuring {build_dir}")
    _run(command)


def _read_cache(build_dir):
    """NAME:TYPE=VALUE lines of CMakeCache.txt, as {NAME: VALUE}."""
    entries = {}
    for line in (build_dir / "CMakeCache.txt").read_text().splitlines():
        match = re.match(r"([A-Za-z_0-9]+):[A-Z]+=(.*)$", line)
        if match:
            entries[match.group(1)] = match.group(2)
    if not entries.get("MDLC_PYTHON_INSTALL_DIR"):
        raise BuildError(
            f"{build_dir} was configured without the Python module: it needs python3-dev, "
            "python3-numpy and pybind11-dev, and -DMDLC_BUILD_PYTHON=ON")
    return entries


def _built_version(build_dir):
    header = (build_dir / "include" / "mdlc" / "version.h").read_text()
    return re.search(r'#define MDLC_VERSION_STRING "([^"]+)"', header).group(1)


def _project_version():
    """The version stated once, in CMakeLists.txt's project()."""
    text = (SOURCE_DIR / "CMakeLists.txt").read_text()
    return re.search(r"project\(mdlc\s+VERSION\s+([0-9.]+)", text).group(1)


# -- the wheel -----------------------------------------------------------------

def _project_table():
    import tomllib
    with open(SOURCE_DIR / "pyproject.toml", "rb") as file:
        return tomllib.load(file)["project"]


def _metadata(version):
    project = _project_table()
    lines = ["Metadata-Version: 2.1", f"Name: {project['name']}", f"Version: {version}",
             f"Summary: {project['description']}",
             f"Requires-Python: {project['requires-python']}"]
    lines += [f"License: {project['license']['text']}"] if "license" in project else []
    lines += [f"Requires-Dist: {requirement}" for requirement in project.get("dependencies", [])]
    return "\n".join(lines) + "\n"


def _wheel_tag():
    python = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{python}-{python}{sys.abiflags}-{platform}"


def _write_wheel(wheel_directory, staging, version, cache):
    from wheel.wheelfile import WheelFile

    package = staging / cache["MDLC_PYTHON_INSTALL_DIR"] / "mdlc"
    extension = package / f"_mdlc{sysconfig.get_config_var('EXT_SUFFIX')}"
    if not extension.is_file():
        built = ", ".join(p.name for p in package.glob("_mdlc*")) or "nothing"
        raise BuildError(f"the build tree's module ({built}) was not built for this Python "
                         f"({sys.executable}); use another MDLC_BUILD_DIR")
    tag = _wheel_tag()
    name = f"mdlc-{version}-{tag}.whl"
    data = f"mdlc-{version}.data"
    dist_info = f"mdlc-{version}.dist-info"
    wheel_directory.mkdir(parents=True, exist_ok=True)
    # sorted, so that the same build makes the same archive
    with WheelFile(wheel_directory / name, "w") as wheel:
        for file in sorted(p for p in staging.rglob("*") if p.is_file()):
            relative = file.relative_to(staging)
            if file.is_relative_to(package):
                arcname = f"mdlc/{file.relative_to(package).as_posix()}"
            elif relative.parts[0] == "bin":
                arcname = f"{data}/scripts/{relative.relative_to('bin').as_posix()}"
            else:
                arcname = f"{data}/data/{relative.as_posix()}"
            wheel.write(str(file), arcname)
        wheel.writestr(f"{dist_info}/METADATA", _metadata(version))
        wheel.writestr(f"{dist_info}/WHEEL",
                       "Wheel-Version: 1.0\nGenerator: mdlc (tools/packaging/pip_backend.py)\n"
                       f"Root-Is-Purelib: false\nTag: {tag}\n")
    _log(f"wrote {name}")
    return name
