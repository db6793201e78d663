// Differential test: mdlc's plant-json dump against an independent oracle
// built from urdfdom (the ROS reference URDF parser) plus Eigen.
//
// Nothing here uses mdlc library code. For every model the oracle
//   1. parses the URDF with urdf::parseURDFFile (and, only to recover what
//      urdfdom loses, reads the XML with tinyxml for which <limit> attributes
//      were written and for <inertial> elements urdfdom left half-parsed),
//   2. applies the mdlc/Drake conventions from features.md in the shared spec folder
//      (cited by feature ID next to each rule),
//   3. computes link poses, joint axes and the joint-space mass matrix
//      geometrically, and
//   4. runs `mdlc compile FILE --emit=plant-json --q ...` as a subprocess at
//      the zero configuration and at 5 seeded random ones, and compares every
//      quantity by name (never by position) to
//      |a - b| <= 1e-9 * max(1, |a|, |b|).
//
// Configuration (all optional):
//   --mdlc=PATH            or env MDLC_BINARY   (default: compiled-in path)
//   env MDLC_ORACLE_CONFIGS=N   number of random configurations (default 5)
//   env MDLC_ORACLE_MAX_MESSAGES=N  discrepancies printed per test (default 60)
//   env MDLC_ORACLE_EXTRA_MODELS=a.urdf:dir  extra models (Extra/...) to compare
//
// Test layout (value-parameterized, one case per model):
//   Corpus/UrdfdomOracle.*/<path>    every corpus URDF that urdfdom loads
//   HandMade/UrdfdomOracle.*/<stem>  tests/models/urdf/*.urdf
//   with two tests per model:
//     MassPropertiesAndJoints  URDF-003/004/005/012/013/014/017, COMMON-040/041/042
//     KinematicsAndMassMatrix  URDF-005/011/012/017 (X_WB, axis_W, M(q))
//   plus OracleSelfCheck.* (the oracle against closed forms; no mdlc needed).
// Corpus models that the spec requires mdlc to reject (kExpectedRejections)
// are skipped when mdlc rejects them with the expected message, and fail
// ("stale entry") when mdlc accepts them, or rejects them for another reason.

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <console_bridge/console.h>
#include <gtest/gtest.h>

#include "default_dump.h"
#include "oracle_util.h"
#include <nlohmann/json.hpp>
#include <tinyxml.h>
#include <urdf_model/model.h>
#include <urdf_parser/urdf_parser.h>

namespace {

namespace fs = std::filesystem;
using namespace mdlc::oracle;
using Eigen::Isometry3d;
using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using json = nlohmann::json;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ---------------------------------------------------------------------------
// The oracle model, built from urdfdom
// ---------------------------------------------------------------------------

enum class JType { kRevolute, kContinuous, kPrismatic, kFixed, kFloating, kPlanar, kUnknown };

const char* UrdfTypeName(JType t) {
  switch (t) {
    case JType::kRevolute: return "revolute";
    case JType::kContinuous: return "continuous";
    case JType::kPrismatic: return "prismatic";
    case JType::kFixed: return "fixed";
    case JType::kFloating: return "floating";
    case JType::kPlanar: return "planar";
    default: return "unknown";
  }
}

// URDF-012: URDF joint type -> plant joint type. Floating makes no joint.
std::string PlantTypeName(JType t) {
  switch (t) {
    case JType::kRevolute:
    case JType::kContinuous: return "revolute";
    case JType::kPrismatic: return "prismatic";
    case JType::kFixed: return "weld";
    case JType::kPlanar: return "planar";
    default: return "";
  }
}

bool IsOneDof(JType t) {
  return t == JType::kRevolute || t == JType::kContinuous || t == JType::kPrismatic;
}

struct OLink {
  std::string name;
  bool is_world = false;
  // Mass properties as the plant should report them (after COMMON-040/041).
  double mass = 0;
  Vector3d com = Vector3d::Zero();       // p_BoBcm in B
  Matrix3d I_B = Matrix3d::Zero();       // about Bcm, expressed in B
  std::string inertia_note;              // non-empty when a rule rewrote them
  std::string parent_joint;              // empty for the root
  std::vector<std::string> child_joints;
};

struct OJoint {
  std::string name;
  JType type = JType::kUnknown;
  std::string parent, child;
  Isometry3d X_PJ = Isometry3d::Identity();
  Vector3d axis = Vector3d::UnitX();  // normalized (URDF-011)
  bool has_limit = false;
  bool lower_given = false, upper_given = false;  // attribute written in the file
  double lower = -kInf, upper = kInf, velocity = kInf, effort = kInf;
  double damping = 0;
  // URDF-018: <mimic joint multiplier offset>, empty name when absent
  std::string mimicked;
  double mimic_multiplier = 1, mimic_offset = 0;
};

struct Oracle {
  std::string robot;  // model instance name
  std::string root;
  std::map<std::string, OLink> links;
  std::map<std::string, OJoint> joints;
  std::vector<std::string> dofs;  // local names of 1-dof joints, sorted
  // Free bodies: root (unless it is `world`, URDF-003/017) and every child of
  // a floating joint (URDF-012), keyed by link name.
  std::vector<std::string> free_bodies;

