// Differential test: mdlc's plant-json dump of SDFormat models against an
// independent oracle built from libsdformat 12 (the reference SDFormat parser,
// the one Drake's own parser is built on) plus Eigen.
//
// Nothing here uses mdlc library code. For every model the oracle
//   1. loads the file with sdf::Root::Load, resolving package:// and model://
//      the way the corpus needs (a package is a folder holding a package.xml
//      whose <name> is the package; model://NAME may also be a folder NAME
//      beside the file or in one of its ancestors, the Gazebo convention),
//   2. applies the Drake/mdlc conventions of the shared spec (spec/features.md)
//      (cited by feature ID next to each rule): one model instance per SDF
//      model, nested ones named `outer::inner` (SDF-030), merge-included
//      models flattened into the includer (SDF-032, libsdformat does it),
//      world-level <frame>s and <joint>s in WorldModelInstance (SDF-035;
//      libsdformat 12 keeps world joints only as raw elements, so they are
//      read from the element tree and resolved against the frames the oracle
//      computed),
//   3. resolves every pose with libsdformat's SemanticPose().Resolve and every
//      axis with JointAxis::ResolveXyz, then computes link poses at seeded
//      random configurations by forward kinematics over the joint tree and
//      the joint-space mass matrix from body Jacobians, and
//   4. runs `mdlc compile FILE --emit=plant-json --q ...` as a subprocess and
//      compares every quantity by (model_instance, name), never by position,
//      to |a - b| <= 1e-9 * max(1, |a|, |b|).
//
// Configuration (all optional):
//   --mdlc=PATH            or env MDLC_BINARY   (default: compiled-in path)
//   env MDLC_ORACLE_CONFIGS=N   number of random configurations (default 3)
//   env MDLC_ORACLE_MAX_MESSAGES=N  discrepancies printed per test (default 60)
//   env MDLC_ORACLE_EXTRA_MODELS=a.sdf:dir  extra models (Extra/...) to compare
//
// Test layout (value-parameterized, one case per model):
//   Corpus/SdformatOracle.*/<path>    every corpus SDF that libsdformat 12 loads
//   HandMade/SdformatOracle.*/<stem>  tests/models/sdf/*.sdf
//   with two tests per model:
//     MassPropertiesFramesAndJoints  SDF-003/005/006/007/008/010/011/012/030/
//                                    031/032/035/042 at the default configuration
//     KinematicsAndMassMatrix        SDF-003/010/012 X_WB, axis_W and M(q)
//   plus SdformatOracleSelfCheck.* (the oracle against closed forms; no mdlc needed).
// Corpus models where Drake (and so mdlc) legitimately disagrees with
// libsdformat are listed in kKnownDisagreements: skipped with the reason when
// mdlc rejects them, a failure ("stale entry") when mdlc accepts them.

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
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "default_dump.h"
#include "oracle_util.h"
#include <ignition/math/Inertial.hh>
#include <ignition/math/Pose3.hh>
#include <nlohmann/json.hpp>
#include <sdf/Console.hh>
#include <sdf/Element.hh>
#include <sdf/Frame.hh>
#include <sdf/Joint.hh>
#include <sdf/JointAxis.hh>
#include <sdf/Link.hh>
#include <sdf/Model.hh>
#include <sdf/ParserConfig.hh>
#include <sdf/Root.hh>
#include <sdf/SemanticPose.hh>
#include <sdf/World.hh>

namespace {

namespace fs = std::filesystem;
using namespace mdlc::oracle;
using Eigen::Isometry3d;
using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using json = nlohmann::json;

const char* const kWorldInstance = "WorldModelInstance";

// ---------------------------------------------------------------------------
// URI resolution for libsdformat (package:// and model://)
// ---------------------------------------------------------------------------

// Every package.xml under `root`: package name -> folder. The first folder in
// sorted path order wins when two packages share a name.
std::map<std::string, fs::path> IndexPackages(const fs::path& root) {
  std::map<std::string, fs::path> out;
  if (root.empty()) return out;
  std::error_code ec;
  std::vector<fs::path> manifests;
  for (fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec), end;
       !ec && it != end; it.increment(ec)) {
    if (it->path().filename() == "package.xml") manifests.push_back(it->path());
  }
  std::sort(manifests.begin(), manifests.end());
  static const std::regex kName(R"(<name>\s*([^<\s]+)\s*</name>)");
  for (const auto& m : manifests) {
    std::ifstream in(m);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    std::smatch match;
    if (std::regex_search(text, match, kName)) out.emplace(match[1].str(), m.parent_path());
  }
  return out;
}

const std::map<std::string, fs::path>& CorpusPackages() {
  static const std::map<std::string, fs::path> packages = [] {
    const std::string shared = MDLC_SHARED_DIR;
    return shared.empty() ? std::map<std::string, fs::path>{}
                          : IndexPackages(fs::path(shared) / "corpus");
  }();
  return packages;
}

// libsdformat's FindFileCallback: libsdformat 12 itself only looks in its
// URI path map, SDF_PATH and the working directory.
std::string ResolveUri(const std::string& uri, const fs::path& file_dir,
                       const std::map<std::string, fs::path>& packages) {
  std::error_code ec;
  std::string s = uri;
  if (s.rfind("file://", 0) == 0) s = s.substr(7);
  for (const char* scheme : {"package://", "model://"}) {
    const std::string sch = scheme;
    if (s.rfind(sch, 0) != 0) continue;
    const std::string rest = s.substr(sch.size());
    const size_t slash = rest.find('/');
    const std::string name = rest.substr(0, slash);
    const std::string sub = slash == std::string::npos ? "" : rest.substr(slash + 1);
    if (const auto it = packages.find(name); it != packages.end()) {
      const fs::path p = sub.empty() ? it->second : it->second / sub;
      if (fs::exists(p, ec)) return p.string();
    }
    if (sch == "model://") {  // Gazebo: a folder NAME beside the file or above it
      for (fs::path a = file_dir; !a.empty(); a = a.parent_path()) {
        const fs::path p = sub.empty() ? a / name : a / name / sub;
        if (fs::is_directory(a / name, ec) && fs::exists(p, ec)) return p.string();
        if (a == a.root_path() || a.parent_path() == a) break;
      }
    }
    return "";
  }
  const fs::path p(s);
  if (p.is_absolute()) return fs::exists(p, ec) ? p.string() : "";
  if (fs::exists(file_dir / p, ec)) return (file_dir / p).string();
  return "";
}

// ---------------------------------------------------------------------------
// The oracle model, built from libsdformat
// ---------------------------------------------------------------------------

Isometry3d ToIso(const ignition::math::Pose3d& p) {
  Isometry3d X = Isometry3d::Identity();
  const auto& q = p.Rot();
  X.linear() = Quaterniond(q.W(), q.X(), q.Y(), q.Z()).normalized().toRotationMatrix();
  X.translation() = Vector3d(p.Pos().X(), p.Pos().Y(), p.Pos().Z());
  return X;
}

Vector3d ToVec(const ignition::math::Vector3d& v) { return Vector3d(v.X(), v.Y(), v.Z()); }

// SDF-003: fixed-axis roll-pitch-yaw, R = Rz(yaw) Ry(pitch) Rx(roll).
Matrix3d Rpy(double r, double p, double y) {
  return (Eigen::AngleAxisd(y, Vector3d::UnitZ()) * Eigen::AngleAxisd(p, Vector3d::UnitY()) *
          Eigen::AngleAxisd(r, Vector3d::UnitX()))
      .toRotationMatrix();
}

std::string ErrorsText(const sdf::Errors& errors) {
  std::string s;
  for (const auto& e : errors) {
    s += (s.empty() ? "" : " | ") + std::string("[") +
         std::to_string(static_cast<int>(e.Code())) + "] " + e.Message();
    if (s.size() > 1500) break;
  }
  return s;
}

// Joint kinds the oracle tells apart (libsdformat's types, plus drake:joint
// which only Drake reads).
enum class JKind { kRevolute, kContinuous, kPrismatic, kFixed, kBall, kUniversal, kScrew,
                   kRevolute2, kGearbox, kUnknown };

const char* SdfTypeName(JKind k) {
  switch (k) {
    case JKind::kRevolute: return "revolute";
    case JKind::kContinuous: return "continuous";
    case JKind::kPrismatic: return "prismatic";
    case JKind::kFixed: return "fixed";
    case JKind::kBall: return "ball";
    case JKind::kUniversal: return "universal";
    case JKind::kScrew: return "screw";
    case JKind::kRevolute2: return "revolute2";
    case JKind::kGearbox: return "gearbox";
    default: return "unknown";
  }
}

// SDF-010: libsdformat joint type -> plant joint type.
std::string PlantTypeName(JKind k) {
  switch (k) {
    case JKind::kRevolute:
    case JKind::kContinuous: return "revolute";
    case JKind::kPrismatic: return "prismatic";
    case JKind::kFixed: return "weld";
    case JKind::kBall: return "ball";
    case JKind::kUniversal: return "universal";
    case JKind::kScrew: return "screw";
    default: return "";
  }
}

JKind KindFromSdf(sdf::JointType t) {
  switch (t) {
    case sdf::JointType::REVOLUTE: return JKind::kRevolute;
    case sdf::JointType::CONTINUOUS: return JKind::kContinuous;
    case sdf::JointType::PRISMATIC: return JKind::kPrismatic;
    case sdf::JointType::FIXED: return JKind::kFixed;
    case sdf::JointType::BALL: return JKind::kBall;
    case sdf::JointType::UNIVERSAL: return JKind::kUniversal;
    case sdf::JointType::SCREW: return JKind::kScrew;
    case sdf::JointType::REVOLUTE2: return JKind::kRevolute2;
    case sdf::JointType::GEARBOX: return JKind::kGearbox;
    default: return JKind::kUnknown;
  }
}

JKind KindFromString(const std::string& s) {
  for (JKind k : {JKind::kRevolute, JKind::kContinuous, JKind::kPrismatic, JKind::kFixed,
                  JKind::kBall, JKind::kUniversal, JKind::kScrew, JKind::kRevolute2,
                  JKind::kGearbox}) {
    if (s == SdfTypeName(k)) return k;
  }
  return JKind::kUnknown;
}

