// check.cc - see check.h.
#include "check.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "backend/json_writer.h"
#include "mdlc/version.h"

namespace mdlc::tools {
namespace {
namespace fs = std::filesystem;

bool IsMjcf(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  return head.find("<mujoco") != std::string::npos;
}

bool IsModelFile(const fs::path& file) {
  const std::string name = file.filename().string();
  if (name.ends_with(".urdf") || name.ends_with(".sdf") || name.ends_with(".world") ||
      name.ends_with(".dmd.yaml")) {
    return true;
  }
  return name.ends_with(".xml") && IsMjcf(file);
}

/// One file's outcome, rendered in the report's format.
struct FileResult {
  std::string path;
  bool skipped = false;
  bool ok = false;
  size_t errors = 0, warnings = 0;
  std::string report;                     // text block or JSON line
  std::vector<std::string> sarif_results;  // SARIF result objects
  /// The MJCF files this one's model includes (<include file=...>), each
  /// with the file that includes it: fragments, never models of their own.
  std::vector<std::pair<std::string, std::string>> includes;
  /// What the package folders say, the same for every file (a package found
  /// twice): reported once per run, not in each file's report.
  std::vector<std::string> package_warnings;
  bool done = false;
};

/// A path as the walk and the compile's sources both name it.
std::string SamePath(const std::string& path) {
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(path, ec);
  return (ec ? fs::path(path) : canonical).lexically_normal().string();
}

/// A warning about the package folders rather than the file: its place is a
/// package.xml (a package found again under the package path).
bool AboutThePackageFolders(const Diagnostic& d, const SourceManager& sources) {
  return d.severity == Severity::Warning && d.loc.valid() &&
         fs::path(sources.Path(d.loc.file)).filename() == "package.xml";
}

std::string Level(Severity s) {
  return s == Severity::Error ? "error" : s == Severity::Warning ? "warning" : "note";
}

std::string JsonString(std::string_view s) {
  backend::JsonWriter w;
  w.String(s);
  return w.Take();
}

std::string SarifResult(const Diagnostic& d, const SourceManager& sources,
                        const std::string& file) {
  backend::JsonWriter w;
  w.BeginObject(backend::JsonWriter::Layout::Compact);
  w.Key("ruleId").String(InfoFor(d.kind).name);
  w.Key("level").String(Level(d.severity));
  w.Key("message").BeginObject().Key("text").String(d.message).EndObject();
  w.Key("locations").BeginArray().BeginObject().Key("physicalLocation").BeginObject();
  w.Key("artifactLocation").BeginObject();
  w.Key("uri").String(d.loc.valid() ? sources.Path(d.loc.file) : file);
  w.EndObject();
  if (d.loc.valid() && d.loc.line > 0) {
    w.Key("region").BeginObject().Key("startLine").Int(d.loc.line);
    if (d.loc.column > 0) w.Key("startColumn").Int(d.loc.column);
    w.EndObject();
  }
  w.EndObject().EndObject().EndArray();
  w.EndObject();
  return w.Take();
}

void CheckOne(const CheckOptions& options, const Options& compile, FileResult& r) {
  const Result result = Compile(Input::File(r.path, options.input_format), compile);
  const SourceManager& sources = result.sources();
  for (size_t f = 0; f < sources.FileCount(); ++f) {
    const FileId id{static_cast<uint32_t>(f)};
    const Loc from = sources.IncludedFrom(id);
    if (from.valid() && !sources.IsExpansion(id) && sources.Path(id).ends_with(".xml") &&
        sources.Path(from.file).ends_with(".xml")) {
      r.includes.emplace_back(SamePath(sources.Path(id)), sources.Path(from.file));
    }
  }
  std::vector<Diagnostic> diagnostics;  // the file's own
  for (const Diagnostic& d : result.diagnostics()) {
    if (AboutThePackageFolders(d, sources)) {
      r.package_warnings.push_back(result.FormatText(d, options.color));
    } else {
      diagnostics.push_back(d);
    }
  }
  r.ok = result.ok();
  r.errors = result.error_count();
  r.warnings = result.warning_count() - r.package_warnings.size();
  switch (options.format) {
    case CheckFormat::Text: {
      for (const Diagnostic& d : diagnostics) {
        r.report += result.FormatText(d, options.color);
      }
      r.report += fmt::format("{}: {}\n", r.path,
                              r.ok ? (r.warnings ? fmt::format("ok, {} warning{}", r.warnings,
                                                               r.warnings == 1 ? "" : "s")
                                                 : std::string("ok"))
                                   : fmt::format("{} error{}, {} warning{}", r.errors,
                                                 r.errors == 1 ? "" : "s", r.warnings,
                                                 r.warnings == 1 ? "" : "s"));
      break;
    }
    case CheckFormat::JsonLines: {
      std::string json;
      for (const Diagnostic& d : diagnostics) {
        json += (json.empty() ? "" : ",") + result.FormatJson(d);
      }
      r.report = fmt::format("{{\"file\":{},\"ok\":{},\"errors\":{},\"warnings\":{},"
                             "\"diagnostics\":[{}]}}\n",
                             JsonString(r.path), r.ok ? "true" : "false", r.errors, r.warnings,
                             json);
      break;
    }
    case CheckFormat::Sarif:
      for (const Diagnostic& d : diagnostics) {
        r.sarif_results.push_back(SarifResult(d, result.sources(), r.path));
      }
      break;
  }
}

/// `r` reported as what it is: a fragment of `includer`, checked as part of
/// it (MuJoCo reads an included file only inside the model that includes it).
void ReportAsFragment(const CheckOptions& options, const std::string& includer, FileResult& r) {
  r.ok = true;
  r.errors = r.warnings = 0;
  r.sarif_results.clear();
  r.report = options.format == CheckFormat::JsonLines
                 ? fmt::format("{{\"file\":{},\"ok\":true,\"errors\":0,\"warnings\":0,"
                               "\"diagnostics\":[],\"included_by\":{}}}\n",
                               JsonString(r.path), JsonString(includer))
                 : fmt::format("{}: fragment, included by {}\n", r.path, includer);
}

/// The files an earlier JSON Lines report lists as ok (each line starts
/// {"file":"...","ok":true, as this file writes them).
std::set<std::string> OkFiles(const std::string& report) {
  std::set<std::string> ok;
  std::ifstream in(report);
  for (std::string line; std::getline(in, line);) {
    constexpr std::string_view kStart = "{\"file\":\"";
    if (!line.starts_with(kStart)) continue;
    std::string file;
    size_t i = kStart.size();
    for (; i < line.size() && line[i] != '"'; ++i) {
      if (line[i] == '\\' && i + 1 < line.size()) ++i;  // \" and \\ (paths need no more)
      file += line[i];
    }
    if (line.compare(i, 11, "\",\"ok\":true") == 0) ok.insert(file);
  }
  return ok;
}

std::string Sarif(const std::vector<FileResult>& results) {
  std::string out = fmt::format(
      "{{\"$schema\":\"https://json.schemastore.org/sarif-2.1.0.json\",\"version\":\"2.1.0\","
      "\"runs\":[{{\"tool\":{{\"driver\":{{\"name\":\"mdlc\",\"version\":\"{}\"}}}},"
      "\"results\":[",
      kVersion);
  bool first = true;
  for (const FileResult& r : results) {
    for (const std::string& s : r.sarif_results) {
      out += (first ? "\n  " : ",\n  ") + s;
      first = false;
    }
  }
  return out + "\n]}]}\n";
}

}  // namespace

std::vector<std::string> FindModelFiles(const std::vector<std::string>& paths,
                                        std::vector<std::string>* unreadable) {
  std::vector<std::string> files;
  for (const std::string& p : paths) {
    std::error_code ec;
    if (!fs::is_directory(p, ec)) {
      files.push_back(p);  // a file as given: compiling it reports what is wrong
      continue;
    }
    std::vector<std::string> found;
    for (auto it = fs::recursive_directory_iterator(
             p, fs::directory_options::skip_permission_denied, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
      if (it->is_regular_file(ec) && IsModelFile(it->path())) found.push_back(it->path().string());
    }
    if (ec) unreadable->push_back(p);
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  return files;
}

int RunCheck(const CheckOptions& options, const std::function<void(std::string_view)>& write) {
  std::vector<std::string> unreadable;
  const std::vector<std::string> files = FindModelFiles(options.paths, &unreadable);
  for (const std::string& dir : unreadable) {
    fmt::print(stderr, "mdlc: warning: could not walk all of '{}'\n", dir);
  }
  const std::set<std::string> skip =
      options.skip_ok_from.empty() ? std::set<std::string>{} : OkFiles(options.skip_ok_from);

  std::vector<FileResult> results(files.size());
  for (size_t i = 0; i < files.size(); ++i) {
    results[i].path = files[i];
    results[i].skipped = skip.count(files[i]) > 0;
  }
  // every file has the same package path: walk its folders once, not per file
  Options compile = options.compile;
  if (!compile.packages.scan) compile.packages.scan = ScanPackages(compile);
  // workers take files in order; the report is written in file order
  std::mutex mutex;
  std::condition_variable ready;
  std::atomic<size_t> next{0};
  auto work = [&] {
    for (size_t i; (i = next++) < results.size();) {
      if (!results[i].skipped) CheckOne(options, compile, results[i]);
      std::lock_guard lock(mutex);
      results[i].done = true;
      ready.notify_all();
    }
  };
  const int jobs = std::max(1, std::min<int>(options.jobs, static_cast<int>(files.size())));
  std::vector<std::thread> workers;
  for (int j = 0; j < jobs; ++j) workers.emplace_back(work);

  // every file is compiled before any is reported: a file is a fragment
  // when any other includes it, which the last file may show
  for (size_t i = 0; i < results.size(); ++i) {
    {
      std::unique_lock lock(mutex);
      ready.wait(lock, [&] { return results[i].done; });
    }
    if (options.progress) {
      fmt::print(stderr, "\r\033[K[{}/{}] {}", i + 1, results.size(), results[i].path);
      if (i + 1 == results.size()) fmt::print(stderr, "\r\033[K");
    }
  }
  for (std::thread& t : workers) t.join();

  std::map<std::string, std::string> includer_of;  // the file that includes each
  std::set<std::string> package_warnings;
  for (const FileResult& r : results) {
    for (const auto& [included, includer] : r.includes) {
      includer_of.try_emplace(included, includer);
    }
  }
  size_t ok = 0, failed = 0, skipped = 0, fragments = 0, warnings = 0;
  std::string reports;
  for (FileResult& r : results) {
    if (r.skipped) {
      ++skipped;
      continue;
    }
    const auto includer = includer_of.find(SamePath(r.path));
    if (includer != includer_of.end()) {
      ReportAsFragment(options, includer->second, r);
      ++fragments;
    } else {
      (r.ok ? ok : failed) += 1;
      warnings += r.warnings;
    }
    // the package folders' warnings, once per run, before the first report
    for (const std::string& w : r.package_warnings) {
      if (package_warnings.insert(w).second) {
        warnings += 1;
        if (options.format == CheckFormat::Text && !options.summary_only) write(w);
      }
    }
    if (options.format != CheckFormat::Sarif && !options.summary_only) write(r.report);
  }
  if (options.format == CheckFormat::Sarif) write(Sarif(results));

  const std::string summary = fmt::format(
      "{} file{}: {} ok, {} with errors{}, {} warning{}{}\n", files.size(),
      files.size() == 1 ? "" : "s", ok, failed,
      fragments ? fmt::format(", {} fragment{} of others", fragments, fragments == 1 ? "" : "s")
                : "",
      warnings, warnings == 1 ? "" : "s",
      skipped ? fmt::format(", {} skipped as ok before", skipped) : "");
  if (options.format == CheckFormat::Text) {
    write(summary);
  } else {
    fmt::print(stderr, "{}", summary);  // standard output stays machine-readable
  }
  return failed ? 1 : 0;
}

}  // namespace mdlc::tools
