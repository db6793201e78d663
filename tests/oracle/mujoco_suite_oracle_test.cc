// Differential test of mdlc's MJCF frontend against MuJoCo 3.3.8 on MuJoCo's
// own test and model files (issue 62): the MJCF files of MuJoCo's test/ and
// model/ folders at google-deepmind/mujoco@6e59f61c70d26a9dc089cdf1b8a3ff6980e5b198,
// the last commit versioned 3.3.8, listed with their expected outcome in
// tests/models/mujoco_suite/manifest.tsv (written and checked by classify.py
// there, which runs both tools; its README says where the files come from).
//
// Per manifest outcome:
//   agree           MuJoCo 3.3.8 must load the file, mdlc must compile it, and
//                   every body, joint and the mass matrix must agree (below);
//   mujoco-rejects  MuJoCo 3.3.8 must still refuse it, and mdlc must refuse it
//                   with a located error (file:line:col: error:) unless the
//                   manifest's note says why mdlc accepts it;
//   not-held:C      mdlc must not crash (exit 0, or 1 with a located error)
//                   and, when it compiles the file, must warn about each
//                   construct C (MuJoCo is not asked);
//   pending:C       compared and reported, not failed: the case is skipped
//                   with its first differences, and passes with a note asking
//                   to mark it `agree` once mdlc agrees.
//
// The comparison follows tests/oracle/mujoco_oracle_test.cc (MuJoCo's dump
// by tests/oracle/mujoco_js/mujoco_dump.mjs, mdlc's plant-json by the CLI at
// each configuration, every quantity by name, never by position), with
// Drake's names for what the file leaves unnamed (MJCF-020/022/023): an
// unnamed body is `body<N>`, N the plant's body count when it is created
// (counting the world and the intermediate bodies of earlier bodies); a body
// with k > 1 joints has k-1 massless intermediate bodies `<body>0`, ...; an
// unnamed joint is `<parent>-<child>`; a free joint is its body's
// quaternion_floating joint. Compared, at the base state (the key named
// "home", else the first key, else qpos0) and MDLC_ORACLE_CONFIGS (default 3)
// seeded random configurations of the hinge and slide joints:
//   MJCF-010/020/023  X_WB of every body, to 1e-9 (kKinTol);
//   MJCF-030/031      mass, COM and inertia about the COM of every body, to
//                     1e-6 relative (kMassTol, as mujoco_oracle_test: MuJoCo
//                     re-diagonalises every inertia and keeps mesh vertices in
//                     single precision);
//   MJCF-022/023      every joint's type, parent and child body, world axis
//                     at every configuration, limits where MuJoCo limits it
//                     and default position, to 1e-9;
//   MJCF-022/024/031  the mass matrix on the hinge and slide dofs at every
//                     configuration, to 1e-6 relative to sqrt(M_ii M_jj), with
//                     MuJoCo's armature taken off its diagonal (plant-json's
//                     mass_matrix leaves reflected inertia out).
//
// Configuration (all optional except the suite):
//   env MDLC_MUJOCO_SUITE_DIR      the MuJoCo tree holding test/ and model/ at
//                                  the pinned commit (default: the CMake
//                                  cache variable of that name); without it
//                                  the one case reports itself skipped
//   env MDLC_BINARY, --mdlc=PATH   the mdlc CLI; env MDLC_NODE: Node.js
//   env MDLC_ORACLE_CONFIGS=N      random configurations (default 3)
// Without Node.js or the installed mujoco-js package every case is skipped.
// CTest runs the cases in four shards, MujocoSuiteOracle.shard_N_of_4, each
// one Node.js process.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "oracle_util.h"

#ifndef MDLC_MUJOCO_SUITE_DIR
#define MDLC_MUJOCO_SUITE_DIR ""
#endif

