// check.h - `mdlc check` (issue 15): compile many model files, each on its
// own, and report a verdict per file and a summary; as text, as JSON Lines
// (one object per file, resumable with --skip-ok) or as SARIF 2.1.0 for
// code-hosting CI. Directories are walked for model files; -j compiles
// files in parallel, each file independent of the others.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "mdlc/mdlc.h"

namespace mdlc::tools {

enum class CheckFormat { Text, JsonLines, Sarif };

struct CheckOptions {
  std::vector<std::string> paths;  // files and directories
  Options compile;                 // each file is compiled with these
  std::optional<Format> input_format;  // -x, --format: each file's (unset: by its name)
  int jobs = 1;
  CheckFormat format = CheckFormat::Text;
  /// A JSON Lines report of an earlier run: files it lists as ok are skipped.
  std::string skip_ok_from;
  bool progress = false;  // a progress line on standard error
  bool color = false;
  /// Text: the totals only, no report per file (--summary).
  bool summary_only = false;
};

/// The model files under `paths`: files as given, directories walked for
/// .urdf, .sdf, .world (Gazebo's), .dmd.yaml and MJCF .xml files (those whose root is
/// <mujoco>), in sorted order.
std::vector<std::string> FindModelFiles(const std::vector<std::string>& paths,
                                        std::vector<std::string>* unreadable);

/// Runs the check, writing the report with `write`; returns the exit status
/// (0 when no file has errors, 1 otherwise). A file that another file of the
/// walk includes (an MJCF <include>) is reported as a fragment of it, not as
/// a model; a warning about the package folders (a package found twice) is
/// reported once, not with every file.
int RunCheck(const CheckOptions& options, const std::function<void(std::string_view)>& write);

}  // namespace mdlc::tools
