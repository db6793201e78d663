#!/usr/bin/env python3
"""`mdlc dynamics` on the example double pendulum, against its closed form
worked out here: gravity forces, bias term, inverse and forward dynamics,
energies and center of mass at a state set by --q, --v, --vdot and --tau;
the text output names every coordinate; and a bad joint name or a malformed
assignment is an error with a non-zero exit status.

    dynamics_test.py MDLC REPOSITORY
"""
import json
import math
import pathlib
import subprocess
import sys

G = 9.81
# examples/urdf/double_pendulum.urdf: a 2 kg plate welded with its center of
# mass 2 m up, the shoulder 2.5 cm below it; both joints turn about y
BASE_MASS, BASE_Z, SHOULDER_Z = 2.0, 2.0, 1.975
M1, LC1, L1, I1 = 1.0, 0.5, 1.0, 0.083490   # upper arm: mass, com, length, Iyy
M2, LC2, I2 = 0.5, 0.4, 0.026717            # lower arm
DAMPING = (0.05, 0.02)


def closed_form(q, v, vdot, tau):
    """The double pendulum's dynamics, each link at angle q1 (q1 + q2) from
    hanging straight down: Drake's signs, tau = M vdot + C v - tau_g."""
    q1, q2 = q
    c2, s2 = math.cos(q2), math.sin(q2)
    M = [[I1 + I2 + M1 * LC1**2 + M2 * (L1**2 + LC2**2 + 2 * L1 * LC2 * c2),
          I2 + M2 * (LC2**2 + L1 * LC2 * c2)],
         [0.0, I2 + M2 * LC2**2]]
    M[1][0] = M[0][1]
    h = M2 * L1 * LC2 * s2
    bias = [-h * (2 * v[0] * v[1] + v[1]**2), h * v[0]**2]
    gravity = [-G * (M1 * LC1 * math.sin(q1) + M2 * (L1 * math.sin(q1) + LC2 * math.sin(q1 + q2))),
               -G * M2 * LC2 * math.sin(q1 + q2)]
    inverse = [sum(M[i][j] * vdot[j] for j in range(2)) + bias[i] - gravity[i] for i in range(2)]
    # forward: M vdot = tau + tau_g - C v, a 2 x 2 solve
    rhs = [tau[i] + gravity[i] - bias[i] for i in range(2)]
    det = M[0][0] * M[1][1] - M[0][1] * M[1][0]
    forward = [(M[1][1] * rhs[0] - M[0][1] * rhs[1]) / det,
               (M[0][0] * rhs[1] - M[1][0] * rhs[0]) / det]
    kinetic = 0.5 * sum(v[i] * M[i][j] * v[j] for i in range(2) for j in range(2))
    # centers of mass (x, z) in the world
    p1 = (-LC1 * math.sin(q1), SHOULDER_Z - LC1 * math.cos(q1))
    p2 = (-L1 * math.sin(q1) - LC2 * math.sin(q1 + q2),
          SHOULDER_Z - L1 * math.cos(q1) - LC2 * math.cos(q1 + q2))
    w1, w2 = v[0], v[0] + v[1]
    v1 = (-LC1 * math.cos(q1) * w1, LC1 * math.sin(q1) * w1)
    v2 = (-L1 * math.cos(q1) * w1 - LC2 * math.cos(q1 + q2) * w2,
          L1 * math.sin(q1) * w1 + LC2 * math.sin(q1 + q2) * w2)
    mass = BASE_MASS + M1 + M2
    com = [(M1 * p1[0] + M2 * p2[0]) / mass, 0.0,
           (BASE_MASS * BASE_Z + M1 * p1[1] + M2 * p2[1]) / mass]
    com_velocity = [(M1 * v1[0] + M2 * v2[0]) / mass, 0.0, (M1 * v1[1] + M2 * v2[1]) / mass]
    potential = G * (BASE_MASS * BASE_Z + M1 * p1[1] + M2 * p2[1])
    return {"gravity_forces": gravity, "bias_term": bias, "inverse_dynamics": inverse,
            "forward_dynamics": forward, "kinetic_energy": kinetic,
            "potential_energy": potential, "mass": mass, "position": com,
            "velocity": com_velocity}


def run(mdlc, args):
    return subprocess.run([mdlc, "dynamics"] + args, capture_output=True, text=True, timeout=60)


