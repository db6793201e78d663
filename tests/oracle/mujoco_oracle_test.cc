// Differential test: mdlc's plant-json dump of MJCF models against MuJoCo
// itself, the reference MJCF compiler.
//
// Nothing here uses mdlc library code. For every model
//   1. MuJoCo 3.3.8 (the official WebAssembly build, npm mujoco-js 0.0.7, run
//      by Node.js: tests/oracle/mujoco_js/mujoco_dump.mjs) loads the file and
//      dumps its compiled model: bodies, joints, geoms, and at qpos0 plus
//      seeded random configurations of the hinge and slide joints the world
//      poses and the joint-space inertia matrix (mj_forward, qM / mj_fullM);
//      files MuJoCo 3.3.8 rejects go to MuJoCo 2.2.2 (Debian libmujoco-dev:
//      tests/oracle/mujoco222/mujoco222_dump.cc), a second opinion only;
//   2. the MuJoCo entities get the names Drake's parser gives them (below);
//   3. `mdlc compile FILE --emit=plant-json [--q JOINT=VALUE ...]` runs as a
//      subprocess at each of those configurations and every quantity is
//      compared by name, never by position.
//
// The reading of MuJoCo's dump and of mdlc's plant-json, Drake's names and
// the comparisons this test shares with mujoco_suite_oracle_test.cc are in
// mujoco_reference.h.
//
// Naming (MJCF-020/022/023/040, Drake's detail_mujoco_parser.cc): a body
// MuJoCo leaves unnamed is `body<N>`, N the plant's body count when the body
// is created (the world, every earlier body, and the massless intermediate
// bodies of earlier bodies); a body with k > 1 joints gets k-1 intermediate
// bodies `<body>0`, `<body>1`, ... between its parent and itself, joint i
// joining the (i-1)th to the ith; an unnamed joint is `<parent>-<child>` of
// those plant bodies; a free joint is the body's `quaternion_floating` joint
// (its MJCF name is not used); a name given twice is `<name>_<k>` the second
// time, as mdlc makes it; an unnamed geom is `geom<N>`, N its index among
// its body's geoms (hfield and sdf geoms are not registered and not counted).
//
// What is compared, and how closely:
//   MJCF-010/020/021/022/023  X_WB of every body at every configuration (p,
//       and the rotation matrix: quaternion sign is a convention), to 1e-9;
//   MJCF-022/023  joint type, parent and child body, axis_W at every
//       configuration (hinge, slide), limits (MuJoCo's jnt_range when
//       jnt_limited, else unbounded) and default position (qpos0, or the
//       key's qpos, MJCF-008 below), to 1e-9; ball and free joints' default
//       positions when a key sets them;
//   MJCF-030/031, BEYOND-001/006  mass, COM (MuJoCo's ipos; none for a massless
//       body) and inertia about
//       the COM in the body frame (rebuilt from iquat and the principal
//       moments), to 1e-6 relative: MuJoCo re-diagonalises every inertia and
//       keeps mesh vertices in single precision. Inertia entries are scaled by
//       the body's largest principal moment;
//   MJCF-040/041/043  every geom: one registration per role set (proximity
//       unless contype = conaffinity = 0; illustration unless group > 2; a geom
//       with neither is not registered at all), its
//       shape in Drake's conventions (box full sizes = 2 x MuJoCo's half
//       sizes, capsule/cylinder length = 2 x half-length, plane = half space)
//       to 1e-6 relative, and X_WG at every configuration to 1e-9. Only what
//       the shape makes observable is compared: a sphere's centre, a capsule's
//       or cylinder's centre and axis, a half space's normal and offset, the
//       full pose of boxes, ellipsoids and meshes;
//   MJCF-050, BEYOND-001  mesh geoms: MuJoCo moves a mesh geom's frame to the
//       mesh's inertial frame (and records the move as mesh_pos/mesh_quat);
//       mdlc keeps the frame of the mesh file. The oracle undoes MuJoCo's move
//       (X_WG_file = X_WG_mujoco * X_mesh^-1) and compares full poses to 1e-6
//       (mesh_pos comes from single-precision vertices), and the scale. MuJoCo
//       2.2.2 records no mesh offset: there mesh poses are not compared;
//   MJCF-022/024  the mass matrix restricted to the hinge and slide dofs at
//       every configuration, to 1e-6 relative (entry (i,j) scaled by
//       sqrt(M_ii M_jj)). MuJoCo's qM includes dof_armature on the diagonal
//       and plant-json's mass_matrix excludes reflected inertia, so the
//       oracle subtracts the armature; mdlc's reflected_inertia must be 0 (no
//       actuator) or the armature (MJCF-024);
//   MJCF-022, BEYOND-007  every hinge, slide and ball joint's damping (dof_damping)
//       and every hinge and slide joint's stiffness (jnt_stiffness: the
//       stiffness of mdlc's joint springs on it, 0 without one) and spring
//       reference (qpos_spring), whether the file gives them or springdamper
//       derives them from the inertia at qpos0 (MuJoCo 3.3.8 dumps only);
//   BEYOND-008  every named joint actuator of the position or velocity
//       servo shape (fixed gain, affine bias, biasprm[0] = 0): kp =
//       gainprm[0] and kd = -biasprm[2] (position: gainprm[0] = -biasprm[1]
//       > 0; a dampratio is already MuJoCo's kd there), or kd = gainprm[0]
//       (velocity: biasprm[1] = 0, gainprm[0] = -biasprm[2] > 0), when mdlc
//       has an actuator of that name. Joint and actuator gains are compared
//       to 1e-9, those derived from the inertia at qpos0 too (the corpus's
//       agree to 2e-14).
// Configuration 0 is mdlc's default configuration and MuJoCo's base state.
// Keyframes (MJCF-008, the "keyframe (default positions)" item): the
// key named "home" if there is one, else the first <key>, sets the default
// configuration: its qpos in MuJoCo's layout over the joints in document
// order (hinge/slide 1 value, ball 4 (w x y z), free 7 (x y z, w x y z))
// becomes each joint's default_positions (ball: roll-pitch-yaw; free:
// [w x y z x y z]). Both dumpers start from that key (mj_resetDataKeyframe's
// qpos) for configuration 0 and use it as the base of every other
// configuration (random values overwrite the hinge and slide joints only);
// without keys the base is qpos0 (every hinge and slide at its ref, MJCF-022).
//
// Configuration (all optional):
//   --mdlc=PATH or env MDLC_BINARY        (default: compiled-in path)
//   env MDLC_NODE                         Node.js (default: found by CMake)
//   env MDLC_ORACLE_CONFIGS=N             random configurations (default 3)
//   env MDLC_ORACLE_MAX_MESSAGES=N        discrepancies printed per test (60)
//   env MDLC_ORACLE_EXTRA_MODELS=a.xml:dir  extra models (Extra/...) to compare
//
// Test layout (value-parameterized, one test per model):
//   Corpus/MujocoOracle.CompiledModelMatches/<path>   every corpus MJCF
//   HandMade/MujocoOracle.CompiledModelMatches/<stem> tests/models/mjcf/oracle
//   Converted/MujocoOracle.CompiledModelMatches/<stem> `mdlc convert --to mjcf`
//     output of the round trips (env MDLC_ORACLE_CONVERTED_MODELS=dir)
// Corpus files where mdlc legitimately disagrees with MuJoCo are listed in
// kKnownDisagreements: skipped with the reason when mdlc rejects them or
// disagrees, a failure ("stale entry") when mdlc compiles them and agrees.
// Without Node.js or the installed mujoco-js package (tools/setup.sh test runs
// `npm ci` in tests/oracle/mujoco_js) every case reports itself skipped.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
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