namespace {

namespace fs = std::filesystem;
using namespace mdlc::oracle;
using Eigen::Isometry3d;
using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using json = nlohmann::json;

// The tolerances of mujoco_oracle_test.cc, for the same reasons: poses, axes,
// limits and default positions are the same chain of double-precision
// rotations and translations on both sides (they agree to about 1e-15 on the
// corpus); mass properties and M(q) go through MuJoCo's re-diagonalised
// inertias (mjuu_eig3) and single-precision mesh vertices.
constexpr double kKinTol = 1e-9;
constexpr double kMassTol = 1e-6;

// ---------------------------------------------------------------------------
// Cases: the manifest's rows
// ---------------------------------------------------------------------------

struct SuiteCase {
  std::string id;       // gtest parameter name
  std::string rel;      // path below the MuJoCo tree, e.g. model/humanoid/humanoid.xml
  std::string path;     // absolute
  std::string outcome;  // agree, mujoco-rejects, not-held:..., pending:...
  std::string note;     // the manifest's note
  std::string skip_reason;
};

void PrintTo(const SuiteCase& c, std::ostream* os) { *os << c.rel; }

fs::path SuiteManifest() { return TestModels("mujoco_suite") / "manifest.tsv"; }

std::string SuiteDir() {
  if (const char* env = std::getenv("MDLC_MUJOCO_SUITE_DIR"); env && *env) return env;
  return MDLC_MUJOCO_SUITE_DIR;
}

std::vector<std::vector<std::string>> ReadSuiteManifest() {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(SuiteManifest());
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || line.rfind("path\t", 0) == 0) continue;
    std::vector<std::string> cols;
    std::stringstream ss(line);
    for (std::string col; std::getline(ss, col, '\t');) cols.push_back(col);
    rows.push_back(cols);
  }
  return rows;
}

std::vector<SuiteCase> SuiteCases() {
  std::vector<SuiteCase> cases;
  const std::string dir = SuiteDir();
  std::string unavailable;
  if (dir.empty()) {
    unavailable = "MDLC_MUJOCO_SUITE_DIR is not set: it names a copy of MuJoCo's test/ and model/ "
                  "at the pinned commit (tests/models/mujoco_suite/README.md)";
  } else if (!fs::is_directory(fs::path(dir) / "model")) {
    unavailable = "MDLC_MUJOCO_SUITE_DIR (" + dir + ") holds no model/ folder";
  }
  const auto rows = ReadSuiteManifest();
  if (rows.empty()) unavailable = "no rows in " + SuiteManifest().string();
  if (!unavailable.empty()) {
    SuiteCase c;
    c.id = "suite_unavailable";
    c.skip_reason = unavailable;
    return {c};
  }
  for (const auto& cols : rows) {
    if (cols.size() < 2) continue;
    SuiteCase c;
    c.rel = cols[0];
    c.id = Sanitize(WithoutSuffix(cols[0], ".xml"));
    c.path = (fs::path(dir) / cols[0]).string();
    c.outcome = cols[1];
    if (cols.size() > 4) c.note = cols[4];
    cases.push_back(c);
  }
  Uniquify(&cases);
  return cases;
}

// ---------------------------------------------------------------------------
// The reference, from MuJoCo's dump, with Drake's names
// ---------------------------------------------------------------------------

struct RBody {
  std::string name;
  int parent = 0;
  std::vector<int> joints;
  std::vector<std::string> dummies;  // intermediate bodies before it
  double mass = 0;
  Vector3d ipos = Vector3d::Zero();
  Matrix3d I = Matrix3d::Zero();
  double max_moment = 0;
};

struct RJoint {
  std::string name, type;  // MuJoCo's type: free ball slide hinge
  int body = 0, dof = 0;
  std::string parent, child;
  bool limited = false;
  double lo = 0, hi = 0, armature = 0, q_default = 0;
  bool keyed = false;
  bool Moving() const { return type == "hinge" || type == "slide"; }
};

struct RConfig {
  std::vector<std::pair<int, double>> q;
  std::vector<Isometry3d> X_WB;
  std::vector<Vector3d> xaxis;
  std::map<std::pair<int, int>, double> M;  // (dof_i, dof_j), i >= j, armature included
};

struct Reference {
  std::vector<RBody> bodies;
  std::vector<RJoint> joints;
  std::vector<RConfig> configs;
};

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

