#include "frontend/xacro/symbols.h"

#include "frontend/pyexpr/number_text.h"

namespace mdlc::xacro {

pyexpr::Value LiteralValue(std::string_view text) {
  if (text.size() >= 2 && text.front() == '\'' && text.back() == '\'') {
    return pyexpr::Value::Str(std::string(text.substr(1, text.size() - 2)));
  }
  // Python reads "1_000" as a number; xacro keeps such text as text
  if (text.find('_') == std::string_view::npos) {
    if (auto i = pyexpr::ParsePythonInt(text)) return pyexpr::Value::Int(*i);
    if (auto f = pyexpr::ParsePythonFloat(text)) return pyexpr::Value::Float(*f);
    if (text == "true" || text == "True") return pyexpr::Value::Bool(true);
    if (text == "false" || text == "False") return pyexpr::Value::Bool(false);
  }
  return pyexpr::Value::Str(std::string(text));
}

pyexpr::Value LiteralValue(const pyexpr::Value& value) {
  return value.IsStr() ? LiteralValue(value.AsStr()) : value;
}

SymbolTable* SymbolTable::Top() {
  SymbolTable* t = this;
  while (t->parent_) t = t->parent_;
  return t;
}

Symbol* SymbolTable::FindHere(std::string_view name) {
  auto it = symbols_.find(name);
  return it == symbols_.end() ? nullptr : &it->second;
}

std::pair<Symbol*, SymbolTable*> SymbolTable::Find(std::string_view name) {
  for (SymbolTable* t = this; t; t = t->parent_) {
    if (Symbol* s = t->FindHere(name)) return {s, t};
  }
  return {nullptr, nullptr};
}

void SymbolTable::Remove(std::string_view name) {
  for (SymbolTable* t = this; t; t = t->parent_) {
    auto it = t->symbols_.find(name);
    if (it != t->symbols_.end()) t->symbols_.erase(it);
  }
}

void SymbolTable::CollectNames(std::vector<std::string>& out) const {
  for (const SymbolTable* t = this; t; t = t->parent_) {
    for (const auto& [name, symbol] : t->symbols_) {
      if (name[0] != '*') out.push_back(name);
    }
  }
}

void SymbolTable::CollectOwnNames(std::vector<std::string>& out) const {
  for (const auto& [name, symbol] : symbols_) {
    if (name[0] != '*') out.push_back(name);
  }
}

const Macro* MacroTable::Find(std::string_view name) const {
  for (const MacroTable* t = this; t; t = t->parent_) {
    auto it = t->macros_.find(name);
    if (it != t->macros_.end()) return it->second.get();
  }
  return nullptr;
}

MacroTable* MacroTable::FindNamespace(std::string_view name) {
  for (MacroTable* t = this; t; t = t->parent_) {
    auto it = t->namespaces_.find(name);
    if (it != t->namespaces_.end()) return it->second.get();
  }
  return nullptr;
}

MacroTable* MacroTable::AddNamespace(const std::string& name) {
  auto& slot = namespaces_[name];
  slot = std::make_unique<MacroTable>();
  return slot.get();
}

void MacroTable::CollectNames(std::vector<std::string>& out) const {
  for (const MacroTable* t = this; t; t = t->parent_) {
    for (const auto& [name, macro] : t->macros_) out.push_back(name);
  }
}

}  // namespace mdlc::xacro
