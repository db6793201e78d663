// package_manifest.h - what a package.xml says about its package: the root
// element, the <name> and a <deprecated> export (COMMON-014).
//
// The package map sits below the format readers (they and the passes
// resolve package:// with it), so it cannot use their XML reader
// (frontend/xml). It reads the three things it needs with libxml2 directly,
// hardened the same way: no network, no DTD loading, no entity expansion,
// and a document that declares an entity is refused before libxml2 sees it.
// The diagnostics are the format readers' own words for the same faults.
#pragma once

#include <optional>
#include <string>

#include "ir/diagnostics.h"
#include "ir/location.h"
#include "ir/source_manager.h"

namespace mdlc::assets {

struct PackageManifest {
  std::string root;  // the root element's name as written ("package")
  Loc root_at;
  /// The root's first <name> child: its text (untrimmed) and location.
  std::optional<std::string> name;
  Loc name_at;
  /// The text of <export><deprecated>, when the package says it is.
  std::optional<std::string> deprecated;
};

/// Reads the package.xml in `file`. Reports a malformed, empty or
/// entity-declaring document to `diags` and returns nullopt.
std::optional<PackageManifest> ReadPackageManifest(FileId file, const SourceManager& sources,
                                                   DiagnosticEngine& diags);

}  // namespace mdlc::assets