Reference BuildReference(const json& d) {
  Reference r;
  const json& bodies = d.at("bodies");
  r.bodies.resize(bodies.size());
  for (const auto& j : d.at("joints")) {
    RJoint J;
    J.name = j.at("name").get<std::string>();
    J.type = j.at("type").get<std::string>();
    J.body = j.at("body").get<int>();
    J.dof = j.at("dof").get<int>();
    J.limited = j.at("limited").get<int>() != 0;
    J.lo = j.at("range").at(0).get<double>();
    J.hi = j.at("range").at(1).get<double>();
    J.armature = j.at("armature").empty() ? 0 : j.at("armature").at(0).get<double>();
    J.keyed = j.contains("key_qpos");
    J.q_default = (J.keyed ? j.at("key_qpos") : j.at("qpos0")).at(0).get<double>();
    r.bodies.at(J.body).joints.push_back(static_cast<int>(r.joints.size()));
    r.joints.push_back(J);
  }
  // MuJoCo's body ids are the document's pre-order, the order Drake's parser
  // creates bodies in.
  // Drake's scheme can name two bodies alike: test/user/testdata/auto_limits.xml's
  // first body has six joints, so five intermediate bodies body10 ... body14,
  // and its third, unnamed, body is the plant's 13th, body13 again. mdlc keeps
  // the first and calls the later one body13_1 (the smallest free _k), and so
  // does the reference.
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
  for (size_t b = 0; b < bodies.size(); ++b) {
    const json& jb = bodies[b];
    RBody& B = r.bodies[b];
    B.parent = jb.at("parent").get<int>();
    B.mass = jb.at("mass").get<double>();
    B.ipos = V3(jb.at("ipos"));
    const Matrix3d R = Q4(jb.at("iquat")).toRotationMatrix();
    const Vector3d moments = V3(jb.at("inertia"));
    B.I = R * moments.asDiagonal() * R.transpose();
    B.max_moment = moments.cwiseAbs().maxCoeff();
    if (b == 0) {
      B.name = "world";
      continue;
    }
    const std::string mj_name = jb.at("name").get<std::string>();
    B.name = unique(mj_name.empty() ? "body" + std::to_string(plant_bodies) : mj_name);
    ++plant_bodies;
    for (size_t k = 0; k + 1 < B.joints.size(); ++k) {
      B.dummies.push_back(unique(B.name + std::to_string(k)));
      ++plant_bodies;
    }
  }
  for (size_t b = 1; b < r.bodies.size(); ++b) {
    RBody& B = r.bodies[b];
    const std::string parent = r.bodies.at(B.parent).name;
    for (size_t k = 0; k < B.joints.size(); ++k) {
      RJoint& J = r.joints[B.joints[k]];
      J.parent = k == 0 ? parent : B.dummies[k - 1];
      J.child = k + 1 == B.joints.size() ? B.name : B.dummies[k];
      if (J.type == "free") J.name = B.name;
      else if (J.name.empty()) J.name = J.parent + "-" + J.child;
    }
  }
  for (const auto& c : d.at("configs")) {
    RConfig C;
    for (const auto& q : c.at("q")) C.q.emplace_back(q.at(0).get<int>(), q.at(1).get<double>());
    for (size_t b = 0; b < c.at("xpos").size(); ++b) {
      C.X_WB.push_back(Pose(V3(c.at("xpos")[b]), Q4(c.at("xquat")[b])));
    }
    for (const auto& a : c.at("xaxis")) C.xaxis.push_back(V3(a));
    for (const auto& e : c.at("M")) C.M[{e.at(0).get<int>(), e.at(1).get<int>()}] = e.at(2).get<double>();
    r.configs.push_back(std::move(C));
  }
  return r;
}

int NumConfigs() { return std::max(0, EnvInt("MDLC_ORACLE_CONFIGS", 3)); }

// One Node.js process serves every file of a test process (a shard).
json DumpMujoco3(const std::string& file, std::string* problem) {
  static LineServer server(MujocoJsServeCommand(
      "mujoco_dump.mjs", {"--configs", std::to_string(NumConfigs()), "--seed", "1"}));
  return AskForDump(server, "MuJoCo 3.3.8 dump helper", file, 600.0, problem);
}

// ---------------------------------------------------------------------------
// mdlc's plant
// ---------------------------------------------------------------------------

struct Plant {
  json root;
  std::map<std::string, const json*> bodies, joints;  // by local name
  std::map<std::string, int> dof_index;               // local joint name -> row of M
  std::set<std::string> duplicate_names;
  std::string cmdline;
};

std::string LocalOf(const std::string& scoped) {
  const size_t at = scoped.rfind("::");
  return at == std::string::npos ? scoped : scoped.substr(at + 2);
}

