// oracle_util.h - what the differential tests share: numbers formatted and
// compared the same way, environment knobs, their cases from the shared
// corpus and tests/models, running the mdlc CLI as a subprocess with a
// timeout (the parser oracles link no mdlc library code), running MuJoCo
// 3.3.8's mujoco-js scripts, reading mdlc's plant-json dump, and collecting
// discrepancies into one report per model.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

extern char** environ;

// Where the tests find things; CMake sets them (tests/oracle/CMakeLists.txt).
#ifndef MDLC_BINARY
#define MDLC_BINARY ""
#endif
#ifndef MDLC_SHARED_DIR
#define MDLC_SHARED_DIR ""
#endif
#ifndef MDLC_TEST_MODELS
#define MDLC_TEST_MODELS ""
#endif
#ifndef MDLC_NODE
#define MDLC_NODE ""
#endif
#ifndef MDLC_MUJOCO_JS_DIR
#define MDLC_MUJOCO_JS_DIR ""
#endif

namespace mdlc::oracle {

/// |a - b| <= kRelTol * max(1, |a|, |b|): the tolerance of every comparison.
constexpr double kRelTol = 1e-9;

inline int EnvInt(const char* name, int fallback) {
  const char* v = std::getenv(name);
  if (!v || !*v) return fallback;
  return std::atoi(v);
}

inline std::string Fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// |a - b| <= tol * max(1, |a|, |b|); equal infinities agree.
inline bool Near(double a, double b, double tol = kRelTol) {
  if (std::isinf(a) || std::isinf(b)) return a == b;
  if (std::isnan(a) || std::isnan(b)) return false;
  return std::abs(a - b) <= tol * std::max({1.0, std::abs(a), std::abs(b)});
}

/// The largest absolute entry of `x`; 0 when it has none.
inline double MaxAbs(const Eigen::MatrixXd& x) { return x.size() ? x.cwiseAbs().maxCoeff() : 0.0; }

/// The largest error seen per quantity, for a test's summary line; the
/// quantity is the first word of what was compared.
using WorstErrors = std::map<std::string, double>;

inline void RecordWorst(WorstErrors* worst, const std::string& what, double error) {
  double& w = (*worst)[what.substr(0, what.find(' '))];
  w = std::max(w, error);
}

// ---------------------------------------------------------------------------
// Parameterized cases
// ---------------------------------------------------------------------------

/// A gtest parameter name from a path: every character that is not a letter
/// or a digit becomes '_'.
inline std::string Sanitize(const std::string& s) {
  std::string out;
  for (char c : s) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return out;
}

/// Makes the cases' `id`s unique (gtest needs them so): the second of a name
/// gets "_2", the third "_3", ...
template <typename Case>
void Uniquify(std::vector<Case>* cases) {
  std::map<std::string, int> seen;
  for (auto& c : *cases) {
    const int n = seen[c.id]++;
    if (n > 0) c.id += "_" + std::to_string(n + 1);
  }
}

/// The files in `dir` (not below it) whose extension is `ext` (".xml"),
/// sorted; none when the folder cannot be read.
inline std::vector<std::filesystem::path> FilesWithExtension(const std::filesystem::path& dir,
                                                             const std::string& ext) {
  std::error_code ec;
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    if (e.path().extension() == ext) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// The rows of the shared corpus's manifest.tsv, split at tabs, header left
/// out; nullopt when the file cannot be read.
inline std::optional<std::vector<std::vector<std::string>>> ReadManifest(
    const std::filesystem::path& manifest) {
  std::ifstream in(manifest);
  if (!in) return std::nullopt;
  std::vector<std::vector<std::string>> rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (header) {
      header = false;
      continue;
    }
    std::vector<std::string> cols;
    std::stringstream ss(line);
    for (std::string col; std::getline(ss, col, '\t');) cols.push_back(col);
    rows.push_back(std::move(cols));
  }
  return rows;
}

/// `s` without `suffix` at its end; `s` itself when it does not end so, or
/// is no longer than `suffix`.
inline std::string WithoutSuffix(std::string s, const std::string& suffix) {
  if (s.size() > suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0) {
    s.resize(s.size() - suffix.size());
  }
  return s;
}

/// tests/models/<sub>, e.g. TestModels("urdf").
inline std::filesystem::path TestModels(const std::string& sub) {
  return std::filesystem::path(MDLC_TEST_MODELS) / sub;
}

/// The shared corpus; its manifest's paths are relative to it.
inline std::filesystem::path CorpusDir() {
  return std::filesystem::path(MDLC_SHARED_DIR) / "corpus";
}

inline std::filesystem::path CorpusManifest() { return CorpusDir() / "manifest.tsv"; }

/// A test's cases of the shared corpus: make(row) for each row of its
/// manifest (the row's columns; nullopt leaves it out), ids made unique.
/// Without the corpus (MDLC_SHARED_DIR empty, or no readable manifest) the
/// one case "shared_corpus_unavailable", skipped with `unavailable`.
template <typename Case, typename Make>
std::vector<Case> ManifestCases(const std::string& unavailable, Make make) {
  std::vector<Case> cases;
  const auto rows = ReadManifest(CorpusManifest());
  if (std::string(MDLC_SHARED_DIR).empty() || !rows) {
    Case c;
    c.id = "shared_corpus_unavailable";
    c.skip_reason = unavailable;
    cases.push_back(c);
    return cases;
  }
  for (const std::vector<std::string>& cols : *rows) {
    if (std::optional<Case> c = make(cols)) cases.push_back(std::move(*c));
  }
  Uniquify(&cases);
  return cases;
}

/// A test's cases of the files in `dir` whose extension is `ext`: make(file)
/// for each, ids made unique. With no such file the one case "no_models",
/// skipped with `none`.
template <typename Case, typename Make>
std::vector<Case> FolderCases(const std::filesystem::path& dir, const std::string& ext,
                              const std::string& none, Make make) {
  std::vector<Case> cases;
  for (const auto& f : FilesWithExtension(dir, ext)) cases.push_back(make(f));
  if (cases.empty()) {
    Case c;
    c.id = "no_models";
    c.skip_reason = none;
    cases.push_back(c);
  }
  Uniquify(&cases);
  return cases;
}

/// The names a table of listed models (known disagreements, models that
/// cannot be compared) gives the cases by: a corpus case's path below
/// corpus/, any other case's display name.
template <typename Case>
std::set<std::string> ListingKeys(const std::vector<Case>& corpus,
                                  const std::vector<Case>& hand_made) {
  std::set<std::string> keys;
  for (const auto& c : corpus) {
    if (c.display.rfind("corpus/", 0) == 0) keys.insert(c.display.substr(7));
  }
  for (const auto& c : hand_made) keys.insert(c.display);
  return keys;
}

// ---------------------------------------------------------------------------
// Subprocess
// ---------------------------------------------------------------------------

struct RunResult {
  int exit_code = -1;  // -1: did not exit normally
  bool timed_out = false;
  std::string out, err;
  std::string spawn_error;
};

/// Starts argv[0] with `in` (-1: this process's own), `out` and `err` as its
/// standard streams; its pid, or -1 with *error set.
inline pid_t SpawnWith(const std::vector<std::string>& argv, int in, int out, int err,
                       std::string* error) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  if (in >= 0) posix_spawn_file_actions_adddup2(&fa, in, 0);
  posix_spawn_file_actions_adddup2(&fa, out, 1);
  posix_spawn_file_actions_adddup2(&fa, err, 2);
  std::vector<char*> cargv;
  for (const auto& a : argv) cargv.push_back(const_cast<char*>(a.c_str()));
  cargv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, cargv[0], &fa, nullptr, cargv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc == 0) return pid;
  *error = "posix_spawn(" + argv[0] + "): " + std::strerror(rc);
  return -1;
}

