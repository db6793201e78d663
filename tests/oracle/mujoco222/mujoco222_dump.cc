// mujoco222_dump - test-only: what MuJoCo 2.2.2 (Debian libmujoco-dev)
// compiles from MJCF files, as the same JSON Lines that
// tests/oracle/mujoco_js/mujoco_dump.mjs prints for MuJoCo 3.3.8 (see that
// file for the schema). A second opinion only: the MuJoCo oracle test uses it
// for the files MuJoCo 3 no longer loads (MuJoCo 2's `composite` models).
//
//   mujoco222_dump [--configs N] [--seed S] [--brief] FILE...
//
// Differences from the 3.3.8 dump: MuJoCo 2.2.2 exposes no mesh_pos/mesh_quat
// (a mesh geom's frame is already moved to the mesh's inertial frame, with no
// record of the offset), so mesh geoms carry no "mesh_pos"; `--q` is not
// offered. The random configurations use the same PRNG (mulberry32) and the
// same draws as the 3.3.8 dump, so the two agree on every configuration.
// Keyframes (MJCF-008) as there: the key named "home", else the first key, is
// the base state of every configuration (its qpos; mj_resetDataKeyframe's),
// qpos0 without keys; "key" and each joint's "key_qpos" record it.
#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace {

using json = nlohmann::json;

const char* const kJointTypes[] = {"free", "ball", "slide", "hinge"};
const char* const kGeomTypes[] = {"plane", "hfield", "sphere", "capsule",
                                  "ellipsoid", "cylinder", "box", "mesh"};

json Vec(const mjtNum* a, int i, int n) {
  json v = json::array();
  for (int k = 0; k < n; ++k) v.push_back(a[i * n + k]);
  return v;
}

std::string Name(const mjModel* m, const int* adr, int id) {
  return std::string(m->names + adr[id]);
}

// The same generator as mujoco_dump.mjs (mulberry32), on uint32 arithmetic.
struct Mulberry32 {
  uint32_t a;
  double operator()() {
    a += 0x6D2B79F5u;
    uint32_t t = (a ^ (a >> 15)) * (1u | a);
    t = (t + ((t ^ (t >> 7)) * (61u | t))) ^ t;
    return static_cast<double>(t ^ (t >> 14)) / 4294967296.0;
  }
};

json MatToQuat(const mjtNum* R) {
  mjtNum q[4];
  mju_mat2Quat(q, R);
  if (q[0] < 0) {
    for (double& c : q) c = -c;
  }
  return json::array({q[0], q[1], q[2], q[3]});
}

