// sdf_drake_test_util.h - lowers SDFormat text into a Module (frontend
// only, or the whole pipeline with the plant-json dump) for tests of the
// SDFormat frontend's drake: elements. Both are strict about diagnostics:
// see diagnostic_claims.h.
#pragma once

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tools/driver/compiler.h"
#include "backend/plant_json.h"
#include "backend/positions.h"
#include "tests/unit/diagnostic_claims.h"
#include "frontend/frontend.h"
#include "ir/module.h"

namespace mdlc::testing {

/// `body` inside <sdf version='1.9'> with the drake namespace declared.
inline std::string SdfDocument(std::string_view body) {
  return fmt::format(
      "<?xml version='1.0'?>\n<sdf version='1.9' xmlns:drake='http://drake.mit.edu'>\n{}\n"
      "</sdf>\n",
      body);
}

/// The SDFormat frontend alone: the IR as lowered, references unresolved.
struct LoweredSdf : ClaimsDiagnostics {
  SourceManager sources;
  DiagnosticEngine diags;
  ir::Module module;
  std::optional<ModelId> model;

  LoweredSdf() : ClaimsDiagnostics(diags) {}
  ~LoweredSdf() { CheckClaimsAtEnd(); }
  LoweredSdf(const LoweredSdf&) = delete;
  LoweredSdf& operator=(const LoweredSdf&) = delete;

  /// Runs the SDFormat frontend on SdfDocument(body).
  bool Read(std::string_view body) {
    FileId file = sources.AddBuffer("test.sdf", SdfDocument(body));
    frontend::FrontendContext ctx{sources, diags, module, {}};
    model = frontend::ReadSdf(file, ctx);
    return model.has_value() && !diags.has_errors();
  }

  const ir::Body* Body(std::string_view name) const {
    for (const auto& b : module.bodies) if (module.Text(b.name) == name) return &b;
    return nullptr;
  }
  const ir::Joint* Joint(std::string_view name) const {
    for (const auto& j : module.joints) if (module.Text(j.name) == name) return &j;
    return nullptr;
  }
  std::string Messages() const {
    std::string out;
    for (const auto& d : diags.diagnostics()) {
      out += fmt::format("{}:{}: {}\n", d.loc.line, d.loc.column, d.message);
    }
    return out;
  }
  /// Line of the first diagnostic whose message holds `text` (0: none).
  uint32_t LineOf(std::string_view text) const {
    for (const auto& d : diags.diagnostics()) {
      if (d.message.find(text) != std::string::npos) return d.loc.line;
    }
    return 0;
  }

};

/// The whole pipeline (frontend, passes, backend) on SdfDocument(body).
class CompiledSdf : public ClaimsDiagnostics {
 public:
  explicit CompiledSdf(std::string_view body) : ClaimsDiagnostics(c_.diags) {
    path_ = std::filesystem::temp_directory_path() /
            fmt::format("mdlc_sdf_drake_{}_{}.sdf", ::getpid(),
                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::ofstream(path_) << SdfDocument(body);
    c_.options.inputs = {Input::File(path_.string())};
    ok_ = c_.Run();
  }
  ~CompiledSdf() {
    CheckClaimsAtEnd();
    std::filesystem::remove(path_);
  }
  CompiledSdf(const CompiledSdf&) = delete;
  CompiledSdf& operator=(const CompiledSdf&) = delete;

  bool ok() const { return ok_; }
  std::string Messages() const {
    std::string out;
    for (const auto& d : c_.diags.diagnostics()) out += d.message + "\n";
    return out;
  }
  const Compilation& compilation() const { return c_; }
  nlohmann::json PlantJson() const {
    return nlohmann::json::parse(
        backend::EmitPlantJson(*c_.model, backend::DefaultPositions(c_.model->plant)));
  }

 private:
  std::filesystem::path path_;
  Compilation c_;
  bool ok_ = false;
};

/// The entry of `list` (a plant-json array) named `name` (null json: none).
inline nlohmann::json Named(const nlohmann::json& list, std::string_view name) {
  for (const auto& e : list) {
    if (e.contains("name") && e["name"] == name) return e;
  }
  return nlohmann::json();
}

}  // namespace mdlc::testing
