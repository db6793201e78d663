// mesh_test_util.h - test meshes (tests/models/meshes, made by generate.py)
// and a small IR fixture for running the mesh and mass passes on geometry
// built by hand, without a frontend. The fixture is strict about
// diagnostics: see diagnostic_claims.h.
#pragma once

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "ir/module.h"
#include "passes/pass.h"
#include "passes/pass_registry.h"
#include "tests/unit/diagnostic_claims.h"

namespace mdlc::testing {

inline std::string MeshPath(std::string_view name) {
  return fmt::format("{}/meshes/{}", MDLC_TEST_MODELS, name);
}

/// A test with a folder of its own, named for the test and removed after
/// it, into which test meshes are copied under the names a test needs.
class MeshFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           fmt::format("mdlc_{}_{}_{}", test->test_suite_name(), ::getpid(), test->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  /// A copy of the test mesh `mesh` named `name` in the test's folder.
  std::string Copy(const std::string& mesh, const std::string& name) {
    const std::filesystem::path to = dir_ / name;
    std::filesystem::copy_file(MeshPath(mesh), to,
                               std::filesystem::copy_options::overwrite_existing);
    return to.string();
  }

  std::filesystem::path dir_;
};

/// EXPECT that two matrices agree entry by entry within `tol`.
inline void ExpectNear(const Eigen::MatrixXd& actual, const Eigen::MatrixXd& expected, double tol,
                       std::string_view what = "") {
  ASSERT_EQ(actual.rows(), expected.rows()) << what;
  ASSERT_EQ(actual.cols(), expected.cols()) << what;
  EXPECT_TRUE((actual - expected).cwiseAbs().maxCoeff() <= tol)
      << what << "\nactual:\n" << actual << "\nexpected:\n" << expected;
}

/// Rotation from MuJoCo's quaternion (w x y z).
inline Eigen::Matrix3d Quat(double w, double x, double y, double z) {
  return Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
}

/// A module with one MJCF-like model; geometries placed by hand; passes run
/// by name. Every entity is located on its own line of a dummy source.
struct MassFixture {
  SourceManager sources;
  DiagnosticEngine diags;
  ir::Module module;
  FileId file;
  ModelId model;
  uint32_t next_line = 1;
  std::shared_ptr<mesh::MeshCache> meshes = std::make_shared<mesh::MeshCache>();

  MassFixture() {
    file = sources.AddBuffer("model.xml", std::string(200, '\n'));
    ir::ModelInstance mi;
    mi.local_name = module.Intern("m");
    mi.format = ir::SourceFormat::Mjcf;
    mi.loc = NextLoc();
    model = module.Add(mi);
  }
  ~MassFixture() { claims_.CheckAtEnd(diags.diagnostics()); }
  MassFixture(const MassFixture&) = delete;
  MassFixture& operator=(const MassFixture&) = delete;
  Loc NextLoc() { return Loc{file, next_line++, 1}; }

  BodyId AddBody(std::string_view name, bool from_geometry = true) {
    ir::Body b;
    b.name = module.Intern(name);
    b.model = model;
    b.loc = NextLoc();
    b.mass_from_geometry = from_geometry;
    return module.Add(b);
  }
  /// A geometry of `shape` on `body` at X_BG contributing with `c`.
  GeometryId AddGeom(BodyId body, ir::Shape shape, const Transform& X_BG = {},
                     std::optional<ir::MassContribution> c = ir::MassContribution{}) {
    ir::Geometry g;
    g.name = module.Intern(fmt::format("g{}", module.geometries.size()));
    g.model = model;
    g.loc = NextLoc();
    g.body = {module[body].name, g.loc, body};
    g.X_BG = X_BG;
    g.shape = std::move(shape);
    g.roles = ir::kProximityRole | ir::kIllustrationRole;
    g.mass_contribution = c;
    return module.Add(g);
  }
  /// A mesh shape for a file of tests/models/meshes, already resolved.
  ir::Mesh Mesh(std::string_view file_name, Eigen::Vector3d scale = Eigen::Vector3d::Ones()) {
    ir::Mesh m;
    m.uri = std::string(file_name);
    m.uri_loc = NextLoc();
    m.resolved = MeshPath(file_name);
    m.scale = scale;
    return m;
  }

  /// Runs the named passes in order and stops, as the pass manager does,
  /// after one that reported an error; false then.
  bool Run(std::vector<std::string_view> names) {
    passes::PassContext ctx{module, diags, sources};
    ctx.meshes = meshes;
    for (std::string_view n : names) {
      auto pass = passes::CreatePass(n);
      EXPECT_TRUE(pass) << n;
      if (!pass || !pass->Run(ctx) || diags.has_errors()) return false;
    }
    return !diags.has_errors();
  }
  /// The mesh and mass passes, in pipeline order.
  bool RunMassPipeline() { return Run({"load-meshes", "fit-to-mesh", "mass-from-geometry"}); }

  std::string Messages() const {
    std::string out;
    for (const auto& d : diags.diagnostics()) {
      out += fmt::format("{}:{}: [{}] {}\n", d.loc.line, d.loc.column, InfoFor(d.kind).name,
                         d.message);
    }
    return out;
  }
  /// The first diagnostic of `kind` (null: none); those of `kind` are then
  /// claimed.
  const Diagnostic* Find(DiagKind kind) const {
    for (const auto& d : diags.diagnostics()) {
      if (d.kind == kind) {
        claims_.Found(kind, "");
        return &d;
      }
    }
    return nullptr;
  }
  /// Claims the diagnostics of `kind` holding `text`; at least one must come.
  void ExpectDiagnostic(DiagKind kind, std::string_view text) { claims_.Expect(kind, text); }
  /// Fails for every diagnostic so far that no claim covers.
  void ExpectNoOtherDiagnostics() const { claims_.Check(diags.diagnostics()); }

  /// The body's inertia about its center of mass, in the body frame.
  Eigen::Matrix3d InertiaB(BodyId body) const {
    const ir::Inertial& in = *module[body].inertial;
    Eigen::Matrix3d I;
    I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
    return in.X_BI.R * I * in.X_BI.R.transpose();
  }
  Eigen::Vector3d Com(BodyId body) const { return module[body].inertial->X_BI.p; }

 private:
  mutable DiagnosticClaims claims_;
};

}  // namespace mdlc::testing
