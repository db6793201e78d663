// cli_fixture.h - what the command-line tests share: a folder of the test's
// own (removed after it) and a way to run the mdlc binary as a user runs it,
// through the shell, with standard input closed.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace mdlc::cli_test {

namespace fs = std::filesystem;

/// How one run of mdlc ended: its exit status (128 + the signal when a
/// signal ended it) and what it printed.
struct Outcome {
  int status = -1;
  std::string out, err;
};

inline std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class CliFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           fmt::format("mdlc_cli_{}_{}_{}", ::getpid(), test->test_suite_name(), test->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// Writes `text` to `name` in the test's folder.
  fs::path Write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  /// Runs `mdlc <args>` (a shell command line), `environment` ("NAME=value
  /// ...") set for it alone.
  Outcome Mdlc(const std::string& args, const std::string& environment = "") {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string command = fmt::format("{} {} {} >{} 2>{} </dev/null", environment,
                                            MDLC_BINARY, args, out.string(), err.string());
    const int raw = std::system(command.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw), ReadFile(out),
            ReadFile(err)};
  }

  fs::path dir_;
};

}  // namespace mdlc::cli_test