// Runs mdlc at configuration q; "" and *plant filled, or why not.
std::string RunMdlc(const std::string& file, const JointValues& q, Plant* plant, RunResult* out) {
  const std::vector<std::string> argv = PlantJsonCommand(file, "", q);
  plant->cmdline = Quote(argv);
  *out = RunProcess(argv, 120.0);
  std::string why = SpawnFailure(*out);
  if (why.empty()) why = ExitFailure(*out, plant->cmdline);
  if (why.empty()) why = ReadPlantJson(*out, plant->cmdline, {"bodies", "joints"}, &plant->root);
  if (!why.empty()) return why;
  for (const auto& b : plant->root["bodies"]) {
    if (!plant->bodies.emplace(b.value("name", ""), &b).second) {
      plant->duplicate_names.insert("body " + b.value("name", ""));
    }
  }
  for (const auto& j : plant->root["joints"]) {
    if (!plant->joints.emplace(j.value("name", ""), &j).second) {
      plant->duplicate_names.insert("joint " + j.value("name", ""));
    }
  }
  if (plant->root.contains("dofs") && plant->root["dofs"].is_array()) {
    for (size_t i = 0; i < plant->root["dofs"].size(); ++i) {
      plant->dof_index[LocalOf(plant->root["dofs"][i].get<std::string>())] = static_cast<int>(i);
    }
  }
  return "";
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

// ---------------------------------------------------------------------------
// Comparison
// ---------------------------------------------------------------------------

// Bodies' mass properties, the body set, joints' static data: configuration 0.
void CompareStatic(const Reference& ref, const Plant& p, Report* rep) {
  for (const auto& dup : p.duplicate_names) rep->Add("plant-json names two entities " + dup);
  std::set<std::string> known;
  for (const RBody& B : ref.bodies) {
    known.insert(B.name);
    known.insert(B.dummies.begin(), B.dummies.end());
  }
  for (const auto& [name, body] : p.bodies) {
    if (!known.count(name)) rep->Add("MJCF-020/023 mdlc's plant has a body '" + name + "' MuJoCo's model lacks");
  }
  for (size_t b = 1; b < ref.bodies.size(); ++b) {
    const RBody& B = ref.bodies[b];
    const std::string ent = "body '" + B.name + "'";
    const auto it = p.bodies.find(B.name);
    if (it == p.bodies.end()) {
      rep->Add("MJCF-020 " + ent + " is missing from mdlc's plant");
      continue;
    }
    for (const auto& dummy : B.dummies) {
      const auto d = p.bodies.find(dummy);
      if (d == p.bodies.end()) {
        rep->Add("MJCF-023 intermediate body '" + dummy + "' is missing from mdlc's plant");
      } else {
        rep->Num("MJCF-023", "intermediate body '" + dummy + "'", "mass",
                 Num(d->second->value("mass", json())), 0.0, kMassTol, 1e-12);
      }
    }
    const json& jb = *it->second;
    rep->Num("MJCF-030/031", ent, "mass", Num(jb.value("mass", json())), B.mass, kMassTol, 1e-12);
    if (B.mass == 0) continue;  // no centre of mass (MuJoCo reports the body origin)
    const json com = jb.value("com", json());
    for (int i = 0; i < 3; ++i) {
      rep->Num("MJCF-030/031", ent, "com[" + std::to_string(i) + "]",
               com.is_array() && com.size() == 3 ? Num(com[i]) : std::nan(""), B.ipos(i), kMassTol);
    }
    const json I = jb.value("inertia", json::array());
    if (!I.is_array() || I.size() != 6) {
      rep->Add("MJCF-030 " + ent + " has no 6-entry inertia");
      continue;
    }
    // entries relative to the largest principal moment
    const double scale = std::max(B.max_moment, 1e-12);
    const int rows[6] = {0, 1, 2, 0, 0, 1}, cols[6] = {0, 1, 2, 1, 2, 2};
    const char* names[6] = {"Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz"};
    for (int k = 0; k < 6; ++k) {
      rep->Num("MJCF-030/031", ent, std::string("inertia.") + names[k], Num(I[k]),
               B.I(rows[k], cols[k]), kMassTol, scale);
    }
  }
  for (const RJoint& J : ref.joints) {
    const std::string ent = "joint '" + J.name + "' (" + J.type + ")";
    if (J.type == "free") {
      bool found = false;
      for (const auto& j : p.root["joints"]) {
        found |= LocalOf(j.value("child", "")) == J.child && j.value("type", "") == "quaternion_floating";
      }
      if (!found) rep->Add("MJCF-021 free body '" + J.child + "' has no quaternion_floating joint in mdlc's plant");
      continue;
    }
    const auto it = p.joints.find(J.name);
    if (it == p.joints.end()) {
      rep->Add("MJCF-022 " + ent + " is missing from mdlc's plant");
      continue;
    }
    const json& jj = *it->second;
    const std::string want = J.type == "hinge" ? "revolute" : J.type == "slide" ? "prismatic" : "ball";
    if (jj.value("type", "") != want) {
      rep->Add("MJCF-022 " + ent + " type: mdlc=" + jj.value("type", "?") + " expected=" + want);
    }
    if (LocalOf(jj.value("parent", "")) != J.parent || LocalOf(jj.value("child", "")) != J.child) {
      rep->Add("MJCF-022/023 " + ent + " joins " + jj.value("parent", "?") + " -> " +
               jj.value("child", "?") + " in mdlc, expected " + J.parent + " -> " + J.child);
    }
    if (!J.Moving()) continue;
    auto limit = [](const json& a, double inf) {
      if (!a.is_array() || a.size() != 1) return std::nan("");
      return a[0].is_null() ? inf : Num(a[0]);
    };
    const double inf = std::numeric_limits<double>::infinity();
    rep->Num("MJCF-004/022", ent, "lower", limit(jj.value("lower", json()), -inf), J.limited ? J.lo : -inf, kKinTol);
    rep->Num("MJCF-004/022", ent, "upper", limit(jj.value("upper", json()), inf), J.limited ? J.hi : inf, kKinTol);
    const json dp = jj.value("default_positions", json::array());
    rep->Num(J.keyed ? "MJCF-008/022" : "MJCF-022", ent,
             J.keyed ? "default_positions[0] (key qpos)" : "default_positions[0] (qpos0)",
             dp.is_array() && dp.size() == 1 ? Num(dp[0]) : std::nan(""), J.q_default, kKinTol);
    if (!p.dof_index.count(J.name)) rep->Add("MJCF-022 " + ent + " is not in plant-json's dofs");
  }
}

// Body poses, joint axes and M(q) at one configuration.
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
  std::vector<const RJoint*> moving;
  for (size_t j = 0; j < ref.joints.size() && j < C.xaxis.size(); ++j) {
    const RJoint& J = ref.joints[j];
    if (!J.Moving()) continue;
    moving.push_back(&J);
    const auto it = p.joints.find(J.name);
    if (it == p.joints.end()) continue;
    const json a = it->second->value("axis_W", json());
    for (int i = 0; i < 3; ++i) {
      rep->Num("MJCF-022", "joint '" + J.name + "'", "axis_W[" + std::to_string(i) + "]",
               a.is_array() && a.size() == 3 ? Num(a[i]) : std::nan(""), C.xaxis[j](i), kKinTol);
    }
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
      rep->Num("MJCF-022/024/031", "M", "(" + moving[x]->name + ", " + moving[y]->name + ")",
               mdlc_entry(moving[x], moving[y]), ref_entry(moving[x], moving[y]), kMassTol,
               std::max(std::sqrt(diag[x] * diag[y]), 1e-300));
    }
  }
}

