"""mdlc: compile robot models (URDF, SDFormat, MJCF, Drake Model Directives).

    import mdlc
    model = mdlc.compile("robot.urdf")
    model = mdlc.compile("robot.urdf", strict=True, disabled_warnings=["inertia"])
    model = mdlc.compile_string(urdf_text, format="urdf")   # text in memory
    arm = mdlc.compile("arm.urdf.xacro", xacro_args={"prefix": "left_"})
    xml = mdlc.expand_xacro("arm.urdf.xacro", {"prefix": "left_"})  # the URDF text
    M = model.mass_matrix()                 # numpy, nv x nv, at the default q
    X_WB = model.body_poses(q)              # one mdlc.Pose per body
    for body in model.bodies: print(body.scoped_name, body.mass, body.com)
    hand = model.bodies["panda_hand"]       # every entity list is indexed by name too

A model with errors raises CompileError, which carries every diagnostic;
warnings are in model.diagnostics (strict=True makes them errors).

compile() and compile_string() take their options by keyword, the command
line's flags with '_' for '-' (mdlc.OPTION_NAMES lists them). mdlc checks
every name as the command line does: a misspelt keyword, warning group or
limit raises ValueError with the nearest known name, instead of being
ignored.
"""

import difflib as _difflib
import errno as _errno
import os as _os

from . import _mdlc
from ._mdlc import (Actuator, Body, Camera, Constraint, Diagnostic, Frame, Geometry, Joint,
                    Model, Pose)

__version__ = _mdlc.__version__
#: The keywords compile() and compile_string() take.
OPTION_NAMES = tuple(_mdlc._option_names())
__all__ = ["compile", "compile_string", "OPTION_NAMES", "expand_xacro", "resolve_uri", "CompileError", "EntityList", "Model",
           "Body", "Joint", "Frame", "Geometry", "Actuator", "Constraint", "Camera", "Pose",
           "Diagnostic"]


class EntityList(list):
    """A model's bodies, joints, frames, ...: a list, indexed by position,
    that is also indexed by name: model.bodies["panda_hand"] or, scoped,
    model.bodies["panda::panda_hand"]. A name that no entity has, or that
    entities of several model instances share (give the scoped name then),
    raises KeyError saying so. `name in model.bodies` and
    model.bodies.get(name) work the same way."""

    def __init__(self, entities=(), kind="entity"):
        super().__init__(entities)
        self.kind = kind

    def __getitem__(self, key):
        if isinstance(key, str):
            return self._named(key)
        found = super().__getitem__(key)
        return EntityList(found, self.kind) if isinstance(key, slice) else found

    def __contains__(self, item):
        if isinstance(item, str):
            return bool(self._matches(item))
        return super().__contains__(item)

    def get(self, name, default=None):
        """The entity named `name` (scoped or not), or `default`."""
        found = self._matches(name)
        return found[0] if len(found) == 1 else default

    def names(self):
        """Every entity's scoped name, in list order."""
        return [_scoped_name(e) for e in self]

    def _matches(self, name):
        scoped = [e for e in self if _scoped_name(e) == name]
        return scoped or [e for e in self if getattr(e, "name", None) == name]

    def _named(self, name):
        found = self._matches(name)
        if len(found) == 1:
            return found[0]
        if found:
            raise KeyError(f"{len(found)} {self.kind} entries are named {name!r}; give the "
                           f"scoped name: {', '.join(_scoped_name(e) for e in found)}")
        if not any(getattr(e, "name", None) for e in self):
            raise KeyError(f"no {self.kind} named {name!r}" +
                           ("; the list is empty" if not self else
                            f"; {self.kind} entries have no names"))
        close = _difflib.get_close_matches(
            name, [n for e in self for n in (e.name, _scoped_name(e))], n=3)
        hint = f"; did you mean {' or '.join(repr(c) for c in dict.fromkeys(close))}?" \
            if close else ""
        raise KeyError(f"no {self.kind} named {name!r}{hint}")


def _scoped_name(entity):
    scoped = getattr(entity, "scoped_name", None)
    if scoped is not None:
        return scoped
    instance = getattr(entity, "model_instance", "")
    name = getattr(entity, "name", "")
    return f"{instance}::{name}" if instance else name


def _entity_list_property(attribute, kind):
    # the extension's property returns a plain list; this one wraps it
    plain = getattr(Model, attribute)
    return property(lambda model: EntityList(plain.__get__(model), kind), doc=plain.__doc__)


