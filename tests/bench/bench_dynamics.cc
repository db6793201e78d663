// bench_dynamics.cc - time per call of mdlc's rigid-body dynamics against
// MuJoCo 2.2.2's on the same MJCF files: inverse dynamics, the mass matrix
// and forward dynamics, at the same (seeded, random) state.
//
// Models, each one MJCF file that both load:
//   iiwa14        MuJoCo Menagerie's KUKA iiwa 14 (7 revolute joints), from
//                 the corpus; Menagerie writes integrator="implicitfast",
//                 which MuJoCo 2.2.2 does not know, so both read a copy with
//                 "implicit" (and its mesh folder made absolute); dynamics
//                 do not depend on the integrator
//   humanoid      MuJoCo's own humanoid (a free joint and 21 hinges, nv = 27)
//   chain_n{10,96,1000}, tree_n1000
//                 the benchmark robot of mechanism.h in MJCF
//                 (model_gen_mjcf.h): N links, N - 1 hinges, link_0 welded to
//                 the world; a chain is N deep, the tree's parent(i) is
//                 (i - 1) / 3. MuJoCo 2.2.2's XML reader refuses elements
//                 nested more than 100 deep, so 96 links is the longest chain
//                 it loads; chain_n1000 is timed for mdlc alone
//
// Benchmarks per model (microseconds per call, CPU time):
//   inverse_dynamics/mdlc/M         mdlc::InverseDynamics(result, q, v, vdot):
//                                   its own kinematics from q included
//   inverse_dynamics/mujoco/M       what MuJoCo needs from qpos for the same
//                                   answer: mj_kinematics, mj_comPos,
//                                   mj_comVel, mj_rne(m, d, 1, out)
//   inverse_dynamics/mujoco_rne/M   mj_rne alone, on kinematics computed
//                                   beforehand (untimed)
//   mass_matrix/mdlc/M              mdlc::MassMatrix(result, q) (CRBA, its
//                                   kinematics included), dense nv x nv
//   mass_matrix/mujoco/M            mj_kinematics, mj_comPos, mj_crb, mj_fullM
//   mass_matrix/mujoco_crb/M        mj_crb and mj_fullM alone
//   forward_dynamics/mdlc/M         mdlc::ForwardDynamics(result, q, v, tau)
//   forward_dynamics/mujoco/M       mj_forward with qfrc_applied = tau and
//                                   constraints, contact, limits, equality,
//                                   friction loss, passive forces, actuation
//                                   and sensors disabled (opt.disableflags)
//
// Both sides compute the same thing: gravity on; no joint damping, springs or
// actuation; no armature (mdlc's reflected inertia off, MuJoCo's
// dof_armature set to zero). MuJoCo lays out q and v depth-first and writes
// a free joint as [p; quat] and [v_W; w_B], mdlc by tree level and as
// [quat; p] and [w_W; v_W], so the state is drawn in mdlc's coordinates and
// mapped joint by joint. Before timing, each model's answers are compared
// (mapped back); the mdlc rows carry the largest difference relative to the
// answer's largest entry as `rel_diff` (0 when the two agree to rounding).
//
//   mdlc_bench_dynamics --corpus=DIR   the corpus folder; else $MDLC_CORPUS,
//                                      else $MDLC_SHARED_DIR/corpus, else
//                                      ../shared/corpus (from the current
//                                      folder)
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bench_main.h"
#include "mdlc/dynamics.h"
#include "mdlc/kinematics.h"
#include "mdlc/mdlc.h"
#include "mechanism.h"
#include "model_gen_mjcf.h"
#include "tools/driver/heap_policy.h"

#ifdef MDLC_BENCH_HAVE_MUJOCO
#include <mujoco/mujoco.h>
#endif