  std::string Scoped(const std::string& link) const {
    return link == "world" && links.at(link).is_world ? "world" : robot + "::" + link;
  }
};

Isometry3d PoseToIso(const urdf::Pose& p) {
  Isometry3d X = Isometry3d::Identity();
  // urdfdom stores origin@rpy as a quaternion built from the fixed-axis
  // convention R = Rz(yaw) Ry(pitch) Rx(roll) (URDF-005).
  Quaterniond q(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z);
  X.linear() = q.normalized().toRotationMatrix();
  X.translation() = Vector3d(p.position.x, p.position.y, p.position.z);
  return X;
}

// COMMON-040: physical validity of a rotational inertia about the COM, as
// Drake's RotationalInertia::CouldBePhysicallyValid states it: principal
// moments non-negative and satisfying the triangle inequality, both to within
// 16 machine epsilons times max(1, trace / 2): an allowance relative to the
// inertia's size and never below an absolute 16 epsilons.
bool RotationalInertiaValid(const Matrix3d& I) {
  if (!I.allFinite()) return false;
  const double allowance =
      16 * std::numeric_limits<double>::epsilon() * std::max(1.0, I.trace() / 2);
  // exactly-diagonal moments when the products are round-off, else eigenvalues
  Vector3d p;
  const double products = std::max({std::abs(I(0, 1)), std::abs(I(0, 2)), std::abs(I(1, 2))});
  if (products <= 2 * std::numeric_limits<double>::epsilon() * std::abs(I.trace())) {
    p = I.diagonal();
    std::sort(p.data(), p.data() + 3);
  } else {
    p = Eigen::SelfAdjointEigenSolver<Matrix3d>(I, Eigen::EigenvaluesOnly).eigenvalues();
  }
  if (p(0) < -allowance) return false;
  return p(0) + p(1) + allowance >= p(2);
}

// Mass properties per URDF-004 plus COMMON-040/041 replacement.
void FillMassProperties(const urdf::Inertial* in, OLink* L) {
  if (in == nullptr) return;  // URDF-004: no <inertial> => massless
  const Isometry3d X_BBi = PoseToIso(in->origin);
  Matrix3d I_Bi;
  I_Bi << in->ixx, in->ixy, in->ixz,
          in->ixy, in->iyy, in->iyz,
          in->ixz, in->iyz, in->izz;
  const double m = in->mass;
  L->com = X_BBi.translation();
  const bool zero_inertia = I_Bi.isZero(0.0);
  if (m == 0 && zero_inertia) {  // COMMON-041: massless body
    L->mass = 0;
    L->I_B.setZero();
    return;
  }
  const Matrix3d R = X_BBi.linear();
  const Matrix3d I_B = R * I_Bi * R.transpose();  // COMMON-042: re-express in B
  std::string why;
  if (!std::isfinite(m) || m < 0) why = "COMMON-041 negative mass";
  else if (m == 0) why = "COMMON-041 zero mass with non-zero inertia";
  else if (!RotationalInertiaValid(I_Bi)) why = "COMMON-040 non-physical inertia";
  if (why.empty()) {
    L->mass = m;
    L->I_B = I_B;
    return;
  }
  // Replacement: solid sphere of water density with the given mass (1 kg when
  // not positive), centred at the given COM.
  const double mm = (std::isfinite(m) && m > 0) ? m : 1.0;
  const double r = std::cbrt((3.0 / (4.0 * M_PI)) * (mm / 1000.0));
  L->mass = mm;
  L->I_B = Matrix3d::Identity() * (0.4 * mm * r * r);
  L->inertia_note = why + ": expected replacement by a 1000 kg/m^3 sphere";
}

struct LimitAttrs {
  bool lower = false, upper = false, velocity = false, effort = false;
};

// urdfdom silently turns a missing limit@lower/@upper into 0, while URDF-013
// says the default is unbounded. Recover which attributes were written.
std::map<std::string, LimitAttrs> ReadLimitAttributes(const std::string& path) {
  std::map<std::string, LimitAttrs> out;
  TiXmlDocument doc;
  if (!doc.LoadFile(path)) return out;
  const TiXmlElement* robot = doc.FirstChildElement("robot");
  if (!robot) return out;
  for (const TiXmlElement* j = robot->FirstChildElement("joint"); j;
       j = j->NextSiblingElement("joint")) {
    const char* name = j->Attribute("name");
    const TiXmlElement* lim = j->FirstChildElement("limit");
    if (!name || !lim) continue;
    LimitAttrs a;
    a.lower = lim->Attribute("lower") != nullptr;
    a.upper = lim->Attribute("upper") != nullptr;
    a.velocity = lim->Attribute("velocity") != nullptr;
    a.effort = lim->Attribute("effort") != nullptr;
    out[name] = a;
  }
  return out;
}

// urdfdom 3.0.1 requires <mass> and all six <inertia> attributes; when one
// is missing it logs an error and leaves the link's Inertial half-filled
// (origin, maybe mass) yet still returns the model. URDF-004 says missing
// sub-elements default to 0, so complete such inertials from the XML.
// Returns the names of the links that needed it.
std::set<std::string> CompleteInertials(const std::string& path, urdf::ModelInterface* model) {
  std::set<std::string> patched;
  TiXmlDocument doc;
  if (!doc.LoadFile(path)) return patched;
  const TiXmlElement* robot = doc.FirstChildElement("robot");
  if (!robot) return patched;
  for (const TiXmlElement* l = robot->FirstChildElement("link"); l; l = l->NextSiblingElement("link")) {
    const char* name = l->Attribute("name");
    const TiXmlElement* in = l->FirstChildElement("inertial");
    if (!name || !in || !model->links_.count(name)) continue;
    const TiXmlElement* mass = in->FirstChildElement("mass");
    const TiXmlElement* inertia = in->FirstChildElement("inertia");
    static const char* kAttrs[6] = {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"};
    bool complete = mass && mass->Attribute("value") && inertia;
    for (const char* a : kAttrs) complete = complete && inertia->Attribute(a);
    if (complete) continue;
    urdf::LinkSharedPtr link = model->links_.at(name);
    if (!link->inertial) link->inertial = std::make_shared<urdf::Inertial>();
    const auto num = [](const TiXmlElement* e, const char* attr) {
      const char* v = e ? e->Attribute(attr) : nullptr;
      return v ? std::strtod(v, nullptr) : 0.0;
    };
    urdf::Inertial& I = *link->inertial;
    I.mass = num(mass, "value");
    I.ixx = num(inertia, "ixx");
    I.ixy = num(inertia, "ixy");
    I.ixz = num(inertia, "ixz");
    I.iyy = num(inertia, "iyy");
    I.iyz = num(inertia, "iyz");
    I.izz = num(inertia, "izz");
    patched.insert(name);
  }
  return patched;
}

// Builds the oracle. Returns an error string on failure.
std::string BuildOracle(const std::string& path, Oracle* o) {
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDFFile(path);
  if (!model) return "urdfdom could not parse " + path;
  const auto limit_attrs = ReadLimitAttributes(path);
  const auto patched_inertials = CompleteInertials(path, model.get());
  o->robot = model->getName();
  o->root = model->getRoot()->name;
  for (const auto& [name, link] : model->links_) {
    OLink L;
    L.name = name;
    // URDF-003: a link named `world` is the world body; <inertial> ignored.
    L.is_world = (name == "world");
    if (!L.is_world) FillMassProperties(link->inertial.get(), &L);
    if (patched_inertials.count(name)) {
      L.inertia_note += std::string(L.inertia_note.empty() ? "" : "; ") +
                        "URDF-004: incomplete <inertial>, missing values taken as 0";
    }
    if (link->parent_joint) L.parent_joint = link->parent_joint->name;
    for (const auto& cj : link->child_joints) L.child_joints.push_back(cj->name);
    o->links[name] = L;
  }
  for (const auto& [name, j] : model->joints_) {
    OJoint J;
    J.name = name;
    switch (j->type) {
      case urdf::Joint::REVOLUTE: J.type = JType::kRevolute; break;
      case urdf::Joint::CONTINUOUS: J.type = JType::kContinuous; break;
      case urdf::Joint::PRISMATIC: J.type = JType::kPrismatic; break;
      case urdf::Joint::FIXED: J.type = JType::kFixed; break;
      case urdf::Joint::FLOATING: J.type = JType::kFloating; break;
      case urdf::Joint::PLANAR: J.type = JType::kPlanar; break;
      default: return "joint '" + name + "' has unknown type";
    }
    J.parent = j->parent_link_name;
    J.child = j->child_link_name;
    J.X_PJ = PoseToIso(j->parent_to_joint_origin_transform);  // URDF-011
    if (J.type != JType::kFixed && J.type != JType::kFloating) {
      // URDF-011: axis default (1,0,0) (urdfdom applies it), normalized.
      Vector3d a(j->axis.x, j->axis.y, j->axis.z);
      if (a.norm() < 1e-8) return "joint '" + name + "' has a zero axis";
      J.axis = a.normalized();
    }
    // URDF-013: limits. Missing attributes default to unbounded.
    if (j->limits) {
      J.has_limit = true;
      const auto it = limit_attrs.find(name);
      const LimitAttrs a = it != limit_attrs.end() ? it->second : LimitAttrs{true, true, true, true};
      if (J.type == JType::kRevolute || J.type == JType::kPrismatic) {
        if (a.lower) J.lower = j->limits->lower;
        if (a.upper) J.upper = j->limits->upper;
        J.lower_given = a.lower;
        J.upper_given = a.upper;
      }
      // (continuous: position limits ignored, URDF-012.)
      if (a.velocity) J.velocity = j->limits->velocity;
      if (a.effort) J.effort = j->limits->effort;
    }
    // URDF-014: dynamics@damping, default 0.
    if (j->dynamics) J.damping = j->dynamics->damping;
    if (j->mimic) {
      J.mimicked = j->mimic->joint_name;
      J.mimic_multiplier = j->mimic->multiplier;
      J.mimic_offset = j->mimic->offset;
    }
    if (IsOneDof(J.type)) o->dofs.push_back(name);
    o->joints[name] = J;
  }
  std::sort(o->dofs.begin(), o->dofs.end());
  if (!o->links.at(o->root).is_world) o->free_bodies.push_back(o->root);  // URDF-017
  for (const auto& [name, J] : o->joints) {
    if (J.type == JType::kFloating) o->free_bodies.push_back(J.child);  // URDF-012
  }
  return "";
}

// Kinematics at configuration q (local joint name -> position).
struct Kinematics {
  std::map<std::string, Isometry3d> X_WB;
  std::map<std::string, Vector3d> axis_W;    // 1-dof joints
  std::map<std::string, Vector3d> origin_W;  // joint frame origin, 1-dof joints
};

Kinematics ComputeKinematics(const Oracle& o, const std::map<std::string, double>& q) {
  Kinematics k;
  // Free bodies and the world root sit at the identity (default free-body pose).
  std::vector<std::pair<std::string, Isometry3d>> stack;
  stack.emplace_back(o.root, Isometry3d::Identity());
  while (!stack.empty()) {
    auto [link, X_WP] = stack.back();
    stack.pop_back();
    k.X_WB[link] = X_WP;
    for (const auto& jn : o.links.at(link).child_joints) {
      const OJoint& J = o.joints.at(jn);
      if (J.type == JType::kFloating) {
        // URDF-012: no joint; the child is a free body at its default pose.
        stack.emplace_back(J.child, Isometry3d::Identity());
        continue;
      }
      const Isometry3d X_WJ = X_WP * J.X_PJ;
      Isometry3d X_JC = Isometry3d::Identity();
      const auto qi = q.find(jn);
      const double qv = qi == q.end() ? 0.0 : qi->second;
      if (J.type == JType::kRevolute || J.type == JType::kContinuous) {
        X_JC.linear() = Eigen::AngleAxisd(qv, J.axis).toRotationMatrix();
      } else if (J.type == JType::kPrismatic) {
        X_JC.translation() = qv * J.axis;
      }  // fixed, planar (default configuration): identity
      if (IsOneDof(J.type)) {
        k.axis_W[jn] = X_WJ.linear() * J.axis;
        k.origin_W[jn] = X_WJ.translation();
      }
      stack.emplace_back(J.child, X_WJ * X_JC);
    }
  }
  return k;
}

// 1-dof joints whose motion moves `link` (stopping at free bodies).
std::vector<std::string> MovingDofs(const Oracle& o, const std::string& link) {
  std::vector<std::string> out;
  std::string cur = link;
  while (true) {
    const OLink& L = o.links.at(cur);
    if (L.parent_joint.empty()) break;
    const OJoint& J = o.joints.at(L.parent_joint);
    if (J.type == JType::kFloating) break;
    if (IsOneDof(J.type)) out.push_back(J.name);
    cur = J.parent;
  }
  return out;
}

// M(q) = sum_b (Jv^T m Jv + Jw^T I_W Jw), restricted to the 1-dof joints, in
// the order of o.dofs.
MatrixXd ComputeMassMatrix(const Oracle& o, const Kinematics& k) {
  const int n = static_cast<int>(o.dofs.size());
  std::map<std::string, int> index;
  for (int i = 0; i < n; ++i) index[o.dofs[i]] = i;
  MatrixXd M = MatrixXd::Zero(n, n);
  for (const auto& [name, L] : o.links) {
    if (L.is_world) continue;
    if (L.mass == 0 && L.I_B.isZero(0.0)) continue;
    const Isometry3d& X_WB = k.X_WB.at(name);
    const Vector3d c = X_WB * L.com;
    const Matrix3d R = X_WB.linear();
    const Matrix3d I_W = R * L.I_B * R.transpose();
    Eigen::Matrix<double, 3, Eigen::Dynamic> Jv = Eigen::MatrixXd::Zero(3, n);
    Eigen::Matrix<double, 3, Eigen::Dynamic> Jw = Eigen::MatrixXd::Zero(3, n);
    for (const auto& jn : MovingDofs(o, name)) {
      const OJoint& J = o.joints.at(jn);
      const int col = index.at(jn);
      const Vector3d a = k.axis_W.at(jn);
      if (J.type == JType::kPrismatic) {
        Jv.col(col) = a;
      } else {
        Jw.col(col) = a;
        Jv.col(col) = a.cross(c - k.origin_W.at(jn));
      }
    }
    M += L.mass * Jv.transpose() * Jv + Jw.transpose() * I_W * Jw;
  }
  return M;
}

// ---------------------------------------------------------------------------
// Model list
// ---------------------------------------------------------------------------

struct ModelCase {
  std::string id;        // readable test-name suffix
  std::string path;      // absolute path of the URDF ("" => skip)
  std::string display;   // how messages name the model
  std::string package_path;  // passed as --package-path when non-empty
  std::string skip_reason;
  // Set when the spec requires mdlc to reject a model urdfdom accepts: mdlc
  // failing with `reject_keyword` in its stderr then skips the case; mdlc
  // accepting the model fails it (the entry is stale).
  std::string reject_keyword, reject_why;
  // extra `mdlc compile` arguments (a converted file: read as written)
  std::vector<std::string> mdlc_args;
};

// Corpus models that urdfdom loads but that the spec makes an error in mdlc
// (Drake agrees: it rejects them too whenever it parses geometry).
struct ExpectedRejection {
  const char* path;  // relative to corpus/
  const char* keyword;
  const char* why;
};
constexpr ExpectedRejection kExpectedRejections[] = {
    {"drake/multibody/plant/test/atlas_with_fixed_joints.urdf", "no <geometry>",
     "URDF-032: a <visual> without <geometry> (link hokuyo_link) is an error"},
    {"example-robot-data/robots/talos_data/robots/talos_left_arm.urdf", "unknown joint",
     "URDF-020: a transmission naming a joint that does not exist (arm_left_1_joint) is an error"},
    {"sdformat/test/sdf/joint_mimic_rack_pinion.urdf", "unsupported scheme 'https://'",
     "COMMON-010: a mesh fetched over https:// (a Gazebo Fuel URL) is an error; mdlc never "
     "downloads anything"},
};

// Keeps gtest from dumping the struct's bytes in test listings.
void PrintTo(const ModelCase& c, std::ostream* os) { *os << c.display; }

std::vector<ModelCase> CorpusCases() {
  return ManifestCases<ModelCase>(
      "shared corpus not found (" + CorpusManifest().string() +
          "); the corpus differential test needs ../shared",
      [](const std::vector<std::string>& cols) -> std::optional<ModelCase> {
        if (cols.size() < 7 || cols[0] != "urdf" || cols[6].rfind("yes", 0) != 0) {
          return std::nullopt;
        }
        ModelCase c;
        c.id = Sanitize(WithoutSuffix(cols[1], ".urdf"));
        c.path = (CorpusDir() / cols[1]).string();
        c.display = "corpus/" + cols[1];
        c.package_path = CorpusDir().string();
        for (const auto& r : kExpectedRejections) {
          if (cols[1] == r.path) {
            c.reject_keyword = r.keyword;
            c.reject_why = r.why;
          }
        }
        return c;
      });
}

std::vector<ModelCase> HandMadeCases() {
  const fs::path dir = TestModels("urdf");
  return FolderCases<ModelCase>(
      dir, ".urdf", "no URDF models in " + dir.string(), [](const fs::path& f) {
        ModelCase c;
        c.id = Sanitize(f.stem().string());
        c.path = f.string();
        c.display = "tests/models/urdf/" + f.filename().string();
        return c;
      });
}

// ---------------------------------------------------------------------------
// Comparison
// ---------------------------------------------------------------------------

// Runs mdlc on the case at `q` (oracle_util.h); a case listed in
// kExpectedRejections is skipped when mdlc rejects it for the listed reason.
bool RunMdlc(const ModelCase& mc, const JointValues& q, Report* rep, Dump* d) {
  std::optional<ListedRejection> listed;
  if (!mc.reject_keyword.empty()) {
    listed = ListedRejection{"kExpectedRejections", mc.reject_keyword, mc.reject_why};
  }
  // the default configuration: once for the file's two checks (default_dump.h)
  if (q.empty()) return RunMdlcAtDefault(mc.path, mc.package_path, listed, rep, d, mc.mdlc_args);
  return mdlc::oracle::RunMdlc(mc.path, mc.package_path, q, listed, rep, d, mc.mdlc_args);
}

// Reads a number-or-null; null means +inf (or -inf when negative_null).
std::optional<double> NumOrNull(const json& v, bool negative_null) {
  if (v.is_null()) return negative_null ? -kInf : kInf;
  if (v.is_number()) return v.get<double>();
  return std::nullopt;
}

// Name of the free joint Drake synthesizes for a body: the body name,
// prefixed with '_' until it does not clash with an existing joint.
std::string FreeJointName(const Oracle& o, const std::string& body) {
  std::string name = body;
  while (o.joints.count(name)) name = "_" + name;
  return name;
}

// Checks one limit array (1-dof: one entry).
void CheckLimitArray(Report* rep, const std::string& feature, const std::string& entity,
                     const json& jj, const char* key, double expected, bool negative_null,
                     const std::string& note = "") {
  if (!jj.contains(key) || !jj[key].is_array() || jj[key].size() != 1) {
    rep->Add(feature + " " + entity + " " + key + ": expected a 1-element array, mdlc gave " +
             (jj.contains(key) ? jj[key].dump() : std::string("<missing>")) +
             " (urdfdom=" + Fmt(expected) + ")");
    return;
  }
  const auto v = NumOrNull(jj[key][0], negative_null);
  if (!v) {
    rep->Add(feature + " " + entity + " " + key + ": not a number or null: " + jj[key][0].dump());
    return;
  }
  if (!Near(*v, expected)) {
    const auto show = [](double x) { return std::isinf(x) ? std::string("null(unbounded)") : Fmt(x); };
    rep->Add(feature + " " + entity + " " + key + "[0]: mdlc=" + show(*v) + " urdfdom=" + show(expected) +
             (note.empty() ? "" : " [" + note + "]"));
  }
}

// Static checks at the default configuration: entity sets, mass properties,
// joint types, topology, limits, damping.
// URDF-018: a <mimic> on a 1-dof joint of a 1-dof joint is one coupler in
// Drake's orientation, q(joint0) = gear_ratio * q(joint1) + offset, with
// joint0 the joint that holds <mimic>. Every coupler must come from a mimic.
void CheckCouplers(const Oracle& o, const Dump& d, Report* rep) {
  std::map<std::string, const OJoint*> expected;  // scoped follower -> joint
  for (const auto& [name, J] : o.joints) {
    if (J.mimicked.empty() || !IsOneDof(J.type)) continue;
    const auto leader = o.joints.find(J.mimicked);
    if (leader == o.joints.end() || !IsOneDof(leader->second.type)) continue;
    expected[o.robot + "::" + name] = &J;
  }
  std::set<std::string> seen;
  for (const json& c : d.root.value("constraints", json::array())) {
    if (c.value("type", "") != "coupler") continue;
    const std::string joint0 = c.value("joint0", ""), joint1 = c.value("joint1", "");
    const auto it = expected.find(joint0);
    if (it == expected.end()) {
      rep->Add("URDF-018 coupler joint0='" + joint0 + "' joint1='" + joint1 +
               "' matches no <mimic> (joint0 must be the joint holding <mimic>)");
      continue;
    }
    seen.insert(joint0);
    const OJoint& J = *it->second;
    const std::string ent = "coupler of '" + joint0 + "'";
    if (joint1 != o.robot + "::" + J.mimicked) {
      rep->Add("URDF-018 " + ent + " joint1: mdlc='" + joint1 + "' urdfdom='" + o.robot +
               "::" + J.mimicked + "'");
    }
    rep->Num("URDF-018", ent, "gear_ratio", c.value("gear_ratio", kNaN), J.mimic_multiplier);
    rep->Num("URDF-018", ent, "offset", c.value("offset", kNaN), J.mimic_offset);
  }
  for (const auto& [follower, J] : expected) {
    if (!seen.count(follower)) {
      rep->Add("URDF-018 joint '" + follower + "' mimics '" + J->mimicked +
               "' but mdlc has no coupler with it as joint0");
    }
  }
}

void CheckStatic(const Oracle& o, const Dump& d, Report* rep) {
  // --- Bodies (URDF-003, URDF-004, URDF-005, COMMON-040/041/042).
  for (const auto& [name, L] : o.links) {
    if (L.is_world) {
      // URDF-003: no body is made for a link named world.
      if (d.bodies.count(Key(o.robot, name))) {
        rep->Add("URDF-003 body '" + o.robot + "::world' exists; a link named world must be the world body");
      }
      continue;
    }
    const auto it = d.bodies.find(Key(o.robot, name));
    const std::string ent = "body '" + o.Scoped(name) + "'";
    if (it == d.bodies.end()) {
      rep->Add("URDF-002 " + ent + " missing from mdlc bodies");
      continue;
    }
    const json& b = *it->second;
    if (!b.contains("mass") || !b["mass"].is_number()) {
      rep->Add("URDF-004 " + ent + " mass missing/not a number");
    } else {
      rep->Num("URDF-004", ent, "mass", b["mass"].get<double>(), L.mass, L.inertia_note);
    }
    Vector3d com;
    if (!ReadVec3(b.value("com", json()), &com)) {
      rep->Add("URDF-004 " + ent + " com missing or malformed");
    } else {
      for (int i = 0; i < 3; ++i) {
        rep->Num("URDF-004", ent, "com[" + std::to_string(i) + "]", com(i), L.com(i), L.inertia_note);
      }
    }
    const json in = b.value("inertia", json());
    if (!in.is_array() || in.size() != 6) {
      rep->Add("COMMON-042 " + ent + " inertia missing or not 6 numbers");
    } else {
      static const char* kNames[6] = {"Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz"};
      const double expect[6] = {L.I_B(0, 0), L.I_B(1, 1), L.I_B(2, 2),
                                L.I_B(0, 1), L.I_B(0, 2), L.I_B(1, 2)};
      for (int i = 0; i < 6; ++i) {
        if (!in[i].is_number()) {
          rep->Add("COMMON-042 " + ent + " inertia." + kNames[i] + " not a number");
          continue;
        }
        rep->Num("URDF-004/COMMON-042", ent, std::string("inertia.") + kNames[i],
                 in[i].get<double>(), expect[i], L.inertia_note);
      }
    }
  }
  for (const auto& [key, b] : d.bodies) {
    if (b->value("model_instance", "") != o.robot) continue;
    const std::string name = b->value("name", "");
    if (!o.links.count(name) || o.links.at(name).is_world) {
      rep->Add("URDF-002 extra body '" + key + "' in mdlc output (not a URDF link)");
    }
  }

  // --- Joints (URDF-011..014, URDF-017).
  std::set<std::string> expected_joint_keys;
  for (const auto& [name, J] : o.joints) {
    const std::string ent = "joint '" + o.robot + "::" + name + "' (" + UrdfTypeName(J.type) + ")";
    if (J.type == JType::kFloating) {
      // URDF-012: floating makes no joint.
      if (d.joints.count(Key(o.robot, name))) {
        rep->Add("URDF-012 " + ent + " present in mdlc output; floating joints must not create a joint");
      }
      continue;
    }
    expected_joint_keys.insert(Key(o.robot, name));
    const auto it = d.joints.find(Key(o.robot, name));
    if (it == d.joints.end()) {
      rep->Add("URDF-012 " + ent + " missing from mdlc joints");
      continue;
    }
    const json& jj = *it->second;
    const std::string type = jj.value("type", "");
    if (type != PlantTypeName(J.type)) {
      rep->Add("URDF-012 " + ent + " type: mdlc='" + type + "' urdfdom-mapped='" +
               PlantTypeName(J.type) + "'");
    }
    if (jj.value("parent", "") != o.Scoped(J.parent)) {
      rep->Add("URDF-010 " + ent + " parent: mdlc='" + jj.value("parent", "") + "' urdfdom='" +
               o.Scoped(J.parent) + "'");
    }
    if (jj.value("child", "") != o.Scoped(J.child)) {
      rep->Add("URDF-010 " + ent + " child: mdlc='" + jj.value("child", "") + "' urdfdom='" +
               o.Scoped(J.child) + "'");
    }
    if (!IsOneDof(J.type)) continue;
    // URDF-013: position limits (continuous => unbounded => null).
    const auto absent = [&](bool given) {
      if (J.type == JType::kContinuous) return std::string("continuous: position limits ignored");
      if (!J.has_limit) return std::string("no <limit> element");
      return given ? std::string() : std::string("attribute absent from <limit>: unbounded by default");
    };
    CheckLimitArray(rep, "URDF-013", ent, jj, "lower", J.lower, true, absent(J.lower_given));
    CheckLimitArray(rep, "URDF-013", ent, jj, "upper", J.upper, false, absent(J.upper_given));
    CheckLimitArray(rep, "URDF-013", ent, jj, "velocity_limit", J.velocity, false);
    CheckLimitArray(rep, "URDF-013", ent, jj, "effort_limit", J.effort, false);
    // URDF-014: damping.
    if (!jj.contains("damping") || !jj["damping"].is_array() || jj["damping"].size() != 1 ||
        !jj["damping"][0].is_number()) {
      rep->Add("URDF-014 " + ent + " damping: expected [" + Fmt(J.damping) + "], mdlc gave " +
               (jj.contains("damping") ? jj["damping"].dump() : std::string("<missing>")));
    } else {
      rep->Num("URDF-014", ent, "damping[0]", jj["damping"][0].get<double>(), J.damping);
    }
  }
  // Free bodies (URDF-017 root, URDF-012 floating children).
  for (const auto& body : o.free_bodies) {
    const std::string jname = FreeJointName(o, body);
    expected_joint_keys.insert(Key(o.robot, jname));
    const std::string ent = "free joint '" + o.robot + "::" + jname + "' of body '" + o.Scoped(body) + "'";
    const auto it = d.joints.find(Key(o.robot, jname));
    if (it == d.joints.end()) {
      rep->Add("URDF-017 " + ent + " missing (expected a quaternion_floating joint to world)");
      continue;
    }
    const json& jj = *it->second;
    if (jj.value("type", "") != "quaternion_floating") {
      rep->Add("URDF-017 " + ent + " type: mdlc='" + jj.value("type", "") + "' expected 'quaternion_floating'");
    }
    if (jj.value("parent", "") != "world") {
      rep->Add("URDF-017 " + ent + " parent: mdlc='" + jj.value("parent", "") + "' expected 'world'");
    }
    if (jj.value("child", "") != o.Scoped(body)) {
      rep->Add("URDF-017 " + ent + " child: mdlc='" + jj.value("child", "") + "' expected '" +
               o.Scoped(body) + "'");
    }
    if (!jj.value("unnamed", false)) {
      rep->Add("URDF-017 " + ent + " is not marked \"unnamed\": true");
    }
  }
  CheckCouplers(o, d, rep);
  for (const auto& [key, j] : d.joints) {
    if (j->value("model_instance", "") != o.robot) continue;
    if (!expected_joint_keys.count(key)) {
      rep->Add("URDF-012 extra joint '" + key + "' (type " + j->value("type", "") + ", child " +
               j->value("child", "") + ") in mdlc output");
    }
  }
}

// Configuration-dependent checks: X_WB, axis_W, dofs, mass matrix.
void CheckKinematics(const Oracle& o, const Kinematics& k, const MatrixXd& M, const Dump& d,
                     Report* rep) {
  // --- X_WB of every link (URDF-005, URDF-011, URDF-012, URDF-017).
  for (const auto& [name, L] : o.links) {
    if (L.is_world) continue;
    const auto it = d.bodies.find(Key(o.robot, name));
    if (it == d.bodies.end()) {
      rep->Add("URDF-002 body '" + o.Scoped(name) + "' missing from mdlc bodies");
      continue;
    }
    const std::string ent = "body '" + o.Scoped(name) + "'";
    const json& X = (*it->second).value("X_WB", json());
    Vector3d p;
    if (!X.is_object() || !ReadVec3(X.value("p", json()), &p) || !X.contains("q") ||
        !X["q"].is_array() || X["q"].size() != 4) {
      rep->Add("URDF-011 " + ent + " X_WB missing or malformed: " + X.dump());
      continue;
    }
    const Isometry3d& E = k.X_WB.at(name);
    for (int i = 0; i < 3; ++i) {
      rep->Num("URDF-011", ent, "X_WB.p[" + std::to_string(i) + "]", p(i), E.translation()(i));
    }
    const double w = X["q"][0].get<double>(), x = X["q"][1].get<double>(),
                 y = X["q"][2].get<double>(), z = X["q"][3].get<double>();
    const double norm = std::sqrt(w * w + x * x + y * y + z * z);
    if (std::abs(norm - 1) > 1e-9) rep->Add("plant-json " + ent + " X_WB.q is not unit: |q|=" + Fmt(norm));
    if (w < 0) rep->Add("plant-json " + ent + " X_WB.q has w < 0 (spec: w >= 0): w=" + Fmt(w));
    const Matrix3d R = Quaterniond(w, x, y, z).normalized().toRotationMatrix();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        rep->Num("URDF-005/011", ent,
                 "R_WB(" + std::to_string(r) + "," + std::to_string(c) + ") from X_WB.q",
                 R(r, c), E.linear()(r, c));
      }
    }
  }
  // --- axis_W of 1-dof joints (URDF-011).
  for (const auto& jn : o.dofs) {
    const auto it = d.joints.find(Key(o.robot, jn));
    if (it == d.joints.end()) continue;  // reported by the static check
    const std::string ent = "joint '" + o.robot + "::" + jn + "'";
    Vector3d a;
    if (!ReadVec3((*it->second).value("axis_W", json()), &a)) {
      rep->Add("URDF-011 " + ent + " axis_W missing or malformed");
      continue;
    }
    const Vector3d& e = k.axis_W.at(jn);
    for (int i = 0; i < 3; ++i) rep->Num("URDF-011", ent, "axis_W[" + std::to_string(i) + "]", a(i), e(i));
  }
  // --- dofs and mass matrix (URDF-012, URDF-017).
  const json& dofs = d.root.value("dofs", json());
  const json& mm = d.root.value("mass_matrix", json());
  if (!dofs.is_array() || !mm.is_array()) {
    rep->Add("plant-json has no dofs/mass_matrix arrays");
    return;
  }
  std::map<std::string, int> mdlc_index;
  for (size_t i = 0; i < dofs.size(); ++i) mdlc_index[dofs[i].get<std::string>()] = static_cast<int>(i);
  std::set<std::string> expected;
  for (const auto& jn : o.dofs) expected.insert(o.robot + "::" + jn);
  for (const auto& e : expected) {
    if (!mdlc_index.count(e)) rep->Add("URDF-012 dof '" + e + "' missing from mdlc dofs");
  }
  for (const auto& [name, i] : mdlc_index) {
    if (!expected.count(name)) rep->Add("URDF-012 extra dof '" + name + "' in mdlc dofs");
  }
  if (mm.size() != dofs.size()) {
    rep->Add("plant-json mass_matrix has " + std::to_string(mm.size()) + " rows for " +
             std::to_string(dofs.size()) + " dofs");
    return;
  }
  for (size_t i = 0; i < o.dofs.size(); ++i) {
    const auto ri = mdlc_index.find(o.robot + "::" + o.dofs[i]);
    if (ri == mdlc_index.end()) continue;
    const json& row = mm[ri->second];
    if (!row.is_array() || row.size() != dofs.size()) {
      rep->Add("plant-json mass_matrix row for '" + ri->first + "' malformed");
      continue;
    }
    for (size_t j = 0; j < o.dofs.size(); ++j) {
      const auto cj = mdlc_index.find(o.robot + "::" + o.dofs[j]);
      if (cj == mdlc_index.end()) continue;
      rep->Num("URDF-017", "mass_matrix", "M(" + o.dofs[i] + ", " + o.dofs[j] + ")",
               row[cj->second].get<double>(), M(static_cast<int>(i), static_cast<int>(j)));
    }
  }
}

