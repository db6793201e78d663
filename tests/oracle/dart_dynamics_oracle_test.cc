// Differential test of mdlc's dynamics (mdlc/dynamics.h) against DART 6.12.
//
// Each URDF (DART's DartLoader) and SDFormat file (DART's SdfParser) is
// compiled by mdlc::Compile and read by DART (dart_model_loader.h); the two
// are paired joint by joint and mdlc's state is converted to DART's
// coordinates once (dart_coordinates.h). At a few seeded random states
// (q within limits, v, vdot, tau) the test compares, with mdlc's gravity in
// DART and reflected inertia off:
//   body poses                    BodyPoses             vs getWorldTransform
//   mass matrix                   MassMatrix            vs getMassMatrix
//   inverse dynamics (gravity;    InverseDynamics       vs computeInverseDynamics
//     with and without damping)
//   bias term C v                 BiasTerm              vs getCoriolisForces
//   gravity forces                GravityForces         vs -getGravityForces
//     (DART's g(q) is on the left of M qdd + C + g = tau)
//   forward dynamics (damping     ForwardDynamics       vs computeForwardDynamics
//     on where the model has it, and off)
//   each body's Jacobian at its   JacobianSpatialVelocity(body, world, world)
//     origin                                            vs getWorldJacobian
//   each body's velocity V_WB_W   FrameSpatialVelocity  vs getAngularVelocity,
//                                                          getLinearVelocity
//   and acceleration A_WB_W       BodySpatialAccelerations (backend)
//                                                       vs getAngularAcceleration,
//                                                          getLinearAcceleration
//   center of mass, its velocity  CenterOfMass          vs getCOM,
//     and Jacobian                                         getCOMLinearJacobian
//   kinetic, potential energy     KineticEnergy, PotentialEnergy
//                                                       vs computeKineticEnergy,
//                                                          computePotentialEnergy
// within 1e-8 * (1 + |reference|) (max norms). Models DART cannot read, or
// reads as a different tree, are skipped with the reason. One CTest case per
// model, e.g. HandMade/DartDynamicsOracle.Matches/urdf_joint_mix.
#include <gtest/gtest.h>
#include <unistd.h>

#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/DegreeOfFreedom.hpp>
#include <dart/dynamics/Skeleton.hpp>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "dart_coordinates.h"
#include "dart_model_loader.h"
#include "mdlc/dynamics.h"
#include "mdlc/kinematics.h"
#include "mdlc/mdlc.h"
#include "oracle_util.h"