inline RunResult RunProcess(const std::vector<std::string>& argv, double timeout_s) {
  RunResult r;
  int out_pipe[2], err_pipe[2];
  if (pipe2(out_pipe, O_CLOEXEC) != 0 || pipe2(err_pipe, O_CLOEXEC) != 0) {
    r.spawn_error = std::string("pipe: ") + std::strerror(errno);
    return r;
  }
  const pid_t pid = SpawnWith(argv, -1, out_pipe[1], err_pipe[1], &r.spawn_error);
  close(out_pipe[1]);
  close(err_pipe[1]);
  if (pid < 0) {
    close(out_pipe[0]);
    close(err_pipe[0]);
    return r;
  }
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::milliseconds(static_cast<int64_t>(timeout_s * 1000));
  pollfd fds[2] = {{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
  std::string* sinks[2] = {&r.out, &r.err};
  int open_fds = 2;
  char buf[65536];
  while (open_fds > 0) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) {
      r.timed_out = true;
      kill(pid, SIGKILL);  // our own child only
      break;
    }
    const int ms = static_cast<int>(
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count()) + 1;
    const int n = poll(fds, 2, ms);
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t got = read(fds[i].fd, buf, sizeof buf);
      if (got > 0) {
        sinks[i]->append(buf, static_cast<size_t>(got));
      } else if (got == 0 || (got < 0 && errno != EINTR && errno != EAGAIN)) {
        close(fds[i].fd);
        fds[i].fd = -1;
        --open_fds;
      }
    }
  }
  for (auto& f : fds) {
    if (f.fd >= 0) close(f.fd);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  return r;
}