// 1-dof joints: plant-json reports axis_W and lists them in `dofs`.
bool IsOneDof(JKind k) {
  return k == JKind::kRevolute || k == JKind::kContinuous || k == JKind::kPrismatic ||
         k == JKind::kScrew;
}

// 1-dof joints whose motion the oracle models at random configurations.
bool IsDrivenDof(JKind k) {
  return k == JKind::kRevolute || k == JKind::kContinuous || k == JKind::kPrismatic;
}

struct OBody {
  std::string inst, name, scoped;
  double mass = 0;
  Vector3d com = Vector3d::Zero();  // p_BoBcm in B (SDF-007)
  Matrix3d I_B = Matrix3d::Zero();  // about Bcm, expressed in B
  Isometry3d X_WB0 = Isometry3d::Identity();  // libsdformat's pose = default pose
  bool is_static = false;           // SDF-006: welded to world
  bool deformable = false;          // EXT-070: no rigid mass properties
};

struct OJoint {
  std::string inst, name;
  JKind kind = JKind::kUnknown;
  std::string parent, child;  // scoped body names ("world" for the world)
  Isometry3d X_WJ0 = Isometry3d::Identity();
  Vector3d axis_W0 = Vector3d::UnitZ();  // normalized, 1-dof joints
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool in_static_model = false;
  bool world_level = false;
  std::string Scoped() const { return inst + "::" + name; }
};

struct OFrame {
  std::string inst, name, body;  // body: scoped body name or "world"
  Isometry3d X_WF0 = Isometry3d::Identity();
};

struct Oracle {
  std::vector<std::string> instances;
  std::map<std::string, OBody> bodies;  // by scoped name
  std::vector<OJoint> joints;
  std::vector<OFrame> frames;
  // drake:joint elements (libsdformat does not see them): instance::name.
  std::set<std::string> drake_joints;
  std::set<std::string> drake_joint_children;  // scoped bodies they move
  // World scope: every frame name a world-level element may refer to.
  struct WorldFrame {
    Isometry3d X_WF;
    std::string body;
  };
  std::map<std::string, WorldFrame> world_frames;
  // The tree the oracle can move: child body -> index of its inbound joint.
  std::map<std::string, int> inbound;
  std::string tree_problem;  // non-empty: no random configurations
  std::string mass_matrix_problem;  // non-empty: M(q) is not compared
  std::vector<int> dofs;  // driven 1-dof joints in the tree, sorted by scoped name

  bool HasInstance(const std::string& i) const {
    return std::find(instances.begin(), instances.end(), i) != instances.end();
  }
};

std::string ScopedBody(const std::string& inst, const std::string& link) {
  if (link == "world" || link.empty()) return "world";
  return inst + "::" + link;
}

// The body a frame is attached to, from ResolveAttachedToBody's answer
// (relative to the scope `inst`; "" for the world scope). A static model
// without links resolves to its own model frame, which is fixed to the world
// (SDF-006).
std::string BodyOfAttachment(const std::string& inst, const std::string& resolved) {
  const std::string suffix = "__model__";
  if (resolved.empty() || resolved == "world") return "world";
  if (resolved.size() >= suffix.size() &&
      resolved.compare(resolved.size() - suffix.size(), suffix.size(), suffix) == 0) {
    return "world";
  }
  return inst.empty() ? resolved : inst + "::" + resolved;
}

// Reads `<pose relative_to=...>x y z r p y</pose>` from a raw element.
bool ReadRawPose(const sdf::ElementPtr& e, Isometry3d* X, std::string* relative_to, std::string* err) {
  *X = Isometry3d::Identity();
  relative_to->clear();
  if (!e) return true;
  const sdf::ElementPtr pose = e->FindElement("pose");
  if (!pose) return true;
  if (const auto a = pose->GetAttribute("relative_to")) *relative_to = a->GetAsString();
  if (const auto a = pose->GetAttribute("rotation_format"); a && a->GetAsString() == "quat_xyzw") {
    *err = "world joint pose: quat_xyzw not handled by the oracle";
    return false;
  }
  const bool degrees = [&] {
    const auto a = pose->GetAttribute("degrees");
    return a && (a->GetAsString() == "true" || a->GetAsString() == "1");
  }();
  const auto v = pose->GetValue();
  std::stringstream ss(v ? v->GetAsString() : "");
  double n[6] = {0, 0, 0, 0, 0, 0};
  int count = 0;
  while (count < 6 && ss >> n[count]) ++count;
  if (count != 0 && count != 6) {
    *err = "world joint pose has " + std::to_string(count) + " numbers";
    return false;
  }
  const double s = degrees ? M_PI / 180.0 : 1.0;
  X->linear() = Rpy(n[3] * s, n[4] * s, n[5] * s);
  X->translation() = Vector3d(n[0], n[1], n[2]);
  return true;
}

std::string ChildText(const sdf::ElementPtr& e, const std::string& name) {
  if (!e) return "";
  const sdf::ElementPtr c = e->FindElement(name);
  if (!c || !c->GetValue()) return "";
  std::string s = c->GetValue()->GetAsString();
  s.erase(0, s.find_first_not_of(" \t\r\n"));
  s.erase(s.find_last_not_of(" \t\r\n") + 1);
  return s;
}

class OracleBuilder {
 public:
  explicit OracleBuilder(Oracle* o) : o_(o) {}

