"""mdlc.Model's dynamics (mdlc/dynamics.h from Python): the identities that
tie inverse and forward dynamics, the mass matrix, bias term, gravity forces,
Jacobians, frame poses and velocities and the center of mass together, on a
double pendulum, a model with free bodies and one with ball and universal
joints; a pendulum against its closed form; and the errors of bad sizes and
names.

Run by ctest (python/dynamics) with the built package on PYTHONPATH; models
come from examples/, tests/models and text written here.
"""

import math
import pathlib
import unittest

import numpy as np

import mdlc

ROOT = pathlib.Path(__file__).resolve().parents[2]
DOUBLE_PENDULUM = ROOT / "examples/urdf/double_pendulum.urdf"
FLOATING = ROOT / "tests/models/urdf/floating_joint.urdf"  # two free bodies, revolutes
BALL = ROOT / "tests/models/sdf/ball_universal.sdf"        # ball, universal, free bodies

# m = 2 kg, its center of mass l = 0.5 m below a revolute joint about y;
# I_yy about the center of mass 0.1
M, L, I_YY, G = 2.0, 0.5, 0.1, 9.81
PENDULUM = f"""<?xml version="1.0"?>
<robot name="pendulum">
  <link name="world"/>
  <link name="arm">
    <inertial><origin xyz="0 0 -{L}"/><mass value="{M}"/>
      <inertia ixx="0.1" iyy="{I_YY}" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <joint name="shoulder" type="continuous">
    <parent link="world"/><child link="arm"/><axis xyz="0 1 0"/>
  </joint>
</robot>
"""

STEP = 1e-6  # central differences: error ~ STEP^2


def random_state(model, rng):
    """A random q (unit quaternions for free bodies) and v."""
    q = rng.uniform(-1.0, 1.0, model.num_positions)
    for joint in model.joints:
        if joint.type == "quaternion_floating":
            quaternion = q[joint.q_start:joint.q_start + 4]
            q[joint.q_start:joint.q_start + 4] = quaternion / np.linalg.norm(quaternion)
    return q, rng.uniform(-1.0, 1.0, model.num_velocities)


def qdot_columns(model):
    """(q index, v index) of each coordinate whose velocity is its qdot: those
    of 1-dof joints and of universal joints (not a ball joint's or a free
    body's, whose v is an angular velocity)."""
    return [(j.q_start + i, j.v_start + i) for j in model.joints
            if j.type in ("revolute", "prismatic", "screw", "universal") for i in range(j.nv)]


def skew_vector(S):
    return np.array([S[2, 1] - S[1, 2], S[0, 2] - S[2, 0], S[1, 0] - S[0, 1]]) / 2


def pose_derivative(model, frame, q, i, point=np.zeros(3)):
    """[w; v of the point] of `frame` for qdot = e_i, by central differences."""
    def at(sign):
        x = q.copy()
        x[i] += sign * STEP
        return model.frame_pose(frame, x)
    plus, minus = at(1), at(-1)
    R = model.frame_pose(frame, q).R
    w = skew_vector((plus.R - minus.R) / (2 * STEP) @ R.T)
    v = ((plus.p + plus.R @ point) - (minus.p + minus.R @ point)) / (2 * STEP)
    return np.concatenate([w, v])


class Models:
    @classmethod
    def setUpClass(cls):
        cls.models = {path.name: mdlc.compile(str(path))
                      for path in (DOUBLE_PENDULUM, FLOATING, BALL)}