namespace mdlc::bench {
namespace {

namespace fs = std::filesystem;

// from --corpus=DIR or the environment, before registration
fs::path g_corpus;

struct ModelSpec {
  std::string name;
  Shape shape = Shape::Chain;
  int links = 0;            // generated when > 0
  std::string corpus_path;  // else this file of the corpus
};

const std::vector<ModelSpec>& Models() {
  static const std::vector<ModelSpec> models = {
      {"iiwa14", Shape::Chain, 0, "mujoco_menagerie/kuka_iiwa_14/iiwa14.xml"},
      {"humanoid", Shape::Chain, 0, "mujoco/model/humanoid/humanoid.xml"},
      {"chain_n10", Shape::Chain, 10, ""},
      {"chain_n96", Shape::Chain, 96, ""},
      {"chain_n1000", Shape::Chain, 1000, ""},
      {"tree_n1000", Shape::Tree, 1000, ""},
  };
  return models;
}

fs::path ScratchDir() {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / fmt::format("mdlc_bench_dynamics_{}", getpid());
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

std::string ReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void Replace(std::string& text, std::string_view from, std::string_view to) {
  if (const size_t at = text.find(from); at != std::string::npos) text.replace(at, from.size(), to);
}

// The MJCF file both read, written into the scratch folder when generated or
// adapted; empty with `error` set when there is none.
std::string ModelFile(const ModelSpec& spec, std::string& error) {
  const fs::path out = ScratchDir() / (spec.name + ".xml");
  if (spec.links > 0) {
    std::ofstream(out, std::ios::binary) << GenerateMjcf(spec.shape, spec.links);
    return out.string();
  }
  // absolute: an adapted copy names its mesh folder from elsewhere
  const fs::path path = fs::absolute(g_corpus / spec.corpus_path).lexically_normal();
  if (!fs::is_regular_file(path)) {
    error = fmt::format("'{}' not found: give the corpus folder with --corpus=DIR or "
                        "$MDLC_CORPUS",
                        path.string());
    return {};
  }
  std::string text = ReadText(path);
  if (text.find("implicitfast") == std::string::npos) return path.string();
  // MuJoCo 2.2.2 predates the implicitfast integrator; the copy lives
  // elsewhere, so its mesh folder is spelled out
  Replace(text, "integrator=\"implicitfast\"", "integrator=\"implicit\"");
  Replace(text, "meshdir=\"assets\"",
          fmt::format("meshdir=\"{}\"", (path.parent_path() / "assets").string()));
  std::ofstream(out, std::ios::binary) << text;
  return out.string();
}

// gravity only: MuJoCo's armature is zeroed, its passive forces disabled
const DynamicsOptions kOptions = [] {
  DynamicsOptions options;
  options.gravity = true;
  options.joint_damping = false;
  options.force_elements = false;
  options.reflected_inertia = false;
  return options;
}();

// Largest |a - b| over the largest |a| (at least 1).
double RelativeDifference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  if (a.size() != b.size()) return INFINITY;
  if (a.size() == 0) return 0;
  return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, a.cwiseAbs().maxCoeff());
}

#ifdef MDLC_BENCH_HAVE_MUJOCO
// One mdlc joint with velocities and where MuJoCo keeps the same joint.
struct JointMap {
  bool free = false;  // quaternion_floating / MuJoCo's free joint; else 1 dof
  int q = 0, v = 0;   // mdlc's q_start, v_start
  int qpos = 0, dof = 0;
};

// mdlc's velocity-like vector x (v, vdot, or a generalized force: the map
// is orthogonal, so forces map as velocities do) in MuJoCo's coordinates.
void ToMujoco(const std::vector<JointMap>& joints, const Eigen::VectorXd& q,
              const Eigen::VectorXd& x, mjtNum* out) {
  for (const JointMap& j : joints) {
    if (!j.free) {
      out[j.dof] = x[j.v];
      continue;
    }
    const Eigen::Matrix3d R_WB =
        Eigen::Quaterniond(q[j.q], q[j.q + 1], q[j.q + 2], q[j.q + 3]).normalized().toRotationMatrix();
    Eigen::Map<Eigen::Vector3d>(out + j.dof) = x.segment<3>(j.v + 3);  // v_W
    Eigen::Map<Eigen::Vector3d>(out + j.dof + 3) = R_WB.transpose() * x.segment<3>(j.v);  // w_B
  }
}

Eigen::VectorXd FromMujoco(const std::vector<JointMap>& joints, const Eigen::VectorXd& q,
                           const mjtNum* in, int nv) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(nv);
  for (const JointMap& j : joints) {
    if (!j.free) {
      x[j.v] = in[j.dof];
      continue;
    }
    const Eigen::Matrix3d R_WB =
        Eigen::Quaterniond(q[j.q], q[j.q + 1], q[j.q + 2], q[j.q + 3]).normalized().toRotationMatrix();
    x.segment<3>(j.v) = R_WB * Eigen::Map<const Eigen::Vector3d>(in + j.dof + 3);
    x.segment<3>(j.v + 3) = Eigen::Map<const Eigen::Vector3d>(in + j.dof);
  }
  return x;
}
#endif

