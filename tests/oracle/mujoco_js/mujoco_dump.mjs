// mujoco_dump.mjs - test-only: what MuJoCo 3.3.8 (the official WebAssembly
// build, npm mujoco-js 0.0.7) compiles from MJCF files, as JSON, for mdlc's
// differential tests (tests/oracle/mujoco_oracle_test.cc, and
// tests/corpus/reference_rejects_mjcf.cc).
//
//   node mujoco_dump.mjs --version
//   node mujoco_dump.mjs [options] FILE...
//   node mujoco_dump.mjs [options] --serve   (FILEs on stdin, one per line)
//
// Options (apply to every FILE):
//   --configs N      N seeded random configurations besides qpos0 (default 3)
//   --seed S         PRNG seed (default 1)
//   --q NAME=V,...   one explicit configuration (repeatable): joint NAME at V
//   --brief          only {file, ok, error, nbody, njnt, ngeom, nv}
//   --root DIR       mirror DIR instead of the file's folder (see below)
//   --serve          read FILEs from stdin, one per line, answering each as
//                    it arrives (one Node.js start for many files)
//
// Prints one JSON object per FILE, one per line (JSON Lines), in order:
//   {"file", "ok": false, "error": "..."}                       load failed, or
//   {"file", "ok": true, "version", "model", "nq", "nv", "nkey",
//    "key":     {id, name} (the key configurations start from; absent: none),
//    "bodies":  [{id, name, parent, jntnum, jnt_types, mass, ipos, iquat,
//                 inertia, pos, quat}],
//    "joints":  [{id, name, type, body, dof, qposadr, axis, pos, range,
//                 limited, armature, qpos0, key_qpos (when "key" is present:
//                 the key's qpos slice of the joint, as MuJoCo stores it),
//                 stiffness (jnt_stiffness), springref (qpos_spring, hinge
//                 and slide), damping, M0, invweight0 (dof_damping,
//                 dof_M0, dof_invweight0: one per dof)}],
//    "actuators": [{id, name, trntype, trnid, gear, dyntype, gaintype,
//                 biastype, gainprm, biasprm (the first 3 of each), as
//                 compiled: a dampratio is already turned into biasprm[2]}],
//    "geoms":   [{id, name, body, type, size, pos, quat, contype,
//                 conaffinity, group, mesh, mesh_pos, mesh_quat, mesh_scale}],
//    "configs": [{"q": [[jnt, value], ...],            (hinge/slide joints set)
//                 "xpos": [[x,y,z] per body], "xquat": [[w,x,y,z] per body],
//                 "xaxis": [[...] per joint], "xanchor": [[...] per joint],
//                 "geom_xpos": [...], "geom_xquat": [...],
//                 "M": [[dof_i, dof_j, value], ...]}]}
//
// Conventions: every number is MuJoCo's own (mjModel/mjData fields of the same
// name), names are "" when the file leaves the element unnamed, quaternions are
// [w x y z], joint types are MuJoCo's (free, ball, slide, hinge), geom types
// MuJoCo's (plane, hfield, sphere, capsule, ellipsoid, cylinder, box, mesh,
// sdf). Keyframes (MJCF-008, the "keyframe (default positions)"):
// the key named "home" if there is one, else the first key, is the base
// state, as mdlc makes it the plant's default configuration: configuration 0
// is mj_resetDataKeyframe's qpos (the key's qpos; MuJoCo fills a key without
// qpos with qpos0), and without keys it is qpos0 (hinge/slide joints at
// `ref`). Every other configuration starts from that base. Random
// configurations set only hinge and slide joints (ball and free joints keep
// the base): uniform in the joint range when limited, else in [-pi, pi]
// (hinge) or [-0.5, 0.5] (slide); values are printed to round-trip a double. "M" is the joint-space
// inertia matrix restricted to the dofs of hinge and slide joints, lower
// triangle (dof_i >= dof_j), nonzero entries, exactly as MuJoCo's qM holds
// them (so INCLUDING dof_armature on the diagonal); for nv <= 400 it is
// cross-checked against mj_fullM.
//
// Files: the module has its own in-memory file system, so the folder holding
// FILE (and, when any XML below it reaches up with "../" in a file, meshdir,
// texturedir or assetdir attribute, as many levels above as that needs) is
// copied into it at the same absolute path before loading; includes, meshes
// and textures then resolve as they do for MuJoCo on disk.
import path from 'node:path';

import { answerAll, dumpFile, mj, mulberry32, nameOf, startModule } from './wasm_host.mjs';

