// py_model.h - what the Python module shows of a compiled model: plain
// structs, one per entity, holding names (scoped, as plant-json writes them)
// and Eigen values (numpy arrays on the Python side).
//
// They are built once per compile from the plant and scene graph, so Python
// code reads attributes without calling back into C++, and the values are the
// very doubles plant-json prints (the tests check it, bit for bit).
#pragma once

#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mdlc/mdlc.h"

namespace mdlc::python {

/// A pose X_AB: translation p, rotation R, and the unit quaternion q = [w, x,
/// y, z] with w >= 0 that plant-json prints.
struct Pose {
  Eigen::Vector3d p;
  Eigen::Matrix3d R;
  Eigen::Vector4d q;
  Eigen::Matrix4d matrix() const;
};
Pose MakePose(const Transform& X);

struct Body {
  std::string name, scoped_name, model_instance;
  double mass = 0;
  Eigen::Vector3d com;      // p_BoBcm_B
  Eigen::Matrix3d inertia;  // I_BBcm_B, about the center of mass, in B
  bool is_world = false, unnamed = false;
  std::optional<std::string> parent, joint;  // scoped names; None for roots
  int index = 0;                             // its row in body_poses()
  std::optional<Eigen::Vector3d> surface_velocity_axis;  // unit, in B (EXT-060)
  /// A deformable link's properties (EXT-070), as plant-json's
  /// bodies[].deformable; None for a rigid body.
  std::optional<pybind11::dict> deformable;
};

struct Joint {
  std::string name, scoped_name, model_instance, type;
  std::string parent, child;  // scoped body names
  Pose X_PF, X_CM;
  Eigen::Vector3d axis;  // in F
  Eigen::VectorXd lower, upper, velocity_lower, velocity_upper, effort, damping,
      default_positions;
  double screw_thread_pitch = 0;
  bool unnamed = false;
  int q_start = 0, nq = 0, v_start = 0, nv = 0;
  Eigen::VectorXd acceleration_lower, acceleration_upper;  // -inf/inf where unbounded
};

struct Frame {
  std::string name, model_instance, body;
  Pose X_BF;
  bool unnamed = false;
};

struct Geometry {
  std::string name, model_instance, body;
  Pose X_BG;
  std::vector<std::string> roles;  // proximity, illustration, perception
  std::string shape;               // box, sphere, ..., mesh, convex, half_space
  pybind11::dict shape_parameters; // as plant-json's "shape" object, minus "type"
  pybind11::dict properties;       // "group/name" -> value
  bool unnamed = false;
};

struct Actuator {
  std::string name, model_instance, joint;
  double effort_limit = 0, gear_ratio = 1, rotor_inertia = 0;
  std::optional<double> kp, kd;
  bool unnamed = false;
};

struct Constraint {
  std::string type, model_instance;
  pybind11::dict parameters;  // as plant-json's constraint object, minus "type"
};

struct ForceElement {
  std::string type;           // linear_bushing_rpy, linear_spring_damper, revolute_spring, ...
  pybind11::dict parameters;  // as plant-json's force element object, minus "type"
};

struct Camera {
  std::string name, model_instance, body;
  Pose X_BC;  // Drake's camera frame: +z forward, +x right, +y down
  int width = 0, height = 0;
  double fov_y = 0;
  bool unnamed = false;
};

/// A compiled model, as Python sees it. Keeps the Result alive.
struct Model {
  std::shared_ptr<const Result> result;
  std::vector<std::string> model_instances;
  std::vector<Body> bodies;  // by BodyId: bodies[0] is the world
  std::vector<Joint> joints;
  std::vector<Frame> frames;
  std::vector<Geometry> geometries;
  std::vector<Actuator> actuators;
  std::vector<Constraint> constraints;
  std::vector<Camera> cameras;
  std::vector<ForceElement> force_elements;
  pybind11::list diagnostics;  // warnings and notes (errors raise instead)
};

/// Builds the Python view of a successful compile.
Model MakeModel(std::shared_ptr<const Result> result, pybind11::list diagnostics);

/// Adds the classes above to the module.
void BindModel(pybind11::module_& m);

/// Adds Model's dynamics methods and CenterOfMass (py_dynamics.cc); after BindModel.
void BindDynamics(pybind11::module_& m);

}  // namespace mdlc::python
