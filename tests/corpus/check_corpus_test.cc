// `mdlc check` over the whole corpus (issue 15): with -j 2 the JSON Lines
// report has one line per model file, in file order, with the verdicts of a
// serial run. (Whether -j 2 is faster is measured, not tested:
// tests/bench/check_parallel.sh.)
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "shared_corpus.h"

namespace {
namespace fs = std::filesystem;
using nlohmann::json;

using mdlc::corpus_test::Corpus;

/// The model files check.h says a folder walk finds, found here without
/// mdlc: .urdf, .sdf, .world and .dmd.yaml files, and .xml files with a <mujoco>
/// root near their start, in sorted path order.
std::vector<std::string> ModelFiles(const fs::path& root) {
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    const std::string name = entry.path().filename().string();
    bool model = name.ends_with(".urdf") || name.ends_with(".sdf") || name.ends_with(".world") ||
                 name.ends_with(".dmd.yaml");
    if (!model && name.ends_with(".xml")) {
      std::ifstream in(entry.path(), std::ios::binary);
      std::string head(4096, '\0');
      in.read(head.data(), static_cast<std::streamsize>(head.size()));
      head.resize(static_cast<size_t>(in.gcount()));
      model = head.find("<mujoco") != std::string::npos;
    }
    if (model) files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// Each line of the report, parsed; fails the test on a line that is not
/// one JSON object.
std::vector<json> Check(const std::string& jobs, const fs::path& report) {
  const std::string command =
      fmt::format("{} check {} --package-path {} --format json -j {} -o {} 2>/dev/null",
                  MDLC_BINARY, Corpus().string(), Corpus().string(), jobs, report.string());
  const int raw = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) <= 1) << command;  // 1: some file has errors
  std::vector<json> lines;
  std::ifstream in(report);
  for (std::string line; std::getline(in, line);) {
    lines.push_back(json::parse(line, nullptr, /*allow_exceptions=*/false));
    EXPECT_TRUE(lines.back().is_object()) << line.substr(0, 200);
  }
  return lines;
}

TEST(CheckCorpus, ParallelReportListsEveryFileInOrderWithTheSerialVerdicts) {
  if (!fs::exists(Corpus())) GTEST_SKIP() << "the shared corpus is absent";
  const fs::path dir = fs::temp_directory_path() / fmt::format("mdlc_check_corpus_{}", ::getpid());
  fs::create_directories(dir);
  const std::vector<std::string> files = ModelFiles(Corpus());
  ASSERT_GT(files.size(), 100u);
  const std::vector<json> parallel = Check("2", dir / "parallel.jsonl");
  const std::vector<json> serial = Check("1", dir / "serial.jsonl");
  fs::remove_all(dir);

  ASSERT_EQ(parallel.size(), files.size());
  ASSERT_EQ(serial.size(), files.size());
  size_t ok = 0;
  for (size_t i = 0; i < files.size(); ++i) {
    ASSERT_TRUE(parallel[i].is_object() && serial[i].is_object());
    EXPECT_EQ(parallel[i]["file"], files[i]);
    EXPECT_EQ(parallel[i]["ok"], serial[i]["ok"]) << files[i];
    EXPECT_EQ(parallel[i]["errors"], serial[i]["errors"]) << files[i];
    EXPECT_EQ(parallel[i]["warnings"], serial[i]["warnings"]) << files[i];
    EXPECT_EQ(parallel[i]["diagnostics"], serial[i]["diagnostics"]) << files[i];
    ok += parallel[i]["ok"].get<bool>();
  }
  // the corpus is mostly good models: a run where nothing compiled is broken
  EXPECT_GT(ok, files.size() / 2);
  fmt::print("{} corpus files checked with -j 2 and -j 1: {} ok\n", files.size(), ok);
}

}  // namespace
