// round_trip_test.cc - `mdlc convert` round trips (issue 14): a model
// compiled, converted to the target format, written beside a temporary
// folder and compiled back is the same plant:
//   - every body is there, under its scoped name (URDF and MJCF hold one
//     model; their writers leave comments from which mdlc's reader restores
//     the instances and names);
//   - every joint connects the mapped bodies with the same type;
//   - at the default and at random configurations, every body's pose and
//     the mass matrix agree to 1e-12 (relative to the quantity's scale);
//   - each role has as many geometries as before (less the ones the writer
//     reported as dropped);
//   - the same body pairs are filtered from collision.
// A conversion that reported structural losses (-Wlossy on a joint the
// target cannot hold) is counted as approximated and not compared; the test
// prints how many models were compared and approximated per format.
//
// Models: the project's own test models and examples, and every corpus model
// the reference tools load (../shared; skipped when absent).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "../corpus/shared_corpus.h"
#include "ir/module.h"
#include "mdlc/convert.h"
#include "mdlc/kinematics.h"
#include "mdlc/mdlc.h"
#include "passes/mesh/mesh_loader.h"

namespace mdlc {
namespace {
namespace fs = std::filesystem;

constexpr double kTolerance = 1e-12;

using corpus_test::Corpus;
using corpus_test::HaveCorpus;

struct ModelCase {
  fs::path path;
  std::string format;  // as the manifest spells it
};

/// The corpus models of `format` that the reference tools load.
std::vector<ModelCase> CorpusModels(std::string_view format) {
  std::vector<ModelCase> out;
  std::ifstream in(Corpus() / "manifest.tsv");
  std::string line;
  std::getline(in, line);  // header: format path ... loads_in_reference
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream row(line);
    for (std::string f; std::getline(row, f, '\t');) fields.push_back(f);
    if (fields.size() < 7 || fields[0] != format) continue;
    if (format != "dmd" && !fields[6].starts_with("yes")) continue;
    out.push_back({Corpus() / fields[1], fields[0]});
  }
  return out;
}

/// The project's own models of a format (they stand alone, without ../shared).
std::vector<ModelCase> OwnModels(std::string_view format, std::string_view extension) {
  std::vector<ModelCase> out;
  const fs::path dir = fs::path(MDLC_TEST_MODELS) / format;
  if (!fs::is_directory(dir)) return out;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().string().ends_with(extension)) {
      out.push_back({entry.path(), std::string(format)});
    }
  }
  std::sort(out.begin(), out.end(),
            [](const ModelCase& a, const ModelCase& b) { return a.path < b.path; });
  return out;
}

/// Where the converted files go: a temporary folder, or the folder
/// MDLC_CONVERT_KEEP_DIR names, where they stay for the reference
/// implementations to load (tests/convert/CMakeLists.txt).
class OutputDir {
 public:
  OutputDir() {
    const char* keep = std::getenv("MDLC_CONVERT_KEEP_DIR");
    keep_ = keep && *keep;
    path_ = keep_ ? fs::path(keep)
                  : fs::temp_directory_path() / fmt::format("mdlc_convert_{}", ::getpid());
    if (!keep_) fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~OutputDir() {
    if (!keep_) fs::remove_all(path_);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
  bool keep_ = false;
};

/// A file name for the converted model: its path, flattened, so models of
/// the same name in different folders do not collide.
std::string OutputName(const ModelCase& mc, std::string_view extension) {
  std::string id = mc.format + "_" + mc.path.lexically_relative(Corpus()).generic_string();
  if (id.find("..") != std::string::npos) id = mc.format + "_own_" + mc.path.filename().string();
  for (char& c : id) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return id + "." + std::string(extension);
}

std::string Messages(const Result& r) {
  std::string out;
  for (const Diagnostic& d : r.diagnostics()) out += r.FormatText(d);
  return out;
}

/// The compile's diagnostics, then a conversion's of its Result.
std::string Messages(const Result& r, const std::vector<Diagnostic>& converted) {
  std::string out = Messages(r);
  for (const Diagnostic& d : converted) out += r.FormatText(d);
  return out;
}

bool Near(double a, double b, double scale) {
  return std::abs(a - b) <= kTolerance * std::max(1.0, scale);
}

/// A random configuration: each coordinate in [-1, 1], quaternions unit.
Eigen::VectorXd RandomPositions(const backend::Plant& plant, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::VectorXd q(plant.num_positions);
  for (int i = 0; i < q.size(); ++i) q[i] = u(rng);
  for (const auto& j : plant.joints) {
    if (j.type == ir::JointType::QuaternionFloating) q.segment(j.q_start, 4).normalize();
  }
  return q;
}

/// The -Wlossy warnings among a conversion's diagnostics that hold `text`.
size_t CountLossy(const std::vector<Diagnostic>& converted, std::string_view text) {
  size_t n = 0;
  for (const Diagnostic& d : converted) {
    n += d.kind == DiagKind::Lossy && d.message.find(text) != std::string::npos;
  }
  return n;
}

enum class Outcome { Compared, Approximated, Rejected };

/// Where a writer puts the converted body's frame: its pose in the
/// original body B, given B's inbound joint.
using LinkFrame = Transform (*)(const backend::PlantJoint& inbound);

/// URDF: the link frame is the joint's child frame M.
Transform UrdfLinkFrame(const backend::PlantJoint& j) { return j.X_CM; }
/// SDFormat: body frames stay where they are.
Transform SdfLinkFrame(const backend::PlantJoint&) { return {}; }
/// MJCF: the body frame, except under a ball joint (rotated as M, since
/// MJCF's ball turns about the body's axes) and a floating joint (M).
Transform MjcfLinkFrame(const backend::PlantJoint& j) {
  if (j.type == ir::JointType::QuaternionFloating && j.parent.index() == 0) return j.X_CM;
  if (j.type == ir::JointType::Ball) return Transform::FromRotation(j.X_CM.R);
  return {};
}

/// The geometry a writer drops (with a -Wlossy warning): half spaces in
/// URDF, geometry on the world in SDFormat, an unreadable mesh in MJCF.
using Drops = bool (*)(const backend::SceneGeometry& g);
bool UrdfDrops(const backend::SceneGeometry& g) {
  return std::holds_alternative<ir::HalfSpace>(g.shape);
}
bool SdfDrops(const backend::SceneGeometry& g) { return g.body.index() == 0; }
bool DropsNothing(const backend::SceneGeometry&) { return false; }
/// MJCF, with --copy-assets: a mesh geometry whose file neither MuJoCo nor
/// mdlc reads (in the corpus: an empty COLLADA file, glTF files without
/// their .bin), as MuJoCo refuses a model naming such a file; every other
/// mesh is written as one it reads.
bool MjcfDrops(const backend::SceneGeometry& g) {
  const auto* mesh = std::get_if<ir::Mesh>(&g.shape);
  // an inline mesh is written back inline (no file to read)
  if (!mesh || mesh->resolved.empty() || mesh->inline_data) return false;
  std::string ext = fs::path(mesh->resolved).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".obj" || ext == ".stl" || ext == ".msh" || ext == ".vtk") return false;
  static std::map<std::string, bool> unreadable;  // each file read once
  auto [it, added] = unreadable.emplace(mesh->resolved, false);
  if (added) it->second = !mesh::LoadMesh(mesh->resolved).ok();
  return it->second;
}

/// The formats `mdlc convert` writes; a new writer adds its line here.
struct Target {
  Format format;
  const char* extension;  // of the converted file
  const char* name;       // in test names
  LinkFrame link_frame;
  /// SDFormat writes each role as it is; a URDF or MJCF visual is both
  /// illustration and perception.
  bool exact_roles;
  Drops drops;
  const char* drop_warning;   // what the writer's -Wlossy warning for it says
  bool writes_world_filters;  // collision filters against the world
  /// Each converted model in a folder of its own, beside copies of its
  /// meshes (MuJoCo's reference loads a model's folder, not its mesh paths
  /// that reach up and out of it).
  bool own_folder;
  /// URDF: plain URDF (--plain), which urdfdom reads: one root link, Drake's
  /// shapes and joints approximated.
  bool plain = false;
};
constexpr Target kTargets[] = {
    {Format::Urdf, "urdf", "Urdf", UrdfLinkFrame, false, UrdfDrops, "half space", false, false},
    {Format::Sdf, "sdf", "Sdf", SdfLinkFrame, true, SdfDrops, "on the world is dropped", false,
     false},
    {Format::Mjcf, "xml", "Mjcf", MjcfLinkFrame, false, MjcfDrops,
     "is dropped: MuJoCo cannot read its mesh", true, true},
    {Format::Urdf, "urdf", "PlainUrdf", UrdfLinkFrame, false, UrdfDrops, "half space", false,
     false, true},
};
// The corpus is converted once per target, as a user loading the result in
// the target's reference would: URDF as plain URDF (urdfdom reads the files,
// tests/convert/CMakeLists.txt), and also in Drake's URDF dialect, which
// keeps what plain URDF approximates, compared but not given to urdfdom
// (its files go to a folder of their own, DialectFolder).
constexpr Target kCorpusTargets[] = {kTargets[3], kTargets[0], kTargets[1], kTargets[2]};

/// Where a target's converted files go inside the output folder: Drake's
/// URDF dialect apart from the plain URDF that urdfdom loads.
fs::path DialectFolder(const fs::path& dir, const Target& to) {
  return to.format == Format::Urdf && !to.plain ? dir / "drake_urdf" : dir;
}

/// The converted model against the original; failures are gtest failures.
class Comparison {
 public:
  /// `converted`: the diagnostics of the conversion of a into b.
  Comparison(const Result& a, const Result& b, const std::vector<Diagnostic>& converted,
             const Target& to)
      : a_(a), b_(b), converted_(converted), pa_(a.plant()), pb_(b.plant()), to_(to) {}