for _attribute, _kind in (("bodies", "body"), ("joints", "joint"), ("frames", "frame"),
                          ("geometries", "geometry"), ("actuators", "actuator"),
                          ("constraints", "constraint"), ("cameras", "camera")):
    setattr(Model, _attribute, _entity_list_property(_attribute, _kind))
del _attribute, _kind


class CompileError(Exception):
    """The model did not compile (or a xacro file did not expand).
    `diagnostics` holds every diagnostic reported (errors, and the warnings and
    notes around them), each with file, line, column, severity, group and
    message; the exception's message is the errors as the command line prints
    them (file:line:column: error: ...)."""

    def __init__(self, diagnostics):
        self.diagnostics = list(diagnostics)
        errors = [d for d in self.diagnostics if d.severity == "error"]
        super().__init__("".join(d.text for d in errors) or "compilation failed")


def _looks_like_text(source):
    # compile(text) is the older spelling of compile_string(text): model text
    # has markup or several lines; a path has neither
    stripped = source.lstrip()
    return stripped.startswith("<") or "\n" in source or stripped.startswith("directives:")


def compile(source, format=None, *, name=None, **options):
    """Compiles one model, or several into one plant, and returns a Model.

    source: a path (str or os.PathLike), or a list of paths. (Model text is
        still taken, as in earlier releases, when it has markup or several
        lines; compile_string says so outright.)
    format: 'urdf', 'sdf', 'mjcf' or 'directives'; default: from the file
        extension.
    name: for text, as compile_string's.

    The options, by keyword only, are the command line's flags with '_' for
    '-'. mdlc's own code checks each name and value, as the command line
    checks its flags: an unknown keyword, warning group, limit or value
    raises ValueError naming the nearest known one ("unknown keyword
    'strcit' for mdlc.compile; did you mean 'strict'?"); a value of the
    wrong type raises TypeError. None leaves an option at its default.

    packages: {name: directory} for package:// URIs (--package);
        package_paths: folders searched for package.xml (--package-path);
        use_ros_package_path: also use the ROS environment (ROS_PACKAGE_PATH,
        and the ament index of each AMENT_PREFIX_PATH prefix).
    strict: warnings are errors (--strict). warnings: -W flags as text,
        e.g. ["error", "no-joint", "error=names"]. disabled_warnings /
        error_warnings: -W groups silenced / made errors (-Wno-GROUP,
        -Werror=GROUP); `mdlc --list-warnings` lists the groups.
        max_errors: stop reporting after this many errors (0: no limit).
    model_name, auto_rename, fixed_base: as --model-name, --auto-rename and
        --fixed-base.
    joint_positions: {joint name: value} applied by default_positions() (--q).
    limits: {limit name: value} as --limit NAME=VALUE, e.g. {"depth": 500,
        "file_size": "64M"}.
    mesh_reader: 'process' (read each mesh file in a child process, so that
        a crash of the mesh importer is a diagnostic, not the interpreter's
        crash) or 'in-process'; as --mesh-reader.
    xacro_args: {name: value} (str to str), the NAME:=VALUE arguments of a
        xacro input (a path, or text whose name= ends in .xacro, e.g.
        robot.urdf.xacro), which $(arg NAME) reads; they win over the
        defaults of <xacro:arg>. A xacro input is expanded before it is read,
        and its format is its root element's (<robot>, <sdf> or <mujoco>).
    collada_up_axis: 'as-written' (COLLADA meshes read in the axes their
        vertices are written in, as Drake reads them) or 'apply' (turned
        from the <up_axis> the file declares to Z-up); as --collada-up-axis.
    cache_dir: keep derived mesh data (convex hulls, mass properties) in
        this folder between compiles (--cache-dir; default: no cache).

    The model's entity lists (bodies, joints, ...) are EntityLists, indexed
    by position and by name. Raises FileNotFoundError when a path names no
    file, CompileError (with every diagnostic) when the model has errors.
    """
    sources = source if isinstance(source, (list, tuple)) else [source]
    inputs = []
    for s in sources:
        if isinstance(s, _os.PathLike) or (isinstance(s, str) and not _looks_like_text(s)):
            path = _os.fspath(s)
            if not _os.path.exists(path):
                # as open() says it: a missing file is no model error
                raise FileNotFoundError(_errno.ENOENT, _os.strerror(_errno.ENOENT), path)
            inputs.append((path, None))
        elif isinstance(s, str):
            inputs.append((name or _default_name(format), s))
        else:
            raise TypeError(f"mdlc.compile: expected a path or model text, got {type(s).__name__}")
    return _compiled(_mdlc._compile(inputs, format, options, "mdlc.compile"))