// Deterministic configurations: index 0 = default (no --q), then random ones
// with each 1-dof joint uniform in [-1.5, 1.5] clamped into its limits.
std::vector<std::pair<std::string, double>> Configuration(const Oracle& o, int index) {
  std::vector<std::pair<std::string, double>> q;
  if (index == 0) return q;
  std::mt19937_64 gen(0x6d646c63ULL * 1000003ULL + static_cast<uint64_t>(index));
  for (const auto& jn : o.dofs) {
    const double u = static_cast<double>(gen() >> 11) * 0x1.0p-53;
    double v = -1.5 + 3.0 * u;
    const OJoint& J = o.joints.at(jn);
    if (J.type == JType::kRevolute || J.type == JType::kPrismatic) {
      v = std::min(std::max(v, J.lower), J.upper);
    }
    q.emplace_back(jn, v);
  }
  return q;
}

class UrdfdomOracle : public ::testing::TestWithParam<ModelCase> {
 protected:
  void SetUp() override {
    const ModelCase& mc = GetParam();
    if (!mc.skip_reason.empty()) GTEST_SKIP() << mc.skip_reason;
    const std::string err = BuildOracle(mc.path, &oracle_);
    ASSERT_TRUE(err.empty()) << "[" << mc.display << "] oracle failed: " << err;
  }
  Oracle oracle_;
};