/// A helper process that answers one line of stdout per line written to its
/// stdin, kept running across requests: a dump tool whose start-up dwarfs a
/// single answer (Node.js and MuJoCo's WebAssembly: 0.4 s to start, tens of
/// milliseconds per file) is started once per test process, not once per
/// file. Its stderr is drained as it comes and kept for failure messages. On
/// a timeout, a closed stdout or a failed write the process is killed, and
/// the next request starts a new one.
class LineServer {
 public:
  explicit LineServer(std::vector<std::string> argv) : argv_(std::move(argv)) {}
  LineServer(const LineServer&) = delete;
  LineServer& operator=(const LineServer&) = delete;
  ~LineServer() { Stop(); }

  /// Writes `request` (one line, no newline in it) and returns the answering
  /// line; nullopt with *problem set when there was none in `timeout_s`.
  std::optional<std::string> Ask(const std::string& request, double timeout_s, std::string* problem) {
    if (request.find('\n') != std::string::npos) {
      *problem = "request holds a newline";
      return std::nullopt;
    }
    if (pid_ <= 0 && !Start(problem)) return std::nullopt;
    const std::string line = request + "\n";
    for (size_t done = 0; done < line.size();) {
      const ssize_t n = write(in_, line.data() + done, line.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return Fail("write to the helper: " + std::string(std::strerror(errno)), problem);
      done += static_cast<size_t>(n);
    }
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::milliseconds(static_cast<int64_t>(timeout_s * 1000));
    for (;;) {
      if (const size_t eol = out_buf_.find('\n'); eol != std::string::npos) {
        std::string answer = out_buf_.substr(0, eol);
        out_buf_.erase(0, eol + 1);
        return answer;
      }
      const auto now = std::chrono::steady_clock::now();
      if (now >= deadline) return Fail("timed out", problem);
      const int ms = static_cast<int>(
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count()) + 1;
      pollfd fds[2] = {{out_, POLLIN, 0}, {err_, POLLIN, 0}};
      const int n = poll(fds, err_ >= 0 ? 2 : 1, ms);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) return Fail("poll: " + std::string(std::strerror(errno)), problem);
      char buf[65536];
      if (err_ >= 0 && (fds[1].revents & (POLLIN | POLLHUP | POLLERR))) {
        const ssize_t got = read(err_, buf, sizeof buf);
        if (got > 0) {
          err_tail_.append(buf, static_cast<size_t>(got));
          if (err_tail_.size() > 4000) err_tail_.erase(0, err_tail_.size() - 4000);
        } else if (got == 0) {
          close(err_);
          err_ = -1;
        }
      }
      if (fds[0].revents & (POLLIN | POLLHUP | POLLERR)) {
        const ssize_t got = read(out_, buf, sizeof buf);
        if (got > 0) {
          out_buf_.append(buf, static_cast<size_t>(got));
        } else if (got == 0 || errno != EINTR) {
          return Fail("the helper closed its output", problem);
        }
      }
    }
  }

 private:
  bool Start(std::string* problem) {
    // a helper that died must fail the write, not end the test with SIGPIPE
    signal(SIGPIPE, SIG_IGN);
    int in_pipe[2], out_pipe[2], err_pipe[2];
    if (pipe2(in_pipe, O_CLOEXEC) != 0) return StartFailed("pipe", problem);
    if (pipe2(out_pipe, O_CLOEXEC) != 0) {
      close(in_pipe[0]), close(in_pipe[1]);
      return StartFailed("pipe", problem);
    }
    if (pipe2(err_pipe, O_CLOEXEC) != 0) {
      close(in_pipe[0]), close(in_pipe[1]), close(out_pipe[0]), close(out_pipe[1]);
      return StartFailed("pipe", problem);
    }
    const pid_t pid = SpawnWith(argv_, in_pipe[0], out_pipe[1], err_pipe[1], problem);
    close(in_pipe[0]), close(out_pipe[1]), close(err_pipe[1]);
    if (pid < 0) {
      close(in_pipe[1]), close(out_pipe[0]), close(err_pipe[0]);
      return false;
    }
    pid_ = pid, in_ = in_pipe[1], out_ = out_pipe[0], err_ = err_pipe[0];
    out_buf_.clear();
    err_tail_.clear();
    return true;
  }

