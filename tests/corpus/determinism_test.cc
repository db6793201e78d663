// determinism_test.cc - the same input gives the same bytes (issue 16):
// every corpus model is compiled once, then again on two threads at once,
// and the plant-json dump, the IR dump and the diagnostics must be equal
// byte for byte (nothing may depend on hash order, addresses, timing or
// which thread compiled what).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "ir/printer.h"
#include "mdlc/ir.h"
#include "mdlc/kinematics.h"
#include "mdlc/mdlc.h"
#include "shared_corpus.h"

namespace mdlc {
namespace {
namespace fs = std::filesystem;

using mdlc::corpus_test::Corpus;

std::vector<std::string> CorpusModels() {
  std::vector<std::string> out;
  std::ifstream in(Corpus() / "manifest.tsv");
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream row(line);
    for (std::string f; std::getline(row, f, '\t');) fields.push_back(f);
    if (fields.size() < 2) continue;
    if (fields[0] == "urdf" || fields[0] == "sdf" || fields[0] == "mjcf" || fields[0] == "dmd") {
      out.push_back((Corpus() / fields[1]).string());
    }
  }
  return out;
}

/// Everything a compile prints: diagnostics, the IR, and plant-json.
std::string Everything(const std::string& path) {
  Options options;
  options.packages.paths = {Corpus().string()};
  const Result r = Compile(Input::File(path), options);
  std::string out;
  for (const Diagnostic& d : r.diagnostics()) out += r.FormatText(d);
  out += ir::PrintModule(mdlc::IrModule(r), r.sources());
  if (r.has_model()) out += mdlc::PlantJson(r, mdlc::DefaultPositions(r));
  return out;
}

TEST(Determinism, TheCorpusCompilesToTheSameBytesTwiceAndOnTwoThreads) {
  if (!fs::exists(Corpus() / "manifest.tsv")) GTEST_SKIP() << "the shared corpus is absent";
  const std::vector<std::string> models = CorpusModels();
  ASSERT_GT(models.size(), 100u);
  std::vector<std::string> first(models.size()), second(models.size());
  for (size_t i = 0; i < models.size(); ++i) first[i] = Everything(models[i]);
  std::atomic<size_t> next{0};
  auto work = [&] {
    for (size_t i; (i = next++) < models.size();) second[i] = Everything(models[i]);
  };
  std::thread a(work), b(work);
  a.join();
  b.join();
  size_t differ = 0;
  for (size_t i = 0; i < models.size(); ++i) {
    if (first[i] == second[i]) continue;
    ++differ;
    size_t at = 0;
    while (at < first[i].size() && at < second[i].size() && first[i][at] == second[i][at]) ++at;
    ADD_FAILURE() << models[i] << " differs from byte " << at << ":\n  first:  "
                  << first[i].substr(at, 120) << "\n  second: " << second[i].substr(at, 120);
  }
  fmt::print("{} models compiled twice (once on two threads): {} differ\n", models.size(),
             differ);
}

}  // namespace
}  // namespace mdlc