const JOINT_TYPES = ['free', 'ball', 'slide', 'hinge'];
const GEOM_TYPES = ['plane', 'hfield', 'sphere', 'capsule', 'ellipsoid', 'cylinder', 'box', 'mesh', 'sdf'];
// MuJoCo's mjtTrn, mjtDyn, mjtGain, mjtBias (3.3.8)
const TRN_TYPES = ['joint', 'jointinparent', 'slidercrank', 'tendon', 'site', 'body'];
const DYN_TYPES = ['none', 'integrator', 'filter', 'filterexact', 'muscle', 'user'];
const GAIN_TYPES = ['fixed', 'affine', 'muscle', 'user'];
const BIAS_TYPES = ['none', 'affine', 'muscle', 'user'];

function usage(msg) {
  process.stderr.write(`mujoco_dump: ${msg}\nusage: node mujoco_dump.mjs [--configs N] [--seed S] ` +
                       `[--q NAME=V,...]... [--brief] [--root DIR] (FILE... | --serve) | --version\n`);
  process.exit(2);
}

// ---------------------------------------------------------------- arguments
const opts = { configs: 3, seed: 1, explicit: [], brief: false, root: null, version: false, serve: false };
const files = [];
{
  const argv = process.argv.slice(2);
  for (let i = 0; i < argv.length; ++i) {
    const a = argv[i];
    const next = () => (i + 1 < argv.length ? argv[++i] : usage(`${a} needs a value`));
    if (a === '--version') opts.version = true;
    else if (a === '--configs') opts.configs = Number.parseInt(next(), 10);
    else if (a === '--seed') opts.seed = Number.parseInt(next(), 10);
    else if (a === '--brief') opts.brief = true;
    else if (a === '--serve') opts.serve = true;
    else if (a === '--root') opts.root = path.resolve(next());
    else if (a === '--q') {
      const q = {};
      for (const item of next().split(',')) {
        const eq = item.lastIndexOf('=');
        if (eq <= 0) usage(`bad --q item '${item}'`);
        q[item.slice(0, eq)] = Number(item.slice(eq + 1));
      }
      opts.explicit.push(q);
    } else if (a.startsWith('--')) usage(`unknown option ${a}`);
    else files.push(path.resolve(a));
  }
  if (!opts.version && !opts.serve && files.length === 0) usage('no FILE');
  if (!(opts.configs >= 0)) usage('--configs must be >= 0');
}

await startModule();

if (opts.version) {
  process.stdout.write(JSON.stringify({ version: mj.mj_versionString() }) + '\n');
  process.exit(0);
}

// ------------------------------------------------------------------- helpers
const vec = (a, i, n) => Array.from(a.subarray(i * n, i * n + n));

function matToQuat(R) {  // row-major 3x3 -> [w x y z], w >= 0
  const [m00, m01, m02, m10, m11, m12, m20, m21, m22] = R;
  const tr = m00 + m11 + m22;
  let w, x, y, z;
  if (tr > 0) {
    const s = Math.sqrt(tr + 1) * 2;
    w = 0.25 * s; x = (m21 - m12) / s; y = (m02 - m20) / s; z = (m10 - m01) / s;
  } else if (m00 > m11 && m00 > m22) {
    const s = Math.sqrt(1 + m00 - m11 - m22) * 2;
    w = (m21 - m12) / s; x = 0.25 * s; y = (m01 + m10) / s; z = (m02 + m20) / s;
  } else if (m11 > m22) {
    const s = Math.sqrt(1 + m11 - m00 - m22) * 2;
    w = (m02 - m20) / s; x = (m01 + m10) / s; y = 0.25 * s; z = (m12 + m21) / s;
  } else {
    const s = Math.sqrt(1 + m22 - m00 - m11) * 2;
    w = (m10 - m01) / s; x = (m02 + m20) / s; y = (m12 + m21) / s; z = 0.25 * s;
  }
  const n = Math.hypot(w, x, y, z) * (w < 0 ? -1 : 1);
  return [w / n, x / n, y / n, z / n];
}

