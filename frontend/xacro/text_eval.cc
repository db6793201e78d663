// text_eval.cc - xacro text: `${...}` expressions, `$(...)` substitution
// arguments and `$$` escapes, and the names expressions see.
#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>

#include "ir/assets/package_map.h"
#include "frontend/pyexpr/builtins.h"
#include "frontend/pyexpr/number_text.h"
#include "frontend/pyexpr/yaml_values.h"
#include "frontend/xacro/expander.h"
#include "ir/scoped_name.h"

namespace mdlc::xacro {

// Bare names in an expression: the property tables, innermost first, then
// the xacro namespace; pyexpr falls back on Python's builtins and math.
class ExpressionScope : public pyexpr::Scope {
 public:
  ExpressionScope(Expander& expander, SymbolTable& symbols)
      : expander_(expander), symbols_(symbols) {}
  pyexpr::Result<std::optional<pyexpr::Value>> Lookup(std::string_view name) override {
    return expander_.LookupName(name, symbols_);
  }

 private:
  Expander& expander_;
  SymbolTable& symbols_;
};

namespace {

enum class PieceKind { kText, kExpression, kSubstitution, kEscape };
struct Piece {
  PieceKind kind;
  std::string_view text;  // the inside of ${...} or $(...); the text otherwise
};

// Cuts xacro text as xacro's lexer does: `$$` before `{` or `(` is one `$`
// of text, `${` runs to the first `}`, `$(` to the first `)`. Returns the
// offset of text it cannot cut (a `${` never closed), or npos.
size_t CutPieces(std::string_view text, std::vector<Piece>& pieces) {
  size_t i = 0;
  while (i < text.size()) {
    if (text[i] != '$') {
      const size_t end = text.find('$', i);
      const size_t stop = end == std::string_view::npos ? text.size() : end;
      pieces.push_back({PieceKind::kText, text.substr(i, stop - i)});
      i = stop;
      continue;
    }
    // a run of '$'s followed by '{' or '(': drop one '$'
    size_t run = i;
    while (run < text.size() && text[run] == '$') ++run;
    if (run - i >= 2 && run < text.size() && (text[run] == '{' || text[run] == '(')) {
      pieces.push_back({PieceKind::kEscape, text.substr(i + 1, run + 1 - (i + 1))});
      i = run + 1;
      continue;
    }
    if (i + 1 < text.size() && (text[i + 1] == '{' || text[i + 1] == '(')) {
      const char close = text[i + 1] == '{' ? '}' : ')';
      const size_t end = text.find(close, i + 2);
      if (end == std::string_view::npos) return i;
      pieces.push_back({close == '}' ? PieceKind::kExpression : PieceKind::kSubstitution,
                        text.substr(i + 2, end - (i + 2))});
      i = end + 1;
      continue;
    }
    // '$' then text up to the next '$', '{' or '(' ... as xacro's TEXT rule
    if (i + 1 == text.size()) {
      pieces.push_back({PieceKind::kText, text.substr(i, 1)});
      ++i;
      continue;
    }
    size_t j = i + 1;
    while (j < text.size() && text[j] != '{' && text[j] != '(' && text[j] != '$') ++j;
    if (j == i + 1) return i;  // "$$" not before '{' or '(': xacro cannot read it either
    pieces.push_back({PieceKind::kText, text.substr(i, j - i)});
    i = j;
  }
  return std::string_view::npos;
}

}  // namespace

pyexpr::Value Expander::EvalText(std::string_view text, SymbolTable& scope, Loc at) {
  std::vector<Piece> pieces;
  const size_t bad = CutPieces(text, pieces);
  if (bad != std::string_view::npos) {
    Fail(at, fmt::format("'{}' opens an expression that is never closed",
                         text.substr(bad, std::min<size_t>(40, text.size() - bad))));
  }
  std::vector<pyexpr::Value> values;
  values.reserve(pieces.size());
  for (const Piece& piece : pieces) {
    switch (piece.kind) {
      case PieceKind::kText:
      case PieceKind::kEscape:
        values.push_back(pyexpr::Value::Str(std::string(piece.text)));
        break;
      case PieceKind::kExpression: {
        // `$(...)` inside an expression is substituted first
        const std::string expression = EvalString(piece.text, scope, at);
        ExpressionScope names(*this, scope);
        pyexpr::Result<pyexpr::Value> result = EvaluateExpression(expression, names);
        if (!result.ok()) {
          const pyexpr::Error& e = result.error();
          std::string message = fmt::format("in '${{{}}}': {}", piece.text, e.message);
          if (e.kind == pyexpr::Error::Kind::kName && !e.missing_name.empty()) {
            message += DidYouMean(e.missing_name, scope);
          }
          if (e.kind == pyexpr::Error::Kind::kHost && e.fatal) {
            message = e.message;
          }
          Fail(at, message);
        }
        values.push_back(std::move(result.value()));
        break;
      }
      case PieceKind::kSubstitution: {
        const std::string body = EvalString(piece.text, scope, at);
        values.push_back(pyexpr::Value::Str(Substitute(body, scope, at)));
        break;
      }
    }
  }
  if (values.size() == 1) return std::move(values[0]);
  std::string joined;
  for (const pyexpr::Value& v : values) joined += pyexpr::Str(v);
  return pyexpr::Value::Str(std::move(joined));
}

pyexpr::Result<pyexpr::Value> Expander::EvaluateExpression(const std::string& expression,
                                                          pyexpr::Scope& names) {
  auto cached = parsed_.find(expression);
  if (cached == parsed_.end()) {
    auto parsed = pyexpr::ParseExpression(expression);
    if (!parsed.ok()) return parsed.error();
    cached = parsed_.emplace(expression, std::move(parsed.value())).first;
  }
  return pyexpr::Evaluate(*cached->second, names);
}

std::string Expander::EvalString(std::string_view text, SymbolTable& scope, Loc at) {
  // most text holds no '$' at all
  if (text.find('$') == std::string_view::npos) return std::string(text);
  pyexpr::Value v = EvalText(text, scope, at);
  return v.IsStr() ? v.AsStr() : pyexpr::Str(v);
}

std::string Expander::DidYouMean(std::string_view name, SymbolTable& scope) const {
  std::vector<std::string> names;
  scope.CollectNames(names);
  const std::vector<std::string_view> candidates(names.begin(), names.end());
  if (auto best = ir::ClosestName(name, candidates)) {
    return fmt::format("; did you mean '{}'?", *best);
  }
  return {};
}

pyexpr::Result<std::optional<pyexpr::Value>> Expander::LookupName(std::string_view name,
                                                                  SymbolTable& scope) {
  auto [symbol, owner] = scope.Find(name);
  if (!symbol) {
    if (name == "xacro") return std::optional<pyexpr::Value>(xacro_namespace_value_);
    // names xacro still reads bare but deprecated: its own functions, and
    // two Python builtins it moved to python.
    if (name == "load_yaml" || name == "abs_filename" || name == "dotify" ||
        name == "sorted" || name == "range") {
      const bool xacro_function = name[0] != 's' && name[0] != 'r';
      if (deprecated_warned_.try_emplace(std::string(name), true).second) {
        Warn(here_, fmt::format("'{}' alone is deprecated; use {}.{}", name,
                                xacro_function ? "xacro" : "python", name));
      }
      if (xacro_function) {
        if (const pyexpr::Value* v = XacroNamespace().Find(name)) {
          return std::optional<pyexpr::Value>(*v);
        }
      }
    }
    return std::optional<pyexpr::Value>();
  }
  switch (symbol->kind) {
    case Symbol::Kind::kValue:
      return std::optional<pyexpr::Value>(symbol->value);
    case Symbol::Kind::kUnevaluated: {
      auto& resolving = owner->resolving();
      const std::string key(name);
      if (std::find(resolving.begin(), resolving.end(), key) != resolving.end()) {
        std::string chain;
        for (const std::string& r : resolving) chain += r + " -> ";
        Fail(symbol->defined_at,
             fmt::format("property '{}' is defined in terms of itself: {}{} (set "
                         "lazy_eval=\"false\" to evaluate it where it is defined)",
                         key, chain, key));
      }
      resolving.push_back(key);
      const std::string text = symbol->text;
      const Loc at = symbol->defined_at;
      pyexpr::Value value = LiteralValue(EvalText(text, *owner, at));
      resolving.pop_back();
      // the table may have changed while evaluating; find the entry again
      if (Symbol* again = owner->FindHere(name); again && again->kind == Symbol::Kind::kUnevaluated) {
        again->kind = Symbol::Kind::kValue;
        again->value = value;
        again->text.clear();
      }
      return std::optional<pyexpr::Value>(std::move(value));
    }
    case Symbol::Kind::kBlock:
    case Symbol::Kind::kContentBlock:
      return std::optional<pyexpr::Value>(pyexpr::Value::Str(symbol->block->name));
    case Symbol::Kind::kNamespace: {
      auto table = std::make_shared<pyexpr::NameTable>();
      std::vector<std::string> names;
      // what the included file defined (a name it does not define is
      // looked up no further: ns.x names the namespace's own x)
      symbol->space->CollectOwnNames(names);
      for (const std::string& n : names) {
        auto v = LookupName(n, *symbol->space);
        if (v.ok() && v.value()) table->Set(n, **v);
      }
      return std::optional<pyexpr::Value>(pyexpr::Value::Namespace(std::string(name), table));
    }
  }
  return std::optional<pyexpr::Value>();
}

// ---- $(...) -------------------------------------------------------------------------

std::string Expander::FindPackage(std::string_view package, Loc at) {
  if (options_.packages) {
    if (const auto* found = options_.packages->Find(package)) {
      return std::filesystem::absolute(found->path).lexically_normal().string();
    }
  }
  Fail(at, fmt::format("$(find {}): no package named '{}' is known (add it with --package "
                       "{}=DIR, --package-path, ROS_PACKAGE_PATH or AMENT_PREFIX_PATH)",
                       package, package, package));
}

std::string Expander::Substitute(std::string_view body, SymbolTable& scope, Loc at) {
  if (body == "cwd") return std::filesystem::current_path().string();
  if (body.starts_with("eval ")) return EvalSubstitutionExpression(body.substr(5), at);
  std::vector<std::string> words;
  for (size_t i = 0; i < body.size();) {
    const size_t start = body.find_first_not_of(' ', i);
    if (start == std::string_view::npos) break;
    const size_t end = body.find(' ', start);
    words.emplace_back(body.substr(start, end == std::string_view::npos ? end : end - start));
    i = end == std::string_view::npos ? body.size() : end;
  }
  if (words.empty()) Fail(at, "'$()' names no substitution");
  const std::string& command = words[0];
  auto expect = [&](size_t n) {
    if (words.size() != n + 1) {
      Fail(at, fmt::format("$({}) takes {} argument{}, and '$({})' gives {}", command, n,
                           n == 1 ? "" : "s", body, words.size() - 1));
    }
  };
  if (command == "arg") {
    expect(1);
    auto it = args_.find(words[1]);
    if (it == args_.end()) {
      std::vector<std::string_view> names;
      for (const auto& [name, value] : args_) names.push_back(name);
      std::string message = fmt::format("$(arg {}): no argument named '{}' is given or declared "
                                        "with <xacro:arg> before this point",
                                        words[1], words[1]);
      if (auto best = ir::ClosestName(words[1], names)) {
        message += fmt::format("; did you mean '{}'?", *best);
      }
      Fail(at, message);
    }
    // what an argument holds may itself name a package
    std::string value = it->second;
    if (value.find("$(find ") != std::string::npos) value = EvalString(value, scope, at);
    return value;
  }
  if (command == "find") {
    expect(1);
    return FindPackage(words[1], at);
  }
  if (command == "env") {
    expect(1);
    const char* value = std::getenv(words[1].c_str());
    if (!value) Fail(at, fmt::format("$(env {}): the environment variable is not set", words[1]));
    return value;
  }
  if (command == "optenv") {
    if (words.size() < 2) Fail(at, "$(optenv) needs the name of an environment variable");
    if (const char* value = std::getenv(words[1].c_str())) return value;
    std::string fallback;
    for (size_t i = 2; i < words.size(); ++i) fallback += (i > 2 ? " " : "") + words[i];
    return fallback;
  }
  if (command == "dirname") {
    // the folder of the file being read (ros/xacro 2 has no file name to
    // give and fails; ROS 1's xacro and roslaunch answer this)
    const std::filesystem::path folder = std::filesystem::path(CurrentFile()).parent_path();
    return (folder.empty() ? std::filesystem::current_path()
                           : std::filesystem::absolute(folder).lexically_normal())
        .string();
  }
  Fail(at, fmt::format("'$({})': unknown substitution '{}'; xacro knows arg, find, env, optenv, "
                       "eval, dirname and cwd",
                       body, command));
}

namespace {

// the names of $(eval ...): arguments read as numbers or bools where they
// look like them, and a few functions
class SubstitutionScope : public pyexpr::Scope {
 public:
  SubstitutionScope(const std::map<std::string, std::string, std::less<>>& args,
                    const pyexpr::NameTable& functions)
      : args_(args), functions_(functions) {}
  pyexpr::Result<std::optional<pyexpr::Value>> Lookup(std::string_view name) override {
    if (const pyexpr::Value* f = functions_.Find(name)) return std::optional<pyexpr::Value>(*f);
    auto it = args_.find(name);
    if (it == args_.end()) return std::optional<pyexpr::Value>();
    return std::optional<pyexpr::Value>(AutoValue(it->second));
  }
  static pyexpr::Value AutoValue(const std::string& text) {
    if (text.find('.') != std::string::npos) {
      if (auto f = pyexpr::ParsePythonFloat(text)) return pyexpr::Value::Float(*f);
    } else if (auto i = pyexpr::ParsePythonInt(text)) {
      return pyexpr::Value::Int(*i);
    }
    std::string lower;
    for (char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower == "true") return pyexpr::Value::Bool(true);
    if (lower == "false") return pyexpr::Value::Bool(false);
    return pyexpr::Value::Str(text);
  }

