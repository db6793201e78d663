// mujoco_reference.h - what the MuJoCo 3.3.8 oracles share: the reference
// model read from MuJoCo's dump (tests/oracle/mujoco_js/mujoco_dump.mjs), with
// the names Drake's parser gives MuJoCo's bodies and joints; mdlc's plant read
// from `mdlc compile --emit=plant-json`; and the comparisons of the two, body
// by body and joint by joint, with their tolerances. Used by
// mujoco_oracle_test.cc (hand-made and corpus models), mujoco_suite_oracle_test.cc
// (MuJoCo's own test files) and, for the naming, mujoco_dynamics_oracle_test.cc.
//
// Naming (MJCF-020/022/023, Drake's detail_mujoco_parser.cc): a body MuJoCo
// leaves unnamed is `body<N>`, N the plant's body count when the body is
// created (the world, every earlier body, and the massless intermediate
// bodies of earlier bodies); a body with k > 1 joints gets k-1 intermediate
// bodies `<body>0`, `<body>1`, ... between its parent and itself, joint i
// joining the (i-1)th to the ith; an unnamed joint is `<parent>-<child>` of
// those plant bodies; a free joint is the body's `quaternion_floating` joint
// (its MJCF name is not used). Drake's scheme can name two bodies alike
// (test/user/testdata/auto_limits.xml: a first body with six joints has
// intermediate bodies body10 ... body14, and the third, unnamed, body is the
// plant's 13th, body13 again): mdlc keeps the first and calls a later one
// `<name>_<k>` with the smallest free k, and so does the reference.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "oracle_util.h"