  // SDF-030/031/032/006: one instance per model, recursively.
  std::string AddModel(const sdf::Model* m, const std::string& inst, const Isometry3d& X_WM,
                       bool static_parent) {
    const bool is_static = static_parent || m->Static();
    o_->instances.push_back(inst);
    ignition::math::Pose3d p;
    std::string err;
    const auto check = [&](const sdf::Errors& e, const std::string& what) {
      if (!e.empty() && err.empty()) err = what + ": " + ErrorsText(e);
    };
    for (uint64_t i = 0; i < m->LinkCount(); ++i) {
      const sdf::Link* l = m->LinkByIndex(i);
      OBody b;
      b.inst = inst;
      b.name = l->Name();
      b.scoped = ScopedBody(inst, l->Name());
      check(l->SemanticPose().Resolve(p, "__model__"), "link " + b.scoped + " pose");
      b.X_WB0 = X_WM * ToIso(p);  // SDF-003: link pose relative to the model frame
      // SDF-007: mass properties; libsdformat's inertial frame is in the link
      // frame; re-express the inertia in the link frame.
      const ignition::math::Inertiald& in = l->Inertial();
      b.mass = in.MassMatrix().Mass();
      const Isometry3d X_LI = ToIso(in.Pose());
      Matrix3d I_I;
      const auto moi = in.MassMatrix().Moi();
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) I_I(r, c) = moi(r, c);
      }
      const Matrix3d R = X_LI.linear();
      b.I_B = R * I_I * R.transpose();
      b.com = X_LI.translation();
      b.is_static = is_static;
      b.deformable = l->Element() && l->Element()->HasElement("drake:deformable_properties");
      o_->bodies[b.scoped] = b;
      o_->world_frames[b.scoped] = {b.X_WB0, b.scoped};
    }
    // SDF-005: the model frame `__model__`, attached to the canonical link.
    {
      OFrame f;
      f.inst = inst;
      f.name = "__model__";
      const auto canonical = m->CanonicalLinkAndRelativeName();
      f.body = canonical.first ? ScopedBody(inst, canonical.second) : "world";
      f.X_WF0 = X_WM;
      o_->frames.push_back(f);
      o_->world_frames[inst] = {X_WM, f.body};
      o_->world_frames[inst + "::__model__"] = {X_WM, f.body};
    }
    // SDF-042: explicit frames.
    for (uint64_t i = 0; i < m->FrameCount(); ++i) {
      const sdf::Frame* fr = m->FrameByIndex(i);
      OFrame f;
      f.inst = inst;
      f.name = fr->Name();
      check(fr->SemanticPose().Resolve(p, "__model__"), "frame " + inst + "::" + f.name + " pose");
      f.X_WF0 = X_WM * ToIso(p);
      std::string body;
      check(fr->ResolveAttachedToBody(body), "frame " + inst + "::" + f.name + " body");
      f.body = BodyOfAttachment(inst, body);
      o_->frames.push_back(f);
      o_->world_frames[inst + "::" + f.name] = {f.X_WF0, f.body};
    }
    // SDF-010/011/012: joints.
    for (uint64_t i = 0; i < m->JointCount(); ++i) {
      const sdf::Joint* j = m->JointByIndex(i);
      OJoint J;
      J.inst = inst;
      J.name = j->Name();
      J.kind = KindFromSdf(j->Type());
      std::string parent, child;
      check(j->ResolveParentLink(parent), "joint " + J.Scoped() + " parent");
      check(j->ResolveChildLink(child), "joint " + J.Scoped() + " child");
      J.parent = ScopedBody(inst, parent);
      J.child = ScopedBody(inst, child);
      check(j->SemanticPose().Resolve(p, "__model__"), "joint " + J.Scoped() + " pose");
      J.X_WJ0 = X_WM * ToIso(p);  // SDF-003: default relative to the child frame
      if (IsOneDof(J.kind) && j->Axis(0) != nullptr) {
        ignition::math::Vector3d xyz;
        check(j->Axis(0)->ResolveXyz(xyz, "__model__"), "joint " + J.Scoped() + " axis");
        J.axis_W0 = (X_WM.linear() * ToVec(xyz)).normalized();  // SDF-012
        if (J.kind == JKind::kRevolute || J.kind == JKind::kPrismatic) {
          J.lower = j->Axis(0)->Lower();
          J.upper = j->Axis(0)->Upper();
        }
      }
      J.in_static_model = is_static;
      o_->world_frames[J.Scoped()] = {J.X_WJ0, J.child};
      o_->joints.push_back(J);
    }
    // drake:joint (EXT-001): Drake-only joints; the oracle cannot model them.
    if (const sdf::ElementPtr e = m->Element()) {
      for (sdf::ElementPtr c = e->GetFirstElement(); c; c = c->GetNextElement()) {
        if (c->GetName() != "drake:joint") continue;
        const auto a = c->GetAttribute("name");
        if (a) o_->drake_joints.insert(inst + "::" + a->GetAsString());
        const std::string child = ChildText(c, "drake:child");
        if (!child.empty()) o_->drake_joint_children.insert(ScopedBody(inst, child));
      }
    }
    // SDF-030: nested models, pose relative to this model's frame by default.
    for (uint64_t i = 0; i < m->ModelCount(); ++i) {
      const sdf::Model* n = m->ModelByIndex(i);
      check(n->SemanticPose().Resolve(p), "model " + inst + "::" + n->Name() + " pose");
      const std::string e2 = AddModel(n, inst + "::" + n->Name(), X_WM * ToIso(p), is_static);
      if (err.empty()) err = e2;
    }
    return err;
  }

  // SDF-035: world-level frames and joints.
  std::string AddWorld(const sdf::World* w) {
    std::string err;
    ignition::math::Pose3d p;
    o_->world_frames["world"] = {Isometry3d::Identity(), "world"};
    for (uint64_t i = 0; i < w->ModelCount(); ++i) {
      const sdf::Model* m = w->ModelByIndex(i);
      const auto e = m->SemanticPose().Resolve(p, "world");
      if (!e.empty() && err.empty()) err = "model " + m->Name() + " pose: " + ErrorsText(e);
      const std::string e2 = AddModel(m, m->Name(), ToIso(p), false);
      if (err.empty()) err = e2;
    }
    for (uint64_t i = 0; i < w->FrameCount(); ++i) {
      const sdf::Frame* fr = w->FrameByIndex(i);
      OFrame f;
      f.inst = kWorldInstance;
      f.name = fr->Name();
      auto e = fr->SemanticPose().Resolve(p, "world");
      if (!e.empty() && err.empty()) err = "world frame " + f.name + ": " + ErrorsText(e);
      f.X_WF0 = ToIso(p);
      std::string body;
      e = fr->ResolveAttachedToBody(body);
      if (!e.empty() && err.empty()) err = "world frame " + f.name + " body: " + ErrorsText(e);
      f.body = BodyOfAttachment("", body);
      o_->frames.push_back(f);
      o_->world_frames[f.name] = {f.X_WF0, f.body};
    }
    // libsdformat 12 has no DOM for world joints (SDFormat 1.10); they stay
    // in the element tree. Resolve them against the frames computed above.
    const sdf::ElementPtr we = w->Element();
    for (sdf::ElementPtr c = we ? we->GetFirstElement() : nullptr; c; c = c->GetNextElement()) {
      if (c->GetName() != "joint") continue;
      OJoint J;
      J.inst = kWorldInstance;
      J.world_level = true;
      if (const auto a = c->GetAttribute("name")) J.name = a->GetAsString();
      std::string type;
      if (const auto a = c->GetAttribute("type")) type = a->GetAsString();
      J.kind = KindFromString(type);
      const std::string parent = ChildText(c, "parent"), child = ChildText(c, "child");
      const auto pf = o_->world_frames.find(parent);
      const auto cf = o_->world_frames.find(child);
      if (pf == o_->world_frames.end() || cf == o_->world_frames.end()) {
        if (err.empty()) err = "world joint " + J.name + ": unknown parent/child frame";
        continue;
      }
      J.parent = pf->second.body;
      J.child = cf->second.body;
      Isometry3d X_RJ;
      std::string rel, perr;
      if (!ReadRawPose(c, &X_RJ, &rel, &perr)) {
        if (err.empty()) err = perr;
        continue;
      }
      if (rel.empty()) rel = child;  // SDF-003: joint pose default relative to the child
      const auto rf = o_->world_frames.find(rel);
      if (rf == o_->world_frames.end()) {
        if (err.empty()) err = "world joint " + J.name + ": unknown relative_to frame " + rel;
        continue;
      }
      J.X_WJ0 = rf->second.X_WF * X_RJ;
      if (IsOneDof(J.kind)) {
        const sdf::ElementPtr axis = c->FindElement("axis");
        const sdf::ElementPtr xyz = axis ? axis->FindElement("xyz") : nullptr;
        Vector3d v = Vector3d::UnitZ();
        std::string expressed_in;
        if (xyz) {
          std::stringstream ss(xyz->GetValue() ? xyz->GetValue()->GetAsString() : "");
          ss >> v.x() >> v.y() >> v.z();
          if (const auto a = xyz->GetAttribute("expressed_in")) expressed_in = a->GetAsString();
        }
        Matrix3d R = J.X_WJ0.linear();  // SDF-012: default expressed in the joint frame
        if (!expressed_in.empty()) {
          const auto ef = o_->world_frames.find(expressed_in);
          if (ef == o_->world_frames.end()) {
            if (err.empty()) err = "world joint " + J.name + ": unknown expressed_in " + expressed_in;
            continue;
          }
          R = ef->second.X_WF.linear();
        }
        J.axis_W0 = (R * v).normalized();
      }
      o_->world_frames[J.name] = {J.X_WJ0, J.child};
      o_->joints.push_back(J);
    }
    return err;
  }

 private:
  Oracle* o_;
};

// Builds the tree the oracle moves, and decides whether M(q) is comparable.
void AnalyzeTree(Oracle* o) {
  for (size_t i = 0; i < o->joints.size(); ++i) {
    const OJoint& J = o->joints[i];
    if (J.in_static_model) continue;  // SDF-006: the links are welded anyway
    if (!o->bodies.count(J.child)) {
      o->tree_problem = "joint " + J.Scoped() + " has child '" + J.child + "' that is not a link";
      continue;
    }
    if (o->inbound.count(J.child)) {
      o->tree_problem = "body " + J.child + " is the child of two joints (a loop)";
      continue;
    }
    if (o->bodies.at(J.child).is_static) {
      o->tree_problem = "static body " + J.child + " is the child of joint " + J.Scoped();
      continue;
    }
    o->inbound[J.child] = static_cast<int>(i);
  }
  // Cycles through inbound joints.
  for (const auto& [child, ji] : o->inbound) {
    std::string cur = child;
    for (size_t steps = 0; steps <= o->joints.size() + 1; ++steps) {
      const auto it = o->inbound.find(cur);
      if (it == o->inbound.end()) break;
      cur = o->joints[it->second].parent;
      if (cur == child || steps == o->joints.size() + 1) {
        o->tree_problem = "kinematic loop through body " + child;
        break;
      }
    }
  }
  for (size_t i = 0; i < o->joints.size(); ++i) {
    const OJoint& J = o->joints[i];
    const auto it = o->inbound.find(J.child);
    if (it == o->inbound.end() || it->second != static_cast<int>(i)) continue;
    if (IsDrivenDof(J.kind)) o->dofs.push_back(static_cast<int>(i));
    if (!IsDrivenDof(J.kind) && J.kind != JKind::kFixed && o->mass_matrix_problem.empty()) {
      o->mass_matrix_problem = std::string("joint ") + J.Scoped() + " is " + SdfTypeName(J.kind) +
                               " (M(q) compared only for trees of 1-dof and fixed joints)";
    }
  }
  for (const auto& J : o->joints) {
    if (J.in_static_model && J.kind != JKind::kFixed && o->mass_matrix_problem.empty()) {
      o->mass_matrix_problem = "joint " + J.Scoped() + " inside a static model";
    }
  }
  if (!o->drake_joints.empty() && o->mass_matrix_problem.empty()) {
    o->mass_matrix_problem = "drake:joint elements (not modeled by the oracle)";
  }
  if (!o->tree_problem.empty() && o->mass_matrix_problem.empty()) {
    o->mass_matrix_problem = o->tree_problem;
  }
  std::sort(o->dofs.begin(), o->dofs.end(), [&](int a, int b) {
    return o->joints[a].Scoped() < o->joints[b].Scoped();
  });
}

// Loads `path` with libsdformat 12 and builds the oracle. Returns "" or an error.
std::string BuildOracle(const std::string& path, Oracle* o) {
  sdf::ParserConfig config;
  const fs::path dir = fs::absolute(path).parent_path();
  const auto& packages = CorpusPackages();
  config.SetFindCallback([dir, &packages](const std::string& uri) {
    return ResolveUri(uri, dir, packages);
  });
  sdf::Root root;
  const sdf::Errors errors = root.Load(path, config);
  if (!errors.empty()) return "libsdformat 12 rejects " + path + ": " + ErrorsText(errors);
  OracleBuilder builder(o);
  std::string err;
  if (root.Model() != nullptr) {
    // Model file: the top model's own <pose> (after its placement_frame,
    // SDF-005) places it in the world.
    ignition::math::Pose3d p;
    const auto e = root.Model()->SemanticPose().Resolve(p);
    if (!e.empty()) return "top model pose: " + ErrorsText(e);
    err = builder.AddModel(root.Model(), root.Model()->Name(), ToIso(p), false);
  } else if (root.WorldCount() == 1) {
    err = builder.AddWorld(root.WorldByIndex(0));
  } else {
    return "file has neither one model nor one world";
  }
  if (!err.empty()) return err;
  AnalyzeTree(o);
  return "";
}

// ---------------------------------------------------------------------------
// Kinematics and mass matrix of the oracle
// ---------------------------------------------------------------------------

struct Kinematics {
  std::map<std::string, Isometry3d> X_WB;   // every body
  std::map<int, Vector3d> axis_W;           // in-tree 1-dof joints, by index
  std::map<int, Vector3d> origin_W;         // joint frame origin
};