// URDF-003/004/005/012/013/014/017, COMMON-040/041/042 at the default configuration.
TEST_P(UrdfdomOracle, MassPropertiesAndJoints) {
  const ModelCase& mc = GetParam();
  Report rep(mc.display, "urdfdom");
  Dump d;
  rep.SetContext("default configuration");
  try {
    if (RunMdlc(mc, {}, &rep, &d)) CheckStatic(oracle_, d, &rep);
  } catch (const json::exception& e) {
    rep.Add(std::string("malformed plant-json (") + e.what() + ")\n    command: " + d.cmdline);
  }
  rep.Flush();
  if (d.rejected_as_expected) GTEST_SKIP() << "mdlc rejects this model as the spec requires (" << mc.reject_why << ")";
}

// URDF-005/011/012/017: X_WB, axis_W and M(q) at the zero configuration and at
// seeded random ones.
TEST_P(UrdfdomOracle, KinematicsAndMassMatrix) {
  const ModelCase& mc = GetParam();
  Report rep(mc.display, "urdfdom");
  const int n_random = EnvInt("MDLC_ORACLE_CONFIGS", 5);
  for (int c = 0; c <= n_random; ++c) {
    const auto q = Configuration(oracle_, c);
    if (c > 0 && q.empty()) break;  // no dofs: one configuration is enough
    std::map<std::string, double> qmap(q.begin(), q.end());
    const Kinematics k = ComputeKinematics(oracle_, qmap);
    const MatrixXd M = ComputeMassMatrix(oracle_, k);
    rep.SetContext("config " + std::to_string(c) + ", " + DescribeQ(q));
    Dump d;
    const size_t before = rep.size();
    if (!RunMdlc(mc, q, &rep, &d)) {  // a failing run usually fails for all
      if (d.rejected_as_expected) {
        GTEST_SKIP() << "mdlc rejects this model as the spec requires (" << mc.reject_why << ")";
      }
      break;
    }
    try {
      CheckKinematics(oracle_, k, M, d, &rep);
    } catch (const json::exception& e) {
      rep.Add(std::string("malformed plant-json (") + e.what() + ")");
    }
    if (rep.size() > before) {
      rep.Add("reproduce with: " + d.cmdline);
    }
  }
  rep.Flush();
}