// A model compiled by mdlc and loaded by MuJoCo, at one random state.
struct Subject {
  std::string error;  // mdlc could not compile it
  std::optional<Result> result;
  Eigen::VectorXd q, v, vdot, tau;
  double id_diff = NAN, mm_diff = NAN, fd_diff = NAN;
#ifdef MDLC_BENCH_HAVE_MUJOCO
  std::string mujoco_error;  // MuJoCo could not load it, or the joints do not map
  mjModel* m = nullptr;
  mjData* d = nullptr;
  std::vector<JointMap> joints;
  std::vector<mjtNum> qpos, qvel, qacc, qfrc;
  ~Subject() {
    if (d) mj_deleteData(d);
    if (m) mj_deleteModel(m);
  }
#endif
};

// The state, drawn in mdlc's coordinates from a seed named after the model.
void DrawState(Subject& s, std::string_view name) {
  const backend::Plant& plant = s.result->plant();
  Rng rng(Fnv1a(fmt::format("{}/dynamics", name)));
  s.q = DefaultPositions(*s.result);
  for (JointId id : plant.joint_order) {
    const backend::PlantJoint& j = plant.joint(id);
    if (j.type == ir::JointType::QuaternionFloating) {
      Eigen::Vector4d quat;
      for (int k = 0; k < 4; ++k) quat[k] = rng.Uniform(-1, 1);
      s.q.segment<4>(j.q_start) = quat.normalized();
      for (int k = 4; k < 7; ++k) s.q[j.q_start + k] = rng.Uniform(-1, 1);
    } else {
      for (int k = 0; k < j.nq; ++k) s.q[j.q_start + k] = rng.Uniform(-1, 1);
    }
  }
  const int nv = plant.num_velocities;
  s.v.resize(nv);
  s.vdot.resize(nv);
  s.tau.resize(nv);
  for (int k = 0; k < nv; ++k) s.v[k] = rng.Uniform(-1, 1);
  for (int k = 0; k < nv; ++k) s.vdot[k] = rng.Uniform(-1, 1);
  for (int k = 0; k < nv; ++k) s.tau[k] = rng.Uniform(-1, 1);
}

#ifdef MDLC_BENCH_HAVE_MUJOCO
constexpr int kDisabled = mjDSBL_CONSTRAINT | mjDSBL_EQUALITY | mjDSBL_FRICTIONLOSS |
                          mjDSBL_LIMIT | mjDSBL_CONTACT | mjDSBL_PASSIVE | mjDSBL_ACTUATION |
                          mjDSBL_SENSOR;