// q: scoped joint name -> position; absent joints stay at zero.
Kinematics ComputeKinematics(const Oracle& o, const std::map<std::string, double>& q) {
  Kinematics k;
  std::function<Isometry3d(const std::string&, int)> pose = [&](const std::string& b, int depth) {
    if (b == "world") return Isometry3d(Isometry3d::Identity());
    if (const auto it = k.X_WB.find(b); it != k.X_WB.end()) return it->second;
    const OBody& B = o.bodies.at(b);
    const auto in = o.inbound.find(b);
    Isometry3d X = B.X_WB0;  // free bodies and welded static links stay put
    if (in != o.inbound.end() && o.tree_problem.empty() && depth < 10000) {
      const int ji = in->second;
      const OJoint& J = o.joints[ji];
      const Isometry3d X_WP0 =
          J.parent == "world" ? Isometry3d::Identity() : o.bodies.at(J.parent).X_WB0;
      const Isometry3d X_PJ = X_WP0.inverse() * J.X_WJ0;
      const Isometry3d X_CJ = B.X_WB0.inverse() * J.X_WJ0;
      const Vector3d a_J = J.X_WJ0.linear().transpose() * J.axis_W0;
      const Isometry3d X_WJ = pose(J.parent, depth + 1) * X_PJ;
      const auto qi = q.find(J.Scoped());
      const double qv = qi == q.end() ? 0.0 : qi->second;
      Isometry3d M = Isometry3d::Identity();
      if (J.kind == JKind::kRevolute || J.kind == JKind::kContinuous) {
        M.linear() = Eigen::AngleAxisd(qv, a_J).toRotationMatrix();
      } else if (J.kind == JKind::kPrismatic) {
        M.translation() = qv * a_J;
      }
      if (IsOneDof(J.kind)) {
        k.axis_W[ji] = X_WJ.linear() * a_J;
        k.origin_W[ji] = X_WJ.translation();
      }
      X = X_WJ * M * X_CJ.inverse();
    }
    k.X_WB[b] = X;
    return X;
  };
  for (const auto& [name, B] : o.bodies) pose(name, 0);
  return k;
}

// Indices of the driven 1-dof joints whose motion moves `body`.
std::vector<int> MovingDofs(const Oracle& o, const std::string& body) {
  std::vector<int> out;
  std::string cur = body;
  for (size_t steps = 0; steps <= o.joints.size(); ++steps) {
    const auto it = o.inbound.find(cur);
    if (it == o.inbound.end()) break;
    if (IsDrivenDof(o.joints[it->second].kind)) out.push_back(it->second);
    cur = o.joints[it->second].parent;
  }
  return out;
}

// M(q) = sum_b (Jv^T m Jv + Jw^T I_W Jw) over the driven dofs, in o.dofs order.
MatrixXd ComputeMassMatrix(const Oracle& o, const Kinematics& k) {
  const int n = static_cast<int>(o.dofs.size());
  std::map<int, int> col_of;
  for (int i = 0; i < n; ++i) col_of[o.dofs[i]] = i;
  MatrixXd M = MatrixXd::Zero(n, n);
  for (const auto& [name, B] : o.bodies) {
    if (B.deformable || (B.mass == 0 && B.I_B.isZero(0.0))) continue;
    const Isometry3d& X_WB = k.X_WB.at(name);
    const Vector3d c = X_WB * B.com;
    const Matrix3d R = X_WB.linear();
    const Matrix3d I_W = R * B.I_B * R.transpose();
    MatrixXd Jv = MatrixXd::Zero(3, n), Jw = MatrixXd::Zero(3, n);
    for (int ji : MovingDofs(o, name)) {
      const int col = col_of.at(ji);
      const Vector3d a = k.axis_W.at(ji);
      if (o.joints[ji].kind == JKind::kPrismatic) {
        Jv.col(col) = a;
      } else {
        Jw.col(col) = a;
        Jv.col(col) = a.cross(c - k.origin_W.at(ji));
      }
    }
    M += B.mass * Jv.transpose() * Jv + Jw.transpose() * I_W * Jw;
  }
  return M;
}

// ---------------------------------------------------------------------------
// Model list
// ---------------------------------------------------------------------------

struct ModelCase {
  std::string id;            // readable test-name suffix
  std::string path;          // absolute path of the SDF ("" => skip)
  std::string display;       // how messages name the model
  std::string package_path;  // passed as --package-path when non-empty
  std::string skip_reason;
  std::string known_disagreement;  // from kKnownDisagreements
};

// Corpus files that libsdformat 12 loads but Drake (and so mdlc, which
// follows Drake) legitimately rejects. When mdlc rejects one, its case is
// skipped with the reason; when mdlc accepts it, the entry is stale and the
// case fails.
// Entries marked `values_differ` are files both accept but where the numbers
// legitimately differ (a feature libsdformat 12 predates); they are always
// skipped.
struct KnownDisagreement {
  const char* path;  // relative to corpus/
  const char* reason;
  bool values_differ = false;
};
constexpr KnownDisagreement kKnownDisagreements[] = {
    {"drake/multibody/parsing/test/sdf_parser_test/joint_parsing_test.sdf",
     "EXT-001: libsdformat does not know drake:joint; in Drake and mdlc the planar and "
     "curvilinear drake:joints connect link6-link7 and link9-link10-link11 at the frames they "
     "name, so those links are not free bodies at their SDF poses",
     true},
    {"sdformat/test/integration/partially_flattened.sdf",
     "SDFormat 1.7 flattened names: libsdformat 12 rebuilds nested models from 'M1::__model__' "
     "frames; mdlc keeps the flattened names in one instance (the bodies' scoped names agree)",
     true},
    {"sdformat/test/sdf/flattened_test_nested_model_with_frames.sdf",
     "SDFormat 1.7 flattened names: libsdformat 12 rebuilds nested models from "
     "'M::__model__' frames; mdlc keeps the flattened names in one instance",
     true},
    {"sdformat/test/sdf/joint_complete.sdf",
     "SDF-010: revolute2 and gearbox joints are not supported by Drake"},
    {"sdformat/test/sdf/world_joint_invalid_child_world.sdf",
     "SDF-035: a world joint whose child is the world is an error (libsdformat 12 ignores "
     "world joints)"},
    {"sdformat/test/sdf/world_joint_invalid_resolved_parent_same_as_child.sdf",
     "SDF-035: a world joint whose parent and child resolve to the same body is an error "
     "(libsdformat 12 ignores world joints)"},
    {"sdformat/test/sdf/joint_axis_invalid_expressed_in.sdf",
     "SDF-012: an axis expressed in an unknown frame is an error (libsdformat 12 loads the file "
     "and reports it only when the axis is resolved)"},
    {"gazebo_models/sun/model.sdf",
     "SDF-002: a file whose only top-level element is a <light> has no model to load"},
    {"gazebo_models/sun/model-1_3.sdf",
     "SDF-002: a file whose only top-level element is a <light> has no model to load"},
    {"gazebo_models/sun/model-1_4.sdf",
     "SDF-002: a file whose only top-level element is a <light> has no model to load"},
    {"sdformat/test/integration/model/test_light/model.sdf",
     "SDF-002: a file whose only top-level element is a <light> has no model to load"},
    {"sdformat/test/integration/model/test_actor/model.sdf",
     "SDF-002: a file whose only top-level element is an <actor> has no model to load"},
    {"sdformat/test/integration/model/model_without_top_level/model.sdf",
     "SDF-002: a file with no <model> or <world> is an error (libsdformat 12 accepts an empty "
     "<sdf>)"},
    {"drake/multibody/parsing/test/sdf_parser_test/negative_damping_joint.sdf",
     "SDF-013: negative joint damping is an error"},
    {"sdformat/test/integration/model/model_with_custom_elements/model.sdf",
     "SDF-014: a revolute joint without <axis> is an error (libsdformat 12 defaults it to z)"},
    {"sdformat/test/sdf/custom_and_unknown_elements.sdf",
     "SDF-001: unknown elements in the SDFormat namespace are errors (libsdformat 12 only warns)"},
    {"sdformat/test/sdf/unrecognized_elements.sdf",
     "SDF-001: unknown elements in the SDFormat namespace are errors (libsdformat 12 only warns)"},
    {"sdformat/test/integration/model/robot/model.sdf",
     "SDF-001: <alwaysOn> (for <always_on>) in a gpu_lidar <sensor> is not an SDFormat element: "
     "an error for every sensor type, as under Drake's policy (libsdformat 12 only warns)"},
    {"gazebo_models/utility_cart/model.sdf", "SDF-010: revolute2 joints are not supported by Drake"},
    {"gazebo_models/utility_cart/model-1_3.sdf", "SDF-010: revolute2 joints are not supported by Drake"},
    {"gazebo_models/utility_cart/model-1_4.sdf", "SDF-010: revolute2 joints are not supported by Drake"},
    {"example-robot-data/robots/cassie_description/robots/cassie_simple.sdf",
     "kinematic loops (a link with two parent joints) are not supported by Drake's plant"},
    {"example-robot-data/robots/cassie_description/robots/cassie_v2.sdf",
     "kinematic loops (a link with two parent joints) are not supported by Drake's plant"},
    {"sdformat/test/sdf/joint_screw_thread_pitch.sdf",
     "several joints share one child link (a loop), which Drake's plant does not support"},
    {"sdformat/test/sdf/world_joint_child_frame.sdf",
     "SDF-035: two world joints share one child link (a loop); libsdformat 12 ignores world joints"},
    {"sdformat/test/sdf/world_joint_parent_frame.sdf",
     "SDF-035: two world joints share one child link (a loop); libsdformat 12 ignores world joints"},
    {"sdformat/test/integration/model/test_model/model.sdf",
     "COMMON: a mesh file that does not exist (meshes/mesh.dae) is an error"},
    {"sdformat/test/integration/model/test_model_with_ns/model.sdf",
     "COMMON: a mesh file that does not exist (meshes/mesh.dae) is an error"},
    {"sdformat/test/integration/model/test_model_with_plugin/model.sdf",
     "COMMON: a mesh file that does not exist (meshes/mesh.dae) is an error"},
    {"sdformat/test/sdf/shapes.sdf",
     "SDF-001/040: <convex_decomposition> (SDFormat 1.11) is unknown to SDFormat 1.9 and an "
     "error (libsdformat 12 only warns); COMMON-010: a mesh fetched over https:// is an error"},
    {"sdformat/test/sdf/shapes_world.sdf",
     "COMMON-010: a mesh fetched over https:// (a Gazebo Fuel URL) is an error; mdlc never "
     "downloads anything"},
    {"sdformat/test/sdf/inertial_stats_auto.sdf",
     "SDF-007: libsdformat 12 predates <inertial auto=\"true\">: it keeps the given/default "
     "inertia where Drake computes it from collision geometry", true},
    {"sdformat/test/sdf/inertial_stats_auto_mass.sdf",
     "SDF-007: libsdformat 12 predates <inertial auto=\"true\">: it keeps the given/default "
     "inertia where Drake computes it from collision geometry", true},
    {"sdformat/test/sdf/mesh_auto_inertial.sdf",
     "SDF-007: libsdformat 12 predates <inertial auto=\"true\">: it keeps the given/default "
     "inertia where Drake computes it from collision geometry", true},
};