def compile_string(text, format=None, *, name=None, **options):
    """Compiles model text held in memory and returns a Model, as compile()
    compiles a file; nothing decides from the text whether it is a path.

    text: the model (str), or a list of texts compiled into one plant.
    format: 'urdf', 'sdf', 'mjcf' or 'directives'; default: from `name`'s
        extension.
    name: the name diagnostics print and relative paths (meshes, includes)
        resolve against: text named "robots/arm.urdf" finds "meshes/a.obj"
        in "robots/meshes/" (default: 'model.' + the format's extension, in
        the current directory). A name ending in .xacro is expanded first.
    options: the keywords of compile(), checked the same way.

        model = mdlc.compile_string(urdf_text, format="urdf", strict=True)
    """
    texts = text if isinstance(text, (list, tuple)) else [text]
    for t in texts:
        if not isinstance(t, str):
            raise TypeError(f"mdlc.compile_string: expected model text (str), got "
                            f"{type(t).__name__}")
    inputs = [(name or _default_name(format, "mdlc.compile_string"), t) for t in texts]
    return _compiled(_mdlc._compile(inputs, format, options, "mdlc.compile_string"))


def _compiled(outcome):
    model, diagnostics = outcome
    if model is None:
        raise CompileError(diagnostics)
    return model


def expand_xacro(path, args=None, *, packages=None, package_paths=(),
                 use_ros_package_path=False, strict=False, limits=None):
    """Expands a xacro file and returns the XML text, as `mdlc xacro` (and
    ROS's xacro command) writes it; nothing is compiled.

    path: the xacro file (str or os.PathLike); the banner comment of the
        output names it as given.
    args: {name: value} (str to str), xacro's NAME:=VALUE arguments, which
        $(arg NAME) reads; they win over the defaults of <xacro:arg>.
    packages, package_paths, use_ros_package_path: where $(find PKG) looks,
        as for compile().
    strict: warnings are errors. limits: as for compile() (macro_depth and
        expansion_nodes bound the expansion).

    Raises CompileError when the file does not expand: its message gives each
    error as file:line:column, with the macro calls and includes that led
    there, and its `diagnostics` every diagnostic. Warnings of an expansion
    that succeeds are not returned (strict=True makes them errors).
    """
    xml, diagnostics = _mdlc._expand_xacro(
        _os.fspath(path), _xacro_args("expand_xacro", args), sorted((packages or {}).items()),
        [_os.fspath(p) for p in package_paths], use_ros_package_path, strict,
        _limit_settings(limits))
    if xml is None:
        raise CompileError(diagnostics)
    return xml


def resolve_uri(uri, *, packages=None, package_paths=(), use_ros_package_path=False,
                relative_to="."):
    """The existing file (or folder) that a package://, model:// or file://
    URI, or a path relative to `relative_to`, names: resolved as a model's
    mesh reference is, with the same package arguments as compile(). For
    files no model names, such as textures or controller configurations.

    Raises FileNotFoundError, whose message gives the reasons (an unknown
    package and the folders searched, or the path that does not exist).
    """
    path, messages = _mdlc._resolve_uri(
        _os.fspath(uri), sorted((packages or {}).items()),
        [_os.fspath(p) for p in package_paths], use_ros_package_path, _os.fspath(relative_to))
    if path is None:
        raise FileNotFoundError("".join(messages) or f"cannot resolve '{uri}'")
    return path


def _limit_settings(limits):
    # {"file_size": "64M"} -> ["file-size=64M"], as --limit spells them
    return [f"{k.replace('_', '-')}={v}" for k, v in (limits or {}).items()]


def _xacro_args(function, args):
    # {name: value} -> [(name, value)], checked: xacro's arguments are text
    pairs = list((args or {}).items())
    for name, value in pairs:
        if not isinstance(name, str) or not isinstance(value, str):
            raise TypeError(f"mdlc.{function}: xacro arguments map str to str, got "
                            f"{type(name).__name__} -> {type(value).__name__} for {name!r}")
    return pairs


_EXTENSIONS = {"urdf": ".urdf", "sdf": ".sdf", "sdformat": ".sdf", "mjcf": ".xml",
               "mujoco": ".xml", "directives": ".dmd.yaml", "dmd": ".dmd.yaml"}


def _default_name(format, function="mdlc.compile"):
    if format is None:
        raise ValueError(f"{function}: model text needs format= (or a name= with an extension)")
    return "model" + _EXTENSIONS.get(format, "")
