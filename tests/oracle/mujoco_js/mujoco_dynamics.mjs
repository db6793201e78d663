// mujoco_dynamics.mjs - test-only: MuJoCo 3.3.8's rigid-body dynamics (the
// official WebAssembly build, npm mujoco-js 0.0.7) at seeded random states of
// MJCF models, as JSON, for mdlc's dynamics differential test
// (tests/oracle/mujoco_dynamics_oracle_test.cc).
//
//   node mujoco_dynamics.mjs [--states N] [--seed S] FILE...
//   node mujoco_dynamics.mjs [--states N] [--seed S] --serve   (FILEs on stdin)
//
// Every model is made a plain multibody tree first: dof_armature is set to 0
// (mdlc's reflected inertia is compared switched off; mj_setConst then
// recomputes dof_M0, which MuJoCo copies into qM for the dofs of "simple"
// bodies instead of computing them), and constraints
// (contacts, limits, equalities, friction loss) and actuation are disabled
// (mjDSBL_CONSTRAINT | mjDSBL_ACTUATION). "Passive off" below means
// mjDSBL_SPRING | mjDSBL_DAMPER as well (MuJoCo 3.3.8 has no mjDSBL_PASSIVE:
// mj_passive returns at once when both are set, gravity compensation and
// fluid forces included).
//
// Prints one JSON object per FILE, one per line, in order:
//   {"file", "ok": false, "error"}                          load failed, or
//   {"file", "ok": true, "version", "nq", "nv", "nbody", "njnt",
//    "gravity": [3], "disableflags" (the file's own),
//    "bodies": [{name, parent, mass}],
//    "joints": [{name, type, body, qposadr, dofadr, stiffness, damping[],
//                springref (hinge, slide)}],
//    "passive": {"compared": bool, "reason": "..." (when not)},
//    "jac_bodies": [body ids whose Jacobians are given: every body but the
//                   world, or 12 of them when nv > --max-full (default 120)],
//    "states": [{                     (none when nv = 0)
//       "qpos", "qvel", "qacc", "tau"   the state and inputs (MuJoCo's layout)
//       "bias"        qfrc_bias after mj_forward, passive off (C v - tau_g)
//       "rne"         mj_rne(flg_acc = 1) at qacc: M qacc + qfrc_bias
//       "M"           mj_fullM, row-major nv x nv (absent when nv > --max-full)
//       "qacc_fwd"    qacc of mj_forward with qfrc_applied = tau, passive off
//       "qacc_passive" the same with springs and dampers on (when compared)
//       "passive_norm" |qfrc_passive| of the passive-off run (0 expected)
//       "jacp", "jacr"  per jac_bodies entry, mj_jacBody at the body origin,
//                     row-major 3 x nv
//       "com", "jac_com"  subtree_com[0] and mj_jacSubtreeCom(body 0)
//       "energy"      [potential, kinetic] (mjENBL_ENERGY), passive off
//       "energy_passive"  the same with springs on (when compared)}]}
//
// States: qpos of hinge and slide joints uniform in the joint's range when
// limited, else in [-pi, pi] (hinge) or [-0.5, 0.5] (slide); ball and free
// joints a uniformly random unit quaternion, free positions uniform in
// [-1, 1]; qvel, qacc and tau uniform in [-1, 1]. Numbers print so that they
// round-trip a double. Files are mirrored into the module's file system by
// wasm_host.mjs (the file's folder, and the levels above it that "../"
// references reach), as for mujoco_dump.mjs.
import path from 'node:path';

import { answerAll, dumpFile, mj, mulberry32, nameOf, startModule } from './wasm_host.mjs';

const JOINT_TYPES = ['free', 'ball', 'slide', 'hinge'];
// mjtDisableBit and mjtEnableBit of MuJoCo 3.3.8 (checked against the
// module's own enums at start-up)
const DSBL = { CONSTRAINT: 1, SPRING: 32, DAMPER: 64, ACTUATION: 2048 };
const ENBL_ENERGY = 2;

function usage(msg) {
  process.stderr.write(`mujoco_dynamics: ${msg}\nusage: node mujoco_dynamics.mjs [--states N] ` +
                       `[--seed S] [--max-full N] (FILE... | --serve)\n`);
  process.exit(2);
}

const opts = { states: 5, seed: 1, maxFull: 120, serve: false };
const files = [];
{
  const argv = process.argv.slice(2);
  for (let i = 0; i < argv.length; ++i) {
    const a = argv[i];
    const next = () => (i + 1 < argv.length ? argv[++i] : usage(`${a} needs a value`));
    if (a === '--states') opts.states = Number.parseInt(next(), 10);
    else if (a === '--seed') opts.seed = Number.parseInt(next(), 10);
    else if (a === '--max-full') opts.maxFull = Number.parseInt(next(), 10);
    else if (a === '--serve') opts.serve = true;
    else if (a.startsWith('--')) usage(`unknown option ${a}`);
    else files.push(path.resolve(a));
  }
  if (!opts.serve && files.length === 0) usage('no FILE');
  if (!(opts.states >= 1)) usage('--states must be >= 1');
}