// Keeps gtest from dumping the struct's bytes in test listings.
void PrintTo(const ModelCase& c, std::ostream* os) { *os << c.display; }

std::vector<ModelCase> CorpusCases() {
  return ManifestCases<ModelCase>(
      "shared corpus not found (" + CorpusManifest().string() +
          "); the corpus differential test needs ../shared",
      [](const std::vector<std::string>& cols) -> std::optional<ModelCase> {
        if (cols.size() < 7 || cols[0] != "sdf" || cols[6].rfind("yes", 0) != 0) {
          return std::nullopt;
        }
        ModelCase c;
        c.id = Sanitize(WithoutSuffix(WithoutSuffix(cols[1], ".sdf"), ".world"));
        c.path = (CorpusDir() / cols[1]).string();
        c.display = "corpus/" + cols[1];
        c.package_path = CorpusDir().string();
        for (const auto& k : kKnownDisagreements) {
          if (cols[1] != k.path) continue;
          c.known_disagreement = k.reason;
          if (k.values_differ) c.skip_reason = std::string("known disagreement: ") + k.reason;
        }
        return c;
      });
}

std::vector<ModelCase> HandMadeCases() {
  const fs::path dir = TestModels("sdf");
  return FolderCases<ModelCase>(
      dir, ".sdf", "no SDF models in " + dir.string(), [&dir](const fs::path& f) {
        ModelCase c;
        c.id = Sanitize(f.stem().string());
        c.path = f.string();
        c.display = "tests/models/sdf/" + f.filename().string();
        c.package_path = dir.string();
        return c;
      });
}

// ---------------------------------------------------------------------------
// Comparison
// ---------------------------------------------------------------------------

// Runs mdlc on the case at `q` (oracle_util.h); a case listed in
// kKnownDisagreements is skipped when mdlc rejects it, whatever the reason.
bool RunMdlc(const ModelCase& mc, const JointValues& q, Report* rep, Dump* d) {
  std::optional<ListedRejection> listed;
  if (!mc.known_disagreement.empty()) {
    listed = ListedRejection{"kKnownDisagreements", "", mc.known_disagreement};
  }
  // the default configuration: once for the file's two checks (default_dump.h)
  if (q.empty()) return RunMdlcAtDefault(mc.path, mc.package_path, listed, rep, d);
  return mdlc::oracle::RunMdlc(mc.path, mc.package_path, q, listed, rep, d);
}

// Reads a plant-json pose {"p":[..], "q":[w,x,y,z]}.
bool ReadPose(const json& X, Isometry3d* out, std::string* problem) {
  Vector3d p;
  if (!X.is_object() || !ReadVec3(X.value("p", json()), &p) || !X.contains("q") ||
      !X["q"].is_array() || X["q"].size() != 4) {
    *problem = "missing or malformed: " + X.dump().substr(0, 200);
    return false;
  }
  for (int i = 0; i < 4; ++i) {
    if (!X["q"][i].is_number()) {
      *problem = "quaternion has a non-number";
      return false;
    }
  }
  const double w = X["q"][0].get<double>(), x = X["q"][1].get<double>(),
               y = X["q"][2].get<double>(), z = X["q"][3].get<double>();
  const double norm = std::sqrt(w * w + x * x + y * y + z * z);
  problem->clear();
  if (std::abs(norm - 1) > 1e-9) *problem = "quaternion is not unit: |q|=" + Fmt(norm);
  else if (w < 0) *problem = "quaternion has w < 0 (spec: w >= 0): w=" + Fmt(w);
  *out = Isometry3d::Identity();
  out->linear() = Quaterniond(w, x, y, z).normalized().toRotationMatrix();
  out->translation() = p;
  return true;
}

// X_WB of every oracle body against mdlc (SDF-003, SDF-006, SDF-008).
void CheckBodyPoses(const Oracle& o, const Kinematics& k, const Dump& d, Report* rep) {
  for (const auto& [scoped, B] : o.bodies) {
    const auto it = d.bodies.find(Key(B.inst, B.name));
    const std::string ent = "body '" + scoped + "'";
    if (it == d.bodies.end()) {
      rep->Add("SDF-030 " + ent + " missing from mdlc bodies");
      continue;
    }
    Isometry3d X;
    std::string problem;
    if (!ReadPose((*it->second).value("X_WB", json()), &X, &problem)) {
      rep->Add("SDF-003 " + ent + " X_WB " + problem);
      continue;
    }
    if (!problem.empty()) rep->Add("plant-json " + ent + " X_WB " + problem);
    ComparePose(rep, "SDF-003", ent, "X_WB", X, k.X_WB.at(scoped));
  }
}

// Pose in world of a body as mdlc reports it ("world" is the identity).
bool MdlcBodyPose(const Dump& d, const std::string& scoped_body, Isometry3d* X) {
  if (scoped_body == "world") {
    *X = Isometry3d::Identity();
    return true;
  }
  for (const auto& [key, b] : d.bodies) {
    if (key != scoped_body) continue;
    std::string problem;
    return ReadPose(b->value("X_WB", json()), X, &problem);
  }
  return false;
}

// Static checks at the default configuration: instances, mass properties,
// frames, joint types and topology, free bodies and static welds.
void CheckStatic(const Oracle& o, const Dump& d, Report* rep) {
  // --- Instances (SDF-030, COMMON-021).
  std::set<std::string> mdlc_instances;
  if (d.root.contains("model_instances") && d.root["model_instances"].is_array()) {
    for (const auto& i : d.root["model_instances"]) {
      if (i.is_string()) mdlc_instances.insert(i.get<std::string>());
    }
  }
  for (const auto& inst : o.instances) {
    if (!mdlc_instances.count(inst)) rep->Add("SDF-030 model instance '" + inst + "' missing from mdlc");
  }
  // --- Bodies: mass properties (SDF-007).
  for (const auto& [scoped, B] : o.bodies) {
    const auto it = d.bodies.find(Key(B.inst, B.name));
    const std::string ent = "body '" + scoped + "'";
    if (it == d.bodies.end()) continue;  // reported by CheckBodyPoses
    if (B.deformable) continue;  // EXT-070: a deformable body has no rigid inertia to compare
    const json& b = *it->second;
    if (!b.contains("mass") || !b["mass"].is_number()) {
      rep->Add("SDF-007 " + ent + " mass missing/not a number");
    } else {
      rep->Num("SDF-007", ent, "mass", b["mass"].get<double>(), B.mass);
    }
    Vector3d com;
    if (!ReadVec3(b.value("com", json()), &com)) {
      rep->Add("SDF-007 " + ent + " com missing or malformed");
    } else {
      for (int i = 0; i < 3; ++i) rep->Num("SDF-007", ent, "com[" + std::to_string(i) + "]", com(i), B.com(i));
    }
    const json in = b.value("inertia", json());
    if (!in.is_array() || in.size() != 6) {
      rep->Add("SDF-007 " + ent + " inertia missing or not 6 numbers");
    } else {
      static const char* kNames[6] = {"Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz"};
      const double expect[6] = {B.I_B(0, 0), B.I_B(1, 1), B.I_B(2, 2),
                                B.I_B(0, 1), B.I_B(0, 2), B.I_B(1, 2)};
      for (int i = 0; i < 6; ++i) {
        if (!in[i].is_number()) {
          rep->Add("SDF-007 " + ent + " inertia." + kNames[i] + " not a number");
          continue;
        }
        rep->Num("SDF-007", ent, std::string("inertia.") + kNames[i], in[i].get<double>(), expect[i]);
      }
    }
  }
  for (const auto& [key, b] : d.bodies) {
    const std::string inst = b->value("model_instance", "");
    if (inst == kWorldInstance || !o.HasInstance(inst)) continue;
    if (!o.bodies.count(key)) rep->Add("SDF-030 extra body '" + key + "' in mdlc output (not an SDF link)");
  }

  // --- Frames: explicit <frame>s and __model__ (SDF-005, SDF-042, SDF-035).
  for (const auto& f : o.frames) {
    const std::string ent = "frame '" + Key(f.inst, f.name) + "'";
    const std::string feature = f.name == "__model__" ? "SDF-005" : "SDF-042";
    const auto it = d.frames.find(Key(f.inst, f.name));
    if (it == d.frames.end()) {
      rep->Add(feature + " " + ent + " missing from mdlc frames");
      continue;
    }
    const json& fj = *it->second;
    const std::string body = fj.value("body", "");
    if (body != f.body) {
      rep->Add(feature + " " + ent + " body: mdlc='" + body + "' libsdformat='" + f.body + "'");
      continue;
    }
    Isometry3d X_WB, X_BF;
    std::string problem;
    if (!MdlcBodyPose(d, body, &X_WB)) {
      rep->Add(feature + " " + ent + " body '" + body + "' has no X_WB in mdlc output");
      continue;
    }
    if (!ReadPose(fj.value("X_BF", json()), &X_BF, &problem)) {
      rep->Add(feature + " " + ent + " X_BF " + problem);
      continue;
    }
    ComparePose(rep, feature, ent, "X_WF", X_WB * X_BF, f.X_WF0);
  }

  // --- Joints (SDF-010, SDF-011, SDF-012, SDF-035).
  std::set<std::string> expected_joint_keys;
  for (const auto& J : o.joints) {
    const std::string ent = "joint '" + J.Scoped() + "' (" + SdfTypeName(J.kind) + ")";
    expected_joint_keys.insert(J.Scoped());
    const std::string feature = J.world_level ? "SDF-035" : "SDF-010";
    const auto it = d.joints.find(J.Scoped());
    if (it == d.joints.end()) {
      rep->Add(feature + " " + ent + " missing from mdlc joints");
      continue;
    }
    const json& jj = *it->second;
    const std::string type = jj.value("type", "");
    if (type != PlantTypeName(J.kind)) {
      rep->Add(feature + " " + ent + " type: mdlc='" + type + "' libsdformat-mapped='" +
               PlantTypeName(J.kind) + "'");
    }
    if (jj.value("parent", "") != J.parent) {
      rep->Add("SDF-011 " + ent + " parent: mdlc='" + jj.value("parent", "") + "' libsdformat='" +
               J.parent + "'");
    }
    if (jj.value("child", "") != J.child) {
      rep->Add("SDF-011 " + ent + " child: mdlc='" + jj.value("child", "") + "' libsdformat='" +
               J.child + "'");
    }
    if (!IsOneDof(J.kind)) continue;
    Vector3d a;
    if (!ReadVec3(jj.value("axis_W", json()), &a)) {
      rep->Add("SDF-012 " + ent + " axis_W missing or malformed");
      continue;
    }
    for (int i = 0; i < 3; ++i) {
      rep->Num("SDF-012", ent, "axis_W[" + std::to_string(i) + "]", a(i), J.axis_W0(i));
    }
  }
  // Free bodies (SDF-008) and static welds (SDF-006): unnamed joints to world.
  std::map<std::string, std::vector<const json*>> unnamed_by_child;
  for (const auto& [key, j] : d.joints) {
    if (j->value("unnamed", false)) unnamed_by_child[j->value("child", "")].push_back(j);
  }
  std::set<std::string> children;
  for (const auto& J : o.joints) children.insert(J.child);
  for (const auto& [scoped, B] : o.bodies) {
    if (o.drake_joint_children.count(scoped)) continue;  // moved by a drake:joint
    const bool welded = B.is_static;
    if (!welded && children.count(scoped)) continue;
    const char* want = welded ? "weld" : "quaternion_floating";
    bool found = false;
    for (const json* j : unnamed_by_child[scoped]) {
      found = found || (j->value("type", "") == want && j->value("parent", "") == "world");
    }
    if (!found && welded) {
      // A static link may also be welded by a named fixed joint of its model.
      for (const auto& J : o.joints) {
        found = found || (J.child == scoped && J.kind == JKind::kFixed);
      }
    }
    if (!found) {
      rep->Add(std::string(welded ? "SDF-006 static" : "SDF-008 free") + " body '" + scoped +
               "' has no unnamed " + want + " joint to world in mdlc output");
    }
  }
  for (const auto& [key, j] : d.joints) {
    const std::string inst = j->value("model_instance", "");
    if (j->value("unnamed", false) || (!o.HasInstance(inst) && inst != kWorldInstance)) continue;
    if (o.drake_joints.count(key)) continue;
    if (!expected_joint_keys.count(key)) {
      rep->Add("SDF-010 extra joint '" + key + "' (type " + j->value("type", "") + ", child " +
               j->value("child", "") + ") in mdlc output");
    }
  }
}