// Loads `path` into s.m and maps mdlc's joints onto MuJoCo's; sets
// s.mujoco_error instead when either fails.
void LoadMujoco(Subject& s, const std::string& path) {
  char error[1024] = "";
  s.m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
  if (!s.m) {
    s.mujoco_error = fmt::format("MuJoCo 2.2.2: {}", error);
    return;
  }
  s.d = mj_makeData(s.m);
  for (int k = 0; k < s.m->nv; ++k) s.m->dof_armature[k] = 0;
  s.m->opt.disableflags |= kDisabled;

  const backend::Plant& plant = s.result->plant();
  if (plant.num_velocities != s.m->nv) {
    s.mujoco_error = fmt::format("mdlc has {} velocities, MuJoCo {}", plant.num_velocities, s.m->nv);
    return;
  }
  for (JointId id : plant.joint_order) {
    const backend::PlantJoint& j = plant.joint(id);
    if (j.nv == 0) continue;
    JointMap map{.free = false, .q = j.q_start, .v = j.v_start};
    int mj = -1;
    if (j.type == ir::JointType::QuaternionFloating) {
      // mdlc names a free joint after its body (MJCF-021)
      const int body = mj_name2id(s.m, mjOBJ_BODY, plant.body(j.child).name.c_str());
      if (body >= 0 && s.m->body_jntnum[body] == 1) mj = s.m->body_jntadr[body];
      map.free = true;
      if (mj >= 0 && s.m->jnt_type[mj] != mjJNT_FREE) mj = -1;
    } else if (j.type == ir::JointType::Revolute || j.type == ir::JointType::Prismatic) {
      mj = mj_name2id(s.m, mjOBJ_JOINT, j.name.c_str());
      if (mj >= 0 && s.m->jnt_type[mj] != (j.type == ir::JointType::Revolute ? mjJNT_HINGE
                                                                               : mjJNT_SLIDE)) {
        mj = -1;
      }
    }
    if (mj < 0) {
      s.mujoco_error = fmt::format("mdlc's joint '{}' ({}) has no counterpart here", j.name,
                                   ir::JointTypeName(j.type));
      return;
    }
    map.qpos = s.m->jnt_qposadr[mj];
    map.dof = s.m->jnt_dofadr[mj];
    s.joints.push_back(map);
  }

  const int nv = s.m->nv;
  s.qpos.assign(s.m->qpos0, s.m->qpos0 + s.m->nq);
  for (const JointMap& j : s.joints) {
    if (j.free) {
      for (int k = 0; k < 3; ++k) s.qpos[j.qpos + k] = s.q[j.q + 4 + k];
      for (int k = 0; k < 4; ++k) s.qpos[j.qpos + 3 + k] = s.q[j.q + k];
    } else {
      s.qpos[j.qpos] = s.q[j.q];
    }
  }
  using Pair = std::pair<const Eigen::VectorXd*, std::vector<mjtNum>*>;
  for (auto [from, to] : {Pair{&s.v, &s.qvel}, Pair{&s.vdot, &s.qacc}, Pair{&s.tau, &s.qfrc}}) {
    to->assign(static_cast<size_t>(nv), 0);
    ToMujoco(s.joints, s.q, *from, to->data());
  }
}

// Puts the subject's state into MuJoCo's data.
void SetMujocoState(Subject& s) {
  mju_copy(s.d->qpos, s.qpos.data(), s.m->nq);
  mju_copy(s.d->qvel, s.qvel.data(), s.m->nv);
  mju_copy(s.d->qacc, s.qacc.data(), s.m->nv);
  mju_copy(s.d->qfrc_applied, s.qfrc.data(), s.m->nv);
  mju_zero(s.d->ctrl, s.m->nu);
}

// The answers of both, compared once (mapped into mdlc's coordinates).
void Compare(Subject& s) {
  const int nv = s.m->nv;
  const Result& r = *s.result;
  SetMujocoState(s);
  std::vector<mjtNum> out(static_cast<size_t>(nv));
  mj_kinematics(s.m, s.d);
  mj_comPos(s.m, s.d);
  mj_comVel(s.m, s.d);
  mj_rne(s.m, s.d, 1, out.data());
  s.id_diff = RelativeDifference(InverseDynamics(r, s.q, s.v, s.vdot, kOptions),
                                 FromMujoco(s.joints, s.q, out.data(), nv));

  // M against T^T M_mj T, applied to a random vector: O(nv^2)
  mj_crb(s.m, s.d);
  std::vector<mjtNum> M(static_cast<size_t>(nv) * nv), u_mj(nv), Mu_mj(nv);
  mj_fullM(s.m, M.data(), s.d->qM);
  const Eigen::VectorXd u = s.vdot;
  ToMujoco(s.joints, s.q, u, u_mj.data());
  mju_mulMatVec(Mu_mj.data(), M.data(), u_mj.data(), nv, nv);
  s.mm_diff = RelativeDifference(MassMatrix(r, s.q) * u, FromMujoco(s.joints, s.q, Mu_mj.data(), nv));

  SetMujocoState(s);
  mj_forward(s.m, s.d);
  s.fd_diff = RelativeDifference(ForwardDynamics(r, s.q, s.v, s.tau, kOptions),
                                 FromMujoco(s.joints, s.q, s.d->qacc, nv));
}
#endif