// Ad-hoc models for investigating a discrepancy: MDLC_ORACLE_EXTRA_MODELS is
// a ':'-separated list of .urdf files or directories of them.
std::vector<ModelCase> ExtraCases() {
  std::vector<ModelCase> cases;
  const char* env = std::getenv("MDLC_ORACLE_EXTRA_MODELS");
  std::stringstream ss(env ? env : "");
  for (std::string item; std::getline(ss, item, ':');) {
    if (item.empty()) continue;
    std::vector<fs::path> files;
    if (fs::is_directory(item)) files = FilesWithExtension(item, ".urdf");
    else files.push_back(item);
    for (const auto& f : files) {
      ModelCase c;
      c.id = Sanitize(f.stem().string());
      c.path = fs::absolute(f).string();
      c.display = f.string();
      cases.push_back(c);
    }
  }
  Uniquify(&cases);
  return cases;
}

// What `mdlc convert --to urdf --plain` wrote (issue 14; tests/convert):
// MDLC_ORACLE_CONVERTED_MODELS names the folder. Plain URDF is one tree of
// urdfdom's elements (issue 58: free bodies hang from a world link by
// floating joints, Drake's shapes and joints are approximated), so urdfdom
// must read every file.
std::vector<ModelCase> ConvertedCases() {
  std::vector<ModelCase> cases;
  const char* dir = std::getenv("MDLC_ORACLE_CONVERTED_MODELS");
  if (!dir || !fs::is_directory(dir)) return cases;
  for (const auto& f : FilesWithExtension(dir, ".urdf")) {
    ModelCase c;
    c.id = Sanitize(f.stem().string());
    c.path = fs::absolute(f).string();
    c.display = f.string();
    std::ifstream in(f);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    c.mdlc_args = ReadAsWrittenArgs(text, std::regex("<robot name=\"([^\"]*)\""));
    cases.push_back(c);
  }
  Uniquify(&cases);
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Corpus, UrdfdomOracle, ::testing::ValuesIn(CorpusCases()), CaseName());
INSTANTIATE_TEST_SUITE_P(Converted, UrdfdomOracle, ::testing::ValuesIn(ConvertedCases()),
                         CaseName());