  bool StartFailed(const char* what, std::string* problem) {
    *problem = std::string(what) + ": " + std::strerror(errno);
    return false;
  }

  std::nullopt_t Fail(const std::string& why, std::string* problem) {
    *problem = why + (err_tail_.empty() ? "" : ": " + err_tail_.substr(0, 2000));
    Stop();
    return std::nullopt;
  }

  void Stop() {
    if (pid_ <= 0) return;
    kill(pid_, SIGKILL);  // our own child only
    for (int fd : {in_, out_, err_}) {
      if (fd >= 0) close(fd);
    }
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1, in_ = out_ = err_ = -1;
  }

  std::vector<std::string> argv_;
  pid_t pid_ = -1;
  int in_ = -1, out_ = -1, err_ = -1;
  std::string out_buf_, err_tail_;
};

// ---------------------------------------------------------------------------
// MuJoCo 3.3.8: the mujoco-js scripts of tests/oracle/mujoco_js under Node.js
// ---------------------------------------------------------------------------

/// `s`, or "" when it is the "<VAR>-NOTFOUND" CMake leaves when it finds no
/// program.
inline std::string Found(const std::string& s) {
  return s.size() >= 9 && s.compare(s.size() - 9, 9, "-NOTFOUND") == 0 ? "" : s;
}

/// Node.js: env MDLC_NODE, else the one CMake found ("" when none).
inline std::string NodeBinary() {
  if (const char* env = std::getenv("MDLC_NODE"); env && *env) return env;
  return Found(MDLC_NODE);
}

/// One of the scripts, e.g. "mujoco_dump.mjs".
inline std::filesystem::path MujocoJsScript(const std::string& name) {
  return std::filesystem::path(MDLC_MUJOCO_JS_DIR) / name;
}

/// Empty when MuJoCo 3.3.8 can run; else why not (the tests skip).
inline std::string MujocoJsUnavailable() {
  if (NodeBinary().empty()) return "Node.js not found at configure time (install nodejs)";
  if (std::string(MDLC_MUJOCO_JS_DIR).empty()) return "MDLC_MUJOCO_JS_DIR not set";
  const std::filesystem::path pkg =
      std::filesystem::path(MDLC_MUJOCO_JS_DIR) / "node_modules" / "mujoco-js" / "package.json";
  std::error_code ec;
  if (!std::filesystem::exists(pkg, ec)) {
    return "mujoco-js is not installed: run `npm ci` in tests/oracle/mujoco_js "
           "(tools/setup.sh test does)";
  }
  return "";
}

/// `node SCRIPT ARGS... --serve`: a script answering the files written to
/// its stdin, one JSON line each (for a LineServer).
inline std::vector<std::string> MujocoJsServeCommand(const std::string& script,
                                                     const std::vector<std::string>& args) {
  std::vector<std::string> argv = {NodeBinary(), MujocoJsScript(script).string()};
  argv.insert(argv.end(), args.begin(), args.end());
  argv.push_back("--serve");
  return argv;
}

/// A dump helper's line as JSON; null with *problem set when it is not JSON.
inline nlohmann::json ParseDumpLine(const std::string& line, std::string* problem) {
  try {
    return nlohmann::json::parse(line);
  } catch (const std::exception& e) {
    *problem = std::string("unreadable dump (") + e.what() + "): " + line.substr(0, 300);
    return nlohmann::json();
  }
}

/// `server`'s answer for `file` as JSON; null with *problem set (starting
/// with `helper`, which names the server, when it gave no answer) when there
/// is none.
inline nlohmann::json AskForDump(LineServer& server, const std::string& helper,
                                 const std::string& file, double timeout_s, std::string* problem) {
  const std::optional<std::string> line = server.Ask(file, timeout_s, problem);
  if (!line) {
    *problem = helper + ": " + *problem;
    return nlohmann::json();
  }
  return ParseDumpLine(*line, problem);
}

