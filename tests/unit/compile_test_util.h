// compile_test_util.h - the whole pipeline (frontends, passes verified after
// each, backend) on model text written to a fresh folder, with the
// plant-json dump and the diagnostics at hand. Strict about diagnostics: see
// diagnostic_claims.h.
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

namespace mdlc::testing {

class CompiledText : public ClaimsDiagnostics {
 public:
  /// Writes `text` as `file_name` in a folder of its own and compiles it
  /// within `limits`.
  CompiledText(std::string_view file_name, std::string_view text, const Limits& limits = {})
      : ClaimsDiagnostics(c_.diags) {
    c_.sources.set_limits(limits);
    dir_ = std::filesystem::temp_directory_path() /
           fmt::format("mdlc_compiled_{}_{}", ::getpid(),
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    path_ = dir_ / file_name;
    std::ofstream(path_) << text;
    c_.options.inputs = {Input::File(path_.string())};
    c_.options.instrumentation.verify_each = true;
    ok_ = c_.Run();
  }
  ~CompiledText() {
    CheckClaimsAtEnd();
    std::filesystem::remove_all(dir_);
  }
  CompiledText(const CompiledText&) = delete;
  CompiledText& operator=(const CompiledText&) = delete;

  bool ok() const { return ok_; }
  const ir::Module& module() const { return c_.module; }
  const backend::CompiledModel& model() const { return *c_.model; }
  const std::filesystem::path& path() const { return path_; }
  const std::vector<Diagnostic>& diagnostics() const { return c_.diags.diagnostics(); }

  /// Every diagnostic as "line:column: kind: message".
  std::string Messages() const {
    std::string out;
    for (const auto& d : c_.diags.diagnostics()) {
      out += fmt::format("{}:{}: {}: {}\n", d.loc.line, d.loc.column, InfoFor(d.kind).name,
                         d.message);
    }
    return out;
  }
  /// The diagnostics of `kind` whose message contains `text`; those found
  /// are claimed.
  std::vector<const Diagnostic*> Find(DiagKind kind, std::string_view text = "") const {
    std::vector<const Diagnostic*> found;
    for (const auto& d : c_.diags.diagnostics()) {
      if (d.kind == kind && d.message.find(text) != std::string::npos) found.push_back(&d);
    }
    if (!found.empty()) claims_.Found(kind, text);
    return found;
  }
  /// plant-json at the default configuration.
  nlohmann::json Json() const {
    return nlohmann::json::parse(
        backend::EmitPlantJson(*c_.model, backend::DefaultPositions(c_.model->plant)));
  }

 private:
  std::filesystem::path dir_, path_;
  Compilation c_;
  bool ok_ = false;
};

/// The entry of `list` (a plant-json array) with this name and instance.
inline const nlohmann::json* Entry(const nlohmann::json& list, std::string_view name,
                                   std::string_view instance) {
  for (const auto& e : list) {
    if (e.value("name", "") == name && e.value("model_instance", "") == instance) return &e;
  }
  return nullptr;
}

}  // namespace mdlc::testing
