// py_dynamics.cc - mdlc.Model's dynamics methods: the free functions of
// mdlc/dynamics.h (inverse and forward dynamics, bias term, gravity forces,
// energy, frame Jacobians, poses and velocities, center of mass), numpy in
// and out.
//
// Sizes are checked here, before the backend's own check, so that a wrong
// one is a ValueError that names the argument and the method. pybind11 turns
// the backend's std::invalid_argument (an unknown frame) and
// std::domain_error (a singular mass matrix, no mass to take the center of)
// into ValueError with their messages.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "mdlc/dynamics.h"
#include "mdlc/kinematics.h"
#include "py_model.h"

namespace mdlc::python {
namespace py = pybind11;

namespace {

// The conventions every docstring below refers to.
constexpr const char* kConventions =
    "Conventions are Drake's (MultibodyPlant; see backend/dynamics.h and mdlc/dynamics.h): "
    "q and v in the plant's order (a joint's q_start/v_start), generalized forces in v order, "
    "tau = M(q) vdot + C(q,v) v - tau_g(q) - tau_applied(q,v). Out of scope: coupler and other "
    "constraints, kinematic loops, contact and joint limits (none of them acts here).";

// The options the dynamics methods take by keyword.
constexpr const char* kOptions =
    "gravity: include the plant's gravity; joint_damping: -damping * v on each velocity; "
    "force_elements: joint springs, linear spring-dampers and roll-pitch-yaw bushings (a "
    "spring-damper whose ends meet, or a bushing at pitch +-90 degrees, raises ValueError); "
    "reflected_inertia: each actuator's rotor_inertia * gear_ratio^2 added to M's "
    "diagonal, as Drake does.";

std::string Doc(const std::string& what, bool with_options = false) {
  return what + "\n\n" + kConventions + (with_options ? std::string("\n\n") + kOptions : "");
}

// "mdlc.Model.inverse_dynamics: v has 3 entries; the model has 2 velocities
// (num_velocities)"
void CheckSize(const char* method, const char* argument, const Eigen::VectorXd& x,
               Eigen::Index expected, const char* what) {
  if (x.size() == expected) return;
  throw py::value_error(fmt::format("mdlc.Model.{}: {} has {} entr{}; the model has {} {}",
                                    method, argument, x.size(), x.size() == 1 ? "y" : "ies",
                                    expected, what));
}

// A floating joint's quaternion of zero length is no rotation: as
// mass_matrix() and body_poses() do, say so rather than take the identity.
void CheckQuaternions(const char* method, const Model& m, const Eigen::VectorXd& q) {
  for (const Joint& j : m.joints) {
    if (j.type != "quaternion_floating") continue;
    const double norm = q.segment<4>(j.q_start).norm();
    if (norm == 0 || !std::isfinite(norm)) {
      throw py::value_error(fmt::format(
          "mdlc.Model.{}: q[{}:{}], the quaternion [w, x, y, z] of joint '{}', {}; a rotation "
          "needs a nonzero finite quaternion (the identity is [1, 0, 0, 0])",
          method, j.q_start, j.q_start + 4, j.scoped_name, norm == 0 ? "is zero" : "is not finite"));
    }
  }
}

const Eigen::VectorXd& Positions(const char* method, const Model& m, const Eigen::VectorXd& q) {
  CheckSize(method, "q", q, m.result->plant().num_positions, "positions (num_positions)");
  CheckQuaternions(method, m, q);
  return q;
}

const Eigen::VectorXd& Velocities(const char* method, const Model& m, const char* argument,
                                  const Eigen::VectorXd& x) {
  CheckSize(method, argument, x, m.result->plant().num_velocities, "velocities (num_velocities)");
  return x;
}

DynamicsOptions MakeOptions(bool gravity, bool joint_damping, bool force_elements,
                            bool reflected_inertia) {
  DynamicsOptions options;
  options.gravity = gravity;
  options.joint_damping = joint_damping;
  options.force_elements = force_elements;
  options.reflected_inertia = reflected_inertia;
  return options;
}

// A frame is named as plant-json names it ("model::link", "world", a local
// name when unambiguous), or given as a Body or Frame of the model.
std::string FrameName(const py::object& frame) {
  if (py::isinstance<py::str>(frame)) return frame.cast<std::string>();
  if (py::isinstance<Body>(frame)) return frame.cast<const Body&>().scoped_name;
  if (py::isinstance<Frame>(frame)) {
    const Frame& f = frame.cast<const Frame&>();
    return f.model_instance.empty() ? f.name : f.model_instance + "::" + f.name;
  }
  throw py::type_error("a frame is a name (str), an mdlc.Body or an mdlc.Frame, got " +
                       py::str(frame.get_type().attr("__name__")).cast<std::string>());
}

std::string Repr(const backend::CenterOfMass& com) {
  const auto vector = [](const Eigen::Vector3d& v) {
    return fmt::format("[{:.6g}, {:.6g}, {:.6g}]", v.x(), v.y(), v.z());
  };
  return fmt::format("<mdlc.CenterOfMass mass={:.6g} position={} velocity={}>", com.mass,
                     vector(com.position), vector(com.velocity));
}

}  // namespace

void BindDynamics(py::module_& m) {
  py::class_<backend::CenterOfMass>(
      m, "CenterOfMass",
      "The combined center of mass S of some bodies: mass, position p_WScm (3), velocity "
      "v_WScm (3, zero without v) and jacobian Js_v_WScm_W (3 x nv), all in the world frame")
      .def_readonly("mass", &backend::CenterOfMass::mass)
      .def_readonly("position", &backend::CenterOfMass::position)
      .def_readonly("velocity", &backend::CenterOfMass::velocity)
      .def_readonly("jacobian", &backend::CenterOfMass::jacobian)
      .def("__repr__", [](const backend::CenterOfMass& c) { return Repr(c); });

  // BindModel made the class; its dynamics are added here
  auto model = py::reinterpret_borrow<py::class_<Model>>(m.attr("Model"));
  model
      .def(
          "inverse_dynamics",
          [](const Model& m, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
             const Eigen::VectorXd& vdot, bool gravity, bool joint_damping, bool force_elements,
             bool reflected_inertia) {
            const char* f = "inverse_dynamics";
            return mdlc::InverseDynamics(
                *m.result, Positions(f, m, q), Velocities(f, m, "v", v),
                Velocities(f, m, "vdot", vdot),
                MakeOptions(gravity, joint_damping, force_elements, reflected_inertia));
          },
          py::arg("q"), py::arg("v"), py::arg("vdot"), py::kw_only(), py::arg("gravity") = true,
          py::arg("joint_damping") = false, py::arg("force_elements") = false,
          py::arg("reflected_inertia") = true,
          Doc("The generalized forces tau (nv) that give accelerations vdot at (q, v): "
              "tau = M vdot + C v - tau_g - tau_applied (Drake's CalcInverseDynamics). With "
              "vdot = 0 and v = 0, the forces that hold the model still.",
              true)
              .c_str())
      .def(
          "bias_term",
          [](const Model& m, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
            const char* f = "bias_term";
            return mdlc::BiasTerm(*m.result, Positions(f, m, q), Velocities(f, m, "v", v));
          },
          py::arg("q"), py::arg("v"),
          Doc("C(q, v) v (nv): the Coriolis, centripetal and gyroscopic terms, without gravity "
              "(Drake's CalcBiasTerm).")
              .c_str())
      .def(
          "gravity_forces",
          [](const Model& m, const Eigen::VectorXd& q) {
            return mdlc::GravityForces(*m.result, Positions("gravity_forces", m, q));
          },
          py::arg("q"),
          Doc("tau_g(q) (nv), the generalized forces of the plant's gravity: positive where "
              "gravity does positive work (Drake's CalcGravityGeneralizedForces), so a pendulum "
              "at angle theta from hanging has tau_g = -m g l sin(theta).")
              .c_str())
      .def(
          "forward_dynamics",
          [](const Model& m, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
             const Eigen::VectorXd& tau, bool gravity, bool joint_damping, bool force_elements,
             bool reflected_inertia) {
            const char* f = "forward_dynamics";
            return mdlc::ForwardDynamics(
                *m.result, Positions(f, m, q), Velocities(f, m, "v", v),
                Velocities(f, m, "tau", tau),
                MakeOptions(gravity, joint_damping, force_elements, reflected_inertia));
          },
          py::arg("q"), py::arg("v"), py::arg("tau"), py::kw_only(), py::arg("gravity") = true,
          py::arg("joint_damping") = false, py::arg("force_elements") = false,
          py::arg("reflected_inertia") = true,
          Doc("The accelerations vdot (nv) that generalized forces tau give at (q, v): the "
              "solution of M vdot + C v = tau + tau_g + tau_applied, the inverse of "
              "inverse_dynamics. Raises ValueError when M is singular (a massless body at the "
              "end of a joint).",
              true)
              .c_str())
      .def(
          "kinetic_energy",
          [](const Model& m, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
             bool reflected_inertia) {
            const char* f = "kinetic_energy";
            return mdlc::KineticEnergy(*m.result, Positions(f, m, q), Velocities(f, m, "v", v),
                                       MakeOptions(true, false, false, reflected_inertia));
          },
          py::arg("q"), py::arg("v"), py::kw_only(), py::arg("reflected_inertia") = true,
          Doc("1/2 v^T M v, in joules (with the actuators' reflected inertia unless "
              "reflected_inertia=False).")
              .c_str())
      .def(
          "potential_energy",
          [](const Model& m, const Eigen::VectorXd& q, bool gravity, bool force_elements) {
            return mdlc::PotentialEnergy(*m.result, Positions("potential_energy", m, q),
                                         MakeOptions(gravity, false, force_elements, true));
          },
          py::arg("q"), py::kw_only(), py::arg("gravity") = true,
          py::arg("force_elements") = false,
          Doc("The potential energy at q, in joules: gravity's -sum m g . p_WBcm (zero at the "
              "world origin), plus the force elements' 1/2 k stretch^2 with "
              "force_elements=True.")
              .c_str())
      .def(
          "jacobian",
          [](const Model& m, const py::object& frame, const Eigen::VectorXd& q,
             const Eigen::Vector3d& point, const py::object& measured_in,
             const py::object& expressed_in, bool translational) {
            const Eigen::VectorXd& q_checked = Positions("jacobian", m, q);
            const std::string B = FrameName(frame), A = FrameName(measured_in),
                              E = FrameName(expressed_in);
            return translational
                       ? mdlc::JacobianTranslationalVelocity(*m.result, q_checked, B, point, A, E)
                       : mdlc::JacobianSpatialVelocity(*m.result, q_checked, B, point, A, E);
          },
          py::arg("frame"), py::arg("q"), py::arg("point") = Eigen::Vector3d::Zero().eval(),
          py::arg("measured_in") = "world", py::arg("expressed_in") = "world",
          py::arg("translational") = false,
          Doc("Js_V_ABp_E (6 x nv, rows [w; v]) such that J @ v is the spatial velocity of "
              "`frame` B shifted to `point` Bp (p_BoBp_B, in B), measured in frame A "
              "(`measured_in`) and expressed in frame E (`expressed_in`): Drake's "
              "CalcJacobianSpatialVelocity with respect to v. translational=True gives "
              "Js_v_ABp_E (3 x nv), its last three rows (CalcJacobianTranslationalVelocity). "
              "Frames are named as plant-json names them ('model::link', 'world', or a local "
              "name when unambiguous), or given as an mdlc.Body or mdlc.Frame; an unknown or "
              "ambiguous name raises ValueError.")
              .c_str())
      .def(
          "frame_pose",
          [](const Model& m, const py::object& frame, const Eigen::VectorXd& q) {
            return MakePose(
                mdlc::FramePose(*m.result, Positions("frame_pose", m, q), FrameName(frame)));
          },
          py::arg("frame"), py::arg("q"),
          Doc("X_WF of a body or frame at q, an mdlc.Pose as body_poses() gives (.p, .R, .q, "
              ".matrix).")
              .c_str())
      .def(
          "frame_velocity",
          [](const Model& m, const py::object& frame, const Eigen::VectorXd& q,
             const Eigen::VectorXd& v) {
            const char* f = "frame_velocity";
            return mdlc::FrameSpatialVelocity(*m.result, Positions(f, m, q),
                                              Velocities(f, m, "v", v), FrameName(frame));
          },
          py::arg("frame"), py::arg("q"), py::arg("v"),
          Doc("V_WF_W (6): [w_WF; v_WFo], the angular velocity of a body or frame F and the "
              "velocity of its origin, measured and expressed in the world; equal to "
              "jacobian(frame, q) @ v.")
              .c_str())
      .def(
          "frame_acceleration",
          [](const Model& m, const py::object& frame, const Eigen::VectorXd& q,
             const Eigen::VectorXd& v, const Eigen::VectorXd& vdot) {
            const char* f = "frame_acceleration";
            return mdlc::FrameSpatialAcceleration(*m.result, Positions(f, m, q),
                                                  Velocities(f, m, "v", v),
                                                  Velocities(f, m, "vdot", vdot), FrameName(frame));
          },
          py::arg("frame"), py::arg("q"), py::arg("v"), py::arg("vdot"),
          Doc("A_WF_W (6): [alpha_WF; a_WFo], the angular acceleration of a body or frame F and "
              "the acceleration of its origin, measured and expressed in the world, gravity not "
              "included: the rate of frame_velocity(frame, q, v) as q moves with v and v with "
              "vdot.")
              .c_str())
      .def(
          "center_of_mass",
          [](const Model& m, const Eigen::VectorXd& q, const std::optional<Eigen::VectorXd>& v,
             const std::optional<std::vector<std::string>>& model_instances) {
            const char* f = "center_of_mass";
            return mdlc::CenterOfMass(*m.result, Positions(f, m, q),
                                      v ? Velocities(f, m, "v", *v) : Eigen::VectorXd(),
                                      model_instances.value_or(std::vector<std::string>{}));
          },
          py::arg("q"), py::arg("v") = py::none(), py::arg("model_instances") = py::none(),
          Doc("The combined center of mass of every body (or of the bodies of the named model "
              "instances), an mdlc.CenterOfMass: mass, position p_WScm, velocity v_WScm (zero "
              "when v is None) and jacobian Js_v_WScm_W (3 x nv), with jacobian @ v == "
              "velocity. Raises ValueError when the bodies have no mass, or a model instance "
              "is unknown.")
              .c_str());
}

}  // namespace mdlc::python