json Dump(const std::string& file, mjModel* m, int n_configs, int seed, bool brief) {
  json out = {{"file", file}, {"ok", true}, {"version", mj_versionString()},
              {"model", std::string(m->names)}, {"nq", m->nq}, {"nv", m->nv},
              {"nbody", m->nbody}, {"njnt", m->njnt}, {"ngeom", m->ngeom},
              {"nkey", m->nkey}};
  if (brief) return out;
  json bodies = json::array();
  for (int b = 0; b < m->nbody; ++b) {
    json types = json::array();
    for (int k = 0; k < m->body_jntnum[b]; ++k) {
      types.push_back(kJointTypes[m->jnt_type[m->body_jntadr[b] + k]]);
    }
    bodies.push_back({{"id", b}, {"name", Name(m, m->name_bodyadr, b)},
                      {"parent", m->body_parentid[b]}, {"jntnum", m->body_jntnum[b]},
                      {"jnt_types", types}, {"mass", m->body_mass[b]},
                      {"ipos", Vec(m->body_ipos, b, 3)}, {"iquat", Vec(m->body_iquat, b, 4)},
                      {"inertia", Vec(m->body_inertia, b, 3)}, {"pos", Vec(m->body_pos, b, 3)},
                      {"quat", Vec(m->body_quat, b, 4)}});
  }
  out["bodies"] = bodies;
  // the base state: key "home", else key 0 (MJCF-008), else qpos0
  int key = -1;
  for (int k = 0; k < m->nkey && key < 0; ++k) {
    if (Name(m, m->name_keyadr, k) == "home") key = k;
  }
  if (key < 0 && m->nkey > 0) key = 0;
  const mjtNum* base = key >= 0 ? m->key_qpos + static_cast<size_t>(key) * m->nq : m->qpos0;
  if (key >= 0) out["key"] = {{"id", key}, {"name", Name(m, m->name_keyadr, key)}};
  json joints = json::array();
  for (int j = 0; j < m->njnt; ++j) {
    const int type = m->jnt_type[j];
    const int nq = type == mjJNT_FREE ? 7 : type == mjJNT_BALL ? 4 : 1;
    const int nd = type == mjJNT_FREE ? 6 : type == mjJNT_BALL ? 3 : 1;
    const int dof = m->jnt_dofadr[j], qadr = m->jnt_qposadr[j];
    json arm = json::array(), q0 = json::array();
    for (int k = 0; k < nd; ++k) arm.push_back(m->dof_armature[dof + k]);
    for (int k = 0; k < nq; ++k) q0.push_back(m->qpos0[qadr + k]);
    joints.push_back({{"id", j}, {"name", Name(m, m->name_jntadr, j)},
                      {"type", kJointTypes[type]}, {"body", m->jnt_bodyid[j]},
                      {"dof", dof}, {"qposadr", qadr}, {"axis", Vec(m->jnt_axis, j, 3)},
                      {"pos", Vec(m->jnt_pos, j, 3)}, {"range", Vec(m->jnt_range, j, 2)},
                      {"limited", m->jnt_limited[j]}, {"armature", arm}, {"qpos0", q0}});
    if (key >= 0) {
      json kq = json::array();
      for (int k = 0; k < nq; ++k) kq.push_back(base[qadr + k]);
      joints.back()["key_qpos"] = kq;
    }
  }
  out["joints"] = joints;
  json geoms = json::array();
  for (int g = 0; g < m->ngeom; ++g) {
    const int type = m->geom_type[g];
    json geom = {{"id", g}, {"name", Name(m, m->name_geomadr, g)}, {"body", m->geom_bodyid[g]},
                 {"type", type >= 0 && type <= mjGEOM_MESH ? kGeomTypes[type] : std::to_string(type)},
                 {"size", Vec(m->geom_size, g, 3)}, {"pos", Vec(m->geom_pos, g, 3)},
                 {"quat", Vec(m->geom_quat, g, 4)}, {"contype", m->geom_contype[g]},
                 {"conaffinity", m->geom_conaffinity[g]}, {"group", m->geom_group[g]}};
    if (type == mjGEOM_MESH && m->geom_dataid[g] >= 0) {
      geom["mesh"] = Name(m, m->name_meshadr, m->geom_dataid[g]);
    }
    geoms.push_back(geom);
  }
  out["geoms"] = geoms;

  std::vector<int> moving;
  std::vector<char> dof_moving(m->nv, 0);
  for (int j = 0; j < m->njnt; ++j) {
    if (m->jnt_type[j] == mjJNT_HINGE || m->jnt_type[j] == mjJNT_SLIDE) {
      moving.push_back(j);
      dof_moving[m->jnt_dofadr[j]] = 1;
    }
  }
  std::vector<std::vector<std::pair<int, double>>> configs(1);
  for (int k = 1; k <= n_configs && !moving.empty(); ++k) {
    Mulberry32 rnd{static_cast<uint32_t>(static_cast<int64_t>(seed) * 1000003 + k)};
    std::vector<std::pair<int, double>> c;
    for (int j : moving) {
      const bool hinge = m->jnt_type[j] == mjJNT_HINGE;
      double lo = hinge ? -M_PI : -0.5, hi = -lo;
      if (m->jnt_limited[j]) {
        lo = m->jnt_range[2 * j];
        hi = m->jnt_range[2 * j + 1];
      }
      c.emplace_back(j, lo + (hi - lo) * rnd());
    }
    configs.push_back(c);
  }

  mjData* d = mj_makeData(m);
  std::vector<mjtNum> full(static_cast<size_t>(m->nv) * m->nv);
  json cfgs = json::array();
  for (const auto& c : configs) {
    mju_copy(d->qpos, base, m->nq);
    json q = json::array();
    for (const auto& [j, v] : c) {
      d->qpos[m->jnt_qposadr[j]] = v;
      q.push_back(json::array({j, v}));
    }
    mj_forward(m, d);
    json cfg = {{"q", q}};
    json xpos = json::array(), xquat = json::array(), xaxis = json::array(),
         xanchor = json::array(), gpos = json::array(), gquat = json::array(), M = json::array();
    for (int b = 0; b < m->nbody; ++b) {
      xpos.push_back(Vec(d->xpos, b, 3));
      xquat.push_back(Vec(d->xquat, b, 4));
    }
    for (int j = 0; j < m->njnt; ++j) {
      xaxis.push_back(Vec(d->xaxis, j, 3));
      xanchor.push_back(Vec(d->xanchor, j, 3));
    }
    for (int g = 0; g < m->ngeom; ++g) {
      gpos.push_back(Vec(d->geom_xpos, g, 3));
      gquat.push_back(MatToQuat(d->geom_xmat + 9 * g));
    }
    if (m->nv > 0) mj_fullM(m, full.data(), d->qM);
    for (int i = 0; i < m->nv; ++i) {
      for (int j = 0; j <= i; ++j) {
        const double v = full[static_cast<size_t>(i) * m->nv + j];
        if (dof_moving[i] && dof_moving[j] && v != 0) M.push_back(json::array({i, j, v}));
      }
    }
    cfg["xpos"] = xpos;
    cfg["xquat"] = xquat;
    cfg["xaxis"] = xaxis;
    cfg["xanchor"] = xanchor;
    cfg["geom_xpos"] = gpos;
    cfg["geom_xquat"] = gquat;
    cfg["M"] = M;
    cfgs.push_back(cfg);
  }
  mj_deleteData(d);
  out["configs"] = cfgs;
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  int n_configs = 3, seed = 1;
  bool brief = false;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--configs" || a == "--seed") && i + 1 < argc) {
      (a == "--configs" ? n_configs : seed) = std::atoi(argv[++i]);
    } else if (a == "--brief") {
      brief = true;
    } else if (a == "--version") {
      std::printf("%s\n", json({{"version", mj_versionString()}}).dump().c_str());
      return 0;
    } else if (a.rfind("--", 0) == 0) {
      std::fprintf(stderr, "usage: mujoco222_dump [--configs N] [--seed S] [--brief] FILE...\n");
      return 2;
    } else {
      files.push_back(a);
    }
  }
  for (const auto& file : files) {
    char error[1000] = "";
    mjModel* m = mj_loadXML(file.c_str(), nullptr, error, sizeof error);
    json line;
    if (!m) {
      line = {{"file", file}, {"ok", false}, {"error", std::string(error)}};
    } else {
      line = Dump(file, m, n_configs, seed, brief);
      if (error[0]) line["messages"] = json::array({std::string(error)});
      mj_deleteModel(m);
    }
    std::printf("%s\n", line.dump(-1, ' ', false, json::error_handler_t::replace).c_str());
    std::fflush(stdout);
  }
  return 0;
}