// Configuration-dependent checks: X_WB, axis_W, dofs, mass matrix.
void CheckKinematics(const Oracle& o, const Kinematics& k, const MatrixXd& M, const Dump& d,
                     bool check_mass_matrix, Report* rep) {
  CheckBodyPoses(o, k, d, rep);
  for (const auto& [ji, a_W] : k.axis_W) {
    const OJoint& J = o.joints[ji];
    const auto it = d.joints.find(J.Scoped());
    if (it == d.joints.end()) continue;  // reported by the static check
    const std::string ent = "joint '" + J.Scoped() + "'";
    Vector3d a;
    if (!ReadVec3((*it->second).value("axis_W", json()), &a)) {
      rep->Add("SDF-012 " + ent + " axis_W missing or malformed");
      continue;
    }
    for (int i = 0; i < 3; ++i) rep->Num("SDF-012", ent, "axis_W[" + std::to_string(i) + "]", a(i), a_W(i));
  }
  if (!check_mass_matrix) return;
  const json& dofs = d.root.value("dofs", json());
  const json& mm = d.root.value("mass_matrix", json());
  if (!dofs.is_array() || !mm.is_array()) {
    rep->Add("plant-json has no dofs/mass_matrix arrays");
    return;
  }
  std::map<std::string, int> mdlc_index;
  for (size_t i = 0; i < dofs.size(); ++i) mdlc_index[dofs[i].get<std::string>()] = static_cast<int>(i);
  std::set<std::string> expected;
  for (int ji : o.dofs) expected.insert(o.joints[ji].Scoped());
  for (const auto& e : expected) {
    if (!mdlc_index.count(e)) rep->Add("SDF-010 dof '" + e + "' missing from mdlc dofs");
  }
  for (const auto& [name, i] : mdlc_index) {
    if (!expected.count(name)) rep->Add("SDF-010 extra dof '" + name + "' in mdlc dofs");
  }
  if (mm.size() != dofs.size()) {
    rep->Add("plant-json mass_matrix has " + std::to_string(mm.size()) + " rows for " +
             std::to_string(dofs.size()) + " dofs");
    return;
  }
  for (size_t i = 0; i < o.dofs.size(); ++i) {
    const auto ri = mdlc_index.find(o.joints[o.dofs[i]].Scoped());
    if (ri == mdlc_index.end()) continue;
    const json& row = mm[ri->second];
    if (!row.is_array() || row.size() != dofs.size()) {
      rep->Add("plant-json mass_matrix row for '" + ri->first + "' malformed");
      continue;
    }
    for (size_t j = 0; j < o.dofs.size(); ++j) {
      const auto cj = mdlc_index.find(o.joints[o.dofs[j]].Scoped());
      if (cj == mdlc_index.end()) continue;
      rep->Num("SDF-010", "mass_matrix", "M(" + ri->first + ", " + cj->first + ")",
               row[cj->second].get<double>(), M(static_cast<int>(i), static_cast<int>(j)));
    }
  }
}

// Deterministic configurations: index 0 = default (no --q), then random ones
// with each driven 1-dof joint uniform in [-1.5, 1.5] clamped into its limits.
std::vector<std::pair<std::string, double>> Configuration(const Oracle& o, int index) {
  std::vector<std::pair<std::string, double>> q;
  if (index == 0 || !o.tree_problem.empty()) return q;
  std::mt19937_64 gen(0x73646663ULL * 1000003ULL + static_cast<uint64_t>(index));
  for (int ji : o.dofs) {
    const OJoint& J = o.joints[ji];
    const double u = static_cast<double>(gen() >> 11) * 0x1.0p-53;
    double v = -1.5 + 3.0 * u;
    if (J.lower <= J.upper) v = std::min(std::max(v, J.lower), J.upper);
    q.emplace_back(J.Scoped(), v);
  }
  return q;
}

// BuildOracle, remembered per file for the life of the test process: each
// file's two checks (and a run of many files, as for the converted models)
// load it with libsdformat once, which is most of a check's time.
std::string CachedOracle(const std::string& path, Oracle* o) {
  static std::map<std::string, std::pair<std::string, Oracle>> built;
  auto it = built.find(path);
  if (it == built.end()) {
    std::pair<std::string, Oracle> entry;
    entry.first = BuildOracle(path, &entry.second);
    it = built.emplace(path, std::move(entry)).first;
  }
  *o = it->second.second;
  return it->second.first;
}

class SdformatOracle : public ::testing::TestWithParam<ModelCase> {
 protected:
  void SetUp() override {
    const ModelCase& mc = GetParam();
    if (!mc.skip_reason.empty()) GTEST_SKIP() << mc.skip_reason;
    const std::string err = CachedOracle(mc.path, &oracle_);
    // A listed disagreement may be a file the oracle cannot build either;
    // mdlc rejecting it skips the case, mdlc accepting it fails it (stale).
    oracle_ok_ = err.empty();
    if (!oracle_ok_ && !mc.known_disagreement.empty()) return;
    ASSERT_TRUE(err.empty()) << "[" << mc.display << "] oracle failed: " << err;
  }
  Oracle oracle_;
  bool oracle_ok_ = false;
};

// SDF-003/005/006/007/008/010/011/012/030/031/032/035/042 at the default
// configuration.
TEST_P(SdformatOracle, MassPropertiesFramesAndJoints) {
  const ModelCase& mc = GetParam();
  Report rep(mc.display, "libsdformat");
  Dump d;
  rep.SetContext("default configuration");
  try {
    if (RunMdlc(mc, {}, &rep, &d) && oracle_ok_) {
      CheckStatic(oracle_, d, &rep);
      CheckBodyPoses(oracle_, ComputeKinematics(oracle_, {}), d, &rep);
    }
  } catch (const json::exception& e) {
    rep.Add(std::string("malformed plant-json (") + e.what() + ")\n    command: " + d.cmdline);
  }
  rep.Flush();
  if (d.rejected_as_expected) GTEST_SKIP() << "known disagreement: " << mc.known_disagreement;
}

