// Differential test: mdlc's rigid-body dynamics (mdlc/dynamics.h) against
// MuJoCo 3.3.8's, on MJCF models.
//
// For every model
//   1. MuJoCo 3.3.8 (the official WebAssembly build, npm mujoco-js 0.0.7, run
//      by Node.js: tests/oracle/mujoco_js/mujoco_dynamics.mjs) loads the file,
//      makes it a plain tree (armature 0; constraints, contacts, limits,
//      equalities and actuation disabled) and, at seeded random states (q, v,
//      vdot, tau), dumps qfrc_bias, mj_rne, mj_fullM, mj_forward's qacc,
//      mj_jacBody of every body, subtree_com and mj_jacSubtreeCom of the
//      world body, and the energy;
//   2. mdlc::Compile compiles the same file in this process; MuJoCo's joints
//      are matched to the plant's by the names Drake's parser gives them
//      (MJCF-020/022/023; a free joint is its body's quaternion_floating
//      joint, MJCF-021), and MuJoCo's coordinates are turned into mdlc's by
//      ToMdlcCoordinates, the one place that knows both conventions;
//   3. mdlc computes the same quantities, which are compared:
//        InverseDynamics (gravity only)          vs mj_rne(flg_acc = 1)
//        BiasTerm - GravityForces                vs qfrc_bias
//        ForwardDynamics (gravity only)          vs qacc, springs/dampers off
//        ForwardDynamics (+ joint_damping,       vs qacc, springs/dampers on,
//          force_elements; MJCF-022, BEYOND-007)    where MuJoCo's passive
//                                                   forces are only those
//        MassMatrix                              vs mj_fullM
//        JacobianSpatialVelocity of each body    vs [jacr; jacp]
//          (origin, measured and expressed in the world)
//        CenterOfMass position and Jacobian      vs subtree_com[0], mj_jacSubtreeCom
//        KineticEnergy, PotentialEnergy          vs energy[1], energy[0]
//        the plant's gravity (MJCF-007)          vs opt.gravity
//      Reflected inertia is off on mdlc's side (MuJoCo's armature is 0).
//      Each quantity agrees when max|mdlc - MuJoCo| <= kDynTol * (1 + max|x|),
//      the max over the vector's or matrix's entries; forward dynamics, a
//      solve, within what cond(M) lets the measured differences of M and of
//      the bias through (see the test). A file that disables gravity
//      (<flag>, which the plant does not hold: MJCF-007) is compared with
//      DynamicsOptions::gravity false, said in a note.
// Per model the output has a summary (its largest relative error per
// quantity, cond(M), why passive forces were not compared) and notes (mdlc's
// warnings). Models whose MuJoCo tree the plant does not hold are listed in
// kNotComparable with the reason: skipped, never silently; a listed model
// the test can compare fails as a stale entry. Files MuJoCo 3.3.8 does not
// load, and models without degrees of freedom, are skipped with the reason.
//
// Configuration (all optional):
//   env MDLC_NODE                   Node.js (default: found by CMake)
//   env MDLC_DYNAMICS_STATES=N      random states per model (default 5)
// Without Node.js or the installed mujoco-js package (tools/setup.sh test runs
// `npm ci` in tests/oracle/mujoco_js) every case reports itself skipped; the
// corpus cases skip without ../shared.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "mdlc/dynamics.h"
#include "mdlc/kinematics.h"
#include "mdlc/mdlc.h"
#include "mujoco_reference.h"
#include "oracle_util.h"