// ---------------------------------------------------------------------------
// The mdlc CLI and its plant-json dump
// ---------------------------------------------------------------------------

/// --mdlc=PATH from the command line; main() sets it.
inline std::string& MdlcBinaryFlag() {
  static std::string path;
  return path;
}

/// The mdlc CLI the tests run: --mdlc=PATH, else env MDLC_BINARY, else the
/// path compiled in.
inline std::string MdlcBinary() {
  if (!MdlcBinaryFlag().empty()) return MdlcBinaryFlag();
  if (const char* env = std::getenv("MDLC_BINARY"); env && *env) return env;
  return MDLC_BINARY;
}

/// Takes --mdlc=PATH from the arguments gtest left.
inline void ParseMdlcFlag(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--mdlc=", 0) == 0) MdlcBinaryFlag() = a.substr(7);
  }
}

/// Joint positions for --q, in order: (joint name, value).
using JointValues = std::vector<std::pair<std::string, double>>;

inline std::string Quote(const std::vector<std::string>& argv) {
  std::string s;
  for (const auto& a : argv) s += (s.empty() ? "" : " ") + a;
  return s;
}

/// A configuration for failure messages: its first six values.
inline std::string DescribeQ(const JointValues& q,
                             const std::string& if_empty = "default configuration",
                             const std::string& unit = "dofs") {
  if (q.empty()) return if_empty;
  std::string s = "q:";
  for (size_t i = 0; i < q.size(); ++i) {
    if (i == 6) {
      s += " ...(" + std::to_string(q.size()) + " " + unit + ")";
      break;
    }
    s += " " + q[i].first + "=" + Fmt(q[i].second);
  }
  return s;
}

/// The error lines of mdlc's stderr (each with the two lines after it), so
/// failures are not buried under warnings; falls back to the head of stderr.
inline std::string ErrorExcerpt(const std::string& err) {
  std::vector<std::string> lines;
  std::stringstream ss(err);
  for (std::string l; std::getline(ss, l);) lines.push_back(l);
  std::string out;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].find("error") == std::string::npos) continue;
    for (size_t k = i; k < lines.size() && k < i + 3; ++k) out += "\n      " + lines[k];
    if (out.size() > 3000) break;
  }
  if (out.empty()) out = "\n      " + err.substr(0, 2000);
  return out;
}

/// For a file `mdlc convert` wrote, the arguments that make mdlc read it as
/// written, as the reference does: its own model name as --model-name. (mdlc
/// gives a converted file's entities back the instances and names they had
/// before conversion, from comments the writer leaves, unless the caller
/// names the model; the round-trip tests check that restoration.) `root`
/// matches the file's root element with its name as the first group.
inline std::vector<std::string> ReadAsWrittenArgs(const std::string& text, const std::regex& root) {
  std::smatch m;
  if (!std::regex_search(text, m, root)) return {};
  return {"--model-name", m[1].str()};
}

/// `mdlc compile FILE --emit=plant-json [--package-path DIR] [--q NAME=V]... [EXTRA...]`
inline std::vector<std::string> PlantJsonCommand(const std::string& file,
                                                 const std::string& package_path,
                                                 const JointValues& q,
                                                 const std::vector<std::string>& extra = {}) {
  std::vector<std::string> argv = {MdlcBinary(), "compile", file, "--emit=plant-json"};
  argv.insert(argv.end(), extra.begin(), extra.end());
  if (!package_path.empty()) {
    argv.push_back("--package-path");
    argv.push_back(package_path);
  }
  for (const auto& [name, v] : q) {
    argv.push_back("--q");
    argv.push_back(name + "=" + Fmt(v));
  }
  return argv;
}

/// Why mdlc could not be run at all ("" when it ran).
inline std::string SpawnFailure(const RunResult& r) {
  return r.spawn_error.empty() ? "" : "could not run mdlc: " + r.spawn_error;
}

/// Why a run failed (timed out, or exited with a non-zero status), with
/// mdlc's errors; "" when it exited 0.
inline std::string ExitFailure(const RunResult& r, const std::string& cmdline) {
  if (!r.timed_out && r.exit_code == 0) return "";
  return std::string("mdlc ") +
         (r.timed_out ? "timed out" : "exited with status " + std::to_string(r.exit_code)) +
         "\n    command: " + cmdline + "\n    stderr (errors):" + ErrorExcerpt(r.err);
}