  /// False when the kinematic structure could not be mapped.
  bool MapStructure(std::string* why) {
    // every body keeps its scoped name: SDFormat keeps the instances as
    // models; URDF and MJCF flatten them into one model ("instance/name",
    // backend/writers/names.h) and leave comments from which mdlc's reader
    // restores instances and names (ir/original_name.h)
    std::map<std::string, BodyId> by_name;
    for (size_t i = 1; i < pb_.bodies.size(); ++i) by_name[pb_.ScopedName(pb_.bodies[i])] = BodyId(i);
    body_map_.assign(pa_.bodies.size(), BodyId());
    body_map_[0] = ir::kWorldBody;
    for (size_t i = 1; i < pa_.bodies.size(); ++i) {
      const auto& body = pa_.bodies[i];
      const std::string name = pa_.ScopedName(body);
      auto it = by_name.find(name);
      if (it == by_name.end()) {
        *why = fmt::format("body '{}' is missing (looked for '{}')", pa_.ScopedName(body), name);
        return false;
      }
      body_map_[i] = it->second;
    }
    if (pa_.bodies.size() != pb_.bodies.size()) {
      *why = fmt::format("{} bodies became {}", pa_.bodies.size(), pb_.bodies.size());
      return false;
    }
    for (size_t j = 0; j < pa_.joints.size(); ++j) {
      const auto& ja = pa_.joints[j];
      const BodyId child = body_map_[ja.child.index()];
      const JointId mapped = pb_.body(child).inbound_joint;
      if (!mapped.valid()) {
        *why = fmt::format("joint '{}' is missing", pa_.ScopedName(ja));
        return false;
      }
      const auto& jb = pb_.joint(mapped);
      if (jb.type != ja.type || jb.parent != body_map_[ja.parent.index()]) {
        *why = fmt::format("joint '{}' ({}) became '{}' ({})", pa_.ScopedName(ja),
                           ir::JointTypeName(ja.type), pb_.ScopedName(jb),
                           ir::JointTypeName(jb.type));
        return false;
      }
      joint_map_.push_back(mapped);
    }
    return true;
  }

  Eigen::VectorXd MapPositions(const Eigen::VectorXd& q) const {
    Eigen::VectorXd out = Eigen::VectorXd::Zero(pb_.num_positions);
    for (size_t j = 0; j < pa_.joints.size(); ++j) {
      const auto& ja = pa_.joints[j];
      out.segment(pb_.joint(joint_map_[j]).q_start, ja.nq) = q.segment(ja.q_start, ja.nq);
    }
    return out;
  }

  /// The converted model's velocity index of each original velocity.
  std::vector<int> VelocityMap() const {
    std::vector<int> map(pa_.num_velocities);
    for (size_t j = 0; j < pa_.joints.size(); ++j) {
      const auto& ja = pa_.joints[j];
      for (int k = 0; k < ja.nv; ++k) map[ja.v_start + k] = pb_.joint(joint_map_[j]).v_start + k;
    }
    return map;
  }

