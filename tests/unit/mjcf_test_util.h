// mjcf_test_util.h - lowers MJCF text with the MJCF frontend alone (the IR
// as lowered, references as the frontend set them) from a fresh folder, so
// tests can add included files and meshes beside the main file. Strict about
// diagnostics: see diagnostic_claims.h.
#pragma once

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "frontend/frontend.h"
#include "ir/module.h"
#include "tests/unit/diagnostic_claims.h"
#include "tests/unit/test_values.h"

namespace mdlc::testing {

class LoweredMjcf : public ClaimsDiagnostics {
 public:
  /// Writes `xml` as model.xml (and each {name, text} file beside it), then
  /// runs the MJCF frontend on model.xml.
  explicit LoweredMjcf(std::string_view xml,
                       std::vector<std::pair<std::string, std::string>> files = {})
      : ClaimsDiagnostics(diags) {
    dir_ = std::filesystem::temp_directory_path() /
           fmt::format("mdlc_mjcf_{}_{}", ::getpid(),
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    for (const auto& [name, text] : files) {
      std::filesystem::create_directories((dir_ / name).parent_path());
      std::ofstream(dir_ / name) << text;
    }
    std::ofstream(dir_ / "model.xml") << xml;
    frontend::FrontendContext ctx{sources, diags, module, {}};
    model = frontend::ReadModelFile((dir_ / "model.xml").string(), ctx);
  }
  ~LoweredMjcf() {
    CheckClaimsAtEnd();
    std::filesystem::remove_all(dir_);
  }
  LoweredMjcf(const LoweredMjcf&) = delete;
  LoweredMjcf& operator=(const LoweredMjcf&) = delete;

  bool ok() const { return model.has_value() && !diags.has_errors(); }

  const ir::Body* Body(std::string_view name) const {
    return FindNamed(module, module.bodies, name);
  }
  const ir::Joint* Joint(std::string_view name) const {
    return FindNamed(module, module.joints, name);
  }
  /// The registration of geometry `name` with any of `roles`.
  const ir::Geometry* Geometry(std::string_view name, uint8_t roles) const {
    for (const auto& g : module.geometries) {
      if (module.Text(g.name) == name && ((g.roles & roles) || (roles == 0 && g.roles == 0))) return &g;
    }
    return nullptr;
  }
  std::string Messages() const {
    std::string out;
    for (const auto& d : diags.diagnostics()) {
      out += fmt::format("{}:{}:{}: [{}] {}\n", sources.Path(d.loc.file), d.loc.line, d.loc.column,
                         InfoFor(d.kind).name, d.message);
    }
    return out;
  }
  /// The first diagnostic of `kind` whose message holds `text` (null: none);
  /// those found are claimed.
  const Diagnostic* Find(DiagKind kind, std::string_view text = "") const {
    for (const auto& d : diags.diagnostics()) {
      if (d.kind == kind && d.message.find(text) != std::string::npos) {
        claims_.Found(kind, text);
        return &d;
      }
    }
    return nullptr;
  }

  SourceManager sources;
  DiagnosticEngine diags;
  ir::Module module;
  std::optional<ModelId> model;

 private:
  std::filesystem::path dir_;
};

}  // namespace mdlc::testing