namespace {

namespace fs = std::filesystem;
using namespace mdlc::oracle;
using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using Eigen::VectorXd;
using json = nlohmann::json;

// Relative to 1 + the largest entry: both sides do the same arithmetic in
// double precision in a different order.
constexpr double kDynTol = 1e-8;
// The relative accuracy of M and the forces forward dynamics starts from
// (both sides agree to about 1e-15 on them), which a solve magnifies by up to
// cond(M).
constexpr double kSolveEps = 1e-14;

// ---------------------------------------------------------------------------
// Models
// ---------------------------------------------------------------------------

struct NotComparable {
  const char* path;    // relative to corpus/, or tests/models/mjcf/oracle/<file>
  const char* reason;
};

// Files whose dynamics cannot be compared, and why.
const std::vector<NotComparable> kNotComparable = {};

const char* NotComparableReason(const std::string& key) {
  for (const auto& n : kNotComparable) {
    if (key == n.path) return n.reason;
  }
  return nullptr;
}

struct ModelCase {
  std::string id;       // gtest parameter name
  std::string path;     // absolute
  std::string display;  // corpus/<path>, tests/models/mjcf/oracle/<file>
  std::string listed;   // kNotComparable reason
  std::string skip_reason;
};

void PrintTo(const ModelCase& c, std::ostream* os) { *os << c.display; }

std::vector<ModelCase> CorpusCases() {
  return ManifestCases<ModelCase>(
      "shared corpus not found (corpus/manifest.tsv under MDLC_SHARED_DIR)",
      [](const std::vector<std::string>& cols) -> std::optional<ModelCase> {
        if (cols.size() < 2 || cols[0] != "mjcf") return std::nullopt;
        ModelCase c;
        c.id = Sanitize(WithoutSuffix(cols[1], ".xml"));
        c.path = (CorpusDir() / cols[1]).string();
        c.display = "corpus/" + cols[1];
        if (const char* r = NotComparableReason(cols[1])) c.listed = r;
        return c;
      });
}

std::vector<ModelCase> HandMadeCases() {
  return FolderCases<ModelCase>(
      TestModels("mjcf/oracle"), ".xml", "no MJCF models in tests/models/mjcf/oracle",
      [](const fs::path& f) {
        ModelCase c;
        c.id = Sanitize(f.stem().string());
        c.path = f.string();
        c.display = "tests/models/mjcf/oracle/" + f.filename().string();
        if (const char* r = NotComparableReason(c.display)) c.listed = r;
        return c;
      });
}

// ---------------------------------------------------------------------------
// MuJoCo's side
// ---------------------------------------------------------------------------

// The dump of one file, from one Node.js process per test process.
json DumpDynamics(const std::string& file, std::string* problem) {
  static LineServer server(MujocoJsServeCommand(
      "mujoco_dynamics.mjs",
      {"--states", std::to_string(std::max(1, EnvInt("MDLC_DYNAMICS_STATES", 5))), "--seed", "1"}));
  return AskForDump(server, "MuJoCo 3.3.8 dynamics helper", file, 120.0, problem);
}

VectorXd Vec(const json& a) {
  VectorXd v(static_cast<Eigen::Index>(a.size()));
  for (size_t i = 0; i < a.size(); ++i) v(static_cast<Eigen::Index>(i)) = a[i].get<double>();
  return v;
}

// A row-major rows x cols matrix from a flat array.
MatrixXd Mat(const json& a, int rows, int cols) {
  MatrixXd m(rows, cols);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) m(r, c) = a.at(static_cast<size_t>(r * cols + c)).get<double>();
  }
  return m;
}

// ---------------------------------------------------------------------------
// Matching MuJoCo's joints and bodies to the plant's
// ---------------------------------------------------------------------------

struct MjJoint {
  std::string type;  // free ball slide hinge
  int qposadr = 0, dofadr = 0;
  std::string plant_name;  // Drake's name for it
  const mdlc::backend::PlantJoint* plant = nullptr;
};

struct Matching {
  std::vector<MjJoint> joints;               // by MuJoCo joint id
  std::vector<std::string> body_names;       // by MuJoCo body id, Drake's names
  std::vector<mdlc::BodyId> body_ids;        // the plant's bodies (invalid: none)
  std::vector<std::string> problems;         // what could not be matched
};