INSTANTIATE_TEST_SUITE_P(HandMade, UrdfdomOracle, ::testing::ValuesIn(HandMadeCases()), CaseName());
INSTANTIATE_TEST_SUITE_P(Extra, UrdfdomOracle, ::testing::ValuesIn(ExtraCases()), CaseName());
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(UrdfdomOracle);

// ---------------------------------------------------------------------------
// Self-checks of the oracle itself against closed forms (no mdlc involved).
// ---------------------------------------------------------------------------

std::string HandModel(const std::string& file) {
  return (TestModels("urdf") / file).string();
}

TEST(OracleSelfCheck, DoublePendulumMassMatrixMatchesClosedForm) {
  Oracle o;
  ASSERT_EQ(BuildOracle(HandModel("double_pendulum_closed_form.urdf"), &o), "");
  ASSERT_EQ(o.dofs, (std::vector<std::string>{"elbow", "shoulder"}));
  const double m1 = 1.0, lc1 = 0.5, I1 = 0.083, l1 = 1.0, m2 = 0.8, lc2 = 0.6, I2 = 0.05;
  for (const auto& [q1, q2] : std::vector<std::pair<double, double>>{
           {0, 0}, {0.3, -0.7}, {1.2, 2.1}, {-1.5, 0.4}, {2.9, -2.9}}) {
    const Kinematics k = ComputeKinematics(o, {{"shoulder", q1}, {"elbow", q2}});
    const MatrixXd M = ComputeMassMatrix(o, k);
    const double c2 = std::cos(q2);
    const double M11 = I1 + I2 + m1 * lc1 * lc1 + m2 * (l1 * l1 + lc2 * lc2 + 2 * l1 * lc2 * c2);
    const double M12 = I2 + m2 * (lc2 * lc2 + l1 * lc2 * c2);
    const double M22 = I2 + m2 * lc2 * lc2;
    // dofs sorted: 0 = elbow, 1 = shoulder.
    EXPECT_NEAR(M(1, 1), M11, 1e-12) << "q=" << q1 << "," << q2;
    EXPECT_NEAR(M(1, 0), M12, 1e-12);
    EXPECT_NEAR(M(0, 1), M12, 1e-12);
    EXPECT_NEAR(M(0, 0), M22, 1e-12);
    // Forward kinematics: lower link origin = (−l1 sin q1, 0, 2 − l1 cos q1).
    const Vector3d p = k.X_WB.at("lower").translation();
    EXPECT_NEAR(p.x(), -l1 * std::sin(q1), 1e-12);
    EXPECT_NEAR(p.y(), 0, 1e-12);
    EXPECT_NEAR(p.z(), 2 - l1 * std::cos(q1), 1e-12);
  }
}