  void CompareAt(const Eigen::VectorXd& q, const std::string& label) {
    const Eigen::VectorXd qb = MapPositions(q);
    const auto X_WA = mdlc::BodyPoses(a_, q);
    const auto X_WB = mdlc::BodyPoses(b_, qb);
    for (size_t i = 1; i < pa_.bodies.size(); ++i) {
      // the converted body's frame, as the target's writer places it
      Transform expected = X_WA[i];
      if (pa_.bodies[i].inbound_joint.valid()) {
        expected = expected * to_.link_frame(pa_.joint(pa_.bodies[i].inbound_joint));
      }
      const Transform& got = X_WB[body_map_[i].index()];
      const double scale = expected.p.cwiseAbs().maxCoeff();
      bool same = true;
      for (int r = 0; r < 3; ++r) {
        same = same && Near(got.p[r], expected.p[r], scale);
        for (int c = 0; c < 3; ++c) same = same && Near(got.R(r, c), expected.R(r, c), 1);
      }
      EXPECT_TRUE(same) << label << ": pose of body '" << pa_.ScopedName(pa_.bodies[i])
                        << "' differs:\n  expected p " << expected.p.transpose() << "\n  got p "
                        << got.p.transpose();
      if (!same) return;
    }
    const Eigen::MatrixXd Ma = mdlc::MassMatrix(a_, q);
    const Eigen::MatrixXd Mb = mdlc::MassMatrix(b_, qb);
    ASSERT_EQ(Ma.rows(), Mb.rows());
    if (Ma.size() == 0) return;  // nothing moves
    const std::vector<int> v = VelocityMap();
    const double scale = Ma.cwiseAbs().maxCoeff();
    for (int r = 0; r < Ma.rows(); ++r) {
      for (int c = 0; c < Ma.cols(); ++c) {
        if (!Near(Mb(v[r], v[c]), Ma(r, c), scale)) {
          ADD_FAILURE() << label << ": mass matrix (" << r << ", " << c << ") is "
                        << Mb(v[r], v[c]) << ", was " << Ma(r, c);
          return;
        }
      }
    }
  }

  void CompareGeometryAndFilters() {
    const auto& sa = a_.scene_graph();
    const auto& sb = b_.scene_graph();
    auto count = [](const backend::SceneGraph& s, uint8_t roles, Drops skip) {
      size_t n = 0;
      for (const auto& g : s.geometries) n += (g.roles & roles) && !skip(g) ? 1 : 0;
      return n;
    };
    size_t n_dropped = 0;
    for (const auto& g : sa.geometries) n_dropped += to_.drops(g) ? 1 : 0;
    if (n_dropped > 0) {
      EXPECT_GT(CountLossy(converted_, to_.drop_warning), 0u);
    }
    EXPECT_EQ(count(sb, ir::kProximityRole, DropsNothing),
              count(sa, ir::kProximityRole, to_.drops));
    if (to_.exact_roles) {
      EXPECT_EQ(count(sb, ir::kIllustrationRole, DropsNothing),
                count(sa, ir::kIllustrationRole, to_.drops));
      EXPECT_EQ(count(sb, ir::kPerceptionRole, DropsNothing),
                count(sa, ir::kPerceptionRole, to_.drops));
    } else {
      EXPECT_EQ(count(sb, ir::kIllustrationRole, DropsNothing),
                count(sa, ir::kIllustrationRole | ir::kPerceptionRole, to_.drops));
    }
    // a body whose every collision geometry the writer dropped (reported
    // above) has nothing left to filter
    std::set<size_t> colliding, kept;
    for (const auto& g : sa.geometries) {
      if (!(g.roles & ir::kProximityRole)) continue;
      colliding.insert(g.body.index());
      if (!to_.drops(g)) kept.insert(g.body.index());
    }
    auto all_dropped = [&](BodyId b) {
      return colliding.count(b.index()) && !kept.count(b.index());
    };
    // filters against the world cannot be written in URDF or SDFormat (reported)
    std::set<std::pair<size_t, size_t>> fa, fb;
    for (const auto& [x, y] : sa.collision_filters.Pairs(pa_)) {
      if (!to_.writes_world_filters && (x.index() == 0 || y.index() == 0)) {
        EXPECT_GT(CountLossy(converted_, "and the world is dropped"), 0u);
        continue;
      }
      if (all_dropped(x) || all_dropped(y)) continue;
      const size_t mx = body_map_[x.index()].index(), my = body_map_[y.index()].index();
      fa.insert({std::min(mx, my), std::max(mx, my)});
    }
    for (const auto& [x, y] : sb.collision_filters.Pairs(pb_)) {
      fb.insert({std::min(x.index(), y.index()), std::max(x.index(), y.index())});
    }
    if (to_.format == Format::Sdf) {
      // a filter group is a model's: a filtered pair across top-level models
      // that is not filtered by the joints between them is reported dropped
      for (const auto& [x, y] : sa.collision_filters.Pairs(pa_)) {
        if (x.index() == 0 || y.index() == 0 || TopInstance(x) == TopInstance(y)) continue;
        const size_t mx = body_map_[x.index()].index(), my = body_map_[y.index()].index();
        const std::pair<size_t, size_t> pair{std::min(mx, my), std::max(mx, my)};
        if (fb.count(pair)) continue;
        EXPECT_GT(CountLossy(converted_, "different top-level models"), 0u);
        fa.erase(pair);
      }
    }
    EXPECT_EQ(fa, fb) << "the filtered body pairs differ";
  }

  /// "outer" for a body of instance "outer::inner".
  std::string TopInstance(BodyId body) const {
    const std::string& instance = pa_.model_instances[pa_.body(body).model.index()];
    return instance.substr(0, instance.find("::"));
  }

