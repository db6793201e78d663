// mujoco_reference.cc - the reference model from MuJoCo's dump, mdlc's plant
// from plant-json, and their comparison (mujoco_reference.h).
#include "mujoco_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <regex>
#include <set>

namespace mdlc::oracle::mujoco {

using Eigen::Isometry3d;
using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using json = nlohmann::json;

// ---------------------------------------------------------------------------
// JSON helpers
// ---------------------------------------------------------------------------

Vector3d V3(const json& a) {
  return Vector3d(a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>());
}

Quaterniond Q4(const json& a) {
  return Quaterniond(a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>(),
                     a.at(3).get<double>())
      .normalized();
}

Isometry3d Pose(const Vector3d& p, const Quaterniond& q) {
  Isometry3d X = Isometry3d::Identity();
  X.linear() = q.toRotationMatrix();
  X.translation() = p;
  return X;
}

double Num(const json& v) {
  return v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

bool ReadPose(const json& X, Isometry3d* out) {
  if (!X.is_object() || !X.contains("p") || !X.contains("q")) return false;
  try {
    *out = Pose(V3(X["p"]), Q4(X["q"]));
  } catch (const json::exception&) {
    return false;
  }
  return true;
}

std::string LocalOf(const std::string& scoped) {
  const size_t at = scoped.rfind("::");
  return at == std::string::npos ? scoped : scoped.substr(at + 2);
}

// ---------------------------------------------------------------------------
// Names
// ---------------------------------------------------------------------------

DrakeNames NameAsDrake(const json& dump) {
  DrakeNames n;
  const json& bodies = dump.at("bodies");
  const json& joints = dump.at("joints");
  n.bodies.assign(bodies.size(), "world");
  n.dummies.resize(bodies.size());
  n.body_joints.resize(bodies.size());
  for (size_t j = 0; j < joints.size(); ++j) {
    n.body_joints.at(joints[j].at("body").get<size_t>()).push_back(static_cast<int>(j));
  }
  // MuJoCo's body ids are the document's pre-order, the order Drake's parser
  // creates bodies in.
  std::set<std::string> used = {"world"};
  auto unique = [&used](std::string name) {
    if (used.count(name)) {
      int k = 1;
      while (used.count(name + "_" + std::to_string(k))) ++k;
      name += "_" + std::to_string(k);
    }
    used.insert(name);
    return name;
  };
  int plant_bodies = 1;  // the world
  for (size_t b = 1; b < bodies.size(); ++b) {
    const std::string mj_name = bodies[b].at("name").get<std::string>();
    n.bodies[b] = unique(mj_name.empty() ? "body" + std::to_string(plant_bodies) : mj_name);
    ++plant_bodies;
    for (size_t k = 0; k + 1 < n.body_joints[b].size(); ++k) {
      n.dummies[b].push_back(unique(n.bodies[b] + std::to_string(k)));
      ++plant_bodies;
    }
  }
  n.joints.resize(joints.size());
  n.parents.resize(joints.size());
  n.children.resize(joints.size());
  for (size_t b = 1; b < bodies.size(); ++b) {
    const std::string parent = n.bodies.at(bodies[b].at("parent").get<size_t>());
    const std::vector<int>& bj = n.body_joints[b];
    for (size_t k = 0; k < bj.size(); ++k) {
      const int j = bj[k];
      n.parents[j] = k == 0 ? parent : n.dummies[b][k - 1];
      n.children[j] = k + 1 == bj.size() ? n.bodies[b] : n.dummies[b][k];
      n.joints[j] = joints[j].at("name").get<std::string>();
      // a free joint is the plant's floating joint of the body
      if (joints[j].at("type").get<std::string>() == "free") n.joints[j] = n.bodies[b];
      else if (n.joints[j].empty()) n.joints[j] = n.parents[j] + "-" + n.children[j];
    }
  }
  return n;
}

// ---------------------------------------------------------------------------
// The reference
// ---------------------------------------------------------------------------

Reference BuildReference(const json& d) {
  Reference r;
  r.version = d.value("version", "");
  const DrakeNames names = NameAsDrake(d);
  const json& bodies = d.at("bodies");
  r.bodies.resize(bodies.size());
  for (const auto& j : d.at("joints")) {
    const size_t id = r.joints.size();
    RJoint J;
    J.name = names.joints.at(id);
    J.parent = names.parents.at(id);
    J.child = names.children.at(id);
    J.type = j.at("type").get<std::string>();
    J.body = j.at("body").get<int>();
    J.dof = j.at("dof").get<int>();
    J.limited = j.at("limited").get<int>() != 0;
    J.lo = j.at("range").at(0).get<double>();
    J.hi = j.at("range").at(1).get<double>();
    J.armature = j.at("armature").empty() ? 0 : j.at("armature").at(0).get<double>();
    const json& q_default = j.contains("key_qpos") ? j.at("key_qpos") : j.at("qpos0");
    J.keyed = j.contains("key_qpos");
    if (j.contains("stiffness") && j.contains("damping")) {
      J.has_gains = true;
      J.stiffness = j.at("stiffness").get<double>();
      J.springref = j.value("springref", 0.0);
      for (const auto& v : j.at("damping")) J.damping.push_back(v.get<double>());
    }
    for (const auto& v : q_default) J.q_default.push_back(v.get<double>());
    J.qpos0 = J.q_default.at(0);
    r.joints.push_back(J);
  }
  for (size_t b = 0; b < bodies.size(); ++b) {
    const json& jb = bodies[b];
    RBody& B = r.bodies[b];
    B.name = names.bodies[b];
    B.joints = names.body_joints[b];
    B.dummies = names.dummies[b];
    B.parent = jb.at("parent").get<int>();
    B.mass = jb.at("mass").get<double>();
    B.ipos = V3(jb.at("ipos"));
    const Matrix3d R = Q4(jb.at("iquat")).toRotationMatrix();
    const Vector3d moments = V3(jb.at("inertia"));
    B.I = R * moments.asDiagonal() * R.transpose();
    B.max_moment = moments.cwiseAbs().maxCoeff();
  }
  std::map<int, int> per_body;  // registered geoms so far
  for (const auto& g : d.at("geoms")) {
    RGeom G;
    const int body = g.at("body").get<int>();
    G.body = r.bodies.at(body).name;
    G.type = g.at("type").get<std::string>();
    G.size = V3(g.at("size"));
    G.contype = g.at("contype").get<int>();
    G.conaffinity = g.at("conaffinity").get<int>();
    G.group = g.at("group").get<int>();
    G.name = g.at("name").get<std::string>();
    if (G.Registered()) {
      if (G.name.empty()) G.name = "geom" + std::to_string(per_body[body]);
      ++per_body[body];
    }
    if (g.contains("mesh_pos")) {
      G.has_mesh_offset = true;
      G.X_mesh = Pose(V3(g.at("mesh_pos")), Q4(g.at("mesh_quat")));
    }
    if (g.contains("mesh_scale")) G.mesh_scale = V3(g.at("mesh_scale"));
    r.geoms.push_back(G);
  }
  for (const auto& a : d.value("actuators", json::array())) {
    RActuator A;
    A.name = a.at("name").get<std::string>();
    A.trntype = a.at("trntype").get<std::string>();
    A.trnid = a.at("trnid").get<int>();
    A.gaintype = a.at("gaintype").get<std::string>();
    A.biastype = a.at("biastype").get<std::string>();
    for (int k = 0; k < 3; ++k) {
      A.gainprm[k] = a.at("gainprm").at(k).get<double>();
      A.biasprm[k] = a.at("biasprm").at(k).get<double>();
    }
    r.actuators.push_back(A);
  }
  for (const auto& c : d.at("configs")) {
    RConfig C;
    for (const auto& q : c.at("q")) C.q.emplace_back(q.at(0).get<int>(), q.at(1).get<double>());
    for (size_t b = 0; b < c.at("xpos").size(); ++b) {
      C.X_WB.push_back(Pose(V3(c.at("xpos")[b]), Q4(c.at("xquat")[b])));
    }
    for (const auto& a : c.at("xaxis")) C.xaxis.push_back(V3(a));
    for (size_t g = 0; g < c.at("geom_xpos").size(); ++g) {
      C.X_WG.push_back(Pose(V3(c.at("geom_xpos")[g]), Q4(c.at("geom_xquat")[g])));
    }
    for (const auto& e : c.at("M")) {
      C.M[{e.at(0).get<int>(), e.at(1).get<int>()}] = e.at(2).get<double>();
    }
    r.configs.push_back(std::move(C));
  }
  return r;
}

int NumConfigs() { return std::max(0, EnvInt("MDLC_ORACLE_CONFIGS", 3)); }

json DumpMujoco3(const std::string& file, std::string* problem) {
  static LineServer server(MujocoJsServeCommand(
      "mujoco_dump.mjs", {"--configs", std::to_string(NumConfigs()), "--seed", "1"}));
  return AskForDump(server, "MuJoCo 3.3.8 dump helper", file, 600.0, problem);
}

// ---------------------------------------------------------------------------
// mdlc's plant
// ---------------------------------------------------------------------------

MdlcRun RunMdlcPlant(const std::string& file, const JointValues& q, Plant* plant,
                     const std::vector<std::string>& extra,
                     const std::vector<std::string>& sections) {
  MdlcRun run;
  const std::vector<std::string> argv = PlantJsonCommand(file, "", q, extra);
  plant->cmdline = Quote(argv);
  run.result = RunProcess(argv, 120.0);
  const RunResult& r = run.result;
  run.problem = SpawnFailure(r);
  if (run.problem.empty()) run.problem = ExitFailure(r, plant->cmdline);
  if (run.problem.empty()) run.problem = ReadPlantJson(r, plant->cmdline, sections, &plant->root);
  if (!run.problem.empty()) return run;
  const json& root = plant->root;
  for (const auto& b : root["bodies"]) {
    const std::string name = b.value("name", "");
    if (!plant->bodies.emplace(name, &b).second) plant->duplicate_names.insert("body " + name);
  }
  for (const auto& j : root["joints"]) {
    const std::string name = j.value("name", "");
    if (!plant->joints.emplace(name, &j).second) plant->duplicate_names.insert("joint " + name);
  }
  if (root.contains("geometries") && root["geometries"].is_array()) {
    for (const auto& g : root["geometries"]) {
      plant->geoms.emplace(LocalOf(g.value("body", "")) + "|" + g.value("name", ""), &g);
    }
  }
  if (root.contains("dofs") && root["dofs"].is_array()) {
    for (size_t i = 0; i < root["dofs"].size(); ++i) {
      plant->dof_index[LocalOf(root["dofs"][i].get<std::string>())] = static_cast<int>(i);
    }
  }
  run.ok = true;
  return run;
}

JointValues ConfigurationQ(const Reference& ref, const RConfig& C,
                           const std::map<std::string, std::string>& scoped) {
  JointValues q;
  for (const auto& [j, v] : C.q) {
    const std::string& name = ref.joints.at(j).name;
    const auto it = scoped.find(name);
    q.emplace_back(it != scoped.end() ? it->second : name, v);
  }
  return q;
}

std::map<std::string, std::string> ScopedJointNames(const Plant& p) {
  std::map<std::string, std::string> scoped;
  for (const auto& j : p.root["joints"]) {
    scoped[j.value("name", "")] = j.value("model_instance", "") + "::" + j.value("name", "");
  }
  return scoped;
}

bool HasLocatedError(const std::string& err) {
  static const std::regex located(R"(:[0-9]+:[0-9]+: error: )");
  return std::regex_search(err, located);
}

std::string MujocoSkipReason(const std::string& case_reason) {
  return case_reason.empty() ? MujocoJsUnavailable() : case_reason;
}

// ---------------------------------------------------------------------------
// Comparison
// ---------------------------------------------------------------------------

void CompareVec(Report* rep, const std::string& feature, const std::string& ent,
                const std::string& what, const Vector3d& mdlc, const Vector3d& ref, double tol) {
  for (int i = 0; i < 3; ++i) {
    rep->Num(feature, ent, what + "[" + std::to_string(i) + "]", mdlc(i), ref(i), tol);
  }
}

namespace {

// MJCF-008 (keyframe (default positions)): a ball or free joint's
// default_positions against the applied key's qpos slice. A ball's key
// quaternion w x y z is the plant's roll-pitch-yaw R = Rz(y) Ry(p) Rx(r); a
// free joint's x y z, w x y z is the plant's [w x y z x y z]. Rotations are
// compared as matrices (a quaternion's sign is a convention), after MuJoCo's
// normalization.
void CompareKeyedDefault(const json& jj, const RJoint& J, const std::string& ent, Report* rep) {
  const json dp = jj.value("default_positions", json::array());
  auto quat = [](const double* wxyz) {
    const Quaterniond q(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
    return q.norm() < 1e-15 ? Quaterniond::Identity() : q.normalized();
  };
  Isometry3d mdlc = Isometry3d::Identity(), ref = Isometry3d::Identity();
  if (J.type == "free" && J.q_default.size() == 7) {
    if (!dp.is_array() || dp.size() != 7) {
      rep->Add("MJCF-008 " + ent + " default_positions: expected 7 values, got " + dp.dump());
      return;
    }
    const double w[4] = {Num(dp[0]), Num(dp[1]), Num(dp[2]), Num(dp[3])};
    mdlc = Pose(Vector3d(Num(dp[4]), Num(dp[5]), Num(dp[6])), quat(w));
    ref = Pose(Vector3d(J.q_default[0], J.q_default[1], J.q_default[2]),
               quat(J.q_default.data() + 3));
  } else if (J.type == "ball" && J.q_default.size() == 4) {
    if (!dp.is_array() || dp.size() != 3) {
      rep->Add("MJCF-008 " + ent + " default_positions: expected 3 values (rpy), got " + dp.dump());
      return;
    }
    mdlc.linear() = (Eigen::AngleAxisd(Num(dp[2]), Vector3d::UnitZ()) *
                     Eigen::AngleAxisd(Num(dp[1]), Vector3d::UnitY()) *
                     Eigen::AngleAxisd(Num(dp[0]), Vector3d::UnitX()))
                        .toRotationMatrix();
    ref.linear() = quat(J.q_default.data()).toRotationMatrix();
  } else {
    return;
  }
  ComparePose(rep, "MJCF-008", ent, "X_default (key qpos)", mdlc, ref, kKinTol);
}

// MJCF-022, BEYOND-007: a joint's damping per dof and, for hinges and
// slides, the stiffness and nominal position of mdlc's joint springs on it.
void CompareJointGains(const RJoint& J, const json& jj, const Plant& p, const std::string& ent,
                       Report* rep) {
  if (!J.has_gains) return;
  const json damping = jj.value("damping", json::array());
  if (!damping.is_array() || damping.size() != J.damping.size()) {
    rep->Add("MJCF-022 " + ent + " damping: expected " + std::to_string(J.damping.size()) +
             " values, got " + damping.dump());
  } else {
    for (size_t k = 0; k < J.damping.size(); ++k) {
      rep->Num("MJCF-022/BEYOND-007", ent, "damping[" + std::to_string(k) + "]", Num(damping[k]),
               J.damping[k], kGainTol);
    }
  }
  if (!J.Moving()) return;
  double stiffness = 0;
  std::vector<double> nominal;
  for (const auto& f : p.root.value("force_elements", json::array())) {
    const std::string type = f.value("type", "");
    if ((type == "revolute_spring" || type == "prismatic_spring") &&
        LocalOf(f.value("joint", "")) == J.name) {
      stiffness += Num(f.value("stiffness", json()));
      nominal.push_back(Num(f.value("nominal", json())));
    }
  }
  rep->Num("BEYOND-007", ent, "stiffness (joint springs)", stiffness, J.stiffness, kGainTol);
  if (J.stiffness != 0) {
    for (double n : nominal) rep->Num("BEYOND-007", ent, "spring nominal (springref)", n, J.springref, kKinTol);
  }
}

// BEYOND-008: named joint actuators of the position or velocity servo shape.
void CompareActuators(const Reference& ref, const Plant& p, Report* rep) {
  std::map<std::string, const json*> mdlc;
  if (!p.root.contains("actuators") || !p.root["actuators"].is_array()) return;
  for (const auto& a : p.root["actuators"]) mdlc[a.value("name", "")] = &a;
  for (const RActuator& A : ref.actuators) {
    if (A.name.empty() || A.trntype != "joint" || A.gaintype != "fixed" ||
        A.biastype != "affine" || A.biasprm[0] != 0) {
      continue;
    }
    const auto it = mdlc.find(A.name);
    if (it == mdlc.end()) continue;  // an actuator mdlc leaves out warns there
    const std::string ent = "actuator '" + A.name + "'";
    const double g = A.gainprm[0];
    const json& a = *it->second;
    if (g > 0 && g == -A.biasprm[1]) {
      rep->Num("BEYOND-008", ent, "kp (gainprm[0])", Num(a.value("kp", json())), g, kGainTol);
      rep->Num("BEYOND-008", ent, "kd (-biasprm[2])", Num(a.value("kd", json())), -A.biasprm[2],
               kGainTol);
    } else if (g > 0 && A.biasprm[1] == 0 && g == -A.biasprm[2]) {
      rep->Num("BEYOND-008", ent, "kd (gainprm[0])", Num(a.value("kd", json())), g, kGainTol);
    }
  }
}

}  // namespace

void CompareStatic(const Reference& ref, const Plant& p, const StaticChecks& checks, Report* rep) {
  for (const auto& dup : p.duplicate_names) rep->Add("plant-json names two entities " + dup);
  for (size_t b = 1; b < ref.bodies.size(); ++b) {
    const RBody& B = ref.bodies[b];
    const std::string ent = "body '" + B.name + "'";
    const auto it = p.bodies.find(B.name);
    if (it == p.bodies.end()) {
      rep->Add("MJCF-020 " + ent + " is missing from mdlc's plant");
      continue;
    }
    const json& jb = *it->second;
    for (const auto& dummy : B.dummies) {
      const auto d = p.bodies.find(dummy);
      if (d == p.bodies.end()) {
        rep->Add("MJCF-023 intermediate body '" + dummy + "' (before '" + B.name +
                 "') is missing from mdlc's plant");
      } else {
        rep->Num("MJCF-023", "intermediate body '" + dummy + "'", "mass",
                 Num(d->second->value("mass", json())), 0.0, kMassTol, 1e-12);
      }
    }
    rep->Num("MJCF-030/031", ent, "mass", Num(jb.value("mass", json())), B.mass, kMassTol, 1e-12);
    // A massless body (no geoms, no inertial) has no centre of mass; MuJoCo
    // then reports its body position as ipos.
    if (B.mass == 0) continue;
    Vector3d com = Vector3d::Constant(std::nan(""));
    if (jb.contains("com") && jb["com"].is_array() && jb["com"].size() == 3) {
      const json& c = jb["com"];
      com = Vector3d(Num(c[0]), Num(c[1]), Num(c[2]));
    }
    CompareVec(rep, "MJCF-030/031", ent, "com", com, B.ipos, kMassTol);
    const json I = jb.value("inertia", json::array());
    if (!I.is_array() || I.size() != 6) {
      rep->Add("MJCF-030 " + ent + " has no 6-entry inertia");
    } else {
      // entries relative to the largest principal moment
      const double scale = std::max({B.max_moment, 1e-12, ref.inertia_floor / kMassTol});
      const int rows[6] = {0, 1, 2, 0, 0, 1}, cols[6] = {0, 1, 2, 1, 2, 2};
      const char* names[6] = {"Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz"};
      for (int k = 0; k < 6; ++k) {
        rep->Num("MJCF-030/031", ent, std::string("inertia.") + names[k], Num(I[k]),
                 B.I(rows[k], cols[k]), kMassTol, scale);
      }
    }
  }

  // every plant body is a MuJoCo body or an intermediate body of one
  std::set<std::string> known_bodies;
  for (const RBody& B : ref.bodies) {
    known_bodies.insert(B.name);
    known_bodies.insert(B.dummies.begin(), B.dummies.end());
  }
  for (const auto& [name, body] : p.bodies) {
    if (!known_bodies.count(name)) {
      rep->Add("MJCF-020/023 mdlc's plant has a body '" + name + "' that MuJoCo's model lacks");
    }
  }
  if (checks.joint_gains) CompareActuators(ref, p, rep);

  for (const RJoint& J : ref.joints) {
    const std::string ent = "joint '" + J.name + "' (" + J.type + ")";
    const json* jj = nullptr;
    if (J.type == "free") {
      for (const auto& j : p.root["joints"]) {
        if (LocalOf(j.value("child", "")) == J.child && j.value("type", "") == "quaternion_floating") {
          jj = &j;
        }
      }
      if (!jj) {
        rep->Add("MJCF-021 free body '" + J.child + "' has no quaternion_floating joint in mdlc's plant");
      } else if (J.keyed && checks.keyed_rotations) {
        // MJCF-008: the key's x y z, w x y z as plant-json's [w x y z x y z]
        CompareKeyedDefault(*jj, J, ent, rep);
      }
      continue;
    }
    const auto it = p.joints.find(J.name);
    if (it == p.joints.end()) {
      rep->Add("MJCF-022 " + ent + " is missing from mdlc's plant");
      continue;
    }
    jj = it->second;
    const std::string want = J.type == "hinge" ? "revolute" : J.type == "slide" ? "prismatic" : "ball";
    if (jj->value("type", "") != want) {
      rep->Add("MJCF-022 " + ent + " type: mdlc=" + jj->value("type", "?") + " expected=" + want);
    }
    if (LocalOf(jj->value("parent", "")) != J.parent || LocalOf(jj->value("child", "")) != J.child) {
      rep->Add("MJCF-022/023 " + ent + " joins " + jj->value("parent", "?") + " -> " +
               jj->value("child", "?") + " in mdlc, expected " + J.parent + " -> " + J.child);
    }
    if (checks.joint_gains) CompareJointGains(J, *jj, p, ent, rep);
    if (!J.Moving()) {
      // MJCF-008: a ball's key
      if (J.keyed && checks.keyed_rotations) CompareKeyedDefault(*jj, J, ent, rep);
      continue;
    }
    const json lower = jj->value("lower", json::array()), upper = jj->value("upper", json::array());
    const json dp = jj->value("default_positions", json::array());
    auto limit = [](const json& a, double inf) {
      if (!a.is_array() || a.size() != 1) return std::nan("");
      return a[0].is_null() ? inf : Num(a[0]);
    };
    const double inf = std::numeric_limits<double>::infinity();
    rep->Num("MJCF-004/022", ent, "lower", limit(lower, -inf), J.limited ? J.lo : -inf, kKinTol);
    rep->Num("MJCF-004/022", ent, "upper", limit(upper, inf), J.limited ? J.hi : inf, kKinTol);
    rep->Num(J.keyed ? "MJCF-008/022" : "MJCF-022", ent,
             J.keyed ? "default_positions[0] (key qpos)" : "default_positions[0] (qpos0)",
             dp.is_array() && dp.size() == 1 ? Num(dp[0]) : std::nan(""), J.qpos0, kKinTol);
    const auto di = p.dof_index.find(J.name);
    if (di == p.dof_index.end()) {
      rep->Add("MJCF-022 " + ent + " is not in plant-json's dofs");
    } else if (checks.reflected_inertia && p.root.contains("reflected_inertia") &&
               p.root["reflected_inertia"].is_array() &&
               di->second < static_cast<int>(p.root["reflected_inertia"].size())) {
      // MJCF-024: reflected inertia is the armature when an actuator drives
      // the joint, else 0.
      const double ri = Num(p.root["reflected_inertia"][di->second]);
      if (ri != 0) rep->Num("MJCF-024", ent, "reflected_inertia (0 or armature)", ri, J.armature, kMassTol, 1e-12);
    }
  }
}

void CompareConfiguration(const Reference& ref, const RConfig& C, const Plant& p, Report* rep) {
  for (size_t b = 1; b < ref.bodies.size() && b < C.X_WB.size(); ++b) {
    const auto it = p.bodies.find(ref.bodies[b].name);
    if (it == p.bodies.end()) continue;  // reported once already
    Isometry3d X;
    if (!ReadPose(it->second->value("X_WB", json()), &X)) {
      rep->Add("body '" + ref.bodies[b].name + "' has no readable X_WB");
      continue;
    }
    ComparePose(rep, "MJCF-010/020/023", "body '" + ref.bodies[b].name + "'", "X_WB", X, C.X_WB[b], kKinTol);
  }
  for (size_t j = 0; j < ref.joints.size() && j < C.xaxis.size(); ++j) {
    const RJoint& J = ref.joints[j];
    if (!J.Moving()) continue;
    const auto it = p.joints.find(J.name);
    if (it == p.joints.end()) continue;
    const json a = it->second->value("axis_W", json());
    Vector3d axis = Vector3d::Constant(std::nan(""));
    if (a.is_array() && a.size() == 3) axis = Vector3d(Num(a[0]), Num(a[1]), Num(a[2]));
    CompareVec(rep, "MJCF-022", "joint '" + J.name + "'", "axis_W", axis, C.xaxis[j], kKinTol);
  }
  // M(q) on hinge and slide dofs, armature removed.
  std::vector<const RJoint*> moving;
  for (const RJoint& J : ref.joints) {
    if (J.Moving()) moving.push_back(&J);
  }
  if (moving.empty()) return;
  if (!p.root.contains("mass_matrix") || !p.root["mass_matrix"].is_array()) {
    rep->Add("plant-json has no mass_matrix (" + std::to_string(moving.size()) + " dofs)");
    return;
  }
  const json& M = p.root["mass_matrix"];
  auto ref_entry = [&](const RJoint* a, const RJoint* b) {
    const auto it = C.M.find({std::max(a->dof, b->dof), std::min(a->dof, b->dof)});
    double v = it == C.M.end() ? 0.0 : it->second;
    if (a == b) v -= a->armature;
    return v;
  };
  auto mdlc_entry = [&](const RJoint* a, const RJoint* b) {
    const auto ia = p.dof_index.find(a->name), ib = p.dof_index.find(b->name);
    if (ia == p.dof_index.end() || ib == p.dof_index.end()) return std::nan("");
    if (ia->second >= static_cast<int>(M.size()) || !M[ia->second].is_array() ||
        ib->second >= static_cast<int>(M[ia->second].size())) {
      return std::nan("");
    }
    return Num(M[ia->second][ib->second]);
  };
  std::vector<double> diag;
  for (const RJoint* a : moving) diag.push_back(std::abs(ref_entry(a, a)));
  for (size_t x = 0; x < moving.size(); ++x) {
    if (!p.dof_index.count(moving[x]->name)) continue;  // reported as missing
    for (size_t y = 0; y <= x; ++y) {
      if (!p.dof_index.count(moving[y]->name)) continue;
      const double scale = std::sqrt(diag[x] * diag[y]);
      rep->Num("MJCF-022/024/031", "M", "(" + moving[x]->name + ", " + moving[y]->name + ")",
               mdlc_entry(moving[x], moving[y]), ref_entry(moving[x], moving[y]), kMassTol,
               std::max({scale, 1e-300, ref.inertia_floor / kMassTol}));
    }
  }
}

void ComparePlant(const Reference& ref, size_t config, const Plant& plant,
                  const StaticChecks& checks, std::map<std::string, std::string>* scoped,
                  Report* rep, const std::function<void()>& more) {
  const size_t before = rep->size();
  try {
    if (config == 0) {
      *scoped = ScopedJointNames(plant);
      CompareStatic(ref, plant, checks, rep);
    }
    CompareConfiguration(ref, ref.configs.at(config), plant, rep);
    if (more) more();
  } catch (const json::exception& e) {
    rep->Add(std::string("malformed plant-json (") + e.what() + ")");
  }
  if (rep->size() > before) rep->Add("reproduce with: " + plant.cmdline);
}

}  // namespace mdlc::oracle::mujoco