await startModule();

// The enum values this script relies on, where the module exposes them.
for (const [name, bit] of Object.entries(DSBL)) {
  const e = mj.mjtDisableBit && mj.mjtDisableBit[`mjDSBL_${name}`];
  if (e && e.value !== undefined && e.value !== bit) {
    throw new Error(`mjDSBL_${name} is ${e.value} in this module, not ${bit}`);
  }
}
{
  const e = mj.mjtEnableBit && mj.mjtEnableBit.mjENBL_ENERGY;
  if (e && e.value !== undefined && e.value !== ENBL_ENERGY) throw new Error('mjENBL_ENERGY moved');
}

// ------------------------------------------------------------------- helpers
// A uniformly random unit quaternion [w x y z] (Shoemake's method).
function randomQuat(rnd) {
  const u1 = rnd(), u2 = 2 * Math.PI * rnd(), u3 = 2 * Math.PI * rnd();
  const a = Math.sqrt(1 - u1), b = Math.sqrt(u1);
  return [a * Math.sin(u2), a * Math.cos(u2), b * Math.sin(u3), b * Math.cos(u3)];
}

const arr = (typed) => Array.from(typed);

// Why MuJoCo's passive forces (springs and dampers on) are more than what
// mdlc's DynamicsOptions{joint_damping, force_elements} can be compared with:
// damping and stiffness of hinge and slide joints, and a ball joint's
// damping when it is the same on its 3 dofs (-b w is then the same vector in
// the child's frame, MuJoCo's, and in the parent's, mdlc's); "" when they
// are not.
function passiveProblem(m) {
  const why = [];
  for (let j = 0; j < m.njnt; ++j) {
    const t = m.jnt_type[j];
    if (t === 2 || t === 3) continue;
    const dof = m.jnt_dofadr[j];
    const nd = t === 0 ? 6 : 3;
    let damped = false, isotropic = true;
    for (let k = 0; k < nd; ++k) {
      damped ||= m.dof_damping[dof + k] !== 0;
      isotropic &&= m.dof_damping[dof + k] === m.dof_damping[dof];
    }
    const what = m.jnt_stiffness[j] !== 0 ? 'stiffness'
               : t === 0 && damped ? 'damping'
               : !isotropic ? 'damping that differs between its dofs' : '';
    if (what) {
      why.push(`${JOINT_TYPES[t]} joint ${j} ('${nameOf(m, m.name_jntadr, j)}') has ${what}`);
      break;
    }
  }
  for (let t = 0; t < m.ntendon; ++t) {
    if (m.tendon_stiffness[t] !== 0 || m.tendon_damping[t] !== 0) {
      why.push('tendon springs or dampers');
      break;
    }
  }
  if (m.ngravcomp > 0) why.push('gravity compensation (gravcomp)');
  if (m.opt.density > 0 || m.opt.viscosity > 0) why.push('fluid forces (density or viscosity)');
  if (m.nflex > 0) why.push('flex elasticity');
  return why.join('; ');
}