// ------------------------------------------------------------------- dumping
function dumpModel(file, m) {
  const out = {
    file, ok: true, version: mj.mj_versionString(), model: nameOf(m, [0], 0),
    nq: m.nq, nv: m.nv, nbody: m.nbody, njnt: m.njnt, ngeom: m.ngeom, nkey: m.nkey,
  };
  if (opts.brief) return out;

  out.bodies = [];
  for (let b = 0; b < m.nbody; ++b) {
    const jnt_types = [];
    for (let k = 0; k < m.body_jntnum[b]; ++k) jnt_types.push(JOINT_TYPES[m.jnt_type[m.body_jntadr[b] + k]]);
    out.bodies.push({
      id: b, name: nameOf(m, m.name_bodyadr, b), parent: m.body_parentid[b],
      jntnum: m.body_jntnum[b], jnt_types,
      mass: m.body_mass[b], ipos: vec(m.body_ipos, b, 3), iquat: vec(m.body_iquat, b, 4),
      inertia: vec(m.body_inertia, b, 3), pos: vec(m.body_pos, b, 3), quat: vec(m.body_quat, b, 4),
    });
  }
  // the base state: key "home", else key 0 (MJCF-008), else qpos0
  let key = -1;
  for (let k = 0; k < m.nkey; ++k) {
    if (nameOf(m, m.name_keyadr, k) === 'home') { key = k; break; }
  }
  if (key < 0 && m.nkey > 0) key = 0;
  const base = key >= 0 ? Array.from(m.key_qpos.subarray(key * m.nq, (key + 1) * m.nq))
                        : Array.from(m.qpos0);
  if (key >= 0) out.key = { id: key, name: nameOf(m, m.name_keyadr, key) };

  out.joints = [];
  for (let j = 0; j < m.njnt; ++j) {
    const dof = m.jnt_dofadr[j];
    const qadr = m.jnt_qposadr[j];
    const type = JOINT_TYPES[m.jnt_type[j]];
    const nq = type === 'free' ? 7 : type === 'ball' ? 4 : 1;
    const nd = type === 'free' ? 6 : type === 'ball' ? 3 : 1;
    const joint = {
      id: j, name: nameOf(m, m.name_jntadr, j), type, body: m.jnt_bodyid[j], dof, qposadr: qadr,
      axis: vec(m.jnt_axis, j, 3), pos: vec(m.jnt_pos, j, 3), range: vec(m.jnt_range, j, 2),
      limited: m.jnt_limited[j], armature: Array.from(m.dof_armature.subarray(dof, dof + nd)),
      qpos0: Array.from(m.qpos0.subarray(qadr, qadr + nq)),
      stiffness: m.jnt_stiffness[j],
      damping: Array.from(m.dof_damping.subarray(dof, dof + nd)),
      M0: Array.from(m.dof_M0.subarray(dof, dof + nd)),
      invweight0: Array.from(m.dof_invweight0.subarray(dof, dof + nd)),
    };
    if (nq === 1) joint.springref = m.qpos_spring[qadr];
    if (key >= 0) joint.key_qpos = base.slice(qadr, qadr + nq);
    out.joints.push(joint);
  }
  out.actuators = [];
  for (let a = 0; a < m.nu; ++a) {
    out.actuators.push({
      id: a, name: nameOf(m, m.name_actuatoradr, a),
      trntype: TRN_TYPES[m.actuator_trntype[a]] || String(m.actuator_trntype[a]),
      trnid: m.actuator_trnid[2 * a], gear: m.actuator_gear[6 * a],
      dyntype: DYN_TYPES[m.actuator_dyntype[a]] || String(m.actuator_dyntype[a]),
      gaintype: GAIN_TYPES[m.actuator_gaintype[a]] || String(m.actuator_gaintype[a]),
      biastype: BIAS_TYPES[m.actuator_biastype[a]] || String(m.actuator_biastype[a]),
      gainprm: vec(m.actuator_gainprm, a, 10).slice(0, 3),
      biasprm: vec(m.actuator_biasprm, a, 10).slice(0, 3),
    });
  }
  out.geoms = [];
  const meshScale = m.mesh_scale && m.mesh_scale.length === 3 * m.nmesh ? m.mesh_scale : null;
  for (let g = 0; g < m.ngeom; ++g) {
    const type = GEOM_TYPES[m.geom_type[g]] || String(m.geom_type[g]);
    const mesh = type === 'mesh' ? m.geom_dataid[g] : -1;
    const geom = {
      id: g, name: nameOf(m, m.name_geomadr, g), body: m.geom_bodyid[g], type,
      size: vec(m.geom_size, g, 3), pos: vec(m.geom_pos, g, 3), quat: vec(m.geom_quat, g, 4),
      contype: m.geom_contype[g], conaffinity: m.geom_conaffinity[g], group: m.geom_group[g],
    };
    if (mesh >= 0) {
      geom.mesh = nameOf(m, m.name_meshadr, mesh);
      geom.mesh_pos = vec(m.mesh_pos, mesh, 3);
      geom.mesh_quat = vec(m.mesh_quat, mesh, 4);
      if (meshScale) geom.mesh_scale = vec(meshScale, mesh, 3);
    }
    out.geoms.push(geom);
  }

  // configurations: the base (key or qpos0), the explicit ones, then seeded
  // random ones, each over the base
  const moving = [];  // hinge and slide joints
  for (let j = 0; j < m.njnt; ++j) {
    const t = m.jnt_type[j];
    if (t === 2 || t === 3) moving.push(j);
  }
  const nameToJoint = new Map(out.joints.map((J) => [J.name, J.id]));
  const configs = [[]];
  for (const q of opts.explicit) {
    const c = [];
    for (const [n, v] of Object.entries(q)) {
      if (!nameToJoint.has(n)) throw new Error(`--q: no joint named '${n}'`);
      c.push([nameToJoint.get(n), v]);
    }
    configs.push(c);
  }
  for (let k = 1; k <= opts.configs && moving.length > 0; ++k) {
    const rnd = mulberry32(opts.seed * 1000003 + k);
    const c = [];
    for (const j of moving) {
      const hinge = m.jnt_type[j] === 3;
      let lo = hinge ? -Math.PI : -0.5;
      let hi = -lo;
      if (m.jnt_limited[j]) {
        lo = m.jnt_range[2 * j];
        hi = m.jnt_range[2 * j + 1];
      }
      c.push([j, lo + (hi - lo) * rnd()]);
    }
    configs.push(c);
  }

  const d = new mj.MjData(m);
  // hinge/slide dof -> joint; M entries between them
  const dofMoving = new Int8Array(m.nv);
  for (const j of moving) dofMoving[m.jnt_dofadr[j]] = 1;
  out.configs = [];
  try {
    for (const c of configs) {
      d.qpos.set(base);
      for (const [j, v] of c) d.qpos[m.jnt_qposadr[j]] = v;
      mj.mj_forward(m, d);
      const cfg = { q: c, xpos: [], xquat: [], xaxis: [], xanchor: [], geom_xpos: [], geom_xquat: [], M: [] };
      for (let b = 0; b < m.nbody; ++b) {
        cfg.xpos.push(vec(d.xpos, b, 3));
        cfg.xquat.push(vec(d.xquat, b, 4));
      }
      for (let j = 0; j < m.njnt; ++j) {
        cfg.xaxis.push(vec(d.xaxis, j, 3));
        cfg.xanchor.push(vec(d.xanchor, j, 3));
      }
      for (let g = 0; g < m.ngeom; ++g) {
        cfg.geom_xpos.push(vec(d.geom_xpos, g, 3));
        cfg.geom_xquat.push(matToQuat(vec(d.geom_xmat, g, 9)));
      }
      // qM, legacy sparse layout: row i holds (i,i) at dof_Madr[i], then its
      // ancestors' columns along dof_parentid.
      const qM = d.qM;
      const sparse = new Map();
      for (let i = 0; i < m.nv; ++i) {
        let adr = m.dof_Madr[i];
        for (let jd = i; jd >= 0; jd = m.dof_parentid[jd], ++adr) {
          if (dofMoving[i] && dofMoving[jd] && qM[adr] !== 0) cfg.M.push([i, jd, qM[adr]]);
          if (m.nv <= 400) sparse.set(i * m.nv + jd, qM[adr]);
        }
      }
      if (m.nv > 0 && m.nv <= 400) {
        const buf = new mj.DoubleBuffer(m.nv * m.nv);
        mj.mj_fullM(m, buf, d.qM);
        const full = buf.GetView();
        for (let i = 0; i < m.nv; ++i) {
          for (let jd = 0; jd <= i; ++jd) {
            const s = sparse.get(i * m.nv + jd) || 0;
            if (s !== full[i * m.nv + jd] || full[i * m.nv + jd] !== full[jd * m.nv + i]) {
              buf.delete();
              throw new Error(`qM layout check failed at (${i},${jd}): ${s} vs mj_fullM ${full[i * m.nv + jd]}`);
            }
          }
        }
        buf.delete();
      }
      out.configs.push(cfg);
    }
  } finally {
    d.delete();
  }
  return out;
}

// One file's line of output.
const dumpOne = (file) => dumpFile(file, dumpModel, { root: opts.root, messages: true });

await answerAll(files, opts.serve, dumpOne);