def close(a, b):
    return abs(a - b) <= 1e-9 * max(1.0, abs(b))


def check_numbers(report, expected, problems, label):
    def compare(key, got, want):
        got_list = got if isinstance(got, list) else [got]
        want_list = want if isinstance(want, list) else [want]
        if len(got_list) != len(want_list) or not all(map(close, got_list, want_list)):
            problems.append(f"{label}: {key} is {got}, expected {want}")
    for key in ("gravity_forces", "bias_term", "inverse_dynamics", "forward_dynamics",
                "kinetic_energy", "potential_energy"):
        compare(key, report[key], expected[key])
    for key in ("mass", "position", "velocity"):
        compare("center_of_mass." + key, report["center_of_mass"][key], expected[key])


def main():
    mdlc, repository = sys.argv[1], pathlib.Path(sys.argv[2])
    model = str(repository / "examples/urdf/double_pendulum.urdf")
    problems = []

    q, v, vdot, tau = (0.4, -0.7), (0.3, 1.1), (0.5, 0.0), (0.0, 0.2)
    state = ["--q", f"shoulder={q[0]}", "--q", f"double_pendulum::elbow={q[1]}",
             "--v", f"shoulder={v[0]}", "--v", f"elbow={v[1]}",
             "--vdot", f"shoulder={vdot[0]}", "--tau", f"elbow={tau[1]}"]
    out = run(mdlc, [model, "--json"] + state)
    if out.returncode != 0:
        problems.append(f"--json exited {out.returncode}: {out.stderr}")
    else:
        report = json.loads(out.stdout)
        if report["velocities"] != ["double_pendulum::shoulder", "double_pendulum::elbow"]:
            problems.append(f"velocity names: {report['velocities']}")
        for key, given in (("q", q), ("v", v), ("vdot", vdot), ("tau", tau)):
            if report[key] != list(given):
                problems.append(f"{key} is {report[key]}, given {list(given)}")
        check_numbers(report, closed_form(q, v, vdot, tau), problems, "at the given state")

    # the defaults: at rest, the torques that hold it and its free fall
    out = run(mdlc, [model, "--format", "json", "--q", "shoulder=1.0"])
    if out.returncode != 0:
        problems.append(f"defaults: exited {out.returncode}: {out.stderr}")
    else:
        check_numbers(json.loads(out.stdout), closed_form((1.0, 0.0), (0, 0), (0, 0), (0, 0)),
                      problems, "at rest")

    # joint damping adds d v to what holds the model, and takes it from free fall
    out = run(mdlc, [model, "--json", "--joint-damping"] + state)
    if out.returncode != 0:
        problems.append(f"--joint-damping exited {out.returncode}: {out.stderr}")
    else:
        expected = closed_form(q, v, vdot, [t - d * w for t, d, w in zip(tau, DAMPING, v)])
        expected["inverse_dynamics"] = [x + d * w for x, d, w in
                                        zip(expected["inverse_dynamics"], DAMPING, v)]
        check_numbers(json.loads(out.stdout), expected, problems, "with joint damping")

    # the text names each coordinate and says what each number is
    out = run(mdlc, [model] + state)
    for words in ("double_pendulum::shoulder", "double_pendulum::elbow", "inverse tau",
                  "forward vdot", "kinetic energy:", "potential energy:", "center of mass: mass 3.5 kg"):
        if out.returncode != 0 or words not in out.stdout:
            problems.append(f"text output (exit {out.returncode}) lacks '{words}':\n{out.stdout}"
                            f"{out.stderr}")

    # errors: an unknown joint in --q (the compile's), in --v (the command's),
    # and an assignment that is not JOINT=VALUE
    for args, status, words in ((["--q", "shouldr=1"], 1, "shouldr"),
                                (["--v", "shouldr=1"], 1, "did you mean 'shoulder'"),
                                (["--tau", "elbow"], 2, "--tau expects JOINT=VALUE")):
        out = run(mdlc, [model] + args)
        if out.returncode != status or words not in out.stderr:
            problems.append(f"{args}: exit {out.returncode} (expected {status}), stderr lacks "
                            f"'{words}':\n{out.stderr}")

    for p in problems:
        print("FAIL:", p)
    if not problems:
        print("mdlc dynamics agrees with the double pendulum's closed form")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