// A located error (file:line:col: error:) among mdlc's diagnostics.
bool HasLocatedError(const std::string& err) {
  static const std::regex located(R"(:[0-9]+:[0-9]+: error: )");
  return std::regex_search(err, located);
}

// The keyword a warning about each not-held construct names it by.
const char* ConstructKeyword(const std::string& construct) {
  static const std::map<std::string, const char*> kKeywords = {
      {"flex", "flex|deformable"}, {"spatial-tendon", "spatial"}, {"plugin", "plugin|<extension>"},
      {"sdf-geom", "sdf"},         {"skin", "skin"},              {"composite", "composite"}};
  const auto it = kKeywords.find(construct);
  return it == kKeywords.end() ? nullptr : it->second;
}

std::vector<std::string> Constructs(const std::string& outcome) {
  std::vector<std::string> out;
  const size_t colon = outcome.find(':');
  if (colon == std::string::npos) return out;
  std::stringstream ss(outcome.substr(colon + 1));
  for (std::string c; std::getline(ss, c, '+');) out.push_back(c);
  return out;
}

std::string Warnings(const std::string& err) {
  std::string out;
  std::stringstream ss(err);
  for (std::string l; std::getline(ss, l);) {
    if (l.find(": warning: ") != std::string::npos) out += l + "\n";
  }
  return out;
}