class Identities(Models, unittest.TestCase):
    def test_inverse_dynamics_undoes_forward_dynamics(self):
        rng = np.random.default_rng(1)
        for name, model in self.models.items():
            for options in ({}, {"joint_damping": True}, {"gravity": False},
                            {"reflected_inertia": False}):
                with self.subTest(model=name, **options):
                    q, v = random_state(model, rng)
                    tau = rng.uniform(-2.0, 2.0, model.num_velocities)
                    vdot = model.forward_dynamics(q, v, tau, **options)
                    self.assertEqual(vdot.shape, (model.num_velocities,))
                    np.testing.assert_allclose(
                        model.inverse_dynamics(q, v, vdot, **options), tau, atol=1e-9)

    def test_inverse_dynamics_is_mass_matrix_bias_and_gravity(self):
        rng = np.random.default_rng(2)
        for name, model in self.models.items():
            with self.subTest(model=name):
                q, v = random_state(model, rng)
                vdot = rng.uniform(-1.0, 1.0, model.num_velocities)
                expected = (model.mass_matrix(q) @ vdot + model.bias_term(q, v)
                            - model.gravity_forces(q))
                np.testing.assert_allclose(
                    model.inverse_dynamics(q, v, vdot, reflected_inertia=False), expected,
                    atol=1e-9)
                # without gravity and at rest, only M vdot is left
                np.testing.assert_allclose(
                    model.inverse_dynamics(q, 0 * v, vdot, gravity=False,
                                           reflected_inertia=False),
                    model.mass_matrix(q) @ vdot, atol=1e-9)

    def test_kinetic_energy_is_half_v_m_v(self):
        rng = np.random.default_rng(3)
        for name, model in self.models.items():
            with self.subTest(model=name):
                q, v = random_state(model, rng)
                self.assertAlmostEqual(model.kinetic_energy(q, v, reflected_inertia=False),
                                       0.5 * v @ model.mass_matrix(q) @ v, places=10)

    def test_gravity_forces_are_minus_the_gradient_of_potential_energy(self):
        rng = np.random.default_rng(4)
        for name, model in self.models.items():
            q, _ = random_state(model, rng)
            tau_g = model.gravity_forces(q)
            for i, k in qdot_columns(model):
                with self.subTest(model=name, coordinate=k):
                    plus, minus = q.copy(), q.copy()
                    plus[i] += STEP
                    minus[i] -= STEP
                    slope = (model.potential_energy(plus) - model.potential_energy(minus)) / (
                        2 * STEP)
                    self.assertAlmostEqual(tau_g[k], -slope, places=6)

    def test_jacobian_times_v_is_the_frame_velocity(self):
        rng = np.random.default_rng(5)
        for name, model in self.models.items():
            q, v = random_state(model, rng)
            for body in model.bodies:
                with self.subTest(model=name, body=body.scoped_name):
                    J = model.jacobian(body.scoped_name, q)
                    self.assertEqual(J.shape, (6, model.num_velocities))
                    np.testing.assert_allclose(J @ v,
                                               model.frame_velocity(body.scoped_name, q, v),
                                               atol=1e-12)
                    Jv = model.jacobian(body, q, translational=True)  # a Body names itself
                    np.testing.assert_allclose(Jv, J[3:], atol=1e-15)

    def test_frame_acceleration_is_the_rate_of_the_frame_velocity(self):
        model = self.models["double_pendulum.urdf"]  # every v is a qdot here
        self.assertEqual(len(qdot_columns(model)), model.num_velocities)
        rng = np.random.default_rng(11)
        q, v = random_state(model, rng)
        vdot = rng.uniform(-1.0, 1.0, model.num_velocities)
        for body in model.bodies:
            with self.subTest(body=body.scoped_name):
                def velocity(t):
                    return model.frame_velocity(body, q + t * v, v + t * vdot)
                rate = (velocity(STEP) - velocity(-STEP)) / (2 * STEP)
                np.testing.assert_allclose(model.frame_acceleration(body, q, v, vdot), rate,
                                           atol=1e-6)

    def test_jacobian_columns_are_finite_differences_of_the_pose(self):
        self.assertEqual(len(qdot_columns(self.models["ball_universal.sdf"])), 2)
        rng = np.random.default_rng(6)
        point = np.array([0.1, -0.2, 0.3])
        for name, model in self.models.items():
            q, _ = random_state(model, rng)
            for body in model.bodies[1:]:
                J = model.jacobian(body.scoped_name, q)
                J_point = model.jacobian(body.scoped_name, q, point=point)
                for i, k in qdot_columns(model):
                    with self.subTest(model=name, body=body.scoped_name, coordinate=k):
                        np.testing.assert_allclose(
                            J[:, k], pose_derivative(model, body.scoped_name, q, i), atol=1e-7)
                        np.testing.assert_allclose(
                            J_point[:, k], pose_derivative(model, body.scoped_name, q, i, point),
                            atol=1e-7)

    def test_measured_and_expressed_in_other_frames(self):
        model = self.models["double_pendulum.urdf"]
        q, v = np.array([0.4, -0.7]), np.array([0.3, 1.1])
        A, B = "double_pendulum::upper_arm", "double_pendulum::lower_arm"
        # a frame does not move relative to itself
        np.testing.assert_allclose(model.jacobian(B, q, measured_in=B), 0, atol=1e-12)
        # expressed in A: both halves turn by R_AW
        R_WA = model.frame_pose(A, q).R
        J_W = model.jacobian(B, q)
        J_A = model.jacobian(B, q, expressed_in=A)
        np.testing.assert_allclose(J_A[:3], R_WA.T @ J_W[:3], atol=1e-12)
        np.testing.assert_allclose(J_A[3:], R_WA.T @ J_W[3:], atol=1e-12)
        # measured and expressed in A: the derivative of p_AB = R_WA^T (p_WB - p_WA)
        def p_AB(x):
            X_WA, X_WB = model.frame_pose(A, x), model.frame_pose(B, x)
            return X_WA.R.T @ (X_WB.p - X_WA.p)
        J_AA = model.jacobian(B, q, measured_in=A, expressed_in=A, translational=True)
        for k in range(2):
            e = np.zeros(2)
            e[k] = STEP
            np.testing.assert_allclose(J_AA[:, k], (p_AB(q + e) - p_AB(q - e)) / (2 * STEP),
                                       atol=1e-7)
        # the shoulder turns A and B together: B does not move in A
        np.testing.assert_allclose(J_AA[:, 0], 0, atol=1e-12)

    def test_frame_pose_of_a_body_is_its_body_pose(self):
        rng = np.random.default_rng(7)
        for name, model in self.models.items():
            q, _ = random_state(model, rng)
            poses = model.body_poses(q)
            for body in model.bodies:
                with self.subTest(model=name, body=body.scoped_name):
                    X = model.frame_pose(body.scoped_name, q)
                    self.assertIsInstance(X, mdlc.Pose)
                    np.testing.assert_allclose(X.matrix, poses[body.index].matrix, atol=1e-12)

    def test_a_frame_on_a_body_moves_with_it(self):
        model = self.models["ball_universal.sdf"]
        rng = np.random.default_rng(8)
        q, v = random_state(model, rng)
        frame = model.frames["socket"]
        X_WB = model.frame_pose(frame.body, q)
        X_WF = model.frame_pose(frame, q)
        np.testing.assert_allclose(X_WF.matrix, X_WB.matrix @ frame.X_BF.matrix, atol=1e-12)
        V_WB = model.frame_velocity(frame.body, q, v)
        V_WF = model.frame_velocity(frame, q, v)
        np.testing.assert_allclose(V_WF[:3], V_WB[:3], atol=1e-12)
        np.testing.assert_allclose(
            V_WF[3:], V_WB[3:] + np.cross(V_WB[:3], X_WB.R @ frame.X_BF.p), atol=1e-12)