Subject& SubjectOf(const ModelSpec& spec) {
  static std::map<std::string, std::unique_ptr<Subject>> subjects;
  auto [it, inserted] = subjects.try_emplace(spec.name);
  if (!inserted) return *it->second;
  it->second = std::make_unique<Subject>();
  Subject& s = *it->second;
  const std::string path = ModelFile(spec, s.error);
  if (!s.error.empty()) return s;
  s.result.emplace(Compile(Input::File(path)));
  if (!s.result->ok() || !s.result->has_model()) {
    s.error = "mdlc: the compile reported errors";
    for (const Diagnostic& d : s.result->diagnostics()) {
      if (d.severity == Severity::Error) {
        s.error = s.result->FormatText(d);
        break;
      }
    }
    return s;
  }
  DrawState(s, spec.name);
#ifdef MDLC_BENCH_HAVE_MUJOCO
  LoadMujoco(s, path);
  if (s.mujoco_error.empty()) {
    try {
      Compare(s);
    } catch (const std::exception& e) {
      s.mujoco_error = fmt::format("comparing the answers: {}", e.what());
    }
  }
#endif
  return s;
}

void Count(benchmark::State& state, const Subject& s) {
  state.counters["nv"] = s.result->plant().num_velocities;
  state.counters["bodies"] = static_cast<double>(s.result->plant().bodies.size() - 1);
}

// ---------------------------------------------------------------- mdlc

enum class Op { InverseDynamics, MassMatrix, ForwardDynamics };