// Compiles the file at every configuration of MuJoCo's dump and compares;
// the discrepancies go to *rep. False when mdlc gave no plant (why in *rep).
bool CompareAll(const SuiteCase& sc, const Reference& ref, Report* rep) {
  std::map<std::string, std::string> scoped;  // local joint name -> name for --q
  for (size_t c = 0; c < ref.configs.size(); ++c) {
    const RConfig& C = ref.configs[c];
    JointValues q;
    for (const auto& [j, v] : C.q) {
      const std::string& name = ref.joints.at(j).name;
      q.emplace_back(scoped.count(name) ? scoped[name] : name, v);
    }
    rep->SetContext("config " + std::to_string(c) + ", " + DescribeQ(q, "base state", "joints"));
    Plant plant;
    RunResult run;
    if (const std::string why = RunMdlc(sc.path, q, &plant, &run); !why.empty()) {
      rep->Add(why);
      return c > 0;
    }
    const size_t before = rep->size();
    try {
      if (c == 0) {
        for (const auto& j : plant.root["joints"]) {
          scoped[j.value("name", "")] = j.value("model_instance", "") + "::" + j.value("name", "");
        }
        CompareStatic(ref, plant, rep);
      }
      CompareConfiguration(ref, C, plant, rep);
    } catch (const json::exception& e) {
      rep->Add(std::string("malformed plant-json (") + e.what() + ")");
    }
    if (rep->size() > before) rep->Add("reproduce with: " + plant.cmdline);
  }
  return true;
}

std::string FirstMessages(const Report& rep, size_t n = 3) {
  std::string out;
  for (size_t i = 0; i < rep.messages().size() && i < n; ++i) out += "\n    " + rep.messages()[i];
  return out;
}

// ---------------------------------------------------------------------------
// The test
// ---------------------------------------------------------------------------

class MujocoSuiteOracle : public ::testing::TestWithParam<SuiteCase> {};