class CenterOfMass(Models, unittest.TestCase):
    def test_position_velocity_and_jacobian(self):
        rng = np.random.default_rng(9)
        for name, model in self.models.items():
            q, v = random_state(model, rng)
            com = model.center_of_mass(q, v)
            poses = model.body_poses(q)
            bodies = [b for b in model.bodies if not b.is_world]
            mass = sum(b.mass for b in bodies)
            position = sum(b.mass * (poses[b.index].p + poses[b.index].R @ b.com)
                           for b in bodies) / mass
            with self.subTest(model=name):
                self.assertAlmostEqual(com.mass, mass, places=12)
                np.testing.assert_allclose(com.position, position, atol=1e-12)
                self.assertEqual(com.jacobian.shape, (3, model.num_velocities))
                np.testing.assert_allclose(com.jacobian @ v, com.velocity, atol=1e-12)
                np.testing.assert_allclose(model.center_of_mass(q).velocity, 0)
            for i, k in qdot_columns(model):
                with self.subTest(model=name, coordinate=k):
                    plus, minus = q.copy(), q.copy()
                    plus[i] += STEP
                    minus[i] -= STEP
                    slope = (model.center_of_mass(plus).position
                             - model.center_of_mass(minus).position) / (2 * STEP)
                    np.testing.assert_allclose(com.jacobian[:, k], slope, atol=1e-7)

    def test_of_one_model_instance(self):
        model = mdlc.compile([str(DOUBLE_PENDULUM), str(BALL)])
        q = model.default_positions()
        whole = model.center_of_mass(q)
        parts = [model.center_of_mass(q, model_instances=[name])
                 for name in ("double_pendulum", "rig")]
        self.assertAlmostEqual(whole.mass, sum(p.mass for p in parts), places=12)
        np.testing.assert_allclose(whole.position * whole.mass,
                                   sum(p.position * p.mass for p in parts), atol=1e-12)
        self.assertIn("mass=", repr(whole))
        with self.assertRaisesRegex(ValueError, "no_such_instance"):
            model.center_of_mass(q, model_instances=["no_such_instance"])