// Drake's names for MuJoCo's bodies and joints, as mujoco_oracle_test.cc
// derives them (mujoco_reference.h): an unnamed body is body<N>, N the
// plant's body count when it is made; a body with k > 1 joints gets k-1
// massless bodies <body>0, ... before it (MJCF-023); an unnamed joint is
// <parent>-<child>; a free joint takes its body's name.
Matching MatchToPlant(const json& dump, const mdlc::backend::Plant& plant) {
  Matching mt;
  const json& bodies = dump.at("bodies");
  const json& joints = dump.at("joints");
  const mdlc::oracle::mujoco::DrakeNames names = mdlc::oracle::mujoco::NameAsDrake(dump);
  mt.body_names = names.bodies;
  mt.joints.resize(joints.size());
  for (size_t j = 0; j < joints.size(); ++j) {
    MjJoint& J = mt.joints[j];
    J.type = joints[j].at("type").get<std::string>();
    J.qposadr = joints[j].at("qposadr").get<int>();
    J.dofadr = joints[j].at("dofadr").get<int>();
    J.plant_name = names.joints[j];
  }
  // the plant's joints and bodies by local name (names are unique within the
  // one model instance an MJCF file makes)
  std::map<std::string, std::vector<const mdlc::backend::PlantJoint*>> plant_joints;
  for (const auto& j : plant.joints) plant_joints[j.name].push_back(&j);
  std::map<std::string, std::vector<mdlc::BodyId>> plant_bodies_by_name;
  for (size_t b = 0; b < plant.bodies.size(); ++b) {
    if (!plant.bodies[b].is_world) plant_bodies_by_name[plant.bodies[b].name].emplace_back(b);
  }
  const auto expected_type = [](const std::string& t) {
    using mdlc::ir::JointType;
    return t == "free" ? JointType::QuaternionFloating : t == "ball" ? JointType::Ball
         : t == "slide" ? JointType::Prismatic : JointType::Revolute;
  };
  std::set<const mdlc::backend::PlantJoint*> used;
  for (MjJoint& J : mt.joints) {
    const auto it = plant_joints.find(J.plant_name);
    if (it == plant_joints.end() || it->second.size() != 1) {
      mt.problems.push_back("MuJoCo's " + J.type + " joint '" + J.plant_name + "' has " +
                            (it == plant_joints.end() ? "no" : "more than one") +
                            " plant joint of that name");
      continue;
    }
    J.plant = it->second.front();
    used.insert(J.plant);
    if (J.plant->type != expected_type(J.type)) {
      mt.problems.push_back("plant joint '" + J.plant_name + "' is not of the type MuJoCo's " +
                            J.type + " joint maps to");
      J.plant = nullptr;
    }
  }
  for (const auto& j : plant.joints) {
    if (j.nv > 0 && !used.count(&j)) {
      mt.problems.push_back("plant joint '" + j.name + "' (" + std::to_string(j.nv) +
                            " velocities) has no MuJoCo joint");
    }
  }
  mt.body_ids.assign(bodies.size(), mdlc::BodyId(size_t{0}));
  for (size_t b = 1; b < bodies.size(); ++b) {
    const auto it = plant_bodies_by_name.find(mt.body_names[b]);
    if (it == plant_bodies_by_name.end() || it->second.size() != 1) {
      mt.problems.push_back("MuJoCo's body '" + mt.body_names[b] + "' has " +
                            (it == plant_bodies_by_name.end() ? "no" : "more than one") +
                            " plant body of that name");
      continue;
    }
    mt.body_ids[b] = it->second.front();
  }
  return mt;
}

// ---------------------------------------------------------------------------
// MuJoCo's coordinates -> mdlc's
// ---------------------------------------------------------------------------

struct MdlcCoordinates {
  VectorXd q;  // mdlc's positions
  // v_mdlc = T * qvel_mujoco. T is orthogonal (a permutation of the joints'
  // blocks with rotations on the rotational ones), so the same T maps
  // accelerations and generalized forces (power tau . v is kept:
  // tau_mdlc = T^-T tau_mujoco = T tau_mujoco), a Jacobian's columns
  // (J_mdlc = J_mujoco T^T) and the mass matrix (M_mdlc = T M_mujoco T^T).
  MatrixXd T;
};