TEST_P(MujocoSuiteOracle, MatchesManifest) {
  const SuiteCase& sc = GetParam();
  if (!sc.skip_reason.empty()) GTEST_SKIP() << sc.skip_reason;
  if (const std::string why = MujocoJsUnavailable(); !why.empty()) GTEST_SKIP() << why;
  ASSERT_TRUE(fs::is_regular_file(sc.path))
      << sc.rel << " is in the manifest but not in MDLC_MUJOCO_SUITE_DIR (" << SuiteDir() << ")";

  const bool agree = sc.outcome == "agree";
  const bool rejects = sc.outcome == "mujoco-rejects";
  const bool not_held = sc.outcome.rfind("not-held:", 0) == 0;
  const bool pending = sc.outcome.rfind("pending:", 0) == 0;
  ASSERT_TRUE(agree || rejects || not_held || pending) << "unknown outcome '" << sc.outcome << "'";

  if (not_held) {
    // mdlc must not crash, and when it compiles the file it must say what it
    // leaves out. MuJoCo is not asked: what the plant holds of such a file is
    // not MuJoCo's model (and MuJoCo's own dump of some flex models at random
    // configurations takes minutes).
    const RunResult r = RunProcess(PlantJsonCommand(sc.path, "", {}), 120.0);
    ASSERT_EQ(SpawnFailure(r), "");
    ASSERT_FALSE(r.timed_out) << "[" << sc.rel << "] mdlc timed out";
    ASSERT_TRUE(r.exit_code == 0 || (r.exit_code == 1 && HasLocatedError(r.err)))
        << "[" << sc.rel << "] mdlc exited with status " << r.exit_code << " on a file with "
        << sc.outcome << ":" << ErrorExcerpt(r.err);
    if (r.exit_code == 0) {
      const std::string warnings = Warnings(r.err);
      for (const std::string& c : Constructs(sc.outcome)) {
        const char* keyword = ConstructKeyword(c);
        ASSERT_NE(keyword, nullptr) << "unknown construct '" << c << "'";
        EXPECT_TRUE(std::regex_search(warnings, std::regex(keyword, std::regex::icase)))
            << "[" << sc.rel << "] no warning names the " << c << " the plant leaves out; warnings:\n"
            << warnings;
      }
    }
    std::printf("[ not-held ] %s: %s, mdlc exit %d%s\n", sc.rel.c_str(), sc.outcome.c_str(),
                r.exit_code, r.exit_code ? ErrorExcerpt(r.err).c_str() : "");
    return;
  }

  std::string problem;
  const json dump = DumpMujoco3(sc.path, &problem);
  ASSERT_TRUE(problem.empty()) << "[" << sc.rel << "] MuJoCo 3.3.8 dump failed: " << problem;
  const bool mujoco_loads = dump.value("ok", false);
  if ((agree || pending) && !mujoco_loads) {
    FAIL() << "[" << sc.rel << "] stale manifest row (" << sc.outcome << "): MuJoCo 3.3.8 rejects it: "
           << dump.value("error", std::string("?")) << " (rerun classify.py --write)";
  }

  if (rejects) {
    ASSERT_FALSE(mujoco_loads) << "[" << sc.rel << "] stale manifest row: MuJoCo 3.3.8 now loads it";
    const RunResult r = RunProcess(PlantJsonCommand(sc.path, "", {}), 120.0);
    ASSERT_EQ(SpawnFailure(r), "");
    ASSERT_FALSE(r.timed_out) << "[" << sc.rel << "] mdlc timed out";
    if (r.exit_code == 1) {
      EXPECT_TRUE(HasLocatedError(r.err))
          << "[" << sc.rel << "] mdlc rejects it without a located error:" << ErrorExcerpt(r.err);
      return;
    }
    ASSERT_EQ(r.exit_code, 0) << "[" << sc.rel << "] mdlc crashed (status " << r.exit_code << ")";
    EXPECT_EQ(sc.note.rfind("mdlc may accept it", 0), 0u)
        << "[" << sc.rel << "] MuJoCo 3.3.8 rejects it (" << dump.value("error", std::string("?"))
        << ") and mdlc accepts it, and the manifest does not say why";
    return;
  }

  Reference ref;
  try {
    ref = BuildReference(dump);
  } catch (const json::exception& e) {
    FAIL() << "[" << sc.rel << "] unexpected dump layout: " << e.what();
  }
  Report rep(sc.rel, "mujoco3.3.8");
  const bool compiled = CompareAll(sc, ref, &rep);
  if (agree) {
    if (!rep.empty()) ADD_FAILURE() << rep.Text();
    return;
  }
  const std::string result =
      !compiled ? "mdlc gives no plant:" + FirstMessages(rep, 1)
      : rep.empty()
          ? "agrees with MuJoCo in every compared quantity"
          : std::to_string(rep.size()) + " discrepancies, the first:" + FirstMessages(rep);
  // pending
  if (rep.empty()) {
    std::printf("[ pending ] %s: %s now agrees (once every file using it does, take the construct out of PENDING in classify.py)\n",
                sc.rel.c_str(), sc.outcome.c_str());
    return;
  }
  GTEST_SKIP() << sc.outcome << " (not failed): " << result;
}

INSTANTIATE_TEST_SUITE_P(Suite, MujocoSuiteOracle, ::testing::ValuesIn(SuiteCases()), CaseName());

// The manifest is classify.py's: every outcome is one the test knows, every
// construct one it can look for in mdlc's warnings.
TEST(MujocoSuiteOracleSelfCheck, ManifestOutcomesAreKnown) {
  const auto rows = ReadSuiteManifest();
  ASSERT_FALSE(rows.empty()) << SuiteManifest();
  std::set<std::string> paths;
  for (const auto& cols : rows) {
    ASSERT_GE(cols.size(), 4u) << cols.at(0);
    EXPECT_TRUE(paths.insert(cols[0]).second) << "listed twice: " << cols[0];
    const std::string& o = cols[1];
    if (o == "agree" || o == "mujoco-rejects" || o.rfind("pending:", 0) == 0) continue;
    ASSERT_EQ(o.rfind("not-held:", 0), 0u) << cols[0] << ": " << o;
    for (const std::string& c : Constructs(o)) EXPECT_NE(ConstructKeyword(c), nullptr) << cols[0] << ": " << c;
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ParseMdlcFlag(argc, argv);
  return RUN_ALL_TESTS();
}