 private:
  const Result& a_;
  const Result& b_;
  const std::vector<Diagnostic>& converted_;
  const backend::Plant& pa_;
  const backend::Plant& pb_;
  const Target& to_;
  std::vector<BodyId> body_map_;
  std::vector<JointId> joint_map_;
};

void PrintTo(const Target& t, std::ostream* os) { *os << t.name; }

Outcome RoundTrip(const ModelCase& mc, const Target& to, const fs::path& dir) {
  Options options;
  options.packages.paths = {Corpus().string()};
  Result a = Compile(Input::File(mc.path.string()), options);
  if (!a.ok()) return Outcome::Rejected;  // which models are rejected is the corpus tests'
  fs::path out = DialectFolder(dir, to) / OutputName(mc, to.extension);
  fs::create_directories(out.parent_path());
  ConvertOptions convert;
  if (to.own_folder) {
    const fs::path folder = dir / to.extension / out.stem();
    fs::create_directories(folder);
    out = folder / out.filename();
    convert.copy_assets_dir = (folder / "assets").string();
  }
  convert.to = to.format;
  convert.output = out.string();
  convert.plain = to.plain;
  const ConvertOutput converted = mdlc::Convert(a, convert);
  const std::optional<std::string>& text = converted.text;
  EXPECT_TRUE(text) << Messages(a, converted.diagnostics);
  if (!text) return Outcome::Compared;
  std::ofstream(out) << *text;
  Result b = Compile(Input::File(out.string()));
  EXPECT_TRUE(b.ok()) << "the converted model does not compile:\n"
                      << Messages(b) << "\n--- converted:\n"
                      << *text;
  if (!b.ok()) return Outcome::Compared;

  Comparison cmp(a, b, converted.diagnostics, to);
  std::string why;
  if (!cmp.MapStructure(&why)) {
    // only a conversion that said it changed the structure may do so
    const bool reported = CountLossy(converted.diagnostics, "joint") > 0;
    EXPECT_TRUE(reported) << "structure changed without a -Wlossy warning: " << why;
    return Outcome::Approximated;
  }
  std::mt19937 rng(20261126);
  cmp.CompareAt(mdlc::DefaultPositions(a), "default q");
  for (int k = 0; k < 3; ++k) cmp.CompareAt(RandomPositions(a.plant(), rng), fmt::format("q #{}", k));
  cmp.CompareGeometryAndFilters();
  return Outcome::Compared;
}

void RunSuite(const std::vector<ModelCase>& models, const Target& to, std::string_view label) {
  OutputDir dir;
  int compared = 0, approximated = 0, rejected = 0;
  for (const ModelCase& mc : models) {
    SCOPED_TRACE(mc.path.string());
    switch (RoundTrip(mc, to, dir.path())) {
      case Outcome::Compared: ++compared; break;
      case Outcome::Approximated: ++approximated; break;
      case Outcome::Rejected: ++rejected; break;
    }
  }
  fmt::print("{} -> {}: {} models compared, {} approximated (reported -Wlossy), {} rejected by "
             "mdlc\n",
             label, FormatName(to.format), compared, approximated, rejected);
  EXPECT_GT(compared, 0);
}

// the project's own models (they stand alone, without ../shared)
class OwnRoundTrip : public ::testing::TestWithParam<Target> {};
TEST_P(OwnRoundTrip, UrdfModels) {
  RunSuite(OwnModels("urdf", ".urdf"), GetParam(), "own URDF");
}
TEST_P(OwnRoundTrip, SdfModels) { RunSuite(OwnModels("sdf", ".sdf"), GetParam(), "own SDFormat"); }
INSTANTIATE_TEST_SUITE_P(To, OwnRoundTrip, ::testing::ValuesIn(kTargets),
                         [](const auto& info) { return std::string(info.param.name); });

// MJCF meshes written in the model file (vertex and face lists) and point
// clouds (issue 62): MJCF writes them back inline; URDF and SDFormat, which
// name mesh files only, get OBJ copies of the triangles the compile took
// (a cloud's convex hull) with --copy-assets, and without it leave their
// geometries out with a located -Wlossy warning. Every result compiles back
// to the same plant (mass properties from the source's inline meshes).
bool InlineMeshDropped(const backend::SceneGeometry& g) {
  const auto* mesh = std::get_if<ir::Mesh>(&g.shape);
  return mesh && mesh->inline_data;
}
bool UrdfDropsInline(const backend::SceneGeometry& g) {
  return UrdfDrops(g) || InlineMeshDropped(g);
}
bool SdfDropsInline(const backend::SceneGeometry& g) {
  return SdfDrops(g) || InlineMeshDropped(g);
}
class InlineMeshes : public ::testing::TestWithParam<Target> {};
TEST_P(InlineMeshes, RoundTrip) {
  const ModelCase mc{fs::path(MDLC_TEST_MODELS) / "mjcf" / "oracle" / "inline_meshes.xml", "mjcf"};
  OutputDir dir;
  EXPECT_EQ(RoundTrip(mc, GetParam(), dir.path()), Outcome::Compared);
}
constexpr Target kInlineMeshTargets[] = {
    kTargets[2],
    // without --copy-assets: the inline meshes' geometries are left out
    {Format::Urdf, "urdf", "Urdf", UrdfLinkFrame, false, UrdfDropsInline,
     "is written in the model file", false, false},
    {Format::Sdf, "sdf", "Sdf", SdfLinkFrame, true, SdfDropsInline,
     "is written in the model file", false, false},
    // with --copy-assets: OBJ copies
    {Format::Urdf, "urdf", "UrdfCopyAssets", UrdfLinkFrame, false, UrdfDrops, "half space", false,
     true},
    {Format::Sdf, "sdf", "SdfCopyAssets", SdfLinkFrame, true, SdfDrops, "on the world is dropped",
     false, true},
};
INSTANTIATE_TEST_SUITE_P(To, InlineMeshes, ::testing::ValuesIn(kInlineMeshTargets),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(InlineMeshes, WrittenAsTheTargetReadsThem) {
  const fs::path source = fs::path(MDLC_TEST_MODELS) / "mjcf" / "oracle" / "inline_meshes.xml";
  Result a = Compile(Input::File(source.string()));
  ASSERT_TRUE(a.ok()) << Messages(a);
  OutputDir dir;
  // MJCF: <mesh vertex= face=>, a cloud without faces, no file named
  ConvertOptions to_mjcf;
  to_mjcf.to = Format::Mjcf;
  to_mjcf.output = (dir.path() / "inline.xml").string();
  const ConvertOutput mjcf = mdlc::Convert(a, to_mjcf);
  ASSERT_TRUE(mjcf.text);
  EXPECT_EQ(mjcf.text->find("<inline mesh"), std::string::npos) << *mjcf.text;
  EXPECT_NE(mjcf.text->find("face=\"0 2 1  0 1 3  0 3 2  1 2 3\""), std::string::npos);
  EXPECT_NE(mjcf.text->find("scale=\"1 2 0.5\""), std::string::npos);
  // URDF without --copy-assets: each geometry left out says so where it is
  ConvertOptions to_urdf;
  to_urdf.to = Format::Urdf;
  to_urdf.output = (dir.path() / "inline.urdf").string();
  const ConvertOutput urdf = mdlc::Convert(a, to_urdf);
  ASSERT_TRUE(urdf.text);
  EXPECT_EQ(urdf.text->find("<inline mesh"), std::string::npos) << *urdf.text;
  size_t located = 0;
  for (const Diagnostic& d : urdf.diagnostics) {
    if (d.message.find("is written in the model file") == std::string::npos) continue;
    EXPECT_NE(d.message.find("--copy-assets writes an OBJ of it"), std::string::npos);
    located += d.loc.valid() ? 1 : 0;
  }
  EXPECT_EQ(located, 7u);  // once per mesh geom but the one of the OBJ file
  // SDFormat with --copy-assets: OBJ copies beside the output, named relative to it
  ConvertOptions to_sdf;
  to_sdf.to = Format::Sdf;
  to_sdf.output = (dir.path() / "sdf" / "inline.sdf").string();
  to_sdf.copy_assets_dir = (dir.path() / "sdf" / "assets").string();
  const ConvertOutput sdf = mdlc::Convert(a, to_sdf);
  ASSERT_TRUE(sdf.text);
  EXPECT_EQ(sdf.text->find("<inline mesh"), std::string::npos) << *sdf.text;
  EXPECT_NE(sdf.text->find("<uri>assets/tetra-"), std::string::npos) << *sdf.text;
  EXPECT_NE(sdf.text->find("<uri>assets/cloud-"), std::string::npos) << *sdf.text;
}

// every corpus model the reference tools load, of each source format
class CorpusRoundTrip
    : public ::testing::TestWithParam<std::tuple<Target, const char*>> {};
TEST_P(CorpusRoundTrip, Converts) {
  if (!HaveCorpus()) GTEST_SKIP() << "the shared corpus is absent";
  const auto& [to, format] = GetParam();
  RunSuite(CorpusModels(format), to, fmt::format("corpus {}", format));
}
INSTANTIATE_TEST_SUITE_P(Corpus, CorpusRoundTrip,
                         ::testing::Combine(::testing::ValuesIn(kCorpusTargets),
                                            ::testing::Values("urdf", "sdf", "mjcf", "dmd")),
                         [](const auto& info) {
                           return fmt::format("{}_from_{}", std::get<0>(info.param).name,
                                              std::get<1>(info.param));
                         });

// ---------------------------------------------------------------------------
// Hand-made models pinning what a writer does with one construct
// ---------------------------------------------------------------------------

/// A model compiled from text, converted and compiled back from the written
/// file (in a temporary folder).
struct Conversion {
  Result source;
  std::optional<std::string> text;
  std::vector<Diagnostic> diagnostics;  // the conversion's
  std::optional<Result> back;
  fs::path file;

  /// The -Wlossy warnings of the conversion whose message holds `text`.
  std::vector<const Diagnostic*> Lossy(std::string_view text) const {
    std::vector<const Diagnostic*> out;
    for (const Diagnostic& d : diagnostics) {
      if (d.kind == DiagKind::Lossy && d.message.find(text) != std::string::npos) out.push_back(&d);
    }
    return out;
  }
};

Conversion ConvertText(const std::string& model, const std::string& name, ConvertOptions convert,
                       const fs::path& dir) {
  Conversion c{Compile(Input::Text(model, (dir / name).string())), {}, {}, {}, {}};
  EXPECT_TRUE(c.source.ok()) << Messages(c.source, c.diagnostics);
  if (!c.source.ok()) return c;
  c.file = dir / ("converted_" + fs::path(name).stem().string() +
                  (convert.to == Format::Urdf  ? ".urdf"
                   : convert.to == Format::Sdf ? ".sdf"
                                               : ".xml"));
  convert.output = c.file.string();
  ConvertOutput converted = mdlc::Convert(c.source, convert);
  c.text = std::move(converted.text);
  c.diagnostics = std::move(converted.diagnostics);
  EXPECT_TRUE(c.text) << Messages(c.source, c.diagnostics);
  if (!c.text) return c;
  std::ofstream(c.file) << *c.text;
  c.back = Compile(Input::File(c.file.string()));
  EXPECT_TRUE(c.back->ok()) << Messages(*c.back) << "\n--- converted:\n" << *c.text;
  return c;
}

ConvertOptions To(Format format) {
  ConvertOptions options;
  options.to = format;
  return options;
}

// MuJoCo collides with the convex hull of every mesh, so a mesh declared
// convex (drake:declare_convex) collides in MuJoCo as declared; but MJCF has
// no flag to carry the declaration, and an MJCF mesh reads back as a plain
// mesh: a -Wlossy warning at the geometry, and only for a collision mesh.
TEST(MjcfWriter, ConvexMeshDeclarationIsALocatedLossyWarning) {
  OutputDir dir;
  const std::string mesh = (fs::path(MDLC_TEST_MODELS) / "meshes" / "box.obj").string();
  const std::string urdf = fmt::format(R"(<robot name="r" xmlns:drake="http://drake.mit.edu">
  <link name="base">
    <inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual name="look"><geometry><mesh filename="{0}"/></geometry></visual>
    <collision name="hull">
      <geometry><mesh filename="{0}"><drake:declare_convex/></mesh></geometry>
    </collision>
  </link>
</robot>
)",
                                       mesh);
  const Conversion c = ConvertText(urdf, "convex.urdf", To(Format::Mjcf), dir.path());
  ASSERT_TRUE(c.back && c.back->ok());
  const auto lossy = c.Lossy("convex");
  ASSERT_EQ(lossy.size(), 1u) << Messages(c.source, c.diagnostics);
  EXPECT_NE(lossy[0]->message.find("geometry 'hull'"), std::string::npos) << lossy[0]->message;
  EXPECT_NE(lossy[0]->message.find("MuJoCo collides with every mesh's convex hull"),
            std::string::npos)
      << lossy[0]->message;
  EXPECT_NE(c.source.FormatText(*lossy[0]).find("convex.urdf:5:"), std::string::npos)
      << c.source.FormatText(*lossy[0]);
  // the geom is a mesh MuJoCo takes the hull of; read back, a plain mesh
  EXPECT_NE(c.text->find("type=\"mesh\""), std::string::npos) << *c.text;
  size_t meshes = 0;
  for (const auto& g : c.back->scene_graph().geometries) {
    const auto* m = std::get_if<ir::Mesh>(&g.shape);
    ASSERT_NE(m, nullptr);
    EXPECT_FALSE(m->convex);
    ++meshes;
  }
  EXPECT_EQ(meshes, 2u);
  // URDF and SDFormat keep the declaration
  for (Format to : {Format::Urdf, Format::Sdf}) {
    const Conversion kept = ConvertText(urdf, "convex.urdf", To(to), dir.path());
    ASSERT_TRUE(kept.back && kept.back->ok());
    EXPECT_TRUE(kept.Lossy("convex").empty()) << Messages(kept.source);
    for (const auto& g : kept.back->scene_graph().geometries) {
      if (g.roles & ir::kProximityRole) {
        EXPECT_TRUE(std::get<ir::Mesh>(g.shape).convex);
      }
    }
  }
}

/// How many times `what` occurs in `text` outside XML comments.
size_t Count(std::string text, std::string_view what) {
  for (size_t at; (at = text.find("<!--")) != std::string::npos;) {
    text.erase(at, text.find("-->", at) + 3 - at);
  }
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// mdlc (as Drake) reads an MJCF body with several joints as a chain of
// massless bodies; MuJoCo refuses a moving body without mass, so the writer
// writes the chain back as one <body> with its <joint>s: the same bodies as
// the source MJCF, and the same plant when read back.
TEST(MjcfWriter, StackedJointsAreOneBodyAgain) {
  OutputDir dir;
  const fs::path source = fs::path(MDLC_TEST_MODELS) / "mjcf" / "oracle" / "stacked_joints_ref.xml";
  std::ifstream in(source);
  const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const Conversion c = ConvertText(xml, source.filename().string(), To(Format::Mjcf), dir.path());
  ASSERT_TRUE(c.back && c.back->ok());
  EXPECT_EQ(Count(*c.text, "<body"), Count(xml, "<body"));
  EXPECT_EQ(Count(*c.text, "<joint "), Count(xml, "<joint "));
  EXPECT_GT(c.source.plant().bodies.size(), Count(xml, "<body") + 1);  // the chains' links
  // the unnamed links come back as they were: nothing to warn about
  EXPECT_TRUE(c.Lossy("").empty()) << Messages(c.source, c.diagnostics);
  Comparison cmp(c.source, *c.back, c.diagnostics, kTargets[2]);
  std::string why;
  ASSERT_TRUE(cmp.MapStructure(&why)) << why;
  std::mt19937 rng(7);
  cmp.CompareAt(mdlc::DefaultPositions(c.source), "default q");
  for (int k = 0; k < 5; ++k) {
    cmp.CompareAt(RandomPositions(c.source.plant(), rng), fmt::format("q #{}", k));
  }
}

// A massless link of a URDF between two revolute joints is merged the same
// way (MuJoCo would refuse it), with a -Wlossy warning naming it: its name
// and frame are not written.
TEST(MjcfWriter, NamedMasslessLinkBetweenJointsIsMergedWithAWarning) {
  OutputDir dir;
  const std::string urdf = R"(<robot name="gimbal">
  <link name="world"/>
  <joint name="pan" type="continuous">
    <parent link="world"/><child link="yoke"/>
    <origin xyz="0 0 0.2" rpy="0 0 0.4"/><axis xyz="0 0 1"/>
  </joint>
  <link name="yoke"/>
  <joint name="tilt" type="revolute">
    <parent link="yoke"/><child link="head"/>
    <origin xyz="0.05 0 0.1" rpy="0.2 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
  <link name="head">
    <inertial><origin xyz="0.01 0 0.02"/><mass value="0.5"/>
      <inertia ixx="0.01" iyy="0.02" izz="0.03" ixy="0.001" ixz="0" iyz="0"/></inertial>
  </link>
</robot>
)";
  const Conversion c = ConvertText(urdf, "gimbal.urdf", To(Format::Mjcf), dir.path());
  ASSERT_TRUE(c.back && c.back->ok());
  const auto lossy = c.Lossy("body 'yoke' is massless");
  ASSERT_EQ(lossy.size(), 1u) << Messages(c.source, c.diagnostics);
  EXPECT_NE(c.source.FormatText(*lossy[0]).find("gimbal.urdf:7:"), std::string::npos)
      << c.source.FormatText(*lossy[0]);
  EXPECT_EQ(Count(*c.text, "<body"), 1u) << *c.text;  // the head, on both joints
  // the head moves as it did, on both joints
  const auto& pa = c.source.plant();
  const auto& pb = c.back->plant();
  std::mt19937 rng(3);
  for (int k = 0; k < 4; ++k) {
    const Eigen::VectorXd qa = k == 0 ? mdlc::DefaultPositions(c.source) : RandomPositions(pa, rng);
    Eigen::VectorXd qb = Eigen::VectorXd::Zero(pb.num_positions);
    for (const auto& ja : pa.joints) {
      if (ja.nq == 0) continue;
      for (const auto& jb : pb.joints) {
        if (jb.name == ja.name) qb.segment(jb.q_start, jb.nq) = qa.segment(ja.q_start, ja.nq);
      }
    }
    const auto X_a = mdlc::BodyPoses(c.source, qa);
    const auto X_b = mdlc::BodyPoses(*c.back, qb);
    size_t head_a = 0, head_b = 0;
    for (size_t i = 0; i < pa.bodies.size(); ++i) head_a = pa.bodies[i].name == "head" ? i : head_a;
    for (size_t i = 0; i < pb.bodies.size(); ++i) head_b = pb.bodies[i].name == "head" ? i : head_b;
    ASSERT_GT(head_a * head_b, 0u);
    EXPECT_TRUE(X_a[head_a].p.isApprox(X_b[head_b].p, 1e-12)) << k;
    EXPECT_TRUE(X_a[head_a].R.isApprox(X_b[head_b].R, 1e-12)) << k;
    const Eigen::MatrixXd Ma = mdlc::MassMatrix(c.source, qa), Mb = mdlc::MassMatrix(*c.back, qb);
    ASSERT_EQ(Ma.rows(), 2);
    ASSERT_EQ(Mb.rows(), 2);
    EXPECT_LE((Ma - Mb).cwiseAbs().maxCoeff(), 1e-12 * Ma.cwiseAbs().maxCoeff()) << k;
  }
}

// --fuse-fixed: each body welded to its parent is fused into it. The mass
// matrix and the total mass stay (mass properties combined exactly), the
// body count drops by the number of fixed joints, the fused bodies' frames
// and their own frames stay where they were (as sites, read back as frames),
// and each fused body gets a note naming it.
TEST(MjcfWriter, FuseFixedCombinesMassPropertiesExactly) {
  OutputDir dir;
  const std::string urdf = R"(<robot name="fused">
  <link name="base">
    <inertial><origin xyz="0.01 -0.02 0.03" rpy="0.1 0.2 0.3"/><mass value="3"/>
      <inertia ixx="0.05" iyy="0.06" izz="0.07" ixy="0.001" ixz="-0.002" iyz="0.003"/></inertial>
    <visual name="base_look"><geometry><box size="0.2 0.2 0.1"/></geometry></visual>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/>
    <origin xyz="0 0.1 0.2" rpy="0.3 0 0.2"/><axis xyz="0 0 1"/>
    <limit lower="-2" upper="2" effort="10" velocity="1"/>
  </joint>
  <link name="upper">
    <inertial><origin xyz="0 0 0.2" rpy="0 0.4 0"/><mass value="1.5"/>
      <inertia ixx="0.02" iyy="0.025" izz="0.004" ixy="0" ixz="0.0005" iyz="0"/></inertial>
  </link>
  <joint name="mount" type="fixed">
    <parent link="upper"/><child link="flange"/>
    <origin xyz="0.1 0.2 0.5" rpy="0.3 -0.2 0.1"/>
  </joint>
  <link name="flange">
    <inertial><origin xyz="0.02 0.01 0" rpy="-0.5 0.1 0.7"/><mass value="0.5"/>
      <inertia ixx="0.001" iyy="0.002" izz="0.0025" ixy="0.0001" ixz="0" iyz="-0.0002"/></inertial>
    <collision name="flange_hit"><origin xyz="0 0 0.01"/><geometry><cylinder radius="0.04" length="0.02"/></geometry></collision>
  </link>
  <joint name="tool_mount" type="fixed">
    <parent link="flange"/><child link="tool"/>
    <origin xyz="0 0 0.05" rpy="0 0 1.2"/>
  </joint>
  <link name="tool">
    <inertial><origin xyz="0 0 0.03"/><mass value="0.25"/>
      <inertia ixx="0.0002" iyy="0.0002" izz="0.0001" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual name="tool_look"><geometry><sphere radius="0.02"/></geometry></visual>
  </link>
  <frame name="tcp" link="tool" xyz="0 0 0.1" rpy="0.1 0 0"/>
  <joint name="wrist" type="continuous">
    <parent link="tool"/><child link="hand"/>
    <origin xyz="0.03 0 0.08" rpy="0 0.5 0"/><axis xyz="1 0 0"/>
  </joint>
  <link name="hand">
    <inertial><origin xyz="0.04 0 0"/><mass value="0.3"/>
      <inertia ixx="0.0003" iyy="0.0004" izz="0.0005" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
</robot>
)";
  ConvertOptions options = To(Format::Mjcf);
  options.fuse_fixed = true;
  const Conversion c = ConvertText(urdf, "fused.urdf", options, dir.path());
  ASSERT_TRUE(c.back && c.back->ok());
  const auto& pa = c.source.plant();
  const auto& pb = c.back->plant();
  size_t welds = 0;
  for (const auto& j : pa.joints) welds += j.type == ir::JointType::Weld && j.parent.index() != 0;
  ASSERT_EQ(welds, 2u);
  EXPECT_EQ(pb.bodies.size(), pa.bodies.size() - welds);
  // a note per fused body, naming it (not a warning: --fuse-fixed asked for it)
  std::vector<std::string> notes;
  for (const Diagnostic& d : c.diagnostics) {
    if (d.kind == DiagKind::FusedBody) notes.push_back(d.message);
  }
  ASSERT_EQ(notes.size(), 2u) << Messages(c.source, c.diagnostics);
  EXPECT_NE(notes[0].find("body 'flange' is fused into body 'upper'"), std::string::npos)
      << notes[0];
  EXPECT_NE(notes[1].find("body 'tool' is fused into body 'upper'"), std::string::npos) << notes[1];
  // the total mass
  double ma = 0, mb = 0;
  for (const auto& b : pa.bodies) ma += b.mass;
  for (const auto& b : pb.bodies) mb += b.mass;
  EXPECT_NEAR(mb, ma, 1e-12 * ma);
  // the same motion: joints map by the body they move
  auto body_named = [](const backend::Plant& p, std::string_view name) {
    for (size_t i = 0; i < p.bodies.size(); ++i) {
      if (p.bodies[i].name == name) return BodyId(i);
    }
    return BodyId();
  };
  auto frame_pose = [](const Result& r, const std::vector<Transform>& X_WB, std::string_view name) {
    for (const auto& f : r.plant().frames) {
      if (f.name == name) return std::optional<Transform>(X_WB[f.body.index()] * f.X_BF);
    }
    return std::optional<Transform>();
  };
  std::vector<int> v_map(pa.num_velocities, -1);
  std::vector<std::pair<int, int>> q_map;  // (a, b) position slices starts, with sizes below
  for (const auto& ja : pa.joints) {
    if (ja.nv == 0) continue;
    const BodyId child = body_named(pb, pa.body(ja.child).name);
    ASSERT_TRUE(child.valid()) << ja.name;
    const auto& jb = pb.joint(pb.body(child).inbound_joint);
    ASSERT_EQ(jb.nv, ja.nv) << ja.name;
    for (int k = 0; k < ja.nv; ++k) v_map[ja.v_start + k] = jb.v_start + k;
    for (int k = 0; k < ja.nq; ++k) q_map.emplace_back(ja.q_start + k, jb.q_start + k);
  }
  std::mt19937 rng(11);
  for (int k = 0; k < 5; ++k) {
    const Eigen::VectorXd qa = k == 0 ? mdlc::DefaultPositions(c.source) : RandomPositions(pa, rng);
    Eigen::VectorXd qb = Eigen::VectorXd::Zero(pb.num_positions);
    for (const auto& [ia, ib] : q_map) qb[ib] = qa[ia];
    const Eigen::MatrixXd Ma = mdlc::MassMatrix(c.source, qa), Mb = mdlc::MassMatrix(*c.back, qb);
    ASSERT_EQ(Ma.rows(), Mb.rows());
    const double scale = Ma.cwiseAbs().maxCoeff();
    for (int r = 0; r < Ma.rows(); ++r) {
      for (int s = 0; s < Ma.cols(); ++s) {
        EXPECT_NEAR(Mb(v_map[r], v_map[s]), Ma(r, s), 1e-12 * scale)
            << k << ": M(" << r << ", " << s << ")";
      }
    }
    // the fused bodies' frames and their frames, where they were
    const auto X_WA = mdlc::BodyPoses(c.source, qa), X_WB = mdlc::BodyPoses(*c.back, qb);
    for (const char* name : {"flange", "tool", "tcp"}) {
      const BodyId ba = body_named(pa, name);
      const std::optional<Transform> was = ba.valid() ? std::optional<Transform>(X_WA[ba.index()])
                                                      : frame_pose(c.source, X_WA, name);
      const std::optional<Transform> is = frame_pose(*c.back, X_WB, name);
      ASSERT_TRUE(was && is) << name;
      EXPECT_TRUE(is->p.isApprox(was->p, 1e-12)) << name << " at q #" << k;
      EXPECT_TRUE(is->R.isApprox(was->R, 1e-12)) << name << " at q #" << k;
    }
  }
  // the geometry is where it was, on the body that holds it now
  EXPECT_EQ(c.back->scene_graph().geometries.size(), c.source.scene_graph().geometries.size());
}