class ClosedForms(unittest.TestCase):
    def test_pendulum_gravity_torque_and_free_fall(self):
        model = mdlc.compile_string(PENDULUM, format="urdf")
        for theta in (0.0, 0.3, -1.2, 2.5):
            q, zero = np.array([theta]), np.zeros(1)
            tau_g = -M * G * L * math.sin(theta)  # Drake's sign: gravity's own work
            self.assertAlmostEqual(model.gravity_forces(q)[0], tau_g, places=12)
            # what holds it still is the opposite
            self.assertAlmostEqual(model.inverse_dynamics(q, zero, zero)[0], -tau_g, places=12)
            inertia = I_YY + M * L * L
            self.assertAlmostEqual(model.forward_dynamics(q, zero, zero)[0], tau_g / inertia,
                                   places=12)
            self.assertAlmostEqual(model.potential_energy(q), -M * G * L * math.cos(theta),
                                   places=12)
            self.assertAlmostEqual(model.kinetic_energy(q, np.array([2.0])),
                                   0.5 * inertia * 4.0, places=12)
            self.assertAlmostEqual(model.bias_term(q, np.array([2.0]))[0], 0.0, places=12)

    def test_free_bodies_fall_with_gravity(self):
        # at rest and with no force, every body falls with g and none turns:
        # each free body's v = [w; v] in its parent frame (here the world)
        # accelerates by [0; g], each revolute joint not at all
        model = mdlc.compile(str(FLOATING))
        q = model.default_positions()
        vdot = model.forward_dynamics(q, np.zeros(model.num_velocities),
                                      np.zeros(model.num_velocities))
        free = [j for j in model.joints if j.type == "quaternion_floating"]
        self.assertEqual(len(free), 2)
        expected = np.zeros(model.num_velocities)
        for joint in free:
            expected[joint.v_start + 3:joint.v_start + 6] = joint.X_PF.R.T @ model.gravity
        np.testing.assert_allclose(vdot, expected, atol=1e-9)


class Errors(Models, unittest.TestCase):
    def test_wrong_sizes_are_value_errors_that_say_which(self):
        model = self.models["double_pendulum.urdf"]
        q, v = np.zeros(2), np.zeros(2)
        with self.assertRaisesRegex(ValueError, r"inverse_dynamics: q has 3 entries.*2 positions"):
            model.inverse_dynamics(np.zeros(3), v, v)
        with self.assertRaisesRegex(ValueError, r"forward_dynamics: tau has 1 entry.*2 velocities"):
            model.forward_dynamics(q, v, np.zeros(1))
        with self.assertRaisesRegex(ValueError, r"inverse_dynamics: vdot has 0 entries"):
            model.inverse_dynamics(q, v, np.zeros(0))
        with self.assertRaisesRegex(ValueError, r"bias_term: v has 4 entries"):
            model.bias_term(q, np.zeros(4))
        with self.assertRaisesRegex(ValueError, r"center_of_mass: v has"):
            model.center_of_mass(q, np.zeros(1))
        for call in (lambda: model.gravity_forces(np.zeros(5)),
                     lambda: model.kinetic_energy(q, np.zeros(1)),
                     lambda: model.potential_energy(np.zeros(1)),
                     lambda: model.jacobian("world", np.zeros(1)),
                     lambda: model.frame_pose("world", np.zeros(1)),
                     lambda: model.frame_velocity("world", q, np.zeros(3))):
            with self.assertRaises(ValueError):
                call()

    def test_a_zero_quaternion_is_a_value_error(self):
        model = self.models["floating_joint.urdf"]
        q = np.zeros(model.num_positions)
        with self.assertRaisesRegex(ValueError, "quaternion"):
            model.gravity_forces(q)

    def test_unknown_frame_is_a_value_error_that_names_it(self):
        model = self.models["double_pendulum.urdf"]
        q = np.zeros(2)
        with self.assertRaisesRegex(ValueError, "no_such_link"):
            model.jacobian("no_such_link", q)
        with self.assertRaisesRegex(ValueError, "no_such_frame"):
            model.frame_pose("no_such_frame", q)
        with self.assertRaisesRegex(ValueError, "elsewhere"):
            model.jacobian("double_pendulum::lower_arm", q, measured_in="elsewhere")
        with self.assertRaises(TypeError):
            model.jacobian(3, q)

    def test_docstrings_state_the_conventions(self):
        for method in ("inverse_dynamics", "bias_term", "gravity_forces", "forward_dynamics",
                       "kinetic_energy", "potential_energy", "jacobian", "frame_pose",
                       "frame_velocity", "frame_acceleration", "center_of_mass"):
            with self.subTest(method=method):
                doc = getattr(mdlc.Model, method).__doc__
                self.assertIn("Drake", doc)
                self.assertIn("constraints", doc)


if __name__ == "__main__":
    unittest.main()