// ------------------------------------------------------------------ dynamics
function dumpModel(file, m) {
  const nv = m.nv;
  const out = {
    file, ok: true, version: mj.mj_versionString(), nq: m.nq, nv, nbody: m.nbody, njnt: m.njnt,
    gravity: arr(m.opt.gravity), disableflags: m.opt.disableflags,
  };
  out.bodies = [];
  for (let b = 0; b < m.nbody; ++b) {
    out.bodies.push({ name: nameOf(m, m.name_bodyadr, b), parent: m.body_parentid[b],
                      mass: m.body_mass[b] });
  }
  out.joints = [];
  for (let j = 0; j < m.njnt; ++j) {
    const type = JOINT_TYPES[m.jnt_type[j]];
    const nd = type === 'free' ? 6 : type === 'ball' ? 3 : 1;
    const dof = m.jnt_dofadr[j];
    const J = {
      name: nameOf(m, m.name_jntadr, j), type, body: m.jnt_bodyid[j], qposadr: m.jnt_qposadr[j],
      dofadr: dof, stiffness: m.jnt_stiffness[j], damping: arr(m.dof_damping.subarray(dof, dof + nd)),
    };
    if (nd === 1) J.springref = m.qpos_spring[m.jnt_qposadr[j]];
    out.joints.push(J);
  }
  const problem = passiveProblem(m);
  out.passive = problem ? { compared: false, reason: problem } : { compared: true };
  // above --max-full dofs: no mass matrix, and Jacobians of 12 bodies spread
  // over the tree instead of all (the dump would be tens of megabytes)
  const full = nv <= opts.maxFull;
  out.jac_bodies = [];
  if (full) {
    for (let b = 1; b < m.nbody; ++b) out.jac_bodies.push(b);
  } else {
    const picks = new Set();
    for (let k = 0; k < 12; ++k) picks.add(1 + Math.floor((k * (m.nbody - 1)) / 12));
    out.jac_bodies = [...picks];
  }

  out.states = [];
  if (nv === 0) return out;  // nothing moves (MuJoCo's Jacobian calls refuse nv = 0)

  // a plain tree: no armature, constraints or actuation
  for (let i = 0; i < nv; ++i) m.dof_armature[i] = 0;
  const fileFlags = m.opt.disableflags;
  const plainFlags = fileFlags | DSBL.CONSTRAINT | DSBL.ACTUATION;
  const passiveOff = plainFlags | DSBL.SPRING | DSBL.DAMPER;
  m.opt.enableflags = m.opt.enableflags | ENBL_ENERGY;

  const d = new mj.MjData(m);
  // the constants derived from the inertia (dof_M0, which a "simple" body's
  // mass matrix entries are copied from) without the armature
  mj.mj_setConst(m, d);
  const bufs = [];
  const buffer = (n) => { const b = new mj.DoubleBuffer(n); bufs.push(b); return b; };
  const rneBuf = buffer(nv), fullBuf = full ? buffer(nv * nv) : null;
  const jacp = buffer(3 * nv), jacr = buffer(3 * nv), jcom = buffer(3 * nv);
  // views of the WebAssembly heap are taken afresh after every allocation
  const view = (b, n) => Array.from(b.GetView().subarray(0, n));
  try {
    for (let s = 0; s < opts.states; ++s) {
      const rnd = mulberry32(opts.seed * 1000003 + s + 1);
      const qpos = new Array(m.nq).fill(0);
      for (let j = 0; j < m.njnt; ++j) {
        const a = m.jnt_qposadr[j];
        const t = m.jnt_type[j];
        if (t === 0) {
          for (let k = 0; k < 3; ++k) qpos[a + k] = 2 * rnd() - 1;
          randomQuat(rnd).forEach((x, k) => { qpos[a + 3 + k] = x; });
        } else if (t === 1) {
          randomQuat(rnd).forEach((x, k) => { qpos[a + k] = x; });
        } else {
          let lo = t === 3 ? -Math.PI : -0.5;
          let hi = -lo;
          if (m.jnt_limited[j]) { lo = m.jnt_range[2 * j]; hi = m.jnt_range[2 * j + 1]; }
          qpos[a] = lo + (hi - lo) * rnd();
        }
      }
      const uniform = () => Array.from({ length: nv }, () => 2 * rnd() - 1);
      const qvel = uniform(), qacc = uniform(), tau = uniform();
      const st = { qpos, qvel, qacc, tau };

      const run = (flags) => {
        m.opt.disableflags = flags;
        d.qpos.set(qpos);
        d.qvel.set(qvel);
        d.qfrc_applied.set(tau);
        d.xfrc_applied.fill(0);
        d.ctrl.fill(0);
        mj.mj_forward(m, d);
      };
      if (out.passive.compared) {
        run(plainFlags);
        st.qacc_passive = arr(d.qacc);
        st.energy_passive = arr(d.energy);
      }
      run(passiveOff);
      st.qacc_fwd = arr(d.qacc);
      st.bias = arr(d.qfrc_bias);
      st.passive_norm = Math.hypot(...arr(d.qfrc_passive));
      st.energy = arr(d.energy);
      st.com = arr(d.subtree_com.subarray(0, 3));
      mj.mj_jacSubtreeCom(m, d, jcom, 0);
      st.jac_com = view(jcom, 3 * nv);
      if (full) {
        mj.mj_fullM(m, fullBuf, d.qM);
        st.M = view(fullBuf, nv * nv);
      }
      st.jacp = [];
      st.jacr = [];
      for (const b of out.jac_bodies) {
        mj.mj_jacBody(m, d, jacp, jacr, b);
        st.jacp.push(view(jacp, 3 * nv));
        st.jacr.push(view(jacr, 3 * nv));
      }
      // inverse dynamics at the forward pass's kinematics
      d.qacc.set(qacc);
      mj.mj_rne(m, d, 1, rneBuf);
      st.rne = view(rneBuf, nv);
      out.states.push(st);
    }
  } finally {
    for (const b of bufs) b.delete();
    d.delete();
  }
  return out;
}

await answerAll(files, opts.serve, (file) => dumpFile(file, dumpModel));