// SDF-003/010/012: X_WB, axis_W and M(q) at the default configuration and at
// seeded random ones.
TEST_P(SdformatOracle, KinematicsAndMassMatrix) {
  const ModelCase& mc = GetParam();
  Report rep(mc.display, "libsdformat");
  const int n_random = EnvInt("MDLC_ORACLE_CONFIGS", 3);
  const bool check_m = oracle_.mass_matrix_problem.empty();
  for (int c = 0; c <= n_random; ++c) {
    const auto q = Configuration(oracle_, c);
    if (c > 0 && q.empty()) break;  // no dofs: one configuration is enough
    const Kinematics k = ComputeKinematics(oracle_, std::map<std::string, double>(q.begin(), q.end()));
    const MatrixXd M = check_m ? ComputeMassMatrix(oracle_, k) : MatrixXd();
    rep.SetContext("config " + std::to_string(c) + ", " + DescribeQ(q));
    Dump d;
    const size_t before = rep.size();
    if (!RunMdlc(mc, q, &rep, &d)) {
      if (d.rejected_as_expected) GTEST_SKIP() << "known disagreement: " << mc.known_disagreement;
      break;
    }
    if (!oracle_ok_) break;  // reported as a stale known disagreement
    try {
      CheckKinematics(oracle_, k, M, d, check_m, &rep);
    } catch (const json::exception& e) {
      rep.Add(std::string("malformed plant-json (") + e.what() + ")");
    }
    if (rep.size() > before) rep.Add("reproduce with: " + d.cmdline);
  }
  rep.Flush();
  if (!check_m) {
    std::printf("[ note ] %s: mass matrix not compared: %s\n", mc.display.c_str(),
                oracle_.mass_matrix_problem.c_str());
  }
}

// Ad-hoc models for investigating a discrepancy: MDLC_ORACLE_EXTRA_MODELS is
// a ':'-separated list of .sdf files or directories of them.
std::vector<ModelCase> ExtraCases() {
  std::vector<ModelCase> cases;
  const char* env = std::getenv("MDLC_ORACLE_EXTRA_MODELS");
  std::stringstream ss(env ? env : "");
  for (std::string item; std::getline(ss, item, ':');) {
    if (item.empty()) continue;
    std::vector<fs::path> files;
    if (fs::is_directory(item)) files = FilesWithExtension(item, ".sdf");
    else files.push_back(item);
    for (const auto& f : files) {
      ModelCase c;
      c.id = Sanitize(f.stem().string());
      c.path = fs::absolute(f).string();
      c.display = f.string();
      c.package_path = fs::absolute(f).parent_path().string();
      cases.push_back(c);
    }
  }
  Uniquify(&cases);
  return cases;
}

// What `mdlc convert --to sdf` wrote (issue 14; tests/convert):
// MDLC_ORACLE_CONVERTED_MODELS names the folder. A file holding a
// <drake:joint> (planar) is skipped: libsdformat 12 does not know the
// element, so the links it connects are free bodies there.
std::vector<ModelCase> ConvertedCases() {
  std::vector<ModelCase> cases;
  const char* dir = std::getenv("MDLC_ORACLE_CONVERTED_MODELS");
  if (!dir || !fs::is_directory(dir)) return cases;
  for (const auto& f : FilesWithExtension(dir, ".sdf")) {
    ModelCase c;
    c.id = Sanitize(f.stem().string());
    c.path = fs::absolute(f).string();
    c.display = f.string();
    // no --package-path: the writer refers to meshes by relative paths, and
    // a package path would have mdlc search this folder of hundreds of
    // converted models for package.xml on every run
    std::ifstream in(f);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.find("<drake:joint") != std::string::npos) {
      c.skip_reason =
          "holds <drake:joint>, a Drake extension libsdformat 12 does not know (the links it "
          "connects would be free bodies there)";
    }
    cases.push_back(c);
  }
  Uniquify(&cases);
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Corpus, SdformatOracle, ::testing::ValuesIn(CorpusCases()), CaseName());
INSTANTIATE_TEST_SUITE_P(Converted, SdformatOracle, ::testing::ValuesIn(ConvertedCases()),
                         CaseName());
INSTANTIATE_TEST_SUITE_P(HandMade, SdformatOracle, ::testing::ValuesIn(HandMadeCases()), CaseName());
INSTANTIATE_TEST_SUITE_P(Extra, SdformatOracle, ::testing::ValuesIn(ExtraCases()), CaseName());
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(SdformatOracle);

// ---------------------------------------------------------------------------
// Self-checks of the oracle itself against closed forms (no mdlc involved).
// ---------------------------------------------------------------------------

std::string HandModel(const std::string& file) {
  return (TestModels("sdf") / file).string();
}

const OBody& BodyOf(const Oracle& o, const std::string& scoped) { return o.bodies.at(scoped); }

const OJoint* JointOf(const Oracle& o, const std::string& scoped) {
  for (const auto& J : o.joints) {
    if (J.Scoped() == scoped) return &J;
  }
  return nullptr;
}

const OFrame* FrameOf(const Oracle& o, const std::string& inst, const std::string& name) {
  for (const auto& f : o.frames) {
    if (f.inst == inst && f.name == name) return &f;
  }
  return nullptr;
}

::testing::AssertionResult IsoNear(const Isometry3d& a, const Isometry3d& b, double tol = 1e-12) {
  const double e = std::max((a.translation() - b.translation()).cwiseAbs().maxCoeff(),
                            (a.linear() - b.linear()).cwiseAbs().maxCoeff());
  if (e <= tol) return ::testing::AssertionSuccess();
  std::stringstream ss;
  ss << "poses differ by " << e << "\n" << a.matrix() << "\nvs\n" << b.matrix();
  return ::testing::AssertionFailure() << ss.str();
}

Isometry3d Pose(double x, double y, double z, double r, double p, double yw) {
  Isometry3d X = Isometry3d::Identity();
  X.linear() = Rpy(r, p, yw);
  X.translation() = Vector3d(x, y, z);
  return X;
}

// SDF-003/012/030/042: relative_to chains through nested model frames, an axis
// expressed in __model__, a frame attached to a joint (tests/models/sdf/
// nested_relative_to.sdf, numbers worked out by hand).
TEST(SdformatOracleSelfCheck, SDF003_SDF012_SDF030_SDF042_NestedRelativeToChains) {
  Oracle o;
  ASSERT_EQ(BuildOracle(HandModel("nested_relative_to.sdf"), &o), "");
  EXPECT_EQ(o.instances, (std::vector<std::string>{"arm", "arm::upper", "arm::upper::tip"}));
  const double h = M_PI / 2;
  const Isometry3d X_WM = Pose(1, 0, 0.5, 0, 0, h);
  EXPECT_TRUE(IsoNear(BodyOf(o, "arm::base").X_WB0, Pose(1, 0, 0.6, 0, 0, h)));
  // mount = base + 0.2 z; upper's model frame = mount * (0.3 x, yaw 0.5).
  const Isometry3d X_W_upper = X_WM * Pose(0, 0, 0.3, 0, 0, 0) * Pose(0.3, 0, 0, 0, 0, 0.5);
  EXPECT_TRUE(IsoNear(X_W_upper, Pose(1, 0.3, 0.8, 0, 0, h + 0.5)));
  // upper::link: 0.1 along upper's x, which points at yaw pi/2 + 0.5.
  const Isometry3d& X_WL = BodyOf(o, "arm::upper::link").X_WB0;
  EXPECT_NEAR(X_WL.translation().x(), 1 - 0.1 * std::sin(0.5), 1e-12);
  EXPECT_NEAR(X_WL.translation().y(), 0.3 + 0.1 * std::cos(0.5), 1e-12);
  EXPECT_NEAR(X_WL.translation().z(), 0.8, 1e-12);
  // tip's model frame sits at upper's elbow frame (0.4 along link x), pitched 0.3.
  const Isometry3d X_W_tip = X_WL * Pose(0.4, 0, 0, 0, 0.3, 0);
  const Isometry3d X_W_finger = X_W_tip * Pose(0, 0, 0.05, 0, 0, 0);
  EXPECT_TRUE(IsoNear(BodyOf(o, "arm::upper::tip::finger").X_WB0, X_W_finger));
  EXPECT_TRUE(IsoNear(BodyOf(o, "arm::upper::tip::nail").X_WB0, X_W_finger * Pose(0.02, 0, 0.03, 0.2, 0, 0)));
  EXPECT_TRUE(IsoNear(BodyOf(o, "arm::sensor").X_WB0, Pose(1 - 0.05, 0, 0.8, 0, 0, h)));
  // __model__ frames of the nested instances (SDF-005: canonical = first link).
  const OFrame* f = FrameOf(o, "arm::upper::tip", "__model__");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->body, "arm::upper::tip::finger");
  EXPECT_TRUE(IsoNear(f->X_WF0, X_W_tip));
  // SDF-042: wrist_marker is attached to the wrist joint, whose frame is the
  // child (finger) frame; its body is the joint's child link.
  f = FrameOf(o, "arm", "wrist_marker");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->body, "arm::upper::tip::finger");
  EXPECT_TRUE(IsoNear(f->X_WF0, X_W_finger * Pose(0, 0, 0.01, 0, 0, 0)));
  f = FrameOf(o, "arm::upper::tip", "pad");
  ASSERT_NE(f, nullptr);
  EXPECT_TRUE(IsoNear(f->X_WF0, X_W_finger * Pose(0, 0.01, 0, 0, 0, 0)));
  // SDF-012: shoulder's axis (0 1 0) in __model__ = arm frame (yaw pi/2) -> -x in world.
  const OJoint* shoulder = JointOf(o, "arm::shoulder");
  ASSERT_NE(shoulder, nullptr);
  EXPECT_TRUE(shoulder->axis_W0.isApprox(Vector3d(-1, 0, 0), 1e-12)) << shoulder->axis_W0.transpose();
  EXPECT_EQ(shoulder->parent, "arm::base");
  EXPECT_EQ(shoulder->child, "arm::upper::link");
  EXPECT_TRUE(IsoNear(shoulder->X_WJ0, X_WM * Pose(0, 0, 0.3, 0, 0, 0)));
  // spin: (0 0 1) in tip's model frame; wrist: x of its joint frame = finger frame.
  EXPECT_TRUE(JointOf(o, "arm::upper::tip::spin")->axis_W0.isApprox(X_W_tip.linear() * Vector3d::UnitZ(), 1e-12));
  EXPECT_TRUE(JointOf(o, "arm::wrist")->axis_W0.isApprox(X_W_finger.linear() * Vector3d::UnitX(), 1e-12));
  // SDF-007: a quarter turn about x of the inertial frame swaps Iyy/Izz, flips Iyz.
  const OBody& L = BodyOf(o, "arm::upper::link");
  EXPECT_NEAR(L.I_B(0, 0), 0.05, 1e-15);
  EXPECT_NEAR(L.I_B(1, 1), 0.04, 1e-15);
  EXPECT_NEAR(L.I_B(2, 2), 0.02, 1e-15);
  EXPECT_NEAR(L.I_B(1, 2), -0.004, 1e-15);
  EXPECT_NEAR(L.com.y(), 0.05, 1e-15);
  // The tree: base is free; three dofs (sensor_weld is fixed).
  EXPECT_EQ(o.tree_problem, "");
  EXPECT_EQ(o.mass_matrix_problem, "");
  ASSERT_EQ(o.dofs.size(), 3u);
  EXPECT_EQ(o.joints[o.dofs[0]].Scoped(), "arm::shoulder");
  // Rotating the shoulder by q turns upper::link about the world -x axis
  // through the joint origin.
  const double q = 0.7;
  const Kinematics k = ComputeKinematics(o, {{"arm::shoulder", q}});
  const Vector3d o_J = shoulder->X_WJ0.translation();
  const Matrix3d R = Eigen::AngleAxisd(q, Vector3d(-1, 0, 0)).toRotationMatrix();
  EXPECT_TRUE(k.X_WB.at("arm::upper::link").translation().isApprox(o_J + R * (X_WL.translation() - o_J), 1e-12));
  EXPECT_TRUE(k.X_WB.at("arm::upper::link").linear().isApprox(R * X_WL.linear(), 1e-12));
  EXPECT_TRUE(IsoNear(k.X_WB.at("arm::base"), BodyOf(o, "arm::base").X_WB0));
}