namespace mdlc::oracle {
namespace {

namespace fs = std::filesystem;
using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr double kTol = 1e-8;
constexpr int kStates = 3;

// ---------------------------------------------------------------------------
// Model list
// ---------------------------------------------------------------------------

struct ModelCase {
  std::string id;
  std::string path;
  std::string display;
  std::string package_path;  // searched for package:// URIs by mdlc
  std::string skip_reason;
  std::string text;  // the model itself, written to `path` first, when set
};

void PrintTo(const ModelCase& c, std::ostream* os) { *os << c.display; }

std::vector<ModelCase> HandMadeCases() {
  std::vector<ModelCase> cases;
  for (const auto& [sub, ext] : {std::pair{"urdf", ".urdf"}, std::pair{"sdf", ".sdf"}}) {
    const fs::path dir = TestModels(sub);
    for (const fs::path& f : FilesWithExtension(dir, ext)) {
      ModelCase c;
      c.id = Sanitize(std::string(sub) + "_" + f.stem().string());
      c.path = f.string();
      c.display = "tests/models/" + std::string(sub) + "/" + f.filename().string();
      c.package_path = dir.string();
      cases.push_back(c);
    }
  }
  Uniquify(&cases);
  return cases;
}

// The hand-made SDFormat models use SDFormat 1.9's frames, which DART's
// SdfParser cannot read; this one is in 1.6 for it: a free body with a posed
// model and an offset, rotated center of mass, a ball joint and a universal
// joint with offset and rotated joint frames, and a damped revolute joint.
constexpr char kBallUniversal16[] = R"(<?xml version="1.0"?>
<sdf version="1.6">
  <model name="ball_universal_16">
    <pose>0.1 -0.2 0.3 0.2 -0.1 0.4</pose>
    <link name="base">
      <pose>0.5 0 1 0.3 0.2 0.1</pose>
      <inertial>
        <pose>0.01 0.02 -0.03 0 0 0</pose>
        <mass>3</mass>
        <inertia><ixx>0.1</ixx><iyy>0.2</iyy><izz>0.25</izz>
                 <ixy>0.01</ixy><ixz>0</ixz><iyz>0.02</iyz></inertia>
      </inertial>
    </link>
    <link name="arm">
      <pose>0.5 0.1 0.6 0 0.4 0.2</pose>
      <inertial>
        <pose>0 0 -0.15 0 0 0</pose>
        <mass>1.2</mass>
        <inertia><ixx>0.02</ixx><iyy>0.03</iyy><izz>0.01</izz>
                 <ixy>0</ixy><ixz>0.001</ixz><iyz>0</iyz></inertia>
      </inertial>
    </link>
    <joint name="shoulder" type="ball">
      <parent>base</parent>
      <child>arm</child>
      <pose>0 0 0.1 0.3 -0.2 0.5</pose>
    </joint>
    <link name="hand">
      <pose>0.45 0.1 0.3 0.2 0.4 0</pose>
      <inertial>
        <pose>0.02 0 -0.05 0 0 0</pose>
        <mass>0.6</mass>
        <inertia><ixx>0.004</ixx><iyy>0.005</iyy><izz>0.003</izz>
                 <ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia>
      </inertial>
    </link>
    <joint name="wrist" type="universal">
      <parent>arm</parent>
      <child>hand</child>
      <pose>0 0.01 0.05 0 0 0.3</pose>
      <axis><xyz>1 0 0</xyz></axis>
      <axis2><xyz>0 1 0</xyz></axis2>
    </joint>
    <link name="finger">
      <pose>0.45 0.12 0.2 0 0 0</pose>
      <inertial>
        <pose>0 0 -0.03 0 0 0</pose>
        <mass>0.1</mass>
        <inertia><ixx>0.0002</ixx><iyy>0.0002</iyy><izz>0.0001</izz>
                 <ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia>
      </inertial>
    </link>
    <joint name="knuckle" type="revolute">
      <parent>hand</parent>
      <child>finger</child>
      <pose>0 0 0.02 0 0 0</pose>
      <axis>
        <xyz>0.6 0 0.8</xyz>
        <limit><lower>-1</lower><upper>1.2</upper></limit>
        <dynamics><damping>0.3</damping></dynamics>
      </axis>
    </joint>
  </model>
</sdf>
)";

// The inline models, written out where the test runs (DART reads files).
std::vector<ModelCase> InlineCases() {
  ModelCase c;
  c.id = "sdf16_ball_universal";
  c.display = "ball_universal_16.sdf (inline, SDFormat 1.6)";
  c.text = kBallUniversal16;
  return {c};
}

// The corpus's URDF and SDFormat files that its reference tools load.
std::vector<ModelCase> CorpusCases() {
  return ManifestCases<ModelCase>(
      "shared corpus not found; the corpus comparison needs ../shared",
      [](const std::vector<std::string>& cols) -> std::optional<ModelCase> {
        if (cols.size() < 7 || (cols[0] != "urdf" && cols[0] != "sdf")) return std::nullopt;
        if (cols[6].rfind("yes", 0) != 0) return std::nullopt;
        ModelCase c;
        c.id = Sanitize(fs::path(cols[1]).replace_extension().string());
        c.path = (CorpusDir() / cols[1]).string();
        c.display = "corpus/" + cols[1];
        c.package_path = CorpusDir().string();
        return c;
      });
}

// ---------------------------------------------------------------------------
// Comparison helpers
// ---------------------------------------------------------------------------

// Largest error of each quantity over the model's states, for the log.
struct Errors {
  WorstErrors max_error;
  int compared = 0;
};

// |mdlc - dart|_max <= kTol * (1 + max(|dart|_max, scale)); records the
// error relative to that. `scale` is the size of what round-off grows with
// where that exceeds the result (the bias term's w x I w).
void ExpectNear(const std::string& what, const MatrixXd& mdlc, const MatrixXd& dart, int state,
                Errors* errors, double scale = 0) {
  ASSERT_EQ(mdlc.rows(), dart.rows()) << what;
  ASSERT_EQ(mdlc.cols(), dart.cols()) << what;
  const double error = MaxAbs(mdlc - dart) / (1 + std::max(MaxAbs(dart), scale));
  RecordWorst(&errors->max_error, what, error);
  ++errors->compared;
  EXPECT_LE(error, kTol) << what << " at state " << state << " differs (relative error " << error
                         << ")\nmdlc:\n"
                         << mdlc << "\nDART (in mdlc's coordinates):\n"
                         << dart;
}

void ExpectNear(const std::string& what, double mdlc, double dart, int state, Errors* errors) {
  ExpectNear(what, MatrixXd::Constant(1, 1, mdlc), MatrixXd::Constant(1, 1, dart), state, errors);
}

double Uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// A random q: 1-dof joints within their limits (clipped to [-pi, pi] or
// [-1, 1] m), a random rotation for ball and floating joints.
VectorXd RandomPositions(const backend::Plant& plant, std::mt19937& rng) {
  VectorXd q = VectorXd::Zero(plant.num_positions);
  for (JointId id : plant.joint_order) {
    const backend::PlantJoint& j = plant.joint(id);
    switch (j.type) {
      case ir::JointType::QuaternionFloating: {
        Eigen::Vector4d quat;
        std::normal_distribution<double> normal;
        for (int k = 0; k < 4; ++k) quat(k) = normal(rng);
        q.segment<4>(j.q_start) = quat.normalized();
        for (int k = 4; k < 7; ++k) q(j.q_start + k) = Uniform(rng, -1, 1);
        break;
      }
      case ir::JointType::Ball:
        for (int k = 0; k < 3; ++k) q(j.q_start + k) = Uniform(rng, -1, 1);
        break;
      default:
        for (int k = 0; k < j.nq; ++k) {
          const double reach = j.type == ir::JointType::Prismatic ? 1.0 : M_PI;
          double lo = std::max(j.lower[k], -reach), hi = std::min(j.upper[k], reach);
          if (lo > hi) lo = hi = std::isfinite(j.lower[k]) ? j.lower[k] : j.upper[k];
          q(j.q_start + k) = Uniform(rng, lo, hi);
        }
    }
  }
  return q;
}

VectorXd RandomVector(int n, std::mt19937& rng) {
  VectorXd x(n);
  for (int i = 0; i < n; ++i) x(i) = Uniform(rng, -1, 1);
  return x;
}

// DART's quantities, each over all skeletons (stacked or block diagonal).
MatrixXd DartMassMatrix(const DartPairing& p) {
  MatrixXd M = MatrixXd::Zero(p.nv, p.nv);
  for (size_t k = 0; k < p.skeletons.size(); ++k) {
    const int o = p.skeleton_v_start[k], n = static_cast<int>(p.skeletons[k]->getNumDofs());
    M.block(o, o, n, n) = p.skeletons[k]->getMassMatrix();
  }
  return M;
}

template <typename Get>
VectorXd DartStacked(const DartPairing& p, Get get) {
  VectorXd x = VectorXd::Zero(p.nv);
  for (size_t k = 0; k < p.skeletons.size(); ++k) {
    const int n = static_cast<int>(p.skeletons[k]->getNumDofs());
    x.segment(p.skeleton_v_start[k], n) = get(*p.skeletons[k]);
  }
  return x;
}

double DartSum(const DartPairing& p, double (*get)(const dart::dynamics::Skeleton&)) {
  double sum = 0;
  for (const auto& s : p.skeletons) sum += get(*s);
  return sum;
}

// The dofs' damping as DART read it, and setting it all to `scale` times that.
VectorXd DartDamping(const DartPairing& p) {
  VectorXd d = VectorXd::Zero(p.nv);
  for (size_t k = 0; k < p.skeletons.size(); ++k) {
    for (size_t i = 0; i < p.skeletons[k]->getNumDofs(); ++i) {
      d(p.skeleton_v_start[k] + static_cast<int>(i)) =
          p.skeletons[k]->getDof(i)->getDampingCoefficient();
    }
  }
  return d;
}

void SetDartDamping(const DartPairing& p, const VectorXd& d) {
  for (size_t k = 0; k < p.skeletons.size(); ++k) {
    for (size_t i = 0; i < p.skeletons[k]->getNumDofs(); ++i) {
      p.skeletons[k]->getDof(i)->setDampingCoefficient(d(p.skeleton_v_start[k] + static_cast<int>(i)));
    }
  }
}

// True when (mass, I_Bcm) could be a rigid body's, with no tolerance: mass
// >= 0 (0 only with zero inertia), principal moments >= 0 and obeying the
// triangle inequality.
bool PhysicalInertia(double mass, const Eigen::Matrix3d& I) {
  if (mass < 0 || (mass == 0 && !I.isZero(0))) return false;
  const Eigen::Vector3d m = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
  return m.minCoeff() >= 0 && m(0) + m(1) >= m(2);
}

// Each body's mass, center of mass and rotational inertia as DART read them
// must be mdlc's, except where the spec has mdlc replace an impossible one
// (COMMON-040/041: negative mass, moments breaking the triangle inequality,
// ...), which DART keeps: DART is then given mdlc's, and `replaced` names
// the body; so too where DART lost the inertia's axes (`rotated`). Returns
// the first real difference ("" when none).
std::string ReconcileInertias(const backend::Plant& plant, const DartPairing& pairing,
                              std::string* replaced, std::string* rotated) {
  for (size_t b = 0; b < plant.bodies.size(); ++b) {
    dart::dynamics::BodyNode* node = pairing.bodies[b];
    if (!node) continue;
    const backend::PlantBody& body = plant.bodies[b];
    const dart::dynamics::Inertia& inertia = node->getInertia();
    const double tol = 1e-12 * (1 + std::abs(body.mass) + body.I_BBcm_B.cwiseAbs().maxCoeff());
    if (std::abs(inertia.getMass() - body.mass) <= tol &&
        (inertia.getLocalCOM() - body.p_BoBcm_B).cwiseAbs().maxCoeff() <= 1e-12 &&
        (inertia.getMoment() - body.I_BBcm_B).cwiseAbs().maxCoeff() <= tol) {
      continue;
    }
    const std::string name = plant.ScopedName(body);
    // DART 6.12's SdfParser drops the rotation of <inertial><pose>: the same
    // mass, center and principal moments in other axes.
    const auto moments = [](const Eigen::Matrix3d& I) {
      return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
    };
    if (std::abs(inertia.getMass() - body.mass) <= tol &&
        (inertia.getLocalCOM() - body.p_BoBcm_B).cwiseAbs().maxCoeff() <= 1e-12 &&
        (moments(inertia.getMoment()) - moments(body.I_BBcm_B)).cwiseAbs().maxCoeff() <= 1e-9 * (1 + body.I_BBcm_B.cwiseAbs().maxCoeff())) {
      node->setMomentOfInertia(body.I_BBcm_B(0, 0), body.I_BBcm_B(1, 1), body.I_BBcm_B(2, 2),
                               body.I_BBcm_B(0, 1), body.I_BBcm_B(0, 2), body.I_BBcm_B(1, 2));
      *rotated += (rotated->empty() ? "" : " ") + name;
      continue;
    }
    if (PhysicalInertia(inertia.getMass(), inertia.getMoment())) {
      std::ostringstream out;
      out << "body " << name << ": mdlc mass " << body.mass << ", com "
          << body.p_BoBcm_B.transpose() << ", inertia\n"
          << body.I_BBcm_B << "\nDART mass " << inertia.getMass() << ", com "
          << inertia.getLocalCOM().transpose() << ", inertia\n"
          << inertia.getMoment();
      return out.str();
    }
    node->setInertia(dart::dynamics::Inertia(body.mass, body.p_BoBcm_B, body.I_BBcm_B));
    *replaced += (replaced->empty() ? "" : " ") + name;
  }
  return "";
}

// ---------------------------------------------------------------------------
// The test
// ---------------------------------------------------------------------------

class DartDynamicsOracle : public ::testing::TestWithParam<ModelCase> {};

TEST_P(DartDynamicsOracle, Matches) {
  const ModelCase& mc = GetParam();
  if (!mc.skip_reason.empty()) GTEST_SKIP() << mc.skip_reason;
  std::string path = mc.path;
  // An inline model goes to a folder of this process, removed on the way out.
  struct RemoveOnExit {
    fs::path dir;
    ~RemoveOnExit() {
      std::error_code ec;
      if (!dir.empty()) fs::remove_all(dir, ec);
    }
  } scratch;
  if (!mc.text.empty()) {
    scratch.dir = fs::temp_directory_path() /
                  ("mdlc_dart_oracle_" + std::to_string(static_cast<long>(getpid())));
    fs::create_directories(scratch.dir);
    path = (scratch.dir / (mc.id + ".sdf")).string();
    std::ofstream(path) << mc.text;
  }

  // DART first, while the process has one thread (mdlc's compile may start
  // more), and so that a file DART cannot read costs no compile.
  if (const std::string crash = DartCrashesOn(path); !crash.empty()) GTEST_SKIP() << crash;
  DartModel dart = LoadDartModel(path);
  if (!dart.skip_reason.empty()) GTEST_SKIP() << "DART: " << dart.skip_reason;

  Options options;
  options.meshes.reader = MeshReader::InProcess;
  if (const char* cache = std::getenv("MDLC_CACHE_DIR")) options.meshes.cache_dir = cache;
  if (!mc.package_path.empty()) options.packages.paths.push_back(mc.package_path);
  const Result result = Compile(Input::File(path), options);
  if (!result.ok() || !result.has_model()) {
    std::string first;
    for (const Diagnostic& d : result.diagnostics()) {
      if (d.severity == Severity::Error) {
        first = d.message;
        break;
      }
    }
    GTEST_SKIP() << "mdlc does not compile " << mc.display << " (no dynamics to compare): "
                 << first;
  }
  const backend::Plant& plant = result.plant();

  for (const backend::PlantBody& body : plant.bodies) {
    if (body.deformable) {
      GTEST_SKIP() << "deformable body " << plant.ScopedName(body)
                   << " (massless in mdlc's rigid dynamics, a rigid link to DART)";
    }
  }
  DartPairing pairing;
  const std::string unpaired = PairWithDart(plant, dart.skeletons, &pairing);
  if (!unpaired.empty()) GTEST_SKIP() << "DART reads another tree: " << unpaired;
  for (const auto& s : pairing.skeletons) {
    s->setGravity(plant.gravity);
    // mdlc, like Drake, ignores SDFormat's <gravity>false</gravity> on a link
    // (it warns); DART honours it.
    for (size_t i = 0; i < s->getNumBodyNodes(); ++i) s->getBodyNode(i)->setGravityMode(true);
    for (size_t i = 0; i < s->getNumDofs(); ++i) s->getDof(i)->setSpringStiffness(0);
  }
  std::string replaced, rotated;
  const std::string inertia_differs = ReconcileInertias(plant, pairing, &replaced, &rotated);
  ASSERT_TRUE(inertia_differs.empty()) << "mass properties differ: " << inertia_differs;

  // The damping both read must agree before dynamics with it can.
  const VectorXd damping = DartDamping(pairing);
  VectorXd damping_mdlc = VectorXd::Zero(plant.num_velocities);
  for (const JointPair& pair : pairing.joints) {
    const backend::PlantJoint& j = plant.joint(pair.joint);
    for (int k = 0; k < j.nv; ++k) damping_mdlc(j.v_start + k) = j.damping[k];
  }
  const bool has_damping = MaxAbs(damping) > 0 || MaxAbs(damping_mdlc) > 0;

  DynamicsOptions rigid;  // gravity on; damping, force elements, reflected inertia off
  rigid.reflected_inertia = false;
  DynamicsOptions damped = rigid;
  damped.joint_damping = true;

  // DART's articulated-body algorithm asserts on a NaN articulated inertia,
  // which a massless body can give even where M is invertible; there the
  // reference solves DART's M vdot = tau - C - g - D v instead.
  bool aba_safe = true;
  for (dart::dynamics::BodyNode* node : pairing.bodies) {
    if (node && (node->getMass() <= 0 ||
                 Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(node->getInertia().getMoment())
                         .eigenvalues()
                         .minCoeff() <= 0)) {
      aba_safe = false;
    }
  }

  Errors errors;
  bool fd_singular = false, fd_not_thrown = false;
  std::mt19937 rng(20261207);
  for (int state = 0; state < kStates; ++state) {
    const VectorXd q = RandomPositions(plant, rng);
    const VectorXd v = RandomVector(plant.num_velocities, rng);
    const VectorXd vdot = RandomVector(plant.num_velocities, rng);
    const VectorXd tau = RandomVector(plant.num_velocities, rng);
    const DartState d = ToDartState(plant, pairing, q, v);
    const MatrixXd T = d.T;
    const MatrixXd T_inv = T.inverse();
    const MatrixXd T_inv_T = T_inv.transpose();  // forces: tau_mdlc = T^-T tau_dart
    const VectorXd vdot_dart = T_inv * (vdot - d.a);
    SetDartPositions(pairing, d.q);
    SetDartVelocities(pairing, d.v);

    // Poses first: they check the position conversion and the pairing.
    const std::vector<Transform> X_WB = BodyPoses(result, q);
    for (size_t b = 0; b < plant.bodies.size(); ++b) {
      if (!pairing.bodies[b]) continue;
      const Eigen::Isometry3d X = pairing.bodies[b]->getWorldTransform();
      MatrixXd mine(3, 4), theirs(3, 4);
      mine << X_WB[b].R, X_WB[b].p;
      theirs << X.linear(), X.translation();
      ExpectNear("pose of " + plant.ScopedName(plant.bodies[b]), mine, theirs, state, &errors);
    }
    if (HasFailure()) break;  // nothing else can agree

    const MatrixXd M_dart = DartMassMatrix(pairing);
    ExpectNear("mass_matrix", MassMatrix(result, q), T_inv_T * M_dart * T_inv, state, &errors);

    SetDartAccelerations(pairing, vdot_dart);
    const VectorXd id_dart = DartStacked(pairing, [](dart::dynamics::Skeleton& s) {
      s.computeInverseDynamics(false, false, false);
      return VectorXd(s.getForces());
    });
    ExpectNear("inverse_dynamics", InverseDynamics(result, q, v, vdot, rigid), T_inv_T * id_dart,
               state, &errors);
    // Each body's acceleration at vdot: [alpha; classical a of Bo] in W.
    const std::vector<backend::Vector6d> A_WB =
        backend::BodySpatialAccelerations(plant, q, v, vdot);
    for (size_t b = 0; b < plant.bodies.size(); ++b) {
      dart::dynamics::BodyNode* node = pairing.bodies[b];
      if (!node) continue;
      Eigen::Matrix<double, 6, 1> A;
      A << node->getAngularAcceleration(), node->getLinearAcceleration();
      ExpectNear("spatial_acceleration of " + plant.ScopedName(plant.bodies[b]), A_WB[b], A, state,
                 &errors);
    }
    if (has_damping) {
      // DART's inverse dynamics damps v + time_step * vdot (its implicit
      // damping; the time step must be positive); mdlc's, like Drake's,
      // damps v: the time step's share is taken back out.
      const VectorXd id_damped = DartStacked(pairing, [](dart::dynamics::Skeleton& s) {
        s.computeInverseDynamics(false, true, false);
        VectorXd implicit(s.getNumDofs());
        for (size_t i = 0; i < s.getNumDofs(); ++i) {
          implicit(i) = s.getDof(i)->getDampingCoefficient() * s.getTimeStep() *
                        s.getDof(i)->getAcceleration();
        }
        return VectorXd(s.getForces() - implicit);
      });
      ExpectNear("inverse_dynamics_damped", InverseDynamics(result, q, v, vdot, damped),
                 T_inv_T * id_damped, state, &errors);
    }

    // mdlc's C v holds vdot_mdlc = 0, which is vdot_dart = -T^-1 a.
    const VectorXd coriolis = DartStacked(pairing, [](dart::dynamics::Skeleton& s) {
      return VectorXd(s.getCoriolisForces());
    });
    const MatrixXd M_mdlc_coords = T_inv_T * M_dart * T_inv;
    ExpectNear("bias_term", BiasTerm(result, q, v), T_inv_T * (coriolis - M_dart * T_inv * d.a),
               state, &errors, MaxAbs(M_mdlc_coords) * MaxAbs(v) * MaxAbs(v));
    const VectorXd gravity = DartStacked(pairing, [](dart::dynamics::Skeleton& s) {
      return VectorXd(s.getGravityForces());
    });
    ExpectNear("gravity_forces", GravityForces(result, q), -(T_inv_T * gravity), state, &errors);

    // Forward dynamics, without damping, then with it where there is some;
    // not where M is singular (a massless body at the end of a joint, a
    // point mass turning about itself), for which mdlc should throw.
    bool singular = false;
    if (pairing.nv > 0) {
      const VectorXd eigenvalues =
          Eigen::SelfAdjointEigenSolver<MatrixXd>(M_mdlc_coords).eigenvalues();
      singular = eigenvalues.minCoeff() <= 1e-12 * eigenvalues.cwiseAbs().maxCoeff();
    }
    for (const bool with_damping : {false, true}) {
      if (with_damping && !has_damping) continue;
      VectorXd vdot_mdlc;
      try {
        vdot_mdlc = ForwardDynamics(result, q, v, tau, with_damping ? damped : rigid);
      } catch (const std::domain_error&) {
        fd_singular = true;
        break;
      }
      if (singular) {
        fd_singular = true;
        fd_not_thrown = true;
        break;
      }
      const VectorXd d_used = with_damping ? damping : VectorXd::Zero(pairing.nv);
      SetDartDamping(pairing, d_used);
      SetDartForces(pairing, T.transpose() * tau);
      VectorXd fd;
      if (aba_safe) {
        fd = DartStacked(pairing, [](dart::dynamics::Skeleton& s) {
          s.computeForwardDynamics();
          return VectorXd(s.getAccelerations());
        });
      } else {
        fd = M_dart.ldlt().solve(T.transpose() * tau - coriolis - gravity -
                                 d_used.cwiseProduct(d.v));
      }
      ExpectNear(with_damping ? "forward_dynamics_damped" : "forward_dynamics", vdot_mdlc,
                 T * fd + d.a, state, &errors);
    }
    SetDartDamping(pairing, damping);

    // Each body's Jacobian at its origin, in the world.
    for (size_t b = 0; b < plant.bodies.size(); ++b) {
      dart::dynamics::BodyNode* node = pairing.bodies[b];
      if (!node) continue;
      MatrixXd J_dart = MatrixXd::Zero(6, pairing.nv);
      const auto skeleton = node->getSkeleton();
      for (size_t k = 0; k < pairing.skeletons.size(); ++k) {
        if (pairing.skeletons[k] != skeleton) continue;
        J_dart.middleCols(pairing.skeleton_v_start[k], skeleton->getNumDofs()) =
            skeleton->getWorldJacobian(node);
      }
      const std::string name = plant.ScopedName(plant.bodies[b]);
      ExpectNear("jacobian of " + name, JacobianSpatialVelocity(result, q, name), J_dart * T_inv,
                 state, &errors);
      // and its velocity, which DART propagates body by body, not by J v
      Eigen::Matrix<double, 6, 1> V_WB;
      V_WB << node->getAngularVelocity(), node->getLinearVelocity();
      ExpectNear("spatial_velocity of " + name, FrameSpatialVelocity(result, q, v, name), V_WB,
                 state, &errors);
    }

    // The center of mass of everything.
    double mass = 0;
    Eigen::Vector3d com = Eigen::Vector3d::Zero();
    MatrixXd J_com = MatrixXd::Zero(3, pairing.nv);
    for (size_t k = 0; k < pairing.skeletons.size(); ++k) {
      const auto& s = pairing.skeletons[k];
      if (s->getMass() == 0) continue;  // DART asserts on a massless skeleton's COM
      mass += s->getMass();
      com += s->getMass() * s->getCOM();
      J_com.middleCols(pairing.skeleton_v_start[k], s->getNumDofs()) =
          s->getMass() * s->getCOMLinearJacobian();
    }
    if (mass > 0) {
      com /= mass;
      J_com /= mass;
      const backend::CenterOfMass cm = CenterOfMass(result, q, v);
      ExpectNear("com_mass", cm.mass, mass, state, &errors);
      ExpectNear("com_position", cm.position, com, state, &errors);
      ExpectNear("com_velocity", cm.velocity, J_com * d.v, state, &errors);
      ExpectNear("com_jacobian", cm.jacobian, J_com * T_inv, state, &errors);
    }

    ExpectNear("kinetic_energy", KineticEnergy(result, q, v, rigid),
               DartSum(pairing, [](const dart::dynamics::Skeleton& s) {
                 return s.computeKineticEnergy();
               }),
               state, &errors);
    // DART 6.12's BodyNode::computePotentialEnergy puts the mass at the body
    // origin, not its center of mass: the reference is -sum m g . p_WBcm
    // from DART's bodies.
    double potential = 0;
    for (dart::dynamics::BodyNode* node : pairing.bodies) {
      if (node) potential -= node->getMass() * plant.gravity.dot(node->getCOM());
    }
    ExpectNear("potential_energy", PotentialEnergy(result, q, rigid), potential, state, &errors);
  }
  if (HasFailure() && !dart.log.empty()) {
    ADD_FAILURE() << "DART's messages while reading " << mc.display << ":\n"
                  << dart.log.substr(0, 4000);
  }

  std::ostringstream summary;
  summary << mc.display << ": nv " << plant.num_velocities << ", " << errors.compared
          << " comparisons" << (dart.note.empty() ? "" : ", " + dart.note)
          << (replaced.empty() ? "" : ", DART given mdlc's replacement inertia of " + replaced)
          << (rotated.empty() ? "" : ", DART given the <inertial> axes it drops of " + rotated)
          << (fd_singular ? ", forward dynamics skipped (singular mass matrix)" : "")
          << (fd_not_thrown ? " though mdlc's ForwardDynamics returned instead of throwing" : "")
          << (aba_safe ? "" : ", DART's forward dynamics from its M, C, g (massless bodies)")
          << "; max relative errors:";
  for (const auto& [what, error] : errors.max_error) summary << " " << what << "=" << error;
  RecordProperty("dart_summary", summary.str());
  std::cout << "[dart-dynamics] " << summary.str() << "\n";
}

INSTANTIATE_TEST_SUITE_P(HandMade, DartDynamicsOracle, ::testing::ValuesIn(HandMadeCases()),
                         CaseName());
INSTANTIATE_TEST_SUITE_P(Inline, DartDynamicsOracle, ::testing::ValuesIn(InlineCases()),
                         CaseName());
INSTANTIATE_TEST_SUITE_P(Corpus, DartDynamicsOracle, ::testing::ValuesIn(CorpusCases()),
                         CaseName());
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(DartDynamicsOracle);

// The loader's geometry stripping keeps everything else.
TEST(DartModelLoader, StripsVisualAndCollisionElements) {
  const std::string text =
      "<link name=\"a\"><visual><geometry><sphere radius=\"0\"/></geometry></visual>"
      "<collision name=\"c\"/><collision_filter_group/><inertial/></link>";
  const std::string stripped = StripElements(StripElements(text, "visual"), "collision");
  EXPECT_EQ(stripped, "<link name=\"a\"><collision_filter_group/><inertial/></link>");
}

}  // namespace
}  // namespace mdlc::oracle
