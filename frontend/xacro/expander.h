// expander.h - the xacro expansion itself (internal to frontend/xacro).
//
// One Expander expands one top-level file, walking the tree as xacro's
// eval_all does: attributes first, then the children in order, where each
// xacro element does its work and is replaced by what it stands for. The
// first error ends the expansion (as in xacro): it is reported where the
// offending text is written, and the walk unwinds with ExpansionFailed.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "frontend/pyexpr/evaluate.h"
#include "frontend/pyexpr/value.h"
#include "frontend/xacro/symbols.h"
#include "frontend/xacro/xacro.h"

namespace mdlc::xml {
class XmlDocument;
}

namespace mdlc::xacro {

/// Thrown once an error is reported: the expansion stops.
struct ExpansionFailed {};

class Expander {
 public:
  Expander(const XacroOptions& options, SourceManager& sources, DiagnosticEngine& diags);
  std::unique_ptr<Expansion> Run(FileId file);

  // ---- used by the expression scope and text evaluation (text_eval.cc) ----
  /// Evaluates xacro text: `${...}` expressions, `$(...)` substitutions and
  /// `$$` escapes. A text that is one expression gives its value as it is
  /// (a float stays a float); anything else gives the joined str().
  pyexpr::Value EvalText(std::string_view text, SymbolTable& scope, Loc at);
  /// Evaluates an expression, parsing each distinct text once.
  pyexpr::Result<pyexpr::Value> EvaluateExpression(const std::string& expression,
                                                   pyexpr::Scope& names);
  /// str() of EvalText.
  std::string EvalString(std::string_view text, SymbolTable& scope, Loc at);
  /// The value of a property, evaluating it in its scope on first use.
  pyexpr::Result<std::optional<pyexpr::Value>> LookupName(std::string_view name,
                                                          SymbolTable& scope);

  [[noreturn]] void Fail(Loc at, std::string message, DiagKind kind = DiagKind::XacroError);
  void Warn(Loc at, std::string message);

 private:
  friend class ExpressionScope;
  // ---- the walk (expander.cc) ----
  void EvalAll(Node* node, MacroTable& macros, SymbolTable& symbols);
  void EvalAttributes(Node* node, SymbolTable& symbols);
  void InsertBlock(Node* node, MacroTable& macros, SymbolTable& symbols);
  void GrabProperty(Node* node, SymbolTable& symbols);
  void GrabMacro(Node* node, MacroTable& macros);
  void DefineArg(Node* node, SymbolTable& symbols);
  void Conditional(Node* node, MacroTable& macros, SymbolTable& symbols);
  /// Expands a macro call in place; false when `node` calls no macro.
  bool CallMacro(Node* node, MacroTable& macros, SymbolTable& symbols);
  void ExpandMacro(Node* node, const Macro& macro, MacroTable& macros, SymbolTable& symbols);
  // ---- includes (include.cc) ----
  void Include(Node* node, MacroTable& macros, SymbolTable& symbols);
  std::vector<std::string> IncludeFiles(const std::string& spec, Loc at);
  /// Reads and parses an included file into a tree; its document element.
  Node* ReadFile(const std::string& path, Loc included_from, bool optional);
  /// Parses a loaded file and copies it into the tree; `path` names it for
  /// the next inclusion of the same file.
  Node* ReadBuffer(FileId file, const std::string* path = nullptr);
  /// Copies a parsed document into the tree, placed in `file`.
  Node* CopyDocument(const xml::XmlDocument& doc, FileId file);
  // ---- tree helpers ----
  void RemovePreviousComments(Node* node);
  void LiftNamespaces(Node* to, const Node& from);
  /// Reads the listed attributes of a xacro element, warning of others.
  std::vector<const Attribute*> CheckAttributes(Node* node,
                                                std::initializer_list<std::string_view> required,
                                                std::initializer_list<std::string_view> optional);
  /// xacro's truth of a condition value: bools and numbers as Python,
  /// "true"/"True"/"false"/"False", or text int() reads.
  bool ConditionValue(const pyexpr::Value& value, std::string_view written, Loc at);
  void CountNode();
  /// xacro warns of a property or parameter named like a global (pi, max).
  void WarnIfGlobal(std::string_view name, Loc at);
  std::string CurrentFile() const;
  /// Lists a file the expansion read, once (`xacro --deps`).
  void NoteDependency(const std::string& path);
  std::string AbsoluteFilename(std::string_view spec) const;

  // ---- $(...) and the xacro namespace (text_eval.cc) ----
  std::string Substitute(std::string_view body, SymbolTable& scope, Loc at);
  std::string EvalSubstitutionExpression(std::string_view expression, Loc at);
  std::string FindPackage(std::string_view package, Loc at);
  const pyexpr::NameTable& XacroNamespace();
  pyexpr::Result<pyexpr::Value> LoadYaml(const std::string& filename);
  std::string DidYouMean(std::string_view name, SymbolTable& scope) const;

  const XacroOptions& options_;
  SourceManager& sources_;
  DiagnosticEngine& diags_;
  std::unique_ptr<Expansion> expansion_;
  std::map<std::string, std::string, std::less<>> args_;
  std::vector<std::string> file_stack_;   // the file being processed is last
  std::vector<std::string> open_files_;   // the same files, as canonical paths
  std::vector<const Macro*> macro_stack_;
  std::vector<std::unique_ptr<SymbolTable>> scopes_;   // every scope made, kept to the end
  std::vector<std::unique_ptr<MacroTable>> macro_scopes_;
  Node* empty_text_ = nullptr;  // xacro's one "\n\n" text node that stops comment removal
  Loc here_;                    // what is being evaluated, for xacro.message and friends
  std::unique_ptr<pyexpr::NameTable> xacro_namespace_;
  pyexpr::Value xacro_namespace_value_;
  std::set<std::string, std::less<>> dependency_seen_;  // dependencies, as a set
  std::map<std::string, pyexpr::Value, std::less<>> yaml_values_;  // by absolute path
  // each included file as first parsed, by path
  std::map<std::string, std::shared_ptr<const xml::XmlDocument>, std::less<>> read_files_;
  std::map<std::string, bool, std::less<>> deprecated_warned_;   // bare names warned of
  // every expression text evaluated, parsed
  std::unordered_map<std::string, std::shared_ptr<const pyexpr::ParsedExpression>> parsed_;
};

}  // namespace mdlc::xacro
