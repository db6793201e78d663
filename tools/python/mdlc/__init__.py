"""mdlc: compile robot models (URDF, SDFormat, MJCF, Drake Model Directives).

    import mdlc
    model = mdlc.compile("robot.urdf")
    arm = mdlc.compile("arm.urdf.xacro", xacro_args={"prefix": "left_"})
    xml = mdlc.expand_xacro("arm.urdf.xacro", {"prefix": "left_"})  # the URDF text
    M = model.mass_matrix()                 # numpy, nv x nv, at the default q
    X_WB = model.body_poses(q)              # one mdlc.Pose per body
    for body in model.bodies: print(body.scoped_name, body.mass, body.com)
    hand = model.bodies["panda_hand"]       # every entity list is indexed by name too

A model with errors raises CompileError, which carries every diagnostic;
warnings are in model.diagnostics (strict=True makes them errors).
"""

import difflib as _difflib
import errno as _errno
import os as _os

from . import _mdlc
from ._mdlc import (Actuator, Body, Camera, Constraint, Diagnostic, Frame, Geometry, Joint,
                    Model, Pose)

__version__ = _mdlc.__version__
__all__ = ["compile", "expand_xacro", "resolve_uri", "CompileError", "EntityList", "Model",
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
    # model text has markup or several lines; a path has neither
    stripped = source.lstrip()
    return stripped.startswith("<") or "\n" in source or stripped.startswith("directives:")


def compile(source, format=None, *, name=None, packages=None, package_paths=(),
            use_ros_package_path=False, strict=False, disabled_warnings=(),
            error_warnings=(), model_name=None, auto_rename=False, joint_positions=None,
            limits=None, mesh_reader="process", xacro_args=None,
            collada_up_axis="as-written"):
    """Compiles one model, or several into one plant, and returns a Model.

    source: a path (str or os.PathLike), model text (str with markup), or a
        list of those.
    format: 'urdf', 'sdf', 'mjcf' or 'directives'; default: from the file
        extension (for text: from `name`'s extension).
    name: for text, the name diagnostics print and relative paths resolve
        against (default: 'model.' + the format's extension, in the current
        directory).
    packages: {name: directory} for package:// URIs; package_paths: folders
        searched for package.xml; use_ros_package_path: also use the ROS
        environment (ROS_PACKAGE_PATH, and the ament index of each
        AMENT_PREFIX_PATH prefix).
    strict: warnings are errors. disabled_warnings / error_warnings: -W groups
        silenced / made errors.
    model_name, auto_rename: as --model-name and --auto-rename.
    joint_positions: {joint name: value} applied by default_positions().
    limits: {limit name: value} as --limit NAME=VALUE, e.g. {"depth": 500,
        "file_size": "64M"}; ValueError for an unknown name or a bad value.
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
    model, diagnostics = _mdlc._compile(
        inputs, format, sorted((packages or {}).items()), [_os.fspath(p) for p in package_paths],
        use_ros_package_path, strict, list(disabled_warnings), list(error_warnings), model_name,
        auto_rename, list((joint_positions or {}).items()),
        _limit_settings(limits), mesh_reader, _xacro_args("compile", xacro_args),
        collada_up_axis)
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


def _default_name(format):
    if format is None:
        raise ValueError("mdlc.compile: model text needs format= (or a name= with an extension)")
    return "model" + _EXTENSIONS.get(format, "")