// Round-trip metadata: URDF and MJCF hold one model, so the writers prefix
// each name with its instance; the comments they leave let mdlc's reader
// give every entity back its instance and name. A caller who names the
// model (--model-name) reads the file as written.
TEST(Names, MultiInstanceRoundTripKeepsScopedNames) {
  OutputDir dir;
  const std::string sdf = R"(<sdf version="1.9">
  <world name="w">
    <model name="arm">
      <link name="base">
        <inertial><mass>2</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy><izz>0.1</izz></inertia></inertial>
      </link>
      <link name="link1">
        <pose>0 0 0.5 0 0 0</pose>
        <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
        <collision name="box"><geometry><box><size>0.1 0.1 0.1</size></box></geometry></collision>
      </link>
      <joint name="joint1" type="revolute">
        <parent>base</parent><child>link1</child>
        <axis><xyz>0 0 1</xyz><limit><effort>3</effort></limit></axis>
      </joint>
      <frame name="tool" attached_to="link1"><pose>0 0 0.1 0 0 0</pose></frame>
      <model name="hand">
        <pose>0 0 1 0 0 0</pose>
        <link name="base">
          <inertial><mass>0.5</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
          <collision name="box"><geometry><box><size>0.05 0.05 0.05</size></box></geometry></collision>
        </link>
        <link name="finger">
          <pose>0 0.05 0 0 0 0</pose>
          <inertial><mass>0.1</mass><inertia><ixx>0.001</ixx><iyy>0.001</iyy><izz>0.001</izz></inertia></inertial>
        </link>
        <joint name="joint1" type="prismatic">
          <parent>base</parent><child>finger</child><axis><xyz>0 1 0</xyz></axis>
        </joint>
      </model>
      <joint name="wrist" type="revolute">
        <parent>link1</parent><child>hand::base</child><axis><xyz>1 0 0</xyz></axis>
      </joint>
    </model>
    <model name="table">
      <static>true</static>
      <link name="base">
        <collision name="box"><geometry><box><size>1 1 0.1</size></box></geometry></collision>
      </link>
    </model>
  </world>
</sdf>
)";
  auto names = [](const Result& r) {
    std::set<std::string> out;
    const auto& p = r.plant();
    for (const auto& b : p.bodies) out.insert("body " + p.ScopedName(b));
    for (const auto& j : p.joints) {
      if (!j.unnamed) out.insert("joint " + p.ScopedName(j));
    }
    for (const auto& f : p.frames) {
      if (!f.unnamed) out.insert("frame " + p.model_instances[f.model.index()] + "::" + f.name);
    }
    for (const auto& a : p.actuators) {
      out.insert("actuator " + p.model_instances[a.model.index()] + "::" + a.name);
    }
    return out;
  };
  for (Format to : {Format::Urdf, Format::Mjcf}) {
    SCOPED_TRACE(FormatName(to));
    const Conversion c = ConvertText(sdf, "scene.sdf", To(to), dir.path());
    ASSERT_TRUE(c.back && c.back->ok());
    // written flat, with the instance in each name...
    EXPECT_NE(c.text->find("\"arm/hand/base\""), std::string::npos) << *c.text;
    EXPECT_NE(c.text->find("<!-- mdlc:name model=\"arm::hand\" name=\"base\" -->"),
              std::string::npos)
        << *c.text;
    // ...and read back under the scoped names it had
    std::set<std::string> before = names(c.source), after = names(*c.back);
    for (const std::string& n : before) EXPECT_TRUE(after.count(n)) << n << " is missing";
    const std::vector<std::string> names_before = c.source.plant().model_instances.ToVector();
    const std::set<std::string> instances_before(names_before.begin(), names_before.end());
    const std::vector<std::string> names_after = c.back->plant().model_instances.ToVector();
    const std::set<std::string> instances_after(names_after.begin(), names_after.end());
    EXPECT_EQ(instances_after, instances_before);
    // the plant is the same under those names
    Comparison cmp(c.source, *c.back, c.diagnostics,
                   to == Format::Urdf ? kTargets[0] : kTargets[2]);
    std::string why;
    ASSERT_TRUE(cmp.MapStructure(&why)) << why;
    cmp.CompareAt(mdlc::DefaultPositions(c.source), "default q");
    // naming the model reads the file as written: one instance, flat names
    Options named;
    named.naming.model_name = "as_written";
    const Result flat = Compile(Input::File(c.file.string()), named);
    ASSERT_TRUE(flat.ok()) << Messages(flat);
    bool found = false;
    for (const auto& b : flat.plant().bodies) {
      found = found || flat.plant().ScopedName(b) == "as_written::arm/hand/base";
    }
    EXPECT_TRUE(found);
  }
}

}  // namespace
}  // namespace mdlc
