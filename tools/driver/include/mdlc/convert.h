// mdlc/convert.h - a compiled model written as URDF, SDFormat or MJCF
// (`mdlc convert`).
//
//   mdlc::ConvertOutput out = mdlc::Convert(result, {.to = mdlc::Format::Mjcf});
//   for (const mdlc::Diagnostic& d : out.diagnostics) std::cerr << result.FormatText(d);
//   if (out.ok()) std::cout << *out.text;
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "mdlc/mdlc.h"

namespace mdlc {

/// What `mdlc convert` writes.
struct ConvertOptions {
  /// The target: urdf, sdf or mjcf.
  Format to = Format::Urdf;
  /// The file the text will be written to: mesh paths are written relative
  /// to its folder (empty: the current directory).
  std::string output;
  /// Copy every mesh into this folder (one copy per distinct content) and
  /// name the copies; a mesh the target cannot read (MJCF: other than STL,
  /// OBJ or MSH) is written as an OBJ of the triangles mdlc read.
  std::optional<std::string> copy_assets_dir;
  /// URDF only: plain URDF that urdfdom and ROS read (`--plain`): one root
  /// link, with a floating joint to each free body, and Drake's shapes and
  /// joints approximated (-Wlossy).
  bool plain = false;
  /// Keep package:// URIs as the source wrote them.
  bool keep_package_uris = false;
  /// MJCF only: fuse each body welded to its parent (not to the world) into
  /// that body, mass properties combined exactly, its geometry, frames and
  /// cameras re-posed there, its own frame kept as a site (`--fuse-fixed`).
  bool fuse_fixed = false;
};

/// What Convert wrote, and what it had to say about it.
struct ConvertOutput {
  /// The model in the target format; unset after an error.
  std::optional<std::string> text;
  /// What the target cannot hold (-Wlossy warnings) and why the model could
  /// not be written, in report order, under the compile's diagnostic policy
  /// (Options::diagnostics.policy): a -Wlossy warning may be an error. They point
  /// into the Result's sources: print them with Result::FormatText.
  std::vector<Diagnostic> diagnostics;
  /// The errors and warnings reported; past Options::diagnostics.policy.max_errors,
  /// errors are counted but not listed.
  size_t error_count = 0;
  size_t warning_count = 0;
  bool ok() const { return text.has_value() && error_count == 0; }
};

/// Writes the compiled model (result.has_model(); else std::logic_error) as
/// options.to. The Result is not changed: converting it twice, or to two
/// targets, gives the same diagnostics each time.
ConvertOutput Convert(const Result& result, const ConvertOptions& options);

}  // namespace mdlc
