"""mdlc: compile robot models (URDF, SDFormat, MJCF, Drake Model Directives).

    import mdlc
    model = mdlc.compile("robot.urdf")
    M = model.mass_matrix()                 # numpy, nv x nv, at the default q
    X_WB = model.body_poses(q)              # one mdlc.Pose per body
    for body in model.bodies: print(body.scoped_name, body.mass, body.com)

A model with errors raises CompileError, which carries every diagnostic;
warnings are in model.diagnostics (strict=True makes them errors).
"""

import os

from . import _mdlc
from ._mdlc import (Actuator, Body, Camera, Constraint, Diagnostic, Frame, Geometry, Joint,
                    Model, Pose)

__version__ = _mdlc.__version__
__all__ = ["compile", "resolve_uri", "CompileError", "Model", "Body", "Joint", "Frame", "Geometry",
           "Actuator", "Constraint", "Camera", "Pose", "Diagnostic"]


class CompileError(Exception):
    """The model did not compile. `diagnostics` holds every diagnostic reported
    (errors, and the warnings and notes around them), each with file, line,
    column, severity, group and message."""

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
            limits=None, mesh_reader="process"):
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

    Raises CompileError (with every diagnostic) when the model has errors.
    """
    sources = source if isinstance(source, (list, tuple)) else [source]
    inputs = []
    for s in sources:
        if isinstance(s, os.PathLike):
            inputs.append((os.fspath(s), None))
        elif isinstance(s, str) and _looks_like_text(s):
            inputs.append((name or _default_name(format), s))
        elif isinstance(s, str):
            inputs.append((s, None))
        else:
            raise TypeError(f"mdlc.compile: expected a path or model text, got {type(s).__name__}")
    model, diagnostics = _mdlc._compile(
        inputs, format, sorted((packages or {}).items()), [os.fspath(p) for p in package_paths],
        use_ros_package_path, strict, list(disabled_warnings), list(error_warnings), model_name,
        auto_rename, list((joint_positions or {}).items()),
        [f"{k.replace('_', '-')}={v}" for k, v in (limits or {}).items()], mesh_reader)
    if model is None:
        raise CompileError(diagnostics)
    return model


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
        os.fspath(uri), sorted((packages or {}).items()),
        [os.fspath(p) for p in package_paths], use_ros_package_path, os.fspath(relative_to))
    if path is None:
        raise FileNotFoundError("".join(messages) or f"cannot resolve '{uri}'")
    return path


_EXTENSIONS = {"urdf": ".urdf", "sdf": ".sdf", "sdformat": ".sdf", "mjcf": ".xml",
               "mujoco": ".xml", "directives": ".dmd.yaml", "dmd": ".dmd.yaml"}


def _default_name(format):
    if format is None:
        raise ValueError("mdlc.compile: model text needs format= (or a name= with an extension)")
    return "model" + _EXTENSIONS.get(format, "")