 private:
  const std::map<std::string, std::string, std::less<>>& args_;
  const pyexpr::NameTable& functions_;
};

}  // namespace

std::string Expander::EvalSubstitutionExpression(std::string_view expression, Loc at) {
  if (expression.find("__") != std::string_view::npos) {
    Fail(at, "$(eval ...) may not name anything with a double underscore");
  }
  pyexpr::NameTable functions;
  functions.Set("true", pyexpr::Value::Bool(true));
  functions.Set("false", pyexpr::Value::Bool(false));
  functions.Set("arg", pyexpr::Value::Function(
                           "arg", [this](std::span<const pyexpr::Value> positional,
                                         std::span<const std::pair<std::string, pyexpr::Value>>)
                                      -> pyexpr::Result<pyexpr::Value> {
                             if (positional.size() != 1 || !positional[0].IsStr()) {
                               return pyexpr::Error{pyexpr::Error::Kind::kType,
                                                    "arg() takes the name of one argument"};
                             }
                             auto it = args_.find(positional[0].AsStr());
                             if (it == args_.end()) {
                               pyexpr::Error e{pyexpr::Error::Kind::kName,
                                               fmt::format("no argument named '{}'",
                                                           positional[0].AsStr())};
                               return e;
                             }
                             return SubstitutionScope::AutoValue(it->second);
                           }));
  SubstitutionScope scope(args_, functions);
  pyexpr::Result<pyexpr::Value> result = pyexpr::Evaluate(expression, scope);
  if (!result.ok()) Fail(at, fmt::format("in '$(eval {})': {}", expression, result.error().message));
  return pyexpr::Str(result.value());
}

// ---- the xacro namespace ------------------------------------------------------------

pyexpr::Result<pyexpr::Value> Expander::LoadYaml(const std::string& filename) {
  const std::string path = AbsoluteFilename(filename);
  // a model loads the same file in every call of a macro: read it once
  // (values are never changed in place, so one may be shared)
  if (auto cached = yaml_values_.find(path); cached != yaml_values_.end()) {
    return cached->second;
  }
  LoadError error;
  std::optional<FileId> file = sources_.LoadFile(path, here_, &error);
  if (!file) {
    return pyexpr::Error{pyexpr::Error::Kind::kHost,
                         fmt::format("xacro.load_yaml cannot read '{}': {}", path, error.message)};
  }
  NoteDependency(path);
  pyexpr::Result<pyexpr::Value> value = pyexpr::LoadYaml(sources_.Contents(*file));
  if (value.ok()) yaml_values_.emplace(path, value.value());
  return value;
}

const pyexpr::NameTable& Expander::XacroNamespace() {
  if (xacro_namespace_) return *xacro_namespace_;
  using Positional = std::span<const pyexpr::Value>;
  using Keywords = std::span<const std::pair<std::string, pyexpr::Value>>;
  using pyexpr::Error;
  using pyexpr::Value;
  auto table = std::make_unique<pyexpr::NameTable>();
  auto one_string = [](std::string_view function, Positional positional) -> std::optional<Error> {
    if (positional.size() != 1 || !positional[0].IsStr()) {
      return Error{Error::Kind::kType, fmt::format("{}() takes one string", function)};
    }
    return std::nullopt;
  };
  table->Set("load_yaml", Value::Function("load_yaml", [this, one_string](Positional p, Keywords)
                                                           -> pyexpr::Result<Value> {
               if (auto e = one_string("load_yaml", p)) return *e;
               return LoadYaml(p[0].AsStr());
             }));
  table->Set("abs_filename",
             Value::Function("abs_filename",
                             [this, one_string](Positional p, Keywords) -> pyexpr::Result<Value> {
                               if (auto e = one_string("abs_filename", p)) return *e;
                               return Value::Str(AbsoluteFilename(p[0].AsStr()));
                             }));
  table->Set("dotify", Value::Function("dotify", [](Positional p, Keywords) -> pyexpr::Result<Value> {
               if (p.size() != 1) return Error{Error::Kind::kType, "dotify() takes one dict"};
               return pyexpr::Dotify(p[0]);
             }));
  table->Set("arg", Value::Function("arg", [this, one_string](Positional p, Keywords)
                                                -> pyexpr::Result<Value> {
               if (auto e = one_string("arg", p)) return *e;
               auto it = args_.find(p[0].AsStr());
               if (it == args_.end()) {
                 Error e{Error::Kind::kKey, fmt::format("no argument named '{}'", p[0].AsStr())};
                 e.missing_name = p[0].AsStr();
                 return e;
               }
               return Value::Str(it->second);
             }));
  table->Set("tokenize", Value::Function("tokenize", [](Positional p, Keywords k)
                                                         -> pyexpr::Result<Value> {
               if (p.empty() || !p[0].IsStr()) {
                 return Error{Error::Kind::kType, "tokenize() takes a string"};
               }
               std::string separators = ",; ";
               bool skip_empty = true;
               if (p.size() > 1 && p[1].IsStr()) separators = p[1].AsStr();
               if (p.size() > 2) skip_empty = pyexpr::Truthy(p[2]);
               for (const auto& [key, value] : k) {
                 if (key == "sep" && value.IsStr()) separators = value.AsStr();
                 if (key == "skip_empty") skip_empty = pyexpr::Truthy(value);
               }
               std::vector<Value> items;
               for (std::string& t : pyexpr::Tokenize(p[0].AsStr(), separators, skip_empty)) {
                 items.push_back(Value::Str(std::move(t)));
               }
               return Value::List(std::move(items));
             }));
  // xacro.message, warning, error, print_location and fatal: located here
  auto joined = [](Positional p) {
    std::string text;
    for (size_t i = 0; i < p.size(); ++i) text += (i ? " " : "") + pyexpr::Str(p[i]);
    return text;
  };
  table->Set("message", Value::Function("message", [this, joined](Positional p, Keywords)
                                                       -> pyexpr::Result<Value> {
               diags_.Report(DiagKind::XacroMessage, here_, joined(p));
               return Value::Str("");
             }));
  table->Set("warning", Value::Function("warning", [this, joined](Positional p, Keywords)
                                                       -> pyexpr::Result<Value> {
               Warn(here_, joined(p));
               return Value::Str("");
             }));
  table->Set("error", Value::Function("error", [this, joined](Positional p, Keywords)
                                                   -> pyexpr::Result<Value> {
               diags_.Report(DiagKind::XacroError, here_, joined(p));
               return Value::Str("");
             }));
  table->Set("print_location", Value::Function("print_location", [](Positional, Keywords)
                                                                     -> pyexpr::Result<Value> {
               return Value::Str("");
             }));
  table->Set("fatal", Value::Function("fatal", [joined](Positional p, Keywords)
                                                   -> pyexpr::Result<Value> {
               Error e{Error::Kind::kHost, joined(p)};
               e.fatal = true;
               return e;
             }));
  xacro_namespace_ = std::move(table);
  xacro_namespace_value_ = Value::Namespace(
      "xacro", std::shared_ptr<const pyexpr::NameTable>(xacro_namespace_.get(),
                                                        [](const pyexpr::NameTable*) {}));
  return *xacro_namespace_;
}

}  // namespace mdlc::xacro