// The one conversion between MuJoCo's and mdlc's coordinates, per joint:
//   hinge, slide  q and v as they are (MJCF-022: the body is placed so that
//                 q = ref reproduces the XML pose, in both);
//   ball          MuJoCo: qpos the unit quaternion q_FM [w x y z], qvel
//                 w_FM expressed in M (the child's frame). mdlc: q the
//                 roll-pitch-yaw of R_FM, v = w_FM expressed in F = R_FM w_M;
//   free          MuJoCo: qpos [p_WB (3), q_WB (w x y z)], qvel [v_WBo in W
//                 (3), w_WB in B (3)]. mdlc (quaternion_floating, F = W,
//                 M = B): q [q_WB, p_WB], v [R_WB w_B; v_WBo].
// For accelerations the same rotation applies: d/dt(R w_B) = R (w_B x w_B) +
// R wdot_B = R wdot_B, and a free body's linear qacc is d^2 p/dt^2 in both.
// The plant's joint frames must be what that assumes (a free joint from the
// world to its body's frame, a ball joint's M without rotation in its
// body); *problem says when not.
MdlcCoordinates ToMdlcCoordinates(const mdlc::backend::Plant& plant, const Matching& mt,
                                  const VectorXd& qpos, int nv_mujoco, std::string* problem) {
  MdlcCoordinates c;
  c.q = VectorXd::Zero(plant.num_positions);
  c.T = MatrixXd::Zero(plant.num_velocities, nv_mujoco);
  const auto is_identity = [](const mdlc::Transform& X) {
    return (X.R - Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-12 && X.p.norm() < 1e-12;
  };
  for (const MjJoint& J : mt.joints) {
    const auto& P = *J.plant;
    const int qa = J.qposadr, d = J.dofadr;
    if (J.type == "hinge" || J.type == "slide") {
      c.q(P.q_start) = qpos(qa);
      c.T(P.v_start, d) = 1;
    } else if (J.type == "ball") {
      if (!J.plant->X_CM.R.isIdentity(1e-12)) {
        *problem = "ball joint '" + J.plant_name + "': X_CM has a rotation (not mapped)";
      }
      const Matrix3d R_FM =
          Quaterniond(qpos(qa), qpos(qa + 1), qpos(qa + 2), qpos(qa + 3)).normalized().toRotationMatrix();
      c.q.segment<3>(P.q_start) = mdlc::RpyFromRotation(R_FM);
      c.T.block<3, 3>(P.v_start, d) = R_FM;
    } else {  // free
      if (!is_identity(P.X_PF) || !is_identity(P.X_CM) || !plant.body(P.parent).is_world) {
        *problem = "free joint '" + J.plant_name + "': not from the world frame to its body's frame";
      }
      const Quaterniond q_WB(qpos(qa + 3), qpos(qa + 4), qpos(qa + 5), qpos(qa + 6));
      c.q.segment<4>(P.q_start) << q_WB.w(), q_WB.x(), q_WB.y(), q_WB.z();
      c.q.segment<3>(P.q_start + 4) = qpos.segment<3>(qa);
      c.T.block<3, 3>(P.v_start, d + 3) = q_WB.normalized().toRotationMatrix();
      c.T.block<3, 3>(P.v_start + 3, d) = Matrix3d::Identity();
    }
  }
  return c;
}

// ---------------------------------------------------------------------------
// Comparison
// ---------------------------------------------------------------------------

// max|a - b| / (1 + max(|a|, |b|)) over the entries; reports it above `tol`
// with the worst entry.
double Compare(Report* rep, WorstErrors* worst, const std::string& feature,
               const std::string& what, const MatrixXd& mdlc_value, const MatrixXd& ref,
               double tol = kDynTol) {
  if (mdlc_value.rows() != ref.rows() || mdlc_value.cols() != ref.cols()) {
    rep->Add(feature + " " + what + ": mdlc is " + std::to_string(mdlc_value.rows()) + "x" +
             std::to_string(mdlc_value.cols()) + ", MuJoCo " + std::to_string(ref.rows()) + "x" +
             std::to_string(ref.cols()));
    return INFINITY;
  }
  if (ref.size() == 0) return 0;
  const double scale = 1 + std::max(MaxAbs(mdlc_value), MaxAbs(ref));
  Eigen::Index r = 0, c = 0;
  const double err = (mdlc_value - ref).cwiseAbs().maxCoeff(&r, &c);
  const double rel = std::isnan(err) ? INFINITY : err / scale;
  RecordWorst(worst, what, rel);
  if (rel <= tol) return rel;
  rep->Add(feature + " " + what + ": max|mdlc - mujoco| / (1 + max|x|) = " + Fmt(rel) +
           ", worst at (" + std::to_string(r) + "," + std::to_string(c) + "): mdlc=" +
           Fmt(mdlc_value(r, c)) + " mujoco3.3.8=" + Fmt(ref(r, c)));
  return rel;
}

void CompareScalar(Report* rep, WorstErrors* worst, const std::string& feature,
                   const std::string& what, double mdlc_value, double ref, double tol = kDynTol) {
  Compare(rep, worst, feature, what, MatrixXd::Constant(1, 1, mdlc_value),
          MatrixXd::Constant(1, 1, ref), tol);
}

std::string DescribeState(const mdlc::backend::Plant& plant, const VectorXd& q) {
  std::string s = "q:";
  for (Eigen::Index i = 0; i < q.size() && i < 6; ++i) s += " " + Fmt(q(i));
  if (q.size() > 6) s += " ...(" + std::to_string(plant.num_positions) + ")";
  return s;
}

class MujocoDynamics : public ::testing::TestWithParam<ModelCase> {};

TEST_P(MujocoDynamics, DynamicsMatch) {
  const ModelCase& mc = GetParam();
  if (const std::string why = mdlc::oracle::mujoco::MujocoSkipReason(mc.skip_reason); !why.empty()) {
    GTEST_SKIP() << why;
  }

  std::string problem;
  const json dump = DumpDynamics(mc.path, &problem);
  ASSERT_TRUE(problem.empty()) << "[" << mc.display << "] " << problem;
  if (!dump.value("ok", false)) {
    GTEST_SKIP() << "MuJoCo 3.3.8 does not load " << mc.display << " ("
                 << dump.value("error", std::string("?")).substr(0, 300)
                 << "); nothing to compare with (mujoco_oracle_test covers the file)";
  }

  mdlc::Options options;
  options.meshes.reader = mdlc::MeshReader::InProcess;
  if (const char* cache = std::getenv("MDLC_CACHE_DIR"); cache && *cache) {
    options.meshes.cache_dir = cache;
  }
  const mdlc::Result result = mdlc::Compile({mdlc::Input::File(mc.path)}, options);
  if (!result.has_model()) {
    std::string diags;
    for (const auto& d : result.diagnostics()) {
      if (d.severity == mdlc::Severity::Error && diags.size() < 2000) diags += result.FormatText(d);
    }
    if (!mc.listed.empty()) GTEST_SKIP() << "not comparable: " << mc.listed;
    FAIL() << "[" << mc.display << "] mdlc does not compile a file MuJoCo 3.3.8 loads:\n" << diags;
  }
  const mdlc::backend::Plant& plant = result.plant();
  const int nv = dump.at("nv").get<int>();
  // mdlc's warnings about what could bear on the dynamics (what the plant
  // does not hold of MuJoCo's model: MJCF-007/024, BEYOND-005/007, ...) go
  // to the output; the comparison below says whether they matter here.
  {
    static const char* const kDynamicsWords[] = {
        "tendon", "armature", "gravcomp", "equality", "composite", "attach", "flex",
        "density", "viscosity", "<flag>", "stiffness", "damping", "frictionloss", "inertia",
        "mass"};
    // one of each kind: the message with its quoted names and numbers blanked
    const std::regex names("'[^']*'|[0-9.]+");
    std::set<std::string> shown;
    for (const auto& d : result.diagnostics()) {
      if (d.severity != mdlc::Severity::Warning || shown.size() >= 4) continue;
      for (const char* word : kDynamicsWords) {
        if (d.message.find(word) == std::string::npos) continue;
        if (shown.insert(std::regex_replace(d.message, names, "_")).second) {
          std::printf("[ note ] %s: mdlc warns: %s\n", mc.display.c_str(), d.message.c_str());
        }
        break;
      }
    }
  }

  const Matching mt = MatchToPlant(dump, plant);
  std::vector<std::string> mapping = mt.problems;
  if (plant.num_velocities != nv) {
    mapping.push_back("the plant has " + std::to_string(plant.num_velocities) +
                      " velocities, MuJoCo " + std::to_string(nv));
  }
  if (!mc.listed.empty()) {
    if (!mapping.empty()) {
      GTEST_SKIP() << "not comparable: " << mc.listed << " (" << mapping.front() << ")";
    }
    ADD_FAILURE() << "[" << mc.display << "] stale kNotComparable entry: the plant now holds "
                  << "MuJoCo's tree (listed because: " << mc.listed << ")";
  }
  if (!mapping.empty()) {
    std::string text;
    for (const auto& p : mapping) text += "\n  " + p;
    FAIL() << "[" << mc.display << "] the plant does not hold MuJoCo's tree (MJCF-020..023):"
           << text;
  }
  if (nv == 0) GTEST_SKIP() << mc.display << " has no degrees of freedom: no dynamics to compare";

  Report rep(mc.display, "mujoco3.3.8");
  WorstErrors worst;
  Compare(&rep, &worst, "MJCF-007", "gravity", plant.gravity, Vec(dump.at("gravity")));

  const bool passive = dump.at("passive").at("compared").get<bool>();
  mdlc::DynamicsOptions rigid;  // gravity only
  rigid.reflected_inertia = false;
  // MJCF-007: <flag gravity="disable"/> is warned about, not held: the plant
  // keeps <option gravity>. MuJoCo then has none, so neither has mdlc here.
  constexpr int kMjDisableGravity = 128;  // mjDSBL_GRAVITY
  if (dump.at("disableflags").get<int>() & kMjDisableGravity) {
    rigid.gravity = false;
    std::printf("[ note ] %s: the file disables gravity (<flag gravity=\"disable\"/>, which the "
                "plant does not hold, MJCF-007): compared with DynamicsOptions::gravity false\n",
                mc.display.c_str());
  }
  mdlc::DynamicsOptions with_passive = rigid;
  with_passive.joint_damping = true;
  with_passive.force_elements = true;
  const json& jac_bodies = dump.at("jac_bodies");
  int states = 0;
  double worst_cond = 0;
  for (const json& st : dump.at("states")) {
    const VectorXd qpos = Vec(st.at("qpos"));
    std::string convention;
    const MdlcCoordinates c = ToMdlcCoordinates(plant, mt, qpos, nv, &convention);
    if (!convention.empty()) FAIL() << "[" << mc.display << "] " << convention;
    const MatrixXd& T = c.T;
    const VectorXd& q = c.q;
    const VectorXd v = T * Vec(st.at("qvel"));
    const VectorXd vdot = T * Vec(st.at("qacc"));
    const VectorXd tau = T * Vec(st.at("tau"));
    rep.SetContext("state " + std::to_string(states) + ", " + DescribeState(plant, q));
    try {
      const VectorXd id = mdlc::InverseDynamics(result, q, v, vdot, rigid);
      const VectorXd rne = T * Vec(st.at("rne"));
      Compare(&rep, &worst, "", "InverseDynamics vs mj_rne", id, rne);
      const VectorXd bias = mdlc::BiasTerm(result, q, v) -
                            (rigid.gravity ? mdlc::GravityForces(result, q) : VectorXd::Zero(nv));
      const VectorXd bias_ref = T * Vec(st.at("bias"));
      Compare(&rep, &worst, "", "BiasTerm-GravityForces vs qfrc_bias", bias, bias_ref);
      const MatrixXd M = mdlc::MassMatrix(result, q);
      // |dM| / |M|: from the matrices when dumped, and as M vdot (inverse
      // dynamics less the bias) either way
      const auto rel = [](const MatrixXd& a, const MatrixXd& b) {
        const double scale = b.cwiseAbs().maxCoeff();
        return scale > 0 ? (a - b).cwiseAbs().maxCoeff() / scale : 0.0;
      };
      double M_rel = rel(id - bias, rne - bias_ref);
      if (st.contains("M")) {
        const MatrixXd M_ref = T * Mat(st.at("M"), nv, nv) * T.transpose();
        Compare(&rep, &worst, "MJCF-022/024", "MassMatrix vs mj_fullM", M, M_ref);
        M_rel = std::max(M_rel, rel(M, M_ref));
      }
      // vdot = M^-1 (tau - C v + tau_g + ...) is only as close as M's
      // condition lets the inputs' differences through: to first order
      // |d vdot| / |vdot| <= cond(M) (|dM| / |M| + |d rhs| / |rhs|). The
      // tolerance is that bound, from the differences just measured (and
      // kSolveEps for the solves themselves), with a factor 4 for the norms
      // mixed (rcond estimates the 1-norm condition; the errors are max-norm).
      const double cond = [&] {
        const double rcond = Eigen::LDLT<MatrixXd>(M).rcond();
        return rcond > 0 ? 1 / rcond : INFINITY;
      }();
      worst_cond = std::max(worst_cond, cond);
      const double rhs_rel = rel(tau - bias, tau - bias_ref);
      const double fd_tol = kDynTol + 4 * cond * (kSolveEps + M_rel + rhs_rel);
      Compare(&rep, &worst, "", "ForwardDynamics vs qacc (springs and dampers off)",
              mdlc::ForwardDynamics(result, q, v, tau, rigid), T * Vec(st.at("qacc_fwd")), fd_tol);
      if (passive) {
        Compare(&rep, &worst, "MJCF-022 BEYOND-007",
                "ForwardDynamics(damping,springs) vs qacc (springs and dampers on)",
                mdlc::ForwardDynamics(result, q, v, tau, with_passive),
                T * Vec(st.at("qacc_passive")), fd_tol);
        CompareScalar(&rep, &worst, "BEYOND-007", "PotentialEnergy(springs) vs energy[0]",
                      mdlc::PotentialEnergy(result, q, with_passive),
                      st.at("energy_passive").at(0).get<double>());
      }
      // MuJoCo's own: nothing passive in the run with springs and dampers off
      CompareScalar(&rep, &worst, "", "qfrc_passive(off) vs 0", st.at("passive_norm").get<double>(), 0);
      CompareScalar(&rep, &worst, "", "KineticEnergy vs energy[1]",
                    mdlc::KineticEnergy(result, q, v, rigid), st.at("energy").at(1).get<double>());
      CompareScalar(&rep, &worst, "", "PotentialEnergy vs energy[0]",
                    mdlc::PotentialEnergy(result, q, rigid), st.at("energy").at(0).get<double>());
      const mdlc::backend::CenterOfMass com = mdlc::CenterOfMass(result, q, v);
      Compare(&rep, &worst, "", "CenterOfMass.position vs subtree_com[0]", com.position,
              Vec(st.at("com")));
      Compare(&rep, &worst, "", "CenterOfMass.jacobian vs mj_jacSubtreeCom",
              com.jacobian, Mat(st.at("jac_com"), 3, nv) * T.transpose());
      {
        // by BodyId: mdlc::JacobianSpatialVelocity's names cannot tell a body
        // from an MJCF site of the same name
        const mdlc::backend::BodyFixedFrame world{mdlc::BodyId(size_t{0})};
        for (size_t k = 0; k < jac_bodies.size(); ++k) {
          const size_t b = jac_bodies[k].get<size_t>();
          MatrixXd ref(6, nv);
          ref << Mat(st.at("jacr")[k], 3, nv), Mat(st.at("jacp")[k], 3, nv);
          Compare(&rep, &worst, "", "JacobianSpatialVelocity of body '" + mt.body_names.at(b) +
                                        "' vs [mj_jacBody jacr; jacp]",
                  mdlc::backend::JacobianSpatialVelocity(
                      plant, q, mdlc::backend::BodyFixedFrame{mt.body_ids.at(b)},
                      Vector3d::Zero(), world, world),
                  ref * T.transpose());
        }
      }
    } catch (const std::exception& e) {
      rep.Add(std::string("mdlc threw: ") + e.what());
    }
    ++states;
  }
  std::string summary;
  for (const auto& [what, err] : worst) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1e", err);
    summary += "\n    " + what + " " + buf;
  }
  std::printf("[ dynamics ] %s: nv=%d, %d states, cond(M) up to %.1e%s%s; largest relative "
              "errors:%s\n",
              mc.display.c_str(), nv, states, worst_cond,
              passive ? "" : ", passive forces not compared (",
              passive ? "" : (dump.at("passive").value("reason", std::string("?")) + ")").c_str(),
              summary.c_str());
  if (!dump.at("states").empty() && !dump.at("states")[0].contains("M")) {
    std::printf("[ dynamics ] %s: nv=%d is above the dump's --max-full: the mass matrix is "
                "compared through mj_rne and mj_forward only, and the Jacobians of %zu of the "
                "%zu bodies\n",
                mc.display.c_str(), nv, jac_bodies.size(), dump.at("bodies").size() - 1);
  }
  if (rep.size() > 0) ADD_FAILURE() << rep.Text();
}

INSTANTIATE_TEST_SUITE_P(Corpus, MujocoDynamics, ::testing::ValuesIn(CorpusCases()), CaseName());
INSTANTIATE_TEST_SUITE_P(HandMade, MujocoDynamics, ::testing::ValuesIn(HandMadeCases()),
                         CaseName());

// Every kNotComparable entry names a model the test runs.
TEST(MujocoDynamicsSelfCheck, NotComparableNamesModels) {
  const std::set<std::string> keys = ListingKeys(CorpusCases(), HandMadeCases());
  if (keys.size() <= 1) GTEST_SKIP() << "shared corpus not found";
  for (const auto& n : kNotComparable) EXPECT_TRUE(keys.count(n.path)) << n.path;
}

}  // namespace
