// sdf_test_util.h - lowers SDFormat text for tests of the SDFormat frontend
// (its drake: elements included): the frontend alone (the IR as lowered,
// references unresolved), or the whole pipeline from a file in a fresh
// temporary folder (so relative mesh and texture URIs have a home), with the
// plant-json dump. Both are strict about diagnostics: see
// diagnostic_claims.h.
#pragma once

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "tools/driver/compiler.h"
#include "backend/plant_json.h"
#include "backend/positions.h"
#include "tests/unit/diagnostic_claims.h"
#include "frontend/frontend.h"
#include "ir/module.h"
#include "tests/unit/test_values.h"

namespace mdlc::testing {

/// `body` inside <sdf version='1.9'> with the drake namespace declared; the
/// body starts on line 3 (tests check the lines diagnostics point at).
inline std::string SdfFileText(std::string_view body) {
  return fmt::format(
      "<?xml version='1.0'?>\n<sdf version='1.9' xmlns:drake='http://drake.mit.edu'>\n{}\n"
      "</sdf>\n",
      body);
}

/// One model `m` with one link `a` holding `link_children`.
inline std::string SdfLink(std::string_view link_children) {
  return fmt::format("<model name='m'><link name='a'>{}</link></model>", link_children);
}

/// The SDFormat frontend alone on SdfFileText(body): the IR as lowered,
/// references unresolved.
struct SdfFrontendResult : ClaimsDiagnostics {
  SourceManager sources;
  DiagnosticEngine diags;
  ir::Module module;
  std::optional<ModelId> model;

  SdfFrontendResult() : ClaimsDiagnostics(diags) {}
  ~SdfFrontendResult() { CheckClaimsAtEnd(); }
  SdfFrontendResult(const SdfFrontendResult&) = delete;
  SdfFrontendResult& operator=(const SdfFrontendResult&) = delete;

  /// Runs the SDFormat frontend on SdfFileText(body).
  bool Read(std::string_view body) {
    FileId file = sources.AddBuffer("test.sdf", SdfFileText(body));
    frontend::FrontendContext ctx{sources, diags, module, {}};
    model = frontend::ReadSdf(file, ctx);
    return model.has_value() && !diags.has_errors();
  }

  const ir::Body* Body(std::string_view name) const {
    return FindNamed(module, module.bodies, name);
  }
  const ir::Joint* Joint(std::string_view name) const {
    return FindNamed(module, module.joints, name);
  }
  /// The geometry `name` having one of `role` (a visual and a collision may
  /// share a name).
  const ir::Geometry* Geometry(std::string_view name, uint8_t role) const {
    for (const auto& g : module.geometries) {
      if (module.Text(g.name) == name && (g.roles & role)) return &g;
    }
    return nullptr;
  }
  /// Every diagnostic as `line:column: message`, one per line.
  std::string Messages() const {
    std::string out;
    for (const auto& d : diags.diagnostics()) {
      out += fmt::format("{}:{}: {}\n", d.loc.line, d.loc.column, d.message);
    }
    return out;
  }
  /// The number of diagnostics of `kind`; counting them claims them all.
  size_t Count(DiagKind kind) const {
    size_t n = 0;
    for (const auto& d : diags.diagnostics()) n += d.kind == kind;
    claims_.Found(kind, "");
    return n;
  }
  /// Line of the first diagnostic whose message holds `text` (0: none).
  uint32_t LineOf(std::string_view text) const {
    for (const auto& d : diags.diagnostics()) {
      if (d.message.find(text) != std::string::npos) return d.loc.line;
    }
    return 0;
  }
};

/// The whole pipeline (frontend, passes, backend) on SdfFileText(body),
/// written as model.sdf into a fresh folder beside which `extra_files`
/// (name -> contents) are written.
class SdfCompileResult : public ClaimsDiagnostics {
 public:
  explicit SdfCompileResult(std::string_view body,
                            const std::vector<std::pair<std::string, std::string>>& extra_files = {})
      : ClaimsDiagnostics(c_.diags) {
    // one folder per fixture: a parameterised test's name holds a '/', and
    // one test may compile twice
    static std::atomic<int> count{0};
    std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::replace(test.begin(), test.end(), '/', '_');
    dir_ = std::filesystem::temp_directory_path() /
           fmt::format("mdlc_sdf_{}_{}_{}", ::getpid(), count++, test);
    std::filesystem::create_directories(dir_);
    for (const auto& [name, contents] : extra_files) std::ofstream(dir_ / name) << contents;
    const auto path = dir_ / "model.sdf";
    std::ofstream(path) << SdfFileText(body);
    c_.options.inputs = {Input::File(path.string())};
    ok_ = c_.Run();
  }
  ~SdfCompileResult() {
    CheckClaimsAtEnd();
    std::filesystem::remove_all(dir_);
  }
  SdfCompileResult(const SdfCompileResult&) = delete;
  SdfCompileResult& operator=(const SdfCompileResult&) = delete;

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
  std::filesystem::path dir_;
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

/// The entries of a plant-json array with this name (a visual and a
/// collision may share one).
inline std::vector<nlohmann::json> AllNamed(const nlohmann::json& list, std::string_view name) {
  std::vector<nlohmann::json> out;
  for (const auto& e : list) {
    if (e.contains("name") && e["name"] == name) out.push_back(e);
  }
  return out;
}

}  // namespace mdlc::testing
