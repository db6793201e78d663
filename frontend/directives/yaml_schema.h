// yaml_schema.h - strict, located reading of YAML for schema-defined formats
// (Model Directives).
//
// yaml-cpp parses the text into mdlc's tree (yaml_tree.h); this reader
// checks the tree against the schema the caller states field by field, the
// way Drake's YAML archive does: a map may hold only the keys the schema
// names (each once), a field has one type, and every problem is reported at
// the node's line and column. Each read reports its own problem and returns
// nullopt, so callers skip what they could not read and go on to report the
// next problem.
#pragma once

#include <Eigen/Core>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frontend/directives/yaml_tree.h"
#include "ir/diagnostics.h"
#include "ir/source_manager.h"

namespace mdlc::frontend {

/// A scalar string with where it was written.
struct LocatedString {
  std::string text;
  Loc loc;
};

class YamlSchemaReader {
 public:
  YamlSchemaReader(FileId file, DiagnosticEngine& diags) : file_(file), diags_(diags) {}

  /// Parses a whole buffer. A syntax error (including nesting beyond
  /// yaml-cpp's depth guard) is reported at its position; null then.
  std::unique_ptr<yaml::Document> Parse(std::string_view contents);

  /// Where `node` starts; `fallback` for nodes without a place
  /// (an absent value).
  Loc LocOf(const yaml::Node& node, Loc fallback = {}) const;

  /// Checks that `node` is a map whose keys are all among `allowed`, each
  /// once. Unknown keys (with a suggestion) and repeated keys are errors.
  /// YAML merge keys (`<<: *anchor`) bring in the keys of other maps, which
  /// are checked too. Returns false when `node` is not a map at all.
  bool CheckMap(const yaml::Node& node, std::string_view what,
                std::initializer_list<std::string_view> allowed, Loc fallback = {});

  /// The value of `key` in map `node` (or in a map it merges), with the
  /// key's location; an undefined node when absent.
  struct Field {
    yaml::Node value;
    Loc key_loc;
    bool present() const { return value.IsDefined(); }
  };
  Field Get(const yaml::Node& map, std::string_view key) const;

  /// A scalar (null reads as ""). `what` names the field in messages.
  std::optional<LocatedString> String(const yaml::Node& node, std::string_view what, Loc fallback);
  /// A finite number.
  std::optional<double> Number(const yaml::Node& node, std::string_view what, Loc fallback);
  /// A sequence of finite numbers; exactly `count` of them when given.
  std::optional<std::vector<double>> Numbers(const yaml::Node& node, std::string_view what,
                                             Loc fallback, std::optional<size_t> count = {});
  std::optional<Eigen::Vector3d> Vector3(const yaml::Node& node, std::string_view what,
                                         Loc fallback);
  /// A sequence of scalars (null reads as an empty list).
  std::optional<std::vector<LocatedString>> Strings(const yaml::Node& node, std::string_view what,
                                                    Loc fallback);

  /// The node's tag when the author wrote one ("!Rpy"); empty otherwise.
  static std::string_view ExplicitTag(const yaml::Node& node);

  DiagnosticEngine& diags() { return diags_; }
  FileId file() const { return file_; }

 private:
  std::vector<yaml::Node> MergedMaps(const yaml::Node& map) const;
  void ReportType(const yaml::Node& node, std::string_view what, std::string_view expected,
                  Loc fallback);

  FileId file_;
  DiagnosticEngine& diags_;
};

}  // namespace mdlc::frontend