TEST(OracleSelfCheck, CartPoleMassMatrixMatchesClosedForm) {
  Oracle o;
  ASSERT_EQ(BuildOracle(HandModel("cart_pole_closed_form.urdf"), &o), "");
  ASSERT_EQ(o.dofs, (std::vector<std::string>{"hinge", "slider"}));
  const double mc = 2, mp = 0.3, l = 0.5, Ip = 0.01;
  for (const auto& [x, th] : std::vector<std::pair<double, double>>{{0, 0}, {0.4, 0.9}, {-1, -2.5}}) {
    const MatrixXd M = ComputeMassMatrix(o, ComputeKinematics(o, {{"slider", x}, {"hinge", th}}));
    EXPECT_NEAR(M(1, 1), mc + mp, 1e-12);
    EXPECT_NEAR(M(0, 1), mp * l * std::cos(th), 1e-12);
    EXPECT_NEAR(M(1, 0), mp * l * std::cos(th), 1e-12);
    EXPECT_NEAR(M(0, 0), Ip + mp * l * l, 1e-12);
  }
}

// URDF-004/005 + COMMON-042: a quarter turn about x swaps Iyy/Izz and flips Iyz.
TEST(OracleSelfCheck, InertiaReexpressedInLinkFrame) {
  Oracle o;
  ASSERT_EQ(BuildOracle(HandModel("inertial_frames.urdf"), &o), "");
  const OLink& L = o.links.at("quarter_turn");
  EXPECT_NEAR(L.I_B(0, 0), 0.05, 1e-15);
  EXPECT_NEAR(L.I_B(1, 1), 0.04, 1e-15);
  EXPECT_NEAR(L.I_B(2, 2), 0.02, 1e-15);
  EXPECT_NEAR(L.I_B(1, 2), -0.004, 1e-15);
  EXPECT_NEAR(L.com.y(), 0.05, 1e-15);
  // Re-expression preserves the trace and the eigenvalues.
  const OLink& S = o.links.at("skewed");
  EXPECT_NEAR(S.I_B.trace(), 0.21 + 0.17 + 0.12, 1e-14);
  EXPECT_TRUE(o.links.at("no_inertial").I_B.isZero(0.0));
  EXPECT_EQ(o.links.at("no_inertial").mass, 0.0);
}

// URDF-012/013: continuous is unbounded; missing lower/upper are unbounded.
TEST(OracleSelfCheck, LimitDefaults) {
  Oracle o;
  ASSERT_EQ(BuildOracle(HandModel("joint_mix.urdf"), &o), "");
  const OJoint& c = o.joints.at("cart_to_spinner");
  EXPECT_EQ(c.lower, -kInf);
  EXPECT_EQ(c.upper, kInf);
  EXPECT_EQ(c.velocity, 7);
  EXPECT_EQ(c.effort, 12);
  const OJoint& w = o.joints.at("arm_to_wrist");
  EXPECT_EQ(w.lower, -kInf);
  EXPECT_EQ(w.upper, kInf);
  const OJoint& f = o.joints.at("wrist_to_free_spin");
  EXPECT_EQ(f.velocity, kInf);
  EXPECT_EQ(f.effort, kInf);
  EXPECT_TRUE(f.axis.isApprox(Vector3d::UnitX()));
  const OJoint& s = o.joints.at("spin_to_slide_tip");
  EXPECT_EQ(s.lower, -kInf);
  EXPECT_EQ(s.upper, 0.02);
  EXPECT_EQ(o.joints.at("rail_to_cart").damping, 3.5);
}

// URDF-011: axes are normalized.
TEST(OracleSelfCheck, AxesNormalized) {
  Oracle o;
  ASSERT_EQ(BuildOracle(HandModel("rotated_axes.urdf"), &o), "");
  EXPECT_TRUE(o.joints.at("j2").axis.isApprox(Vector3d(0, 0.6, 0.8), 1e-15));
  EXPECT_NEAR(o.joints.at("j1").axis.norm(), 1.0, 1e-15);
}