/// Parses mdlc's stdout as plant-json (schema mdlc-plant/1) holding the
/// top-level arrays `sections`; returns why not, or "".
inline std::string ReadPlantJson(const RunResult& r, const std::string& cmdline,
                                 const std::vector<std::string>& sections, nlohmann::json* root) {
  try {
    *root = nlohmann::json::parse(r.out);
  } catch (const std::exception& e) {
    return std::string("mdlc output is not JSON (") + e.what() + ")\n    command: " + cmdline +
           "\n    stdout starts: " + r.out.substr(0, 300) + "\n    stderr: " + r.err.substr(0, 1000);
  }
  if (!root->is_object() || root->value("schema", "") != "mdlc-plant/1") {
    return "plant-json schema is not mdlc-plant/1: " +
           (root->is_object() ? root->value("schema", std::string("<missing>")) : root->dump().substr(0, 100));
  }
  for (const auto& section : sections) {
    if (!root->contains(section) || !(*root)[section].is_array()) {
      return "plant-json has no '" + section + "' array";
    }
  }
  return "";
}

/// Collects the discrepancies of one model, each tagged with the model and
/// the current context (e.g. the configuration), and reports them as one
/// failure.
class Report {
 public:
  /// `oracle` names the reference in messages ("urdfdom", "mujoco3.3.8").
  Report(std::string model, std::string oracle)
      : model_(std::move(model)), oracle_(std::move(oracle)) {}
  void SetContext(std::string ctx) { ctx_ = std::move(ctx); }
  void Add(const std::string& what) {
    msgs_.push_back("[" + model_ + (ctx_.empty() ? "" : " | " + ctx_) + "] " + what);
  }
  /// Agreement within |mdlc - ref| <= tol * max(scale, |mdlc|, |ref|); equal
  /// infinities agree, NaN never does. feature: spec ID; entity: e.g. "body
  /// 'r::l'"; quantity: e.g. "X_WB.p[0]".
  void Num(const std::string& feature, const std::string& entity, const std::string& quantity,
           double mdlc, double ref, double tol = kRelTol, double scale = 1.0) {
    if (Agree(mdlc, ref, tol, scale)) return;
    Add(Disagreement(feature, entity, quantity, mdlc, ref));
  }
  /// As Num, to kRelTol, with a note on why the expected value is what it is.
  void Num(const std::string& feature, const std::string& entity, const std::string& quantity,
           double mdlc, double ref, const std::string& note) {
    if (Agree(mdlc, ref, kRelTol, 1.0)) return;
    Add(Disagreement(feature, entity, quantity, mdlc, ref) + (note.empty() ? "" : " [" + note + "]"));
  }
  bool empty() const { return msgs_.empty(); }
  size_t size() const { return msgs_.size(); }
  const std::vector<std::string>& messages() const { return msgs_; }
  /// All messages, up to MDLC_ORACLE_MAX_MESSAGES (default 60) of them.
  std::string Text() const {
    const size_t limit = static_cast<size_t>(EnvInt("MDLC_ORACLE_MAX_MESSAGES", 60));
    std::string text = std::to_string(msgs_.size()) + " discrepancies for " + model_ + ":\n";
    for (size_t i = 0; i < msgs_.size() && i < limit; ++i) text += "  " + msgs_[i] + "\n";
    if (msgs_.size() > limit) text += "  ... and " + std::to_string(msgs_.size() - limit) + " more\n";
    return text;
  }
  /// Fails the test with Text() when there is anything to report, and clears.
  void Flush() {
    if (msgs_.empty()) return;
    ADD_FAILURE() << Text();
    msgs_.clear();
  }

 private:
  static bool Agree(double mdlc, double ref, double tol, double scale) {
    if (std::isinf(mdlc) || std::isinf(ref)) return mdlc == ref;
    if (std::isnan(mdlc) || std::isnan(ref)) return false;
    return std::abs(mdlc - ref) <= tol * std::max({scale, std::abs(mdlc), std::abs(ref)});
  }
  std::string Disagreement(const std::string& feature, const std::string& entity,
                           const std::string& quantity, double mdlc, double ref) const {
    return feature + " " + entity + " " + quantity + ": mdlc=" + Fmt(mdlc) + " " + oracle_ + "=" +
           Fmt(ref) + " (|diff|=" + Fmt(std::abs(mdlc - ref)) + ")";
  }

  std::string model_, oracle_, ctx_;
  std::vector<std::string> msgs_;
};

