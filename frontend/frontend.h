// frontend.h - the entry point of every format frontend.
//
// A frontend lowers one file's syntax into the IR Module: it records what the
// file says (names, numbers, references by name, locations) and reports what
// it cannot read. It resolves nothing across entities; passes do that.
#pragma once

#include <memory>
#include <optional>
#include <vector>
#include <string>

#include "ir/assets/package_map.h"
#include "frontend/xml/document_cache.h"
#include "ir/diagnostics.h"
#include "ir/format.h"
#include "ir/module.h"
#include "ir/source_manager.h"

namespace mdlc::frontend {

struct FrontendOptions {
  /// Name the model instance this, instead of the name in the file.
  std::optional<std::string> model_name;
  /// On an instance-name collision, pick NAME_1, NAME_2, ... instead of failing.
  bool auto_rename = false;
  /// Prepended to the instance name ("outer::" for a model an SDFormat file
  /// includes): the instance is scoped by its includer (COMMON-022).
  std::string name_prefix;
  /// Drake's Parser::AddModel (a directive's add_model): the file must hold
  /// exactly one model, so an SDFormat <world> is an error.
  bool single_model = false;
  /// xacro's NAME:=VALUE arguments for the top-level file, when it is a
  /// `.xacro`; a xacro file that a model or directive includes is expanded
  /// with its own defaults.
  std::vector<std::pair<std::string, std::string>> xacro_args;
};

struct RenameSuffixes;  // model_naming.h

/// Everything a frontend works with. Owns nothing.
struct FrontendContext {
  SourceManager& sources;
  DiagnosticEngine& diags;
  ir::Module& module;
  FrontendOptions options;
  /// Packages for the files a model includes (SDFormat <include>, directives).
  const assets::PackageMap& packages = assets::NoPackages();
  /// The compile's parsed XML files, so a file loaded many times is parsed
  /// once; null to parse every load.
  xml::DocumentCache* documents = nullptr;
  /// The compile's auto-rename suffixes, so renaming many copies of one
  /// name stays linear; null to search each rename from NAME_1.
  RenameSuffixes* renames = nullptr;
};

/// Parses an XML buffer through ctx.documents, when there is one. A
/// `.xacro` file is expanded first (frontend/xacro/).
std::shared_ptr<const xml::XmlDocument> ParseXml(FileId file, FrontendContext& ctx);

/// Loads `path` and lowers it as `format`, or else with the frontend its
/// extension selects. Returns the new model instance, or nullopt after
/// reporting errors.
std::optional<ModelId> ReadModelFile(const std::string& path, FrontendContext& ctx,
                                     std::optional<Format> format = {});

/// The format of a `.xacro` file: the one its root element names (<robot>
/// URDF, <sdf> SDFormat, <mujoco> MJCF), which xacro leaves as written.
std::optional<Format> XacroFormat(FileId file, const SourceManager& sources);

/// Lowers a buffer already in the SourceManager as the given format.
std::optional<ModelId> ReadModel(FileId file, Format format, FrontendContext& ctx);

/// URDF frontend (frontend/urdf/).
std::optional<ModelId> ReadUrdf(FileId file, FrontendContext& ctx);
/// SDFormat frontend (frontend/sdf/).
std::optional<ModelId> ReadSdf(FileId file, FrontendContext& ctx);
/// MJCF (MuJoCo XML) frontend (frontend/mjcf/).
std::optional<ModelId> ReadMjcf(FileId file, FrontendContext& ctx);
/// Model Directives frontend (frontend/directives/): loads every model the
/// file adds; returns the default instance, which holds its global filter
/// groups.
std::optional<ModelId> ReadDirectives(FileId file, FrontendContext& ctx);

}  // namespace mdlc::frontend