// URDF-012/017: floating children and the root are free bodies at identity,
// and the floating joint separates the kinematic trees.
TEST(OracleSelfCheck, FloatingJointMakesFreeBody) {
  Oracle o;
  ASSERT_EQ(BuildOracle(HandModel("floating_joint.urdf"), &o), "");
  EXPECT_EQ(o.free_bodies, (std::vector<std::string>{"base", "payload"}));
  const Kinematics k = ComputeKinematics(o, {{"base_to_arm", 0.7}});
  EXPECT_TRUE(k.X_WB.at("payload").isApprox(Isometry3d::Identity()));
  EXPECT_EQ(MovingDofs(o, "fingertip"), (std::vector<std::string>{"payload_to_finger"}));
  const MatrixXd M = ComputeMassMatrix(o, k);
  // dofs: base_to_arm, payload_to_finger -- independent trees.
  EXPECT_EQ(M(0, 1), 0.0);
}

// COMMON-040/041 replacement rules.
TEST(OracleSelfCheck, NonPhysicalInertiaReplacement) {
  Oracle o;
  ASSERT_EQ(BuildOracle(HandModel("nonphysical_inertia.urdf"), &o), "");
  const auto sphere = [](double m) {
    const double r = std::cbrt(3.0 / (4.0 * M_PI) * m / 1000.0);
    return 0.4 * m * r * r;
  };
  EXPECT_FALSE(o.links.at("triangle_violation").inertia_note.empty());
  EXPECT_NEAR(o.links.at("triangle_violation").I_B(0, 0), sphere(1.5), 1e-15);
  EXPECT_EQ(o.links.at("zero_mass_with_inertia").mass, 1.0);
  EXPECT_EQ(o.links.at("negative_mass").mass, 1.0);
  EXPECT_TRUE(o.links.at("massless").inertia_note.empty());
  EXPECT_EQ(o.links.at("massless").mass, 0.0);
  EXPECT_TRUE(o.links.at("point_mass").inertia_note.empty());
  EXPECT_FALSE(o.links.at("negative_moment").inertia_note.empty());
  EXPECT_TRUE(o.links.at("base").inertia_note.empty());
}

// Every listed model builds in the oracle, and its mass matrix is symmetric
// positive semi-definite at a random configuration. Set MDLC_ORACLE_VERBOSE=1
// to print what the oracle derived for each model (no mdlc involved).
TEST(OracleSelfCheck, AllModelsBuildWithSaneMassMatrix) {
  std::vector<ModelCase> cases = CorpusCases();
  const auto hand = HandMadeCases();
  cases.insert(cases.end(), hand.begin(), hand.end());
  const bool verbose = EnvInt("MDLC_ORACLE_VERBOSE", 0) != 0;
  for (const auto& mc : cases) {
    if (!mc.skip_reason.empty()) continue;
    Oracle o;
    const std::string err = BuildOracle(mc.path, &o);
    EXPECT_EQ(err, "") << mc.display;
    if (!err.empty()) continue;
    const auto q = Configuration(o, 1);
    const Kinematics k = ComputeKinematics(o, std::map<std::string, double>(q.begin(), q.end()));
    EXPECT_EQ(k.X_WB.size(), o.links.size()) << mc.display << ": links unreachable from the root";
    const MatrixXd M = ComputeMassMatrix(o, k);
    if (M.size() > 0) {
      const double scale = std::max(1.0, M.cwiseAbs().maxCoeff());
      EXPECT_LE((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale) << mc.display;
      Eigen::SelfAdjointEigenSolver<MatrixXd> es(M);
      EXPECT_GE(es.eigenvalues().minCoeff(), -1e-10 * scale) << mc.display;
    }
    if (verbose) {
      int n_fixed = 0, n_float = 0, n_planar = 0;
      for (const auto& [n, J] : o.joints) {
        n_fixed += J.type == JType::kFixed;
        n_float += J.type == JType::kFloating;
        n_planar += J.type == JType::kPlanar;
      }
      std::printf("%-90s links=%zu dofs=%zu fixed=%d floating=%d planar=%d free=%zu root=%s\n",
                  mc.display.c_str(), o.links.size(), o.dofs.size(), n_fixed, n_float, n_planar,
                  o.free_bodies.size(), o.root.c_str());
      for (const auto& [n, L] : o.links) {
        if (!L.inertia_note.empty()) std::printf("    link %s: %s\n", n.c_str(), L.inertia_note.c_str());
      }
    }
  }
}

// kExpectedRejections entries as RunMdlc judges them, on small models of
// its own: a model mdlc rejects for the listed reason is skipped; one mdlc
// accepts is a stale entry, and one it rejects for another reason is a
// failure, both reported instead of skipped (as the SDFormat and MuJoCo
// oracles treat their kKnownDisagreements).
class ExpectedRejectionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("mdlc_urdfdom_expected_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // Runs mdlc on `urdf` as a case listed with `keyword`.
  Dump Run(const std::string& urdf, const std::string& keyword, Report* rep) {
    const fs::path path = dir_ / "listed.urdf";
    std::ofstream(path) << urdf;
    ModelCase mc;
    mc.path = path.string();
    mc.display = "listed.urdf";
    mc.reject_keyword = keyword;
    mc.reject_why = "listed by this test";
    Dump d;
    RunMdlc(mc, {}, rep, &d);
    return d;
  }
  fs::path dir_;
};

// URDF-032: a <visual> without <geometry>, as atlas_with_fixed_joints.urdf
constexpr const char* kVisualWithoutGeometry = R"(<robot name="r">
  <link name="a"><visual><origin xyz="0 0 0"/></visual></link>
</robot>)";
constexpr const char* kFine = R"(<robot name="r">
  <link name="a"><visual><geometry><box size="1 1 1"/></geometry></visual></link>
</robot>)";

TEST_F(ExpectedRejectionTest, RejectedForTheListedReasonIsSkipped) {  // URDF-032
  Report rep("listed.urdf", "urdfdom");
  const Dump d = Run(kVisualWithoutGeometry, "no <geometry>", &rep);
  EXPECT_TRUE(d.rejected_as_expected);
  EXPECT_TRUE(rep.empty());
}

TEST_F(ExpectedRejectionTest, AcceptedIsAStaleEntry) {  // URDF-032
  Report rep("listed.urdf", "urdfdom");
  const Dump d = Run(kFine, "no <geometry>", &rep);
  EXPECT_FALSE(d.rejected_as_expected);
  ASSERT_EQ(rep.size(), 1u);
  EXPECT_NE(rep.messages()[0].find("stale kExpectedRejections entry: mdlc now accepts this file"),
            std::string::npos)
      << rep.messages()[0];
}

TEST_F(ExpectedRejectionTest, RejectedForAnotherReasonFails) {  // URDF-032
  Report rep("listed.urdf", "urdfdom");
  const Dump d = Run(kVisualWithoutGeometry, "unknown joint", &rep);
  EXPECT_FALSE(d.rejected_as_expected);
  ASSERT_EQ(rep.size(), 1u);
  EXPECT_NE(rep.messages()[0].find("exited with status 1"), std::string::npos)
      << rep.messages()[0];
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ParseMdlcFlag(argc, argv);
  console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_ERROR);
  return RUN_ALL_TESTS();
}