/// "instance::name", the key of Dump's maps.
inline std::string Key(const std::string& inst, const std::string& name) { return inst + "::" + name; }

/// mdlc's plant-json, its entities by "instance::name".
struct Dump {
  bool rejected_as_expected = false;  // see ListedRejection
  nlohmann::json root;
  std::map<std::string, const nlohmann::json*> bodies, joints, frames;
  std::string cmdline;
};

/// A file a table lists as one mdlc must reject: mdlc exiting with status 1
/// and `keyword` (empty: any) in its stderr is the listed outcome; mdlc
/// accepting the file makes the entry stale, a failure.
struct ListedRejection {
  std::string table;    // the table's name, for the stale-entry message
  std::string keyword;
  std::string why;
};

/// Fills the Dump's maps from its root.
inline void IndexDump(Dump* d) {
  d->bodies.clear();
  d->joints.clear();
  d->frames.clear();
  for (const auto& b : d->root["bodies"]) {
    d->bodies[Key(b.value("model_instance", ""), b.value("name", ""))] = &b;
  }
  for (const auto& j : d->root["joints"]) {
    d->joints[Key(j.value("model_instance", ""), j.value("name", ""))] = &j;
  }
  if (d->root.contains("frames") && d->root["frames"].is_array()) {
    for (const auto& f : d->root["frames"]) {
      d->frames[Key(f.value("model_instance", ""), f.value("name", ""))] = &f;
    }
  }
}

/// Runs mdlc on `file` at configuration `q`; returns false (after reporting,
/// unless the run is a listed rejection) when there is no usable dump.
inline bool RunMdlc(const std::string& file, const std::string& package_path,
                    const JointValues& q, const std::optional<ListedRejection>& listed,
                    Report* rep, Dump* d, const std::vector<std::string>& extra = {}) {
  const std::vector<std::string> argv = PlantJsonCommand(file, package_path, q, extra);
  d->cmdline = Quote(argv);
  const RunResult r = RunProcess(argv, 60.0);
  if (const std::string why = SpawnFailure(r); !why.empty()) {
    rep->Add(why);
    return false;
  }
  if (listed) {
    if (r.exit_code == 1 && r.err.find(listed->keyword) != std::string::npos) {
      d->rejected_as_expected = true;
      return false;
    }
    if (r.exit_code == 0) {
      rep->Add("stale " + listed->table + " entry: mdlc now accepts this file (listed because: " +
               listed->why + ")");
    }
    // a rejection for another reason fails below, with mdlc's errors
  }
  if (const std::string why = ExitFailure(r, d->cmdline); !why.empty()) {
    rep->Add(why);
    return false;
  }
  if (const std::string why = ReadPlantJson(r, d->cmdline, {"bodies", "joints"}, &d->root);
      !why.empty()) {
    rep->Add(why);
    return false;
  }
  IndexDump(d);
  return true;
}

/// A 3-vector of numbers; false when `v` is anything else.
inline bool ReadVec3(const nlohmann::json& v, Eigen::Vector3d* out) {
  if (!v.is_array() || v.size() != 3) return false;
  for (int i = 0; i < 3; ++i) {
    if (!v[i].is_number()) return false;
    (*out)(i) = v[i].get<double>();
  }
  return true;
}

/// Compares a pose: translation entries and (unless `rotation` is false) the
/// rotation matrix, never raw quaternions, whose sign is a convention.
/// `what` names the pose, e.g. "X_WB" (its rotation is then "R_WB").
inline void ComparePose(Report* rep, const std::string& feature, const std::string& ent,
                        const std::string& what, const Eigen::Isometry3d& mdlc,
                        const Eigen::Isometry3d& ref, double tol = kRelTol, bool rotation = true) {
  for (int i = 0; i < 3; ++i) {
    rep->Num(feature, ent, what + ".p[" + std::to_string(i) + "]", mdlc.translation()(i),
             ref.translation()(i), tol);
  }
  if (!rotation) return;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      rep->Num(feature, ent,
               "R" + what.substr(1) + "(" + std::to_string(r) + "," + std::to_string(c) + ")",
               mdlc.linear()(r, c), ref.linear()(r, c), tol);
    }
  }
}

/// gtest names the parameterized cases by their `id`.
struct CaseName {
  template <typename Case>
  std::string operator()(const ::testing::TestParamInfo<Case>& info) const {
    return info.param.id;
  }
};

}  // namespace mdlc::oracle