// Times `call` (one call of the operation on the subject's state), whose
// result is what the public function returns, unconverted.
template <typename Call>
void TimeMdlc(benchmark::State& state, const Subject& s, Call call) {
  try {
    benchmark::DoNotOptimize(call());  // throws here, not in the loop
  } catch (const std::exception& e) {
    state.SkipWithError(fmt::format("mdlc: {}", e.what()).c_str());
    return;
  }
  for (auto _ : state) {
    auto out = call();
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
}

void BM_Mdlc(benchmark::State& state, const ModelSpec* spec, Op op) {
  const Subject& s = SubjectOf(*spec);
  if (!s.error.empty()) {
    state.SkipWithError(s.error.c_str());
    return;
  }
  const Result& r = *s.result;
  double diff = NAN;
  switch (op) {
    case Op::InverseDynamics:
      TimeMdlc(state, s, [&] { return InverseDynamics(r, s.q, s.v, s.vdot, kOptions); });
      diff = s.id_diff;
      break;
    case Op::MassMatrix:
      TimeMdlc(state, s, [&] { return MassMatrix(r, s.q); });
      diff = s.mm_diff;
      break;
    case Op::ForwardDynamics:
      TimeMdlc(state, s, [&] { return ForwardDynamics(r, s.q, s.v, s.tau, kOptions); });
      diff = s.fd_diff;
      break;
  }
  Count(state, s);
  if (!std::isnan(diff)) state.counters["rel_diff"] = diff;
}

// --------------------------------------------------------------- MuJoCo

#ifdef MDLC_BENCH_HAVE_MUJOCO
enum class MujocoRun {
  RnePipeline,  // kinematics, comPos, comVel, rne
  RneOnly,
  MassMatrixPipeline,  // kinematics, comPos, crb, fullM
  CrbOnly,             // crb, fullM
  Forward,             // mj_forward, constraints off
};

void BM_Mujoco(benchmark::State& state, const ModelSpec* spec, MujocoRun run) {
  Subject& s = SubjectOf(*spec);
  const std::string& error = s.error.empty() ? s.mujoco_error : s.error;
  if (!error.empty()) {
    state.SkipWithError(error.c_str());
    return;
  }
  const mjModel* m = s.m;
  mjData* d = s.d;
  SetMujocoState(s);
  // what the "alone" rows take as given
  mj_kinematics(m, d);
  mj_comPos(m, d);
  mj_comVel(m, d);
  std::vector<mjtNum> out(static_cast<size_t>(m->nv));
  std::vector<mjtNum> M(static_cast<size_t>(m->nv) * m->nv);
  switch (run) {
    case MujocoRun::RnePipeline:
      for (auto _ : state) {
        mj_kinematics(m, d);
        mj_comPos(m, d);
        mj_comVel(m, d);
        mj_rne(m, d, 1, out.data());
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
      }
      break;
    case MujocoRun::RneOnly:
      for (auto _ : state) {
        mj_rne(m, d, 1, out.data());
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
      }
      break;
    case MujocoRun::MassMatrixPipeline:
      for (auto _ : state) {
        mj_kinematics(m, d);
        mj_comPos(m, d);
        mj_crb(m, d);
        mj_fullM(m, M.data(), d->qM);
        benchmark::DoNotOptimize(M.data());
        benchmark::ClobberMemory();
      }
      break;
    case MujocoRun::CrbOnly:
      for (auto _ : state) {
        mj_crb(m, d);
        mj_fullM(m, M.data(), d->qM);
        benchmark::DoNotOptimize(M.data());
        benchmark::ClobberMemory();
      }
      break;
    case MujocoRun::Forward:
      for (auto _ : state) {
        mj_forward(m, d);
        benchmark::DoNotOptimize(d->qacc);
        benchmark::ClobberMemory();
      }
      break;
  }
  Count(state, s);
}
#endif

void RegisterAll() {
  struct MdlcRow {
    const char* op_name;
    Op op;
  };
  static constexpr MdlcRow kMdlcRows[] = {{"inverse_dynamics", Op::InverseDynamics},
                                          {"mass_matrix", Op::MassMatrix},
                                          {"forward_dynamics", Op::ForwardDynamics}};
#ifdef MDLC_BENCH_HAVE_MUJOCO
  struct MujocoRow {
    const char* name;
    MujocoRun run;
  };
  static constexpr MujocoRow kMujocoRows[] = {
      {"inverse_dynamics/mujoco", MujocoRun::RnePipeline},
      {"inverse_dynamics/mujoco_rne", MujocoRun::RneOnly},
      {"mass_matrix/mujoco", MujocoRun::MassMatrixPipeline},
      {"mass_matrix/mujoco_crb", MujocoRun::CrbOnly},
      {"forward_dynamics/mujoco", MujocoRun::Forward},
  };
#endif
  for (const ModelSpec& spec : Models()) {
    for (const MdlcRow& row : kMdlcRows) {
      benchmark::RegisterBenchmark(fmt::format("{}/mdlc/{}", row.op_name, spec.name).c_str(),
                                   BM_Mdlc, &spec, row.op)
          ->Unit(benchmark::kMicrosecond);
    }
#ifdef MDLC_BENCH_HAVE_MUJOCO
    for (const MujocoRow& row : kMujocoRows) {
      benchmark::RegisterBenchmark(fmt::format("{}/{}", row.name, spec.name).c_str(), BM_Mujoco,
                                   &spec, row.run)
          ->Unit(benchmark::kMicrosecond);
    }
#endif
  }
}

fs::path CorpusFolder(std::string_view flag) {
  if (!flag.empty()) return fs::path(flag);
  if (const char* env = std::getenv("MDLC_CORPUS"); env && *env) return fs::path(env);
  if (const char* env = std::getenv("MDLC_SHARED_DIR"); env && *env) {
    return fs::path(env) / "corpus";
  }
  return fs::path("..") / "shared" / "corpus";
}

}  // namespace
}  // namespace mdlc::bench

int main(int argc, char** argv) {
  mdlc::KeepFreedMemoryForReuse();
  // our own flag first; Google Benchmark rejects flags it does not know
  constexpr std::string_view kCorpus = "--corpus=";
  std::string_view corpus;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg.starts_with(kCorpus)) {
      corpus = arg.substr(kCorpus.size());
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  mdlc::bench::g_corpus = mdlc::bench::CorpusFolder(corpus);
  const int status = mdlc::bench::RunBenchmarks(argc, argv, mdlc::bench::RegisterAll);
  std::error_code ec;
  std::filesystem::remove_all(mdlc::bench::ScratchDir(), ec);
  return status;
}