#include "mujoco_reference.h"
#include "oracle_util.h"

namespace {

namespace fs = std::filesystem;
using namespace mdlc::oracle;
using namespace mdlc::oracle::mujoco;
using Eigen::Isometry3d;
using Eigen::Matrix3d;
using Eigen::Vector3d;
using json = nlohmann::json;

#ifndef MDLC_MUJOCO222_DUMP
#define MDLC_MUJOCO222_DUMP ""
#endif

// Tolerances (kKinTol, kMassTol, kGainTol): mujoco_reference.h. Besides the
// bodies and joints the suite test compares, this test holds mdlc to joint
// gains and servos, keyed ball and free joints and reflected inertia.
constexpr StaticChecks kEveryStaticCheck = {
    /*joint_gains=*/true, /*keyed_rotations=*/true, /*reflected_inertia=*/true};

fs::path DumpScript() { return MujocoJsScript("mujoco_dump.mjs"); }

// ---------------------------------------------------------------------------
// Known disagreements
// ---------------------------------------------------------------------------

struct KnownDisagreement {
  const char* path;    // relative to corpus/, or tests/models/mjcf/oracle/<file>
  const char* reason;  // feature ID and what differs
};

// Files where mdlc, following Drake or the spec, legitimately differs from
// MuJoCo. A listed file is
// skipped with the reason and the discrepancies found; an entry whose file mdlc
// compiles and that then agrees with MuJoCo in every compared quantity fails
// as stale.
const std::vector<KnownDisagreement> kKnownDisagreements = {
    {"mujoco/model/adhesion/active_adhesion.xml",
     "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 rejects its attributes; the oracle is MuJoCo "
     "2.2.2): Drake and mdlc warn that composite is unsupported and drop the bodies, joints and "
     "geoms it generates, which MuJoCo 2.2.2 builds"},
    {"mujoco/model/composite/cloth.xml",
     "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 rejects its attributes; the oracle is MuJoCo "
     "2.2.2): Drake and mdlc warn that composite is unsupported and drop the bodies, joints and "
     "geoms it generates, which MuJoCo 2.2.2 builds"},
    {"mujoco/model/composite/grid2pin.xml",
     "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 rejects its attributes; the oracle is MuJoCo "
     "2.2.2): Drake and mdlc warn that composite is unsupported and drop the bodies, joints and "
     "geoms it generates, which MuJoCo 2.2.2 builds"},
    {"mujoco/model/composite/loop.xml",
     "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 rejects its attributes; the oracle is MuJoCo "
     "2.2.2): Drake and mdlc warn that composite is unsupported and drop the bodies, joints and "
     "geoms it generates, which MuJoCo 2.2.2 builds"},
    {"mujoco/model/composite/particle.xml",
     "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 rejects its attributes; the oracle is MuJoCo "
     "2.2.2): Drake and mdlc warn that composite is unsupported and drop the bodies, joints and "
     "geoms it generates, which MuJoCo 2.2.2 builds"},
    {"mujoco/model/composite/rope.xml",
     "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 rejects its attributes; the oracle is MuJoCo "
     "2.2.2): Drake and mdlc warn that composite is unsupported and drop the bodies, joints and "
     "geoms it generates, which MuJoCo 2.2.2 builds"},
    {"mujoco/model/composite/softbox.xml",
     "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 rejects its attributes; the oracle is MuJoCo "
     "2.2.2): Drake and mdlc warn that composite is unsupported and drop the bodies, joints and "
     "geoms it generates, which MuJoCo 2.2.2 builds"},
    {"mujoco/model/flag/flag.xml",
     "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 rejects its attributes; the oracle is MuJoCo "
     "2.2.2): Drake and mdlc warn that composite is unsupported and drop the bodies, joints and "
     "geoms it generates, which MuJoCo 2.2.2 builds"},
    {"mujoco/model/hammock/hammock.xml",
     "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 rejects its attributes; the oracle is MuJoCo "
     "2.2.2): Drake and mdlc warn that composite is unsupported and drop the bodies, joints and "
     "geoms it generates, which MuJoCo 2.2.2 builds"},
};

// Files where MuJoCo's own mass properties are less accurate than the
// tolerance, for a reason its source shows (MJCF-031, BEYOND-001): MuJoCo
// diagonalises each mesh's unit-density inertia with mjuu_eig3
// (user_util.cc), which stops once the largest off-diagonal entry is below
// 1e-12 in absolute terms. Scaled by density 1000 that leaves MuJoCo's body
// inertia entries, and the mass matrix entries built from them, up to about
// 1e-9 kg m^2 off per mesh (robotiq 2f85 base_mount Iyz: mdlc 1.275e-9,
// MuJoCo -6.0e-12; allegro th_medial Ixy: mdlc 2.08e-10, MuJoCo 0, with
// moments near 7e-6). These files are compared in full like every other,
// with kMujocoEigenResidual as an absolute floor on inertia and M entries.
const char* const kMujocoEigenResidualFiles[] = {
    "mujoco_menagerie/robotiq_2f85/2f85.xml",     "mujoco_menagerie/robotiq_2f85/scene.xml",
    "mujoco_menagerie/wonik_allegro/left_hand.xml", "mujoco_menagerie/wonik_allegro/right_hand.xml",
    "mujoco_menagerie/wonik_allegro/scene_left.xml", "mujoco_menagerie/wonik_allegro/scene_right.xml",
};
constexpr double kMujocoEigenResidual = 5e-9;  // kg m^2: a few meshes' residual

double InertiaFloorFor(const std::string& corpus_path) {
  for (const char* f : kMujocoEigenResidualFiles) {
    if (corpus_path == f) return kMujocoEigenResidual;
  }
  return 0;
}

const char* KnownReason(const std::string& key) {
  for (const auto& k : kKnownDisagreements) {
    if (key == k.path) return k.reason;
  }
  return nullptr;
}

// ---------------------------------------------------------------------------
// Cases
// ---------------------------------------------------------------------------

struct ModelCase {
  std::string id;       // gtest parameter name
  std::string path;     // absolute
  std::string display;  // corpus/<path>, tests/models/mjcf/oracle/<file>
  std::string known;    // kKnownDisagreements reason, if listed
  std::string skip_reason;
  double inertia_floor = 0;  // kg m^2: see kMujocoEigenResidualFiles
  bool converted = false;    // written by `mdlc convert` (ConvertedCases)
  // what mdlc compiles instead of `path` (a converted file against its
  // source: MDLC_ORACLE_MDLC_SOURCE), and extra arguments for it
  std::string mdlc_path;
  std::vector<std::string> mdlc_args;
};

void PrintTo(const ModelCase& c, std::ostream* os) { *os << c.display; }

std::vector<ModelCase> CorpusCases() {
  return ManifestCases<ModelCase>(
      "shared corpus not found (" + CorpusManifest().string() +
          "); the corpus differential test needs ../shared",
      [](const std::vector<std::string>& cols) -> std::optional<ModelCase> {
        if (cols.size() < 2 || cols[0] != "mjcf") return std::nullopt;
        ModelCase c;
        c.id = Sanitize(WithoutSuffix(cols[1], ".xml"));
        c.path = (CorpusDir() / cols[1]).string();
        c.display = "corpus/" + cols[1];
        if (const char* r = KnownReason(cols[1])) c.known = r;
        c.inertia_floor = InertiaFloorFor(cols[1]);
        return c;
      });
}

std::vector<ModelCase> HandMadeCases() {
  const fs::path dir = TestModels("mjcf/oracle");
  return FolderCases<ModelCase>(
      dir, ".xml", "no MJCF models in " + dir.string(), [](const fs::path& f) {
        ModelCase c;
        c.id = Sanitize(f.stem().string());
        c.path = f.string();
        c.display = "tests/models/mjcf/oracle/" + f.filename().string();
        if (const char* r = KnownReason(c.display)) c.known = r;
        return c;
      });
}

// Ad-hoc models for investigating a discrepancy: MDLC_ORACLE_EXTRA_MODELS is
// a ':'-separated list of .xml files or directories of them. With
// MDLC_ORACLE_MDLC_SOURCE=FILE, mdlc compiles FILE instead of each of them:
// MuJoCo's reading of a converted model against mdlc's of its source (the
// README's walk-through, tests/convert).
std::vector<ModelCase> ExtraCases() {
  std::vector<ModelCase> cases;
  const char* env = std::getenv("MDLC_ORACLE_EXTRA_MODELS");
  const char* source = std::getenv("MDLC_ORACLE_MDLC_SOURCE");
  std::stringstream ss(env ? env : "");
  for (std::string item; std::getline(ss, item, ':');) {
    if (item.empty()) continue;
    std::vector<fs::path> files;
    if (fs::is_directory(item)) files = FilesWithExtension(item, ".xml");
    else files.push_back(item);
    for (const auto& f : files) {
      ModelCase c;
      c.id = Sanitize(f.stem().string());
      c.path = fs::absolute(f).string();
      c.display = f.string();
      if (source && *source) c.mdlc_path = fs::absolute(source).string();
      cases.push_back(c);
    }
  }
  Uniquify(&cases);
  return cases;
}

// What `mdlc convert --to mjcf` wrote for the corpus round trips
// (tests/convert): MDLC_ORACLE_CONVERTED_MODELS names their folder, where
// each model has a folder of its own under xml/ beside copies of its meshes.
// MuJoCo must load each one as mdlc reads it back; a file MuJoCo rejects for
// a reason of its own (kConvertedRejections) is skipped with MuJoCo's words.
std::vector<ModelCase> ConvertedCases() {
  std::vector<ModelCase> cases;
  const char* dir = std::getenv("MDLC_ORACLE_CONVERTED_MODELS");
  if (!dir || !fs::is_directory(fs::path(dir) / "xml")) return cases;
  std::vector<fs::path> folders;
  for (const auto& e : fs::directory_iterator(fs::path(dir) / "xml")) {
    if (e.is_directory()) folders.push_back(e.path());
  }
  std::sort(folders.begin(), folders.end());
  for (const fs::path& folder : folders) {
    for (const auto& f : FilesWithExtension(folder, ".xml")) {
      ModelCase c;
      c.id = Sanitize(f.stem().string());
      c.path = fs::absolute(f).string();
      c.display = f.filename().string();
      c.converted = true;
      {
        std::ifstream in(f);
        const std::string text((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
        c.mdlc_args = ReadAsWrittenArgs(text, std::regex("<mujoco model=\"([^\"]*)\""));
      }
      // a source with MuJoCo's eigen residual keeps it when written back
      for (const char* source : kMujocoEigenResidualFiles) {
        std::string stem = std::string("mjcf_") + source;
        for (char& ch : stem) {
          if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
        }
        if (f.stem().string() == stem) c.inertia_floor = kMujocoEigenResidual;
      }
      cases.push_back(c);
    }
  }
  Uniquify(&cases);
  return cases;
}

/// MuJoCo 3.3.8's rejections of converted files that are MuJoCo's own
/// limits, not the writer's mistakes: the plant holds what MuJoCo refuses
/// (and one limit of the dump harness, said as such).
const char* ConvertedRejection(const std::string& error) {
  static constexpr std::pair<const char*, const char*> kConvertedRejections[] = {
      // Drake and mdlc keep massless bodies (between an MJCF body's stacked
      // joints, massless links); MuJoCo requires mass on every moving body
      {"mass and inertia of moving bodies must be larger than mjMINVAL",
       "a moving body is massless in the plant, which MuJoCo refuses"},
      {"inertia must have positive eigenvalues",
       "a body's inertia is singular in the plant, which MuJoCo refuses"},
      {"inertia must satisfy A + B >= C",
       "a body's inertia fails MuJoCo's triangle inequality, which the plant accepts"},
      // seen on Gazebo's breakable test model (many welded-by-limits
      // hinges); the cause is not yet understood
      {"rank-deficient sparse Hessian",
       "MuJoCo's solver cannot factor its Hessian for this model (cause not yet understood)"},
      // (a mesh MuJoCo cannot read - DAE, glTF, PLY, an STL of more than
      // 200000 faces - is no refusal of MuJoCo's: --copy-assets writes it
      // as OBJ, issue 58)
      // not MuJoCo's verdict: mujoco_dump.mjs keeps a typed-array view
      // across a call that grows the WebAssembly heap (the fire hose's 41
      // links); to be fixed in the harness
      {"on a detached ArrayBuffer",
       "the dump harness fails on it (its view of the WebAssembly heap was detached as the "
       "heap grew): a harness limit, not MuJoCo's"},
      {"plane only allowed in static bodies",
       "a half space is on a moving body, which MuJoCo refuses for its planes"},
  };
  for (const auto& [text, reason] : kConvertedRejections) {
    if (error.find(text) != std::string::npos) return reason;
  }
  return nullptr;
}

// ---------------------------------------------------------------------------
// MuJoCo 2.2.2's dump (MuJoCo 3.3.8's: mujoco_reference.h)
// ---------------------------------------------------------------------------

// Runs a dump tool on one file; the parsed line, or an error in *problem.
json RunDump(const std::vector<std::string>& argv, std::string* problem) {
  const RunResult r = RunProcess(argv, 600.0);
  if (!r.spawn_error.empty()) {
    *problem = r.spawn_error;
    return json();
  }
  if (r.timed_out || r.exit_code != 0) {
    *problem = std::string(r.timed_out ? "timed out" : "exit status " + std::to_string(r.exit_code)) +
               ": " + r.err.substr(0, 2000);
    return json();
  }
  return ParseDumpLine(r.out.substr(0, r.out.find('\n')), problem);
}

json DumpMujoco2(const std::string& file, std::string* problem) {
  const std::string tool = Found(MDLC_MUJOCO222_DUMP);
  if (tool.empty()) {
    *problem = "mujoco222_dump not built (libmujoco-dev missing)";
    return json();
  }
  return RunDump({tool, "--configs", std::to_string(NumConfigs()), "--seed", "1", file}, problem);
}

// ---------------------------------------------------------------------------
// Geometry (the rest of the comparison: mujoco_reference.h)
// ---------------------------------------------------------------------------

// Shape and roles of every geom (configuration independent); returns the
// registrations found per reference geom for the pose checks.
struct GeomMatch {
  const RGeom* ref = nullptr;
  int ref_index = 0;
  std::vector<const json*> regs;
};

std::vector<GeomMatch> CompareGeometry(const Reference& ref, const Plant& p, Report* rep) {
  std::vector<GeomMatch> matches;
  std::set<const json*> used;
  for (size_t g = 0; g < ref.geoms.size(); ++g) {
    const RGeom& G = ref.geoms[g];
    if (!G.Registered()) continue;
    const std::string ent = "geom '" + G.name + "' on '" + G.body + "' (" + G.type + ")";
    GeomMatch m{&G, static_cast<int>(g), {}};
    const auto [lo, hi] = p.geoms.equal_range(G.body + "|" + G.name);
    bool proximity = false, illustration = false;
    for (auto it = lo; it != hi; ++it) {
      if (!used.insert(it->second).second) continue;
      m.regs.push_back(it->second);
      for (const auto& role : it->second->value("roles", json::array())) {
        if (role == "proximity") proximity = true;
        if (role == "illustration") illustration = true;
      }
    }
    const bool want_proximity = !(G.contype == 0 && G.conaffinity == 0);
    const bool want_illustration = G.group <= 2;
    if (!want_proximity && !want_illustration) {
      // MJCF-043: neither a collision nor a visual role: not registered
      if (!m.regs.empty()) {
        rep->Add("MJCF-043 " + ent + " is registered by mdlc although contype = conaffinity = 0 "
                 "and group = " + std::to_string(G.group) + " > 2 leave it no role");
      }
      continue;
    }
    if (m.regs.empty()) {
      rep->Add("MJCF-040 " + ent + " is missing from mdlc's scene graph");
      continue;
    }
    if (proximity != want_proximity || illustration != want_illustration) {
      rep->Add("MJCF-043 " + ent + " roles: mdlc proximity=" + std::to_string(proximity) +
               " illustration=" + std::to_string(illustration) + ", expected proximity=" +
               std::to_string(want_proximity) + " illustration=" + std::to_string(want_illustration) +
               " (contype=" + std::to_string(G.contype) + " conaffinity=" +
               std::to_string(G.conaffinity) + " group=" + std::to_string(G.group) + ")");
    }
    for (const json* reg : m.regs) {
      const json shape = reg->value("shape", json::object());
      const std::string type = shape.value("type", "");
      auto want_type = [&](std::initializer_list<const char*> ok) {
        for (const char* t : ok) {
          if (type == t) return true;
        }
        rep->Add("MJCF-040 " + ent + " shape: mdlc=" + (type.empty() ? "?" : type) +
                 " expected " + *ok.begin());
        return false;
      };
      const Vector3d& s = G.size;
      if (G.type == "sphere") {
        if (want_type({"sphere"})) rep->Num("MJCF-040", ent, "radius", Num(shape.value("radius", json())), s[0], kMassTol, 0);
      } else if (G.type == "capsule" || G.type == "cylinder") {
        if (want_type({G.type.c_str()})) {
          rep->Num("MJCF-040/041", ent, "radius", Num(shape.value("radius", json())), s[0], kMassTol, 0);
          rep->Num("MJCF-040/041", ent, "length", Num(shape.value("length", json())), 2 * s[1], kMassTol, 0);
        }
      } else if (G.type == "ellipsoid") {
        if (want_type({"ellipsoid"})) {
          rep->Num("MJCF-040", ent, "a", Num(shape.value("a", json())), s[0], kMassTol, 0);
          rep->Num("MJCF-040", ent, "b", Num(shape.value("b", json())), s[1], kMassTol, 0);
          rep->Num("MJCF-040", ent, "c", Num(shape.value("c", json())), s[2], kMassTol, 0);
        }
      } else if (G.type == "box") {
        if (want_type({"box"})) {
          const json sz = shape.value("size", json::array());
          for (int i = 0; i < 3; ++i) {
            rep->Num("MJCF-040", ent, "size[" + std::to_string(i) + "]",
                     sz.is_array() && sz.size() == 3 ? Num(sz[i]) : std::nan(""), 2 * s[i], kMassTol, 0);
          }
        }
      } else if (G.type == "plane") {
        want_type({"half_space"});
      } else if (G.type == "mesh") {
        if (want_type({"mesh", "convex"}) && G.mesh_scale) {
          const json sc = shape.value("scale", json());
          Vector3d scale = Vector3d::Constant(std::nan(""));
          if (sc.is_number()) scale = Vector3d::Constant(sc.get<double>());
          else if (sc.is_array() && sc.size() == 3) scale = V3(sc);
          CompareVec(rep, "MJCF-050", ent, "scale", scale, *G.mesh_scale, kKinTol);
        }
      }
    }
    matches.push_back(std::move(m));
  }
  return matches;
}

// MJCF-040/041/050: every registered geom's world pose at one configuration
// (what its shape makes observable).
void CompareGeometryPoses(const RConfig& C, const std::vector<GeomMatch>& geoms, Report* rep) {
  for (const GeomMatch& m : geoms) {
    const RGeom& G = *m.ref;
    if (m.ref_index >= static_cast<int>(C.X_WG.size())) continue;
    const std::string ent = "geom '" + G.name + "' on '" + G.body + "' (" + G.type + ")";
    Isometry3d X_ref = C.X_WG[m.ref_index];
    double tol = kKinTol;
    if (G.type == "mesh") {
      if (!G.has_mesh_offset) continue;  // MuJoCo 2.2.2: the offset is unknown
      X_ref = X_ref * G.X_mesh.inverse();
      tol = kMassTol;
    }
    for (const json* reg : m.regs) {
      Isometry3d X;
      if (!ReadPose(reg->value("X_WG", json()), &X)) {
        rep->Add(ent + " has no readable X_WG");
        continue;
      }
      if (G.type == "sphere") {
        ComparePose(rep, "MJCF-040", ent, "X_WG", X, X_ref, tol, /*rotation=*/false);
      } else if (G.type == "capsule" || G.type == "cylinder") {
        ComparePose(rep, "MJCF-040/041", ent, "X_WG", X, X_ref, tol, false);
        CompareVec(rep, "MJCF-040/041", ent, "X_WG z axis", X.linear().col(2), X_ref.linear().col(2), tol);
      } else if (G.type == "plane") {
        const Vector3d n = X.linear().col(2), n_ref = X_ref.linear().col(2);
        CompareVec(rep, "MJCF-040", ent, "half-space normal", n, n_ref, tol);
        rep->Num("MJCF-040", ent, "half-space offset", n.dot(X.translation()),
                 n_ref.dot(X_ref.translation()), tol);
      } else {
        ComparePose(rep, G.type == "mesh" ? "MJCF-050" : "MJCF-040", ent, "X_WG", X, X_ref, tol);
      }
    }
  }
}

std::string DescribeQ(const JointValues& q) {
  return mdlc::oracle::DescribeQ(q, "default configuration (key 'home' or first key, else qpos0)",
                                 "joints");
}

// ---------------------------------------------------------------------------
// The test
// ---------------------------------------------------------------------------

class MujocoOracle : public ::testing::TestWithParam<ModelCase> {};

TEST_P(MujocoOracle, CompiledModelMatches) {
  const ModelCase& mc = GetParam();
  if (const std::string why = MujocoSkipReason(mc.skip_reason); !why.empty()) GTEST_SKIP() << why;

  std::string problem;
  json dump = DumpMujoco3(mc.path, &problem);
  ASSERT_TRUE(problem.empty()) << "[" << mc.display << "] MuJoCo 3.3.8 dump failed: " << problem;
  std::string oracle = "mujoco3.3.8";
  bool mujoco2 = false;
  if (!dump.value("ok", false) && mc.converted) {
    // mdlc wrote it for MuJoCo 3: only MuJoCo's own limits may reject it
    const std::string err3 = dump.value("error", std::string("?"));
    if (const char* reason = ConvertedRejection(err3)) {
      GTEST_SKIP() << "MuJoCo 3.3.8 cannot load " << mc.display << ": " << reason << " ("
                   << err3 << ")";
    }
    FAIL() << "[" << mc.display << "] MuJoCo 3.3.8 rejects the converted file: " << err3;
  }
  if (!dump.value("ok", false)) {
    // MuJoCo 3.3.8 rejects the file: MuJoCo 2.2.2's opinion decides.
    const std::string err3 = dump.value("error", std::string("?"));
    std::string problem2;
    json dump2 = DumpMujoco2(mc.path, &problem2);
    if (!problem2.empty() || !dump2.value("ok", false)) {
      GTEST_SKIP() << "MuJoCo 3.3.8 rejects " << mc.display << " (" << err3 << "); MuJoCo 2.2.2 "
                   << (problem2.empty() ? "rejects it too (" + dump2.value("error", std::string("?")) + ")"
                                        : "unavailable: " + problem2)
                   << "; tests/corpus/reference_rejects_mjcf.cc covers it";
    }
    dump = std::move(dump2);
    oracle = "mujoco2.2.2";
    mujoco2 = true;
  }
  Reference ref;
  try {
    ref = BuildReference(dump);
  } catch (const json::exception& e) {
    FAIL() << "[" << mc.display << "] unexpected dump layout: " << e.what();
  }
  ref.inertia_floor = mc.inertia_floor;

  Report rep(mc.display, oracle);
  std::map<std::string, std::string> scoped;  // joint local name -> name for --q
  bool compiled = false;
  for (size_t c = 0; c < ref.configs.size(); ++c) {
    const JointValues q = ConfigurationQ(ref, ref.configs[c], scoped);
    rep.SetContext("config " + std::to_string(c) + ", " + DescribeQ(q));
    Plant plant;
    const MdlcRun run = RunMdlcPlant(mc.mdlc_path.empty() ? mc.path : mc.mdlc_path, q, &plant,
                                     mc.mdlc_args, {"bodies", "joints", "geometries"});
    if (!run.ok) {
      if (c == 0 && mujoco2 && run.result.exit_code == 1 && HasLocatedError(run.result.err)) {
        // MuJoCo 3 rejects it and mdlc rejects it with a located diagnostic:
        // the outcome the MuJoCo 2-only files may have.
        std::printf("[ note ] %s: MuJoCo 3.3.8 rejects it, MuJoCo 2.2.2 loads it, mdlc rejects it:%s\n",
                    mc.display.c_str(), ErrorExcerpt(run.result.err).c_str());
        return;
      }
      if (c == 0 && !mc.known.empty() && run.result.exit_code == 1) {
        GTEST_SKIP() << "known disagreement (mdlc rejects it): " << mc.known;
      }
      rep.Add(run.problem + (mujoco2 ? "\n    (MuJoCo 3.3.8 rejects this file, MuJoCo 2.2.2 loads "
                                       "it: mdlc must compile it as 2.2.2 does or reject it with "
                                       "a located error)"
                                     : ""));
      break;
    }
    compiled = true;
    ComparePlant(ref, c, plant, kEveryStaticCheck, &scoped, &rep, [&] {
      // shapes and roles are reported at configuration 0 only
      Report quiet(mc.display, oracle);
      const std::vector<GeomMatch> geoms = CompareGeometry(ref, plant, c == 0 ? &rep : &quiet);
      CompareGeometryPoses(ref.configs[c], geoms, &rep);
    });
  }
  if (!mc.known.empty()) {
    if (compiled && rep.size() == 0) {
      ADD_FAILURE() << "[" << mc.display << "] stale kKnownDisagreements entry: mdlc now agrees "
                    << "with " << oracle << " (listed because: " << mc.known << ")";
      return;
    }
    GTEST_SKIP() << "known disagreement: " << mc.known << "\n" << rep.Text();
  }
  if (rep.size() > 0) ADD_FAILURE() << rep.Text();
}

INSTANTIATE_TEST_SUITE_P(Corpus, MujocoOracle, ::testing::ValuesIn(CorpusCases()), CaseName());
INSTANTIATE_TEST_SUITE_P(HandMade, MujocoOracle, ::testing::ValuesIn(HandMadeCases()), CaseName());
INSTANTIATE_TEST_SUITE_P(Extra, MujocoOracle, ::testing::ValuesIn(ExtraCases()), CaseName());
INSTANTIATE_TEST_SUITE_P(Converted, MujocoOracle, ::testing::ValuesIn(ConvertedCases()),
                         CaseName());
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(MujocoOracle);

// ---------------------------------------------------------------------------
// Self-checks of the oracle (no mdlc involved)
// ---------------------------------------------------------------------------

std::string HandModel(const std::string& file) {
  return (TestModels("mjcf/oracle") / file).string();
}

// Every kKnownDisagreements entry names a model the test runs.
TEST(MujocoOracleSelfCheck, KnownDisagreementsNameModels) {
  const std::set<std::string> keys = ListingKeys(CorpusCases(), HandMadeCases());
  if (keys.size() <= 1) GTEST_SKIP() << "shared corpus not found";
  for (const auto& k : kKnownDisagreements) EXPECT_TRUE(keys.count(k.path)) << k.path;
}

// MuJoCo 3.3.8 is the version the tests claim.
TEST(MujocoOracleSelfCheck, VersionIs338) {
  if (const std::string why = MujocoJsUnavailable(); !why.empty()) GTEST_SKIP() << why;
  const RunResult r = RunProcess({NodeBinary(), DumpScript().string(), "--version"}, 120.0);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(json::parse(r.out).value("version", ""), "3.3.8");
}

// The served dumps (one Node.js process for every file of a test process)
// are the dumps a process of its own prints for each file, also right after
// a file MuJoCo rejects (the helper then starts a fresh MuJoCo instance:
// mujoco_dump.mjs says why). The stack of boxes makes MuJoCo's solver fail
// while dumping, the error a reused instance garbles.
TEST(MujocoOracleSelfCheck, ServedDumpsEqualOwnProcessDumps) {
  if (const std::string why = MujocoJsUnavailable(); !why.empty()) GTEST_SKIP() << why;
  const fs::path dir = fs::path(::testing::TempDir()) / "mujoco_served_dumps";
  fs::create_directories(dir);
  const fs::path rejected = dir / "massless_moving_body.xml";
  std::ofstream(rejected) << "<mujoco><worldbody><body name=\"b\"><joint type=\"hinge\"/>"
                             "</body></worldbody></mujoco>\n";
  const fs::path solver_failure = dir / "touching_boxes_8x8.xml";
  {
    std::ofstream out(solver_failure);
    out << "<mujoco><worldbody>\n";
    for (int column = 0; column < 8; ++column) {
      for (int row = 0; row < 8; ++row) {
        out << "<body pos=\"" << 0.05 * column << " 0 " << 1 + 0.05 * row << "\">"
            << "<inertial pos=\"0 0 0\" mass=\"0.3375\" diaginertia=\"1.40625e-4 1.40625e-4 "
               "1.40625e-4\"/><joint type=\"hinge\" axis=\"0 0 1\"/>"
            << "<geom type=\"box\" size=\"0.025 0.025 0.025\"/></body>\n";
      }
    }
    out << "</worldbody></mujoco>\n";
  }
  std::vector<std::string> files = {rejected.string(), solver_failure.string()};
  for (const auto& f : FilesWithExtension(HandModel(""), ".xml")) {
    files.push_back(rejected.string());
    files.push_back(fs::absolute(f).string());
  }
  ASSERT_GE(files.size(), 10u);
  // a process of its own has no history: its dump of a file is the same each
  // time, so the rejected file asked for before every model is run once
  std::map<std::string, json> own_dumps;
  for (const std::string& file : files) {
    std::string problem;
    const json served = DumpMujoco3(file, &problem);
    ASSERT_EQ(problem, "") << file;
    auto own = own_dumps.find(file);
    if (own == own_dumps.end()) {
      const RunResult run = RunProcess({NodeBinary(), DumpScript().string(), "--configs",
                                        std::to_string(NumConfigs()), "--seed", "1", file},
                                       600.0);
      ASSERT_EQ(run.exit_code, 0) << run.err;
      own = own_dumps.emplace(file, json::parse(run.out)).first;
    }
    EXPECT_EQ(served, own->second) << file;
    const bool loads = file != rejected.string() && file != solver_failure.string();
    EXPECT_EQ(served.value("ok", true), loads) << served.dump().substr(0, 300);
    if (file == solver_failure.string()) {
      EXPECT_NE(served.value("error", "").find("FactorizeHessian"), std::string::npos)
          << served.value("error", "");
    }
  }
}

// MJCF-020/022/023/040: Drake's names for unnamed bodies (counting the
// intermediate bodies of stacked joints), joints and geoms.
TEST(MujocoOracleSelfCheck, MJCF020_MJCF023_DrakeNames) {
  if (const std::string why = MujocoJsUnavailable(); !why.empty()) GTEST_SKIP() << why;
  std::string problem;
  const json d = DumpMujoco3(HandModel("stacked_joints_ref.xml"), &problem);
  ASSERT_EQ(problem, "");
  ASSERT_TRUE(d.value("ok", false)) << d.dump();
  const Reference r = BuildReference(d);
  std::vector<std::string> bodies;
  for (const auto& b : r.bodies) bodies.push_back(b.name);
  // world(0) base(1) hip(2) hip0(3) hip1(4) body5(5) body50(6) body7(7)
  // body8(8) after_weld(9) after_weld0(10)
  EXPECT_EQ(bodies, (std::vector<std::string>{"world", "base", "hip", "body5", "body7", "body8",
                                              "after_weld"}));
  EXPECT_EQ(r.bodies[2].dummies, (std::vector<std::string>{"hip0", "hip1"}));
  EXPECT_EQ(r.bodies[3].dummies, (std::vector<std::string>{"body50"}));
  std::vector<std::string> joints;
  for (const auto& j : r.joints) joints.push_back(j.name + ":" + j.parent + ">" + j.child);
  EXPECT_EQ(joints, (std::vector<std::string>{
                        "base_yaw:world>base", "hip_x:base>hip0", "hip_slide:hip0>hip1",
                        "hip_z:hip1>hip", "hip-body50:hip>body50", "body50-body5:body50>body5",
                        "body5-body7:body5>body7", "body8-after_weld0:body8>after_weld0",
                        "after_weld0-after_weld:after_weld0>after_weld"}));
  std::vector<std::string> geoms;
  for (const auto& g : r.geoms) geoms.push_back(g.body + "/" + g.name);
  EXPECT_EQ(geoms, (std::vector<std::string>{"base/geom0", "hip/geom0", "body5/geom0",
                                             "body7/geom0", "body8/geom0", "after_weld/geom0"}));
  // qpos0 is the ref (degrees converted), the default configuration.
  EXPECT_NEAR(r.joints[0].qpos0, 15 * M_PI / 180, 1e-15);
  EXPECT_NEAR(r.joints[2].qpos0, 0.03, 1e-15);
}

// The dump's mass matrix: a single hinge at distance l from a point mass m
// has M = m l^2 + armature; the oracle removes the armature.
TEST(MujocoOracleSelfCheck, MassMatrixAndArmature) {
  if (const std::string why = MujocoJsUnavailable(); !why.empty()) GTEST_SKIP() << why;
  std::string problem;
  const json d = DumpMujoco3(HandModel("defaults_childclass.xml"), &problem);
  ASSERT_EQ(problem, "");
  ASSERT_TRUE(d.value("ok", false)) << d.dump();
  const Reference r = BuildReference(d);
  // shoulder's class "arm" sets armature 0.01; root_hinge has none.
  for (const auto& J : r.joints) {
    if (J.name == "shoulder") {
      EXPECT_DOUBLE_EQ(J.armature, 0.01);
    }
    if (J.name == "root_hinge") {
      EXPECT_DOUBLE_EQ(J.armature, 0.0);
    }
  }
  ASSERT_GE(r.configs.size(), 2u);
  for (const auto& C : r.configs) {
    // M is symmetric positive definite on the moving dofs, and the diagonal
    // entry of a joint with armature is at least the armature.
    for (const auto& [ij, v] : C.M) {
      if (ij.first == ij.second) {
        EXPECT_GT(v, 0);
      }
    }
  }
}

// Geometry poses: MuJoCo's mesh offset undone puts the mesh back in the
// frame the file gives it (the wedge's first vertex is at (0.1, 0, 0) in its
// file; the world_wedge geom is at (1, 0, 0) yawed 90 degrees).
TEST(MujocoOracleSelfCheck, MJCF050_MeshOffsetUndone) {
  if (const std::string why = MujocoJsUnavailable(); !why.empty()) GTEST_SKIP() << why;
  std::string problem;
  const json d = DumpMujoco3(HandModel("mesh_geoms.xml"), &problem);
  ASSERT_EQ(problem, "");
  ASSERT_TRUE(d.value("ok", false)) << d.dump();
  const Reference r = BuildReference(d);
  ASSERT_EQ(r.geoms[0].name, "world_wedge");
  ASSERT_TRUE(r.geoms[0].has_mesh_offset);
  const Isometry3d X = r.configs[0].X_WG[0] * r.geoms[0].X_mesh.inverse();
  EXPECT_TRUE(X.translation().isApprox(Vector3d(1, 0, 0), 1e-6)) << X.translation().transpose();
  const Matrix3d Rz = Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_TRUE(X.linear().isApprox(Rz, 1e-6)) << X.linear();
  // the wedge's volume is 0.2 * 0.05 / 2 * 0.12 = 6e-4 m^3 at density 1000,
  // and the scaled one (2 x 1 x 1.5) 1.8e-3 m^3 at density 500.
  EXPECT_NEAR(r.bodies[1].mass, 0.6 + 0.9, 1e-6);
}

// BEYOND-007/008: the dump's joint and actuator gains are MuJoCo's derived
// ones: for a springdamper joint dof_damping = 2 I / timeconst and
// jnt_stiffness = I / (timeconst dampratio)^2 with I = 1 / dof_invweight0;
// on the slide-only "simple" body dof_invweight0 is 1 / its mass (box 0.2
// x 0.16 x 0.12 m at 1000 kg/m^3: 3.84 kg), leaving the armature out; a
// position's kd = 2 dampratio sqrt(kp dof_M0 / gear^2).
TEST(MujocoOracleSelfCheck, Beyond007Beyond008DumpedGains) {
  if (const std::string why = MujocoJsUnavailable(); !why.empty()) GTEST_SKIP() << why;
  std::string problem;
  const json d = DumpMujoco3(HandModel("springdamper_dampratio.xml"), &problem);
  ASSERT_EQ(problem, "");
  ASSERT_TRUE(d.value("ok", false)) << d.dump();
  std::map<std::string, json> joints;
  for (const auto& j : d.at("joints")) joints[j.at("name").get<std::string>()] = j;
  const struct { const char* name; double timeconst, dampratio; } sd[] = {
      {"yaw", 0.5, 1}, {"shoulder", 0.3, 0.5}, {"elbow", 0.2, 0.7}, {"extend", 0.1, 2},
      {"slide_x", 0.25, 1.5}, {"slide_y", 0.2, 0.7}, {"flap_hinge", 0.15, 0.8}};
  for (const auto& s : sd) {
    const json& j = joints.at(s.name);
    const double I = 1 / j.at("invweight0").at(0).get<double>();
    const double damping = 2 * I / s.timeconst;
    const double stiffness = I / (s.timeconst * s.timeconst * s.dampratio * s.dampratio);
    EXPECT_NEAR(j.at("damping").at(0).get<double>(), damping, 1e-12 * damping) << s.name;
    EXPECT_NEAR(j.at("stiffness").get<double>(), stiffness, 1e-12 * stiffness) << s.name;
  }
  EXPECT_NEAR(1 / joints.at("slide_x").at("invweight0").at(0).get<double>(), 3.84, 1e-12);
  EXPECT_NEAR(joints.at("slide_x").at("M0").at(0).get<double>(), 3.84 + 0.3, 1e-12);
  const json& a = d.at("actuators").at(0);
  ASSERT_EQ(a.at("name"), "shoulder_servo");
  const double M0 = joints.at("shoulder").at("M0").at(0).get<double>();
  EXPECT_NEAR(-a.at("biasprm").at(2).get<double>(), 2 * 1 * std::sqrt(40 * M0), 1e-12);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ParseMdlcFlag(argc, argv);
  return RUN_ALL_TESTS();
}