// SDF-005/031/032: placement frames put the named frame at the given pose;
// a merge-include adds its links to the including instance.
TEST(SdformatOracleSelfCheck, SDF005_SDF031_SDF032_PlacementFramesAndIncludes) {
  Oracle o;
  ASSERT_EQ(BuildOracle(HandModel("placement_include.sdf"), &o), "");
  EXPECT_EQ(o.instances, (std::vector<std::string>{"station", "station::left"}));
  // The top model's placement frame `foot` lands at the model pose.
  const OFrame* foot = FrameOf(o, "station", "foot");
  ASSERT_NE(foot, nullptr);
  EXPECT_TRUE(IsoNear(foot->X_WF0, Pose(2, 1, 0, 0, 0, 0.7)));
  // So the table (foot = table * (0.1, 0, -0.4)) is at pose * (-0.1, 0, 0.4).
  EXPECT_TRUE(IsoNear(BodyOf(o, "station::table").X_WB0, Pose(2, 1, 0, 0, 0, 0.7) * Pose(-0.1, 0, 0.4, 0, 0, 0)));
  // The included gripper's `grip` frame lands at table_top * (0 0.3 0, yaw 0.4).
  const OFrame* top = FrameOf(o, "station", "table_top");
  const OFrame* grip = FrameOf(o, "station::left", "grip");
  ASSERT_NE(top, nullptr);
  ASSERT_NE(grip, nullptr);
  EXPECT_TRUE(IsoNear(grip->X_WF0, top->X_WF0 * Pose(0, 0.3, 0, 0, 0, 0.4)));
  // palm = grip * inverse(0 0 0.15, roll pi).
  EXPECT_TRUE(IsoNear(BodyOf(o, "station::left::palm").X_WB0,
                      grip->X_WF0 * Pose(0, 0, 0.15, M_PI, 0, 0).inverse()));
  // Merged links belong to the including instance; their model frame is the
  // include's pose (the included file's own <pose> is replaced).
  ASSERT_TRUE(o.bodies.count("station::palm"));
  ASSERT_TRUE(o.bodies.count("station::finger"));
  EXPECT_TRUE(IsoNear(BodyOf(o, "station::palm").X_WB0, top->X_WF0 * Pose(0, -0.3, 0.2, 0, 0, 0)));
  const OJoint* slide = JointOf(o, "station::slide");
  ASSERT_NE(slide, nullptr);
  EXPECT_EQ(slide->parent, "station::palm");
  EXPECT_EQ(JointOf(o, "station::left::slide")->child, "station::left::finger");
}

// SDF-006: static links keep their poses and are not in the moving tree.
TEST(SdformatOracleSelfCheck, SDF006_StaticModel) {
  Oracle o;
  ASSERT_EQ(BuildOracle(HandModel("static_shelf.sdf"), &o), "");
  for (const auto& [name, B] : o.bodies) EXPECT_TRUE(B.is_static) << name;
  const Isometry3d X_WM = Pose(0.5, -1, 0, 0, 0, -0.3);
  const Isometry3d X_WBoard = X_WM * Pose(0, 0, 0.8, 0, 0.1, 0);
  EXPECT_TRUE(IsoNear(BodyOf(o, "shelf::board").X_WB0, X_WBoard));
  EXPECT_TRUE(IsoNear(BodyOf(o, "shelf::bin::tray").X_WB0,
                      X_WBoard * Pose(0.2, 0, 0.02, 0, 0, 0) * Pose(0, 0, 0.05, 0, 0, 0.2)));
  EXPECT_TRUE(o.dofs.empty());
}

// SDF-035: world joints are read from the element tree; the hinge's mass
// matrix has a closed form because every axis is vertical:
//   M(hinge, hinge) = Izz_base + m_b r_b^2 + Izz_wheel + m_w r_w^2,
//   M(hinge, spin) = M(spin, spin) = Izz_wheel, at every configuration.
TEST(SdformatOracleSelfCheck, SDF035_WorldJointMassMatrix) {
  Oracle o;
  ASSERT_EQ(BuildOracle(HandModel("world_two_models.sdf"), &o), "");
  const OJoint* hinge = JointOf(o, "WorldModelInstance::hinge");
  ASSERT_NE(hinge, nullptr);
  EXPECT_EQ(hinge->parent, "post::pillar");
  EXPECT_EQ(hinge->child, "cart::base");
  EXPECT_TRUE(hinge->axis_W0.isApprox(Vector3d::UnitZ(), 1e-15));
  EXPECT_TRUE(IsoNear(hinge->X_WJ0, Pose(0, 0, 1, 0, 0, 0)));
  const OJoint* anchor = JointOf(o, "WorldModelInstance::anchor");
  ASSERT_NE(anchor, nullptr);
  EXPECT_EQ(anchor->parent, "world");
  const OFrame* dock = FrameOf(o, "WorldModelInstance", "dock");
  ASSERT_NE(dock, nullptr);
  EXPECT_EQ(dock->body, "post::pillar");
  ASSERT_EQ(o.dofs.size(), 2u);  // sorted: WorldModelInstance::hinge, cart::spin
  EXPECT_EQ(o.mass_matrix_problem, "");
  for (const auto& [qh, qs] : std::vector<std::pair<double, double>>{{0, 0}, {0.6, -1.1}, {2.5, 0.3}}) {
    const Kinematics k = ComputeKinematics(o, {{"WorldModelInstance::hinge", qh}, {"cart::spin", qs}});
    const MatrixXd M = ComputeMassMatrix(o, k);
    EXPECT_NEAR(M(0, 0), 0.3 + 3 * 0.7 * 0.7 + 0.02 + 0.5 * 1.4 * 1.4, 1e-12);
    EXPECT_NEAR(M(0, 1), 0.02, 1e-14);
    EXPECT_NEAR(M(1, 0), 0.02, 1e-14);
    EXPECT_NEAR(M(1, 1), 0.02, 1e-14);
    const Vector3d p = k.X_WB.at("cart::wheel").translation();
    EXPECT_NEAR(p.x(), 1.4 * std::cos(qh), 1e-12);
    EXPECT_NEAR(p.y(), 1.4 * std::sin(qh), 1e-12);
    EXPECT_NEAR(p.z(), 1, 1e-12);
  }
}

// Every listed model builds in the oracle, and its mass matrix is symmetric
// positive semi-definite at a random configuration. Set MDLC_ORACLE_VERBOSE=1
// to print what the oracle derived for each model (no mdlc involved).
TEST(SdformatOracleSelfCheck, AllModelsBuildWithSaneMassMatrix) {
  std::vector<ModelCase> cases = CorpusCases();
  const auto hand = HandMadeCases();
  cases.insert(cases.end(), hand.begin(), hand.end());
  const bool verbose = EnvInt("MDLC_ORACLE_VERBOSE", 0) != 0;
  for (const auto& mc : cases) {
    if (!mc.skip_reason.empty()) continue;
    Oracle o;
    const std::string err = BuildOracle(mc.path, &o);
    if (!err.empty() && !mc.known_disagreement.empty()) continue;
    EXPECT_EQ(err, "") << mc.display;
    if (!err.empty()) continue;
    const auto q = Configuration(o, 1);
    const Kinematics k = ComputeKinematics(o, std::map<std::string, double>(q.begin(), q.end()));
    if (o.mass_matrix_problem.empty()) {
      const MatrixXd M = ComputeMassMatrix(o, k);
      if (M.size() > 0) {
        const double scale = std::max(1.0, M.cwiseAbs().maxCoeff());
        EXPECT_LE((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale) << mc.display;
        Eigen::SelfAdjointEigenSolver<MatrixXd> es(M);
        EXPECT_GE(es.eigenvalues().minCoeff(), -1e-10 * scale) << mc.display;
      }
    }
    if (verbose) {
      std::printf("%-90s instances=%zu bodies=%zu joints=%zu frames=%zu dofs=%zu%s%s\n",
                  mc.display.c_str(), o.instances.size(), o.bodies.size(), o.joints.size(),
                  o.frames.size(), o.dofs.size(),
                  o.mass_matrix_problem.empty() ? "" : " | no M: ",
                  o.mass_matrix_problem.c_str());
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ParseMdlcFlag(argc, argv);
  sdf::Console::Instance()->SetQuiet(true);
  return RUN_ALL_TESTS();
}
