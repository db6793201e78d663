// symbols.h - xacro's scopes of properties and macros.
//
// xacro scopes are dynamic: a macro body is evaluated in a scope whose
// parent is the *caller's* scope, and a property is stored as text and
// evaluated, in the scope that holds it, the first time it is used (unless
// lazy_eval="false"). Text that reads as a number or a bool becomes one on
// the way in ("1.50" is the float 1.5), as xacro's literal rule has it.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frontend/pyexpr/value.h"
#include "frontend/xacro/xacro_tree.h"
#include "ir/location.h"

namespace mdlc::xacro {

/// xacro's rule for text that enters a scope: 'quoted' text loses its
/// quotes, text that Python's int() or float() reads becomes that number
/// (not when it holds '_'), true/True/false/False become bools.
pyexpr::Value LiteralValue(std::string_view text);
/// LiteralValue of a str value; any other value as it is.
pyexpr::Value LiteralValue(const pyexpr::Value& value);

class SymbolTable;

struct Symbol {
  enum class Kind { kValue, kUnevaluated, kBlock, kContentBlock, kNamespace };
  Kind kind = Kind::kValue;
  pyexpr::Value value;         // kValue
  std::string text;            // kUnevaluated: the text to evaluate
  Node* block = nullptr;       // kBlock (a *param), kContentBlock (a **param or block property)
  SymbolTable* space = nullptr;  // kNamespace (an <xacro:include ns=...>)
  Loc defined_at;
};

class SymbolTable {
 public:
  /// `parent` null: the document's top scope (its parent is the globals).
  explicit SymbolTable(SymbolTable* parent, bool is_namespace = false)
      : parent_(parent), is_namespace_(is_namespace) {}

  SymbolTable* parent() const { return parent_; }
  bool is_namespace() const { return is_namespace_; }
  /// The top scope of the document.
  SymbolTable* Top();

  /// This scope's own entry for `name`.
  Symbol* FindHere(std::string_view name);
  /// The nearest scope's entry for `name`, and that scope.
  std::pair<Symbol*, SymbolTable*> Find(std::string_view name);
  void Set(const std::string& name, Symbol symbol) { symbols_[name] = std::move(symbol); }
  /// Removes `name` from this scope and every one above it.
  void Remove(std::string_view name);
  /// Every name visible from here, for did-you-mean.
  void CollectNames(std::vector<std::string>& out) const;
  /// The names this scope itself holds.
  void CollectOwnNames(std::vector<std::string>& out) const;

  /// The names being evaluated now (a circular definition meets itself).
  std::vector<std::string>& resolving() { return resolving_; }

 private:
  SymbolTable* parent_;
  bool is_namespace_;
  std::map<std::string, Symbol, std::less<>> symbols_;
  std::vector<std::string> resolving_;
};

struct Macro {
  std::string name;
  Node* body = nullptr;  // the <xacro:macro> element, as defined
  std::vector<std::string> params;  // in order; "*b" and "**b" for blocks
  struct Default {
    std::optional<std::string> forward;  // ^: the caller's property of that name
    std::optional<std::string> text;     // the default's text, evaluated at the call
  };
  std::map<std::string, Default, std::less<>> defaults;
  Loc defined_at;
};

class MacroTable {
 public:
  explicit MacroTable(MacroTable* parent = nullptr) : parent_(parent) {}
  /// A macro by name, here or in a scope above.
  const Macro* Find(std::string_view name) const;
  /// A namespace made by <xacro:include ns=...>, here or above.
  MacroTable* FindNamespace(std::string_view name);
  void Define(std::shared_ptr<Macro> macro) {
    std::string name = macro->name;
    macros_[name] = std::move(macro);
  }
  MacroTable* AddNamespace(const std::string& name);
  void CollectNames(std::vector<std::string>& out) const;

 private:
  MacroTable* parent_;
  std::map<std::string, std::shared_ptr<Macro>, std::less<>> macros_;
  std::map<std::string, std::unique_ptr<MacroTable>, std::less<>> namespaces_;
};

}  // namespace mdlc::xacro
