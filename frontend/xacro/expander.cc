#include "frontend/xacro/expander.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "frontend/pyexpr/builtins.h"
#include "frontend/pyexpr/number_text.h"
#include "frontend/xacro/macro_params.h"
#include "ir/scoped_name.h"

namespace mdlc::xacro {
namespace {

constexpr std::string_view kPrefix = "xacro:";

bool IsXacroTag(const Node& node, std::string_view tag) {
  return node.name.size() == kPrefix.size() + tag.size() && node.name.starts_with(kPrefix) &&
         std::string_view(node.name).substr(kPrefix.size()) == tag;
}

bool IsBlankWithAtMostOneNewline(const Node& node) {
  if (node.kind != Node::Kind::kText || node.text.empty()) return false;
  for (char c : node.text) {
    if (c != ' ' && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v') return false;
  }
  return std::count(node.text.begin(), node.text.end(), '\n') <= 1;
}

// Python's str.isidentifier() for ASCII names, and not a keyword: a
// property must be a name an expression can use
bool IsValidName(std::string_view name) {
  static constexpr std::string_view kKeywords[] = {
      "False", "None", "True", "and", "as", "assert", "async", "await", "break", "class",
      "continue", "def", "del", "elif", "else", "except", "finally", "for", "from", "global",
      "if", "import", "in", "is", "lambda", "nonlocal", "not", "or", "pass", "raise", "return",
      "try", "while", "with", "yield"};
  if (name.empty()) return false;
  const auto start = [](unsigned char c) { return std::isalpha(c) || c == '_' || c >= 0x80; };
  if (!start(name[0])) return false;
  for (unsigned char c : name) {
    if (!start(c) && !std::isdigit(c)) return false;
  }
  return std::find(std::begin(kKeywords), std::end(kKeywords), name) == std::end(kKeywords);
}

}  // namespace

Expander::Expander(const XacroOptions& options, SourceManager& sources, DiagnosticEngine& diags)
    : options_(options), sources_(sources), diags_(diags) {
  for (const auto& [name, value] : options.args) args_[name] = value;
}

void Expander::Fail(Loc at, std::string message, DiagKind kind) {
  diags_.Report(kind, at, std::move(message));
  throw ExpansionFailed{};
}

void Expander::Warn(Loc at, std::string message) {
  diags_.Report(DiagKind::XacroWarning, at, std::move(message));
}

void Expander::WarnIfGlobal(std::string_view name, Loc at) {
  if (pyexpr::StandardGlobals().Find(name) || name == "xacro") {
    Warn(at, fmt::format("'{}' is defined again here, hiding the global of that name", name));
  }
}

void Expander::CountNode() {
  if (expansion_->tree.size() > sources_.limits().expansion_nodes) {
    Fail(here_,
         fmt::format("the expansion makes more than {} nodes, the expansion-nodes limit "
                     "(raise it with --limit expansion-nodes=N)",
                     sources_.limits().expansion_nodes),
         DiagKind::LimitExceeded);
  }
}

void Expander::NoteDependency(const std::string& path) {
  if (dependency_seen_.insert(path).second) expansion_->dependencies.push_back(path);
}

std::string Expander::CurrentFile() const {
  return file_stack_.empty() ? std::string() : file_stack_.back();
}

std::string Expander::AbsoluteFilename(std::string_view spec) const {
  std::filesystem::path path(spec);
  if (path.is_absolute()) return std::string(spec);
  const std::string current = CurrentFile();
  const std::filesystem::path base =
      current.empty() ? std::filesystem::path(".") : std::filesystem::path(current).parent_path();
  return (base / path).string();
}

std::unique_ptr<Expansion> Expander::Run(FileId file) {
  expansion_ = std::make_unique<Expansion>();
  expansion_->file = file;
  file_stack_.push_back(sources_.Path(file));
  std::error_code ec;
  open_files_.push_back(std::filesystem::weakly_canonical(sources_.Path(file), ec).string());
  XacroNamespace();
  try {
    Node* root = ReadBuffer(file);
    expansion_->root = root;
    empty_text_ = expansion_->tree.Make(Node::Kind::kText);
    empty_text_->text = "\n\n";
    scopes_.push_back(std::make_unique<SymbolTable>(nullptr));
    macro_scopes_.push_back(std::make_unique<MacroTable>());
    // xacro:targetNamespace becomes the document's default namespace
    if (const Attribute* target = root->FindAttribute("xacro:targetNamespace")) {
      const std::string uri = target->value;
      const Loc at = target->loc;
      root->RemoveAttribute("xacro:targetNamespace");
      root->SetAttribute("xmlns", uri, at);
    }
    EvalAll(root, *macro_scopes_.back(), *scopes_.back());
  } catch (const ExpansionFailed&) {
    return nullptr;
  }
  return std::move(expansion_);
}

// ---- the walk ----------------------------------------------------------------------

void Expander::EvalAttributes(Node* node, SymbolTable& symbols) {
  for (size_t i = 0; i < node->attributes.size();) {
    Attribute& a = node->attributes[i];
    if (a.name.starts_with(kPrefix)) {
      node->attributes.erase(node->attributes.begin() + static_cast<ptrdiff_t>(i));
      continue;
    }
    here_ = a.loc;
    std::string value = EvalString(a.value, symbols, a.loc);
    node->attributes[i].value = std::move(value);
    ++i;
  }
  node->RemoveAttribute("xmlns:xacro");
}

void Expander::EvalAll(Node* node, MacroTable& macros, SymbolTable& symbols) {
  EvalAttributes(node, symbols);
  bool eval_comments = false;
  Node* child = node->first_child();
  while (child) {
    Node* next = child->next();
    here_ = child->loc;
    switch (child->kind) {
      case Node::Kind::kElement: {
        eval_comments = false;
        if (IsXacroTag(*child, "insert_block")) {
          InsertBlock(child, macros, symbols);
        } else if (IsXacroTag(*child, "include")) {
          Include(child, macros, symbols);
        } else if (IsXacroTag(*child, "property")) {
          GrabProperty(child, symbols);
        } else if (IsXacroTag(*child, "macro")) {
          GrabMacro(child, macros);
        } else if (IsXacroTag(*child, "arg")) {
          DefineArg(child, symbols);
        } else if (IsXacroTag(*child, "element")) {
          const Attribute* name = child->FindAttribute("xacro:name");
          if (!name) Fail(child->loc, "<xacro:element> needs a 'xacro:name' attribute");
          std::string tag = EvalString(name->value, symbols, name->loc);
          if (tag.empty()) Fail(name->loc, "<xacro:element> names an empty element");
          child->RemoveAttribute("xacro:name");
          child->name = std::move(tag);
          continue;  // the element is walked again under its new name
        } else if (IsXacroTag(*child, "attribute")) {
          CheckAttributes(child, {"name", "value"}, {});
          const Attribute* name = child->FindAttribute("name");
          const Attribute* value = child->FindAttribute("value");
          std::string attribute = EvalString(name->value, symbols, name->loc);
          if (attribute.empty()) Fail(name->loc, "<xacro:attribute> names an empty attribute");
          std::string text = EvalString(value->value, symbols, value->loc);
          node->SetAttribute(attribute, std::move(text), value->loc);
          expansion_->tree.Replace(child, nullptr, false);
        } else if (IsXacroTag(*child, "if") || IsXacroTag(*child, "unless")) {
          Conditional(child, macros, symbols);
        } else if (!CallMacro(child, macros, symbols)) {
          EvalAll(child, macros, symbols);
        }
        break;
      }
      case Node::Kind::kText: {
        if (child != empty_text_) {
          child->text = EvalString(child->text, symbols, child->loc);
          if (child->text.find_first_not_of(" \t\r\n") != std::string::npos) eval_comments = false;
        }
        break;
      }
      case Node::Kind::kComment: {
        if (child->text.find("xacro:eval-comments") != std::string::npos) {
          eval_comments = child->text.find("xacro:eval-comments:off") == std::string::npos;
          expansion_->tree.Replace(child, nullptr, false);
        } else if (eval_comments) {
          child->text = EvalString(child->text, symbols, child->loc);
        }
        break;
      }
      case Node::Kind::kCdata:
        break;
    }
    child = next;
  }
}

std::vector<const Attribute*> Expander::CheckAttributes(
    Node* node, std::initializer_list<std::string_view> required,
    std::initializer_list<std::string_view> optional) {
  std::vector<const Attribute*> found;
  for (std::string_view name : required) {
    const Attribute* a = node->FindAttribute(name);
    if (!a) Fail(node->loc, fmt::format("<{}> needs a '{}' attribute", node->name, name));
    found.push_back(a);
  }
  for (std::string_view name : optional) found.push_back(node->FindAttribute(name));
  for (const Attribute& a : node->attributes) {
    if (a.name.starts_with("xmlns:")) continue;
    const bool known = std::find(required.begin(), required.end(), a.name) != required.end() ||
                       std::find(optional.begin(), optional.end(), a.name) != optional.end();
    if (!known) {
      Warn(a.loc, fmt::format("<{}> has no attribute '{}'; it is ignored", node->name, a.name));
    }
  }
  return found;
}

void Expander::RemovePreviousComments(Node* node) {
  Node* next = node->next();
  Node* previous = node->previous();
  while (previous) {
    if (IsBlankWithAtMostOneNewline(*previous)) previous = previous->previous();
    if (previous && previous->kind == Node::Kind::kComment) {
      Node* comment = previous;
      previous = previous->previous();
      expansion_->tree.Unlink(comment);
    } else {
      // xacro's single blank node moves here, and stops the next removal
      // from reaching further back
      if (next && next != empty_text_) expansion_->tree.InsertBefore(next, empty_text_);
      return;
    }
  }
}

void Expander::LiftNamespaces(Node* to, const Node& from) {
  if (!to) return;
  for (const Attribute& a : from.attributes) {
    if (!a.name.starts_with("xmlns:")) continue;
    const Attribute* old = to->FindAttribute(a.name);
    if (old && old->value != a.value) {
      Warn(a.loc, fmt::format("namespace prefix '{}' is declared again as '{}'; the first "
                              "declaration, '{}', is kept",
                              a.name.substr(6), a.value, old->value));
    } else {
      to->SetAttribute(a.name, a.value, a.loc);
    }
  }
}

void Expander::InsertBlock(Node* node, MacroTable& macros, SymbolTable& symbols) {
  const auto attributes = CheckAttributes(node, {"name"}, {});
  const std::string& name = attributes[0]->value;
  Symbol* block = symbols.Find("**" + name).first;
  bool content_only = true;
  if (!block) {
    block = symbols.Find("*" + name).first;
    content_only = false;
  }
  if (!block || !block->block) {
    Fail(attributes[0]->loc, fmt::format("no block parameter named '{}' is in scope", name));
  }
  Node* copy = expansion_->tree.Clone(*block->block);
  CountNode();
  // the copy is evaluated again here, as xacro does
  EvalAll(copy, macros, symbols);
  expansion_->tree.Replace(node, copy, content_only);
}

void Expander::GrabProperty(Node* node, SymbolTable& symbols) {
  RemovePreviousComments(node);
  const auto a = CheckAttributes(node, {"name"}, {"value", "default", "remove", "scope", "lazy_eval"});
  const Attribute *value = a[1], *default_value = a[2], *remove = a[3], *scope = a[4],
                  *lazy = a[5];
  std::string name = EvalString(a[0]->value, symbols, a[0]->loc);
  if (!IsValidName(name)) {
    Fail(a[0]->loc, fmt::format("property name '{}' is not a valid Python identifier", name));
  }
  if (name.starts_with("__")) {
    Fail(a[0]->loc, fmt::format("property name '{}' starts with a double underscore", name));
  }
  bool removing = false;
  if (remove) {
    removing = ConditionValue(EvalText(remove->value, symbols, remove->loc), remove->value,
                              remove->loc);
  }
  if ((value != nullptr) + (default_value != nullptr) + removing > 1) {
    Fail(node->loc, fmt::format("property '{}' may have only one of 'value', 'default' and "
                                "'remove'",
                                name));
  }
  const bool defined = symbols.Find(name).first != nullptr || pyexpr::StandardGlobals().Find(name) ||
                       name == "xacro";
  if (removing) {
    if (defined) symbols.Remove(name);
    expansion_->tree.Replace(node, nullptr, false);
    return;
  }
  std::optional<std::string> text;
  if (value) text = value->value;
  if (default_value) {
    if (scope) Warn(scope->loc, fmt::format("property '{}': a default is set in the local scope "
                                            "only; 'scope' is ignored",
                                            name));
    if (defined) {
      expansion_->tree.Replace(node, nullptr, false);
      return;
    }
    text = default_value->value;
  }
  expansion_->tree.Replace(node, nullptr, false);

  bool lazy_eval = true;
  if (lazy) lazy_eval = ConditionValue(EvalText(lazy->value, symbols, lazy->loc), lazy->value,
                                       lazy->loc);
  SymbolTable* target = &symbols;
  if (scope && scope->value == "global") {
    target = symbols.Top();
    lazy_eval = false;
  } else if (scope && scope->value == "parent") {
    if (!symbols.parent()) {
      Warn(scope->loc, fmt::format("property '{}' has scope=\"parent\" at the top scope, which "
                                   "has no parent; it is not set",
                                   name));
      return;
    }
    target = symbols.parent();
    lazy_eval = false;
    if (!symbols.is_namespace()) {
      while (target->is_namespace() && target->parent()) target = target->parent();
    }
  }
  WarnIfGlobal(name, a[0]->loc);

  Symbol symbol;
  symbol.defined_at = node->loc;
  if (!text) {
    // a block property: its content, inserted with <xacro:insert_block>
    symbol.kind = Symbol::Kind::kContentBlock;
    symbol.block = node;
    target->Set("**" + name, std::move(symbol));
    return;
  }
  const Loc at = value ? value->loc : default_value->loc;
  pyexpr::Value literal = lazy_eval ? LiteralValue(*text)
                                    : LiteralValue(EvalText(*text, symbols, at));
  if (lazy_eval && literal.IsStr()) {
    symbol.kind = Symbol::Kind::kUnevaluated;
    symbol.text = literal.AsStr();
    symbol.defined_at = at;
  } else {
    symbol.value = std::move(literal);
  }
  target->Set(name, std::move(symbol));
}

void Expander::GrabMacro(Node* node, MacroTable& macros) {
  RemovePreviousComments(node);
  const auto a = CheckAttributes(node, {"name"}, {"params"});
  std::string name = a[0]->value;
  if (name == "call") Fail(a[0]->loc, "a macro may not be named 'call'");
  if (name.find('.') != std::string::npos) {
    Fail(a[0]->loc, fmt::format("macro name '{}' holds a '.', which separates namespaces", name));
  }
  if (name.starts_with(kPrefix)) {
    Warn(a[0]->loc, fmt::format("macro name '{}' starts with 'xacro:'; the prefix is dropped",
                                name));
    name = name.substr(kPrefix.size());
  }
  auto macro = std::make_shared<Macro>();
  macro->name = name;
  macro->body = node;
  macro->defined_at = node->loc;
  if (a[1]) {
    std::string_view rest = a[1]->value;
    while (!rest.empty() && rest.find_first_not_of(" \t\n\r") != std::string_view::npos) {
      MacroParam param = NextMacroParam(rest);
      macro->params.push_back(param.name);
      if (param.has_default) {
        macro->defaults[param.name] = Macro::Default{param.forward, param.default_text};
      }
    }
  }
  macros.Define(std::move(macro));
  expansion_->tree.Replace(node, nullptr, false);
}

void Expander::DefineArg(Node* node, SymbolTable& symbols) {
  const auto a = CheckAttributes(node, {"name", "default"}, {});
  const std::string& name = a[0]->value;
  if (!args_.contains(name)) args_[name] = EvalString(a[1]->value, symbols, a[1]->loc);
  RemovePreviousComments(node);
  expansion_->tree.Replace(node, nullptr, false);
}

bool Expander::ConditionValue(const pyexpr::Value& value, std::string_view written, Loc at) {
  if (!value.IsStr()) return pyexpr::Truthy(value);
  const std::string& s = value.AsStr();
  if (s == "true" || s == "True") return true;
  if (s == "false" || s == "False") return false;
  if (auto i = pyexpr::ParsePythonInt(s)) return *i != 0;
  Fail(at, fmt::format("condition '{}' is '{}', which is not a boolean: write true, false, 1 "
                       "or 0",
                       written, s));
}

void Expander::Conditional(Node* node, MacroTable& macros, SymbolTable& symbols) {
  RemovePreviousComments(node);
  const auto a = CheckAttributes(node, {"value"}, {});
  bool keep = ConditionValue(EvalText(a[0]->value, symbols, a[0]->loc), a[0]->value, a[0]->loc);
  if (IsXacroTag(*node, "unless")) keep = !keep;
  if (keep) {
    EvalAll(node, macros, symbols);
    expansion_->tree.Replace(node, node, true);
  } else {
    expansion_->tree.Replace(node, nullptr, false);
  }
}

bool Expander::CallMacro(Node* node, MacroTable& macros, SymbolTable& symbols) {
  if (IsXacroTag(*node, "call")) {
    const Attribute* target = node->FindAttribute("macro");
    if (!target || target->value.empty()) {
      Fail(node->loc, "<xacro:call> needs a 'macro' attribute naming the macro to call");
    }
    std::string name = EvalString(target->value, symbols, target->loc);
    node->RemoveAttribute("macro");
    node->name = std::string(kPrefix) + name;
  } else if (!node->name.starts_with(kPrefix)) {
    return false;
  }
  const std::string_view full = std::string_view(node->name).substr(kPrefix.size());
  MacroTable* in_macros = &macros;
  SymbolTable* in_symbols = &symbols;
  const Macro* macro = macros.Find(full);
  if (!macro) {
    // ns.name: a macro of a namespace an include made
    size_t dot = full.rfind('.');
    if (dot != std::string_view::npos) {
      size_t start = 0;
      bool found = true;
      while (start < dot) {
        size_t end = full.find('.', start);
        const std::string_view space = full.substr(start, end - start);
        MacroTable* next_macros = in_macros->FindNamespace(space);
        auto [symbol, owner] = in_symbols->Find(space);
        if (!next_macros || !symbol || symbol->kind != Symbol::Kind::kNamespace) {
          found = false;
          break;
        }
        in_macros = next_macros;
        in_symbols = symbol->space;
        start = end + 1;
      }
      if (found) macro = in_macros->Find(full.substr(dot + 1));
    }
  }
  if (!macro) {
    std::vector<std::string> names;
    macros.CollectNames(names);
    std::string message = fmt::format("no macro named '{}' is defined", full);
    const std::vector<std::string_view> candidates(names.begin(), names.end());
    if (auto best = ir::ClosestName(full, candidates)) {
      message += fmt::format("; did you mean '{}'?", *best);
    }
    Fail(node->loc, message);
  }
  ExpandMacro(node, *macro, *in_macros, *in_symbols);
  return true;
}

void Expander::ExpandMacro(Node* node, const Macro& macro, MacroTable& macros,
                           SymbolTable& symbols) {
  if (macro_stack_.size() >= sources_.limits().macro_depth) {
    Fail(node->loc,
         fmt::format("macro '{}' is called {} macro calls deep, over the macro-depth limit of {} "
                     "(raise it with --limit macro-depth=N)",
                     macro.name, macro_stack_.size() + 1, sources_.limits().macro_depth),
         DiagKind::LimitExceeded);
  }
  macro_stack_.push_back(&macro);
  const Loc call_at = node->loc;
  scopes_.push_back(std::make_unique<SymbolTable>(&symbols));
  SymbolTable& scoped = *scopes_.back();
  macro_scopes_.push_back(std::make_unique<MacroTable>(&macros));
  MacroTable& scoped_macros = *macro_scopes_.back();

  std::vector<std::string> params = macro.params;
  for (Attribute& a : node->attributes) {
    auto it = std::find(params.begin(), params.end(), a.name);
    if (it == params.end()) {
      std::string message = fmt::format("macro '{}' has no parameter '{}'", macro.name, a.name);
      Fail(a.loc, message);
    }
    params.erase(it);
    here_ = a.loc;
    Symbol symbol;
    symbol.value = LiteralValue(EvalText(a.value, symbols, a.loc));
    symbol.defined_at = a.loc;
    WarnIfGlobal(a.name, a.loc);
    scoped.Set(a.name, std::move(symbol));
    a.value.clear();  // not evaluated again below
  }
  // the blocks are evaluated in the caller's scope first
  EvalAll(node, macros, symbols);
  Node* block = node->FirstElementChild();
  for (auto it = params.begin(); it != params.end();) {
    if ((*it)[0] != '*') {
      ++it;
      continue;
    }
    if (!block) {
      Fail(call_at, fmt::format("macro '{}' takes block parameter '{}', and the call gives no "
                                "element for it",
                                macro.name, *it));
    }
    Symbol symbol;
    symbol.kind = it->starts_with("**") ? Symbol::Kind::kContentBlock : Symbol::Kind::kBlock;
    symbol.block = block;
    symbol.defined_at = block->loc;
    scoped.Set(*it, std::move(symbol));
    block = block->NextElementSibling();
    it = params.erase(it);
  }
  if (block) {
    Fail(block->loc, fmt::format("the call of macro '{}' has an element <{}> that no block "
                                 "parameter takes",
                                 macro.name, block->name));
  }
  for (auto it = params.begin(); it != params.end();) {
    auto d = macro.defaults.find(*it);
    // `p:=` with nothing after it is no default at all, as in xacro
    if ((*it)[0] == '*' || d == macro.defaults.end() ||
        (!d->second.forward && !d->second.text)) {
      ++it;
      continue;
    }
    const Macro::Default& def = d->second;
    Symbol symbol;
    symbol.defined_at = macro.defined_at;
    if (def.forward) {
      auto found = LookupName(*def.forward, symbols);
      if (found.ok() && found.value()) {
        symbol.value = LiteralValue(**found);
      } else if (def.text) {
        symbol.value = LiteralValue(EvalText(*def.text, symbols, call_at));
      } else {
        Fail(call_at, fmt::format("macro '{}' forwards parameter '{}' from the caller's property "
                                  "'{}', which is not defined",
                                  macro.name, *it, *def.forward));
      }
    } else {
      symbol.value = LiteralValue(EvalText(*def.text, symbols, call_at));
    }
    scoped.Set(*it, std::move(symbol));
    it = params.erase(it);
  }
  if (!params.empty()) {
    std::string list;
    for (const std::string& p : params) list += (list.empty() ? "'" : ", '") + p + "'";
    Fail(call_at, fmt::format("the call of macro '{}' gives no value for {} {}", macro.name,
                              params.size() == 1 ? "parameter" : "parameters", list));
  }

  // the body, placed in an expansion of its file, so diagnostics can say
  // which call made it
  std::map<uint32_t, FileId> expansion_files;
  const std::string note = fmt::format("in expansion of macro '{}'", macro.name);
  Node* body = expansion_->tree.Clone(*macro.body, [&](Loc loc) {
    if (!loc.valid()) return loc;
    auto [it, inserted] = expansion_files.try_emplace(loc.file.value);
    if (inserted) it->second = sources_.AddExpansion(loc.file, call_at, note);
    return Loc{it->second, loc.line, loc.column};
  });
  CountNode();
  EvalAll(body, scoped_macros, scoped);
  RemovePreviousComments(node);
  LiftNamespaces(node->parent(), *body);
  expansion_->tree.Replace(node, body, true);
  macro_stack_.pop_back();
}

}  // namespace mdlc::xacro