namespace mdlc::oracle::mujoco {

/// Poses, axes, limits and default positions: the same chain of
/// double-precision rotations and translations on both sides (they agree to
/// about 1e-15).
constexpr double kKinTol = 1e-9;
/// Mass properties, M(q), geometry sizes, mesh poses: MuJoCo re-diagonalises
/// every inertia (mjuu_eig3) and keeps mesh vertices in single precision.
constexpr double kMassTol = 1e-6;
/// Joint damping and stiffness, actuator gains: as given, or derived from the
/// inertia at qpos0 (springdamper, dampratio).
constexpr double kGainTol = 1e-9;

// ---------------------------------------------------------------------------
// JSON helpers
// ---------------------------------------------------------------------------

Eigen::Vector3d V3(const nlohmann::json& a);
/// A quaternion w x y z, normalized.
Eigen::Quaterniond Q4(const nlohmann::json& a);
Eigen::Isometry3d Pose(const Eigen::Vector3d& p, const Eigen::Quaterniond& q);
/// The number, or NaN for anything else.
double Num(const nlohmann::json& v);
/// plant-json's {"p": [...], "q": [...]}; false when unreadable.
bool ReadPose(const nlohmann::json& X, Eigen::Isometry3d* out);
/// "instance::name" -> "name".
std::string LocalOf(const std::string& scoped);

// ---------------------------------------------------------------------------
// Drake's names for MuJoCo's bodies and joints
// ---------------------------------------------------------------------------

struct DrakeNames {
  std::vector<std::string> bodies;                // by MuJoCo body id (0: "world")
  std::vector<std::vector<std::string>> dummies;  // intermediate bodies before each body
  std::vector<std::vector<int>> body_joints;      // MuJoCo joint ids of each body, in order
  std::vector<std::string> joints;                // by MuJoCo joint id
  std::vector<std::string> parents, children;     // each joint's plant bodies
};

/// The names, from a dump's "bodies" (name, parent) and "joints" (name, type,
/// body).
DrakeNames NameAsDrake(const nlohmann::json& dump);

// ---------------------------------------------------------------------------
// The reference model, from a MuJoCo dump
// ---------------------------------------------------------------------------

struct RBody {
  std::string name;                  // Drake's plant name
  int parent = 0;
  std::vector<int> joints;           // MuJoCo joint ids, in order
  std::vector<std::string> dummies;  // intermediate bodies before it
  double mass = 0;
  Eigen::Vector3d ipos = Eigen::Vector3d::Zero();
  Eigen::Matrix3d I = Eigen::Matrix3d::Zero();  // about the COM, in the body frame
  double max_moment = 0;
};

struct RJoint {
  std::string name, type;  // MuJoCo type: free ball slide hinge
  int body = 0, dof = 0;
  std::string parent, child;  // plant body names
  bool limited = false;
  double lo = 0, hi = 0, armature = 0;
  /// the default position: the applied key's qpos (MJCF-008) when the dump
  /// has a key, else qpos0; all of the joint's values (free 7, ball 4, else 1)
  double qpos0 = 0;
  std::vector<double> q_default;
  bool keyed = false;
  /// jnt_stiffness, qpos_spring (hinge, slide) and dof_damping, when the
  /// dump has them (MuJoCo 3.3.8's)
  bool has_gains = false;
  double stiffness = 0, springref = 0;
  std::vector<double> damping;
  bool Moving() const { return type == "hinge" || type == "slide"; }
};

struct RActuator {
  std::string name, trntype, gaintype, biastype;
  int trnid = -1;
  double gainprm[3] = {0, 0, 0}, biasprm[3] = {0, 0, 0};
};

struct RGeom {
  std::string name, body, type;  // type: MuJoCo's
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  int contype = 1, conaffinity = 1, group = 0;
  bool has_mesh_offset = false;
  Eigen::Isometry3d X_mesh = Eigen::Isometry3d::Identity();  // mesh_pos/mesh_quat
  std::optional<Eigen::Vector3d> mesh_scale;
  bool Registered() const { return type != "hfield" && type != "sdf"; }
};

struct RConfig {
  std::vector<std::pair<int, double>> q;  // MuJoCo joint id -> value
  std::vector<Eigen::Isometry3d> X_WB;
  std::vector<Eigen::Vector3d> xaxis;
  std::vector<Eigen::Isometry3d> X_WG;
  std::map<std::pair<int, int>, double> M;  // (dof_i, dof_j), i >= j, with armature
};

struct Reference {
  std::string version;
  std::vector<RBody> bodies;
  std::vector<RJoint> joints;
  std::vector<RGeom> geoms;
  std::vector<RConfig> configs;
  std::vector<RActuator> actuators;  // MuJoCo 3.3.8 dumps only
  /// kg m^2: inertia and M entries this close agree (MuJoCo's own residual on
  /// a few meshes; 0 unless the test sets it)
  double inertia_floor = 0;
};

/// Builds the reference from one dump line (ok == true); throws
/// nlohmann::json::exception on an unexpected layout.
Reference BuildReference(const nlohmann::json& d);

/// env MDLC_ORACLE_CONFIGS: random configurations per file (default 3).
int NumConfigs();

/// MuJoCo 3.3.8's dump of one file (NumConfigs() seeded configurations), from
/// one Node.js process that serves every file this test process dumps
/// (starting it is most of a file's cost); an error in *problem.
nlohmann::json DumpMujoco3(const std::string& file, std::string* problem);

// ---------------------------------------------------------------------------
// mdlc's plant
// ---------------------------------------------------------------------------

struct Plant {
  nlohmann::json root;
  std::map<std::string, const nlohmann::json*> bodies;       // local name (world: "world")
  std::map<std::string, const nlohmann::json*> joints;       // local name
  std::multimap<std::string, const nlohmann::json*> geoms;   // "body|name", body scoped -> local
  std::map<std::string, int> dof_index;  // local joint name -> row of mass_matrix
  std::set<std::string> duplicate_names;
  std::string cmdline;
};

struct MdlcRun {
  RunResult result;
  bool ok = false;  // exit 0 and a readable dump
  std::string problem;
};

/// Runs `mdlc compile FILE --emit=plant-json` at configuration q (with
/// `extra` arguments) and indexes the plant; plant-json must hold the
/// top-level arrays `sections`.
MdlcRun RunMdlcPlant(const std::string& file, const JointValues& q, Plant* plant,
                     const std::vector<std::string>& extra = {},
                     const std::vector<std::string>& sections = {"bodies", "joints"});

/// The configuration's values for --q, each joint by the name given in
/// `scoped` (ScopedJointNames of configuration 0's plant) when it has one.
JointValues ConfigurationQ(const Reference& ref, const RConfig& C,
                           const std::map<std::string, std::string>& scoped);

/// local joint name -> "instance::name", for --q.
std::map<std::string, std::string> ScopedJointNames(const Plant& p);

/// A located error (file:line:col: error:) among mdlc's diagnostics.
bool HasLocatedError(const std::string& err);

/// Why a test case is skipped: its own reason, else why MuJoCo 3.3.8 cannot
/// run (MujocoJsUnavailable); "" when it runs.
std::string MujocoSkipReason(const std::string& case_reason);

// ---------------------------------------------------------------------------
// Comparison
// ---------------------------------------------------------------------------

/// What CompareStatic checks beyond bodies (MJCF-020/023/030/031) and joints'
/// type, bodies, limits and default position (MJCF-004/008/021/022).
struct StaticChecks {
  bool joint_gains = false;        // MJCF-022/BEYOND-007 damping, stiffness, springref; BEYOND-008 servos
  bool keyed_rotations = false;    // MJCF-008 a ball or free joint's default from the key
  bool reflected_inertia = false;  // MJCF-024 0 or the armature
};

/// Three entries, "what[i]".
void CompareVec(Report* rep, const std::string& feature, const std::string& ent,
                const std::string& what, const Eigen::Vector3d& mdlc, const Eigen::Vector3d& ref,
                double tol);

/// Mass properties, the body set and joints' static data: configuration 0.
void CompareStatic(const Reference& ref, const Plant& p, const StaticChecks& checks, Report* rep);

/// Body poses, joint axes and M(q) on the hinge and slide dofs (armature
/// taken off MuJoCo's diagonal: plant-json's mass_matrix leaves reflected
/// inertia out) at one configuration.
void CompareConfiguration(const Reference& ref, const RConfig& C, const Plant& p, Report* rep);

/// The comparisons of one configuration's plant: at configuration 0 also
/// CompareStatic, and *scoped filled; `more` (when given) compares what else
/// the caller compares. A malformed plant-json is a discrepancy, and any
/// discrepancy is followed by the command that reproduces it.
void ComparePlant(const Reference& ref, size_t config, const Plant& plant,
                  const StaticChecks& checks, std::map<std::string, std::string>* scoped,
                  Report* rep, const std::function<void()>& more = {});

}  // namespace mdlc::oracle::mujoco
