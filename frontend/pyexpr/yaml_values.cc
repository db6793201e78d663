// yaml_values.cc - yaml-cpp nodes to values with PyYAML's type resolution.
#include "frontend/pyexpr/yaml_values.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <regex>

#include "frontend/pyexpr/internal.h"
#include "frontend/pyexpr/number_text.h"

namespace mdlc::pyexpr {
namespace {

using internal::Fail;

// PyYAML's YAML 1.1 implicit resolvers (resolver.py), as regular expressions
// over the whole scalar.
const std::regex& BoolPattern() {
  static const std::regex r("yes|Yes|YES|no|No|NO|true|True|TRUE|false|False|FALSE|on|On|ON|off|Off|OFF");
  return r;
}
const std::regex& IntPattern() {
  static const std::regex r(
      "[-+]?0b[0-1_]+|[-+]?0[0-7_]+|[-+]?(?:0|[1-9][0-9_]*)|[-+]?0x[0-9a-fA-F_]+|[-+]?[1-9][0-9_]*(?::[0-5]?[0-9])+");
  return r;
}
const std::regex& FloatPattern() {
  static const std::regex r(
      "[-+]?(?:[0-9][0-9_]*)\\.[0-9_]*(?:[eE][-+][0-9]+)?|\\.[0-9][0-9_]*(?:[eE][-+][0-9]+)?|"
      "[-+]?[0-9][0-9_]*(?::[0-5]?[0-9])+\\.[0-9_]*|[-+]?\\.(?:inf|Inf|INF)|\\.(?:nan|NaN|NAN)");
  return r;
}

std::string Where(const YAML::Mark& mark) {
  if (mark.is_null()) return "yaml";
  return fmt::format("yaml line {}, column {}", mark.line + 1, mark.column + 1);
}

Error YamlError(const YAML::Mark& mark, std::string message, Error::Kind kind = Error::Kind::kValue) {
  return Error{kind, fmt::format("{}: {}", Where(mark), message)};
}

Result<Value> ConstructInt(std::string text, const YAML::Mark& mark) {
  std::string s;
  for (char c : text)
    if (c != '_') s.push_back(c);
  bool negative = false;
  if (!s.empty() && (s[0] == '-' || s[0] == '+')) {
    negative = s[0] == '-';
    s.erase(0, 1);
  }
  auto overflow = [&] { return YamlError(mark, fmt::format("the integer {} does not fit in 64 bits", text), Error::Kind::kOverflow); };
  __int128 v = 0;
  auto digits = [&](std::string_view d, int base) -> bool {
    for (char c : d) {
      int x = c <= '9' ? c - '0' : (c | 0x20) - 'a' + 10;
      v = v * base + x;
      if (v > (static_cast<__int128>(1) << 64)) return false;
    }
    return true;
  };
  bool ok = true;
  if (s == "0") {
    v = 0;
  } else if (s.starts_with("0b")) {
    ok = digits(std::string_view(s).substr(2), 2);
  } else if (s.starts_with("0x")) {
    ok = digits(std::string_view(s).substr(2), 16);
  } else if (s[0] == '0') {
    ok = digits(std::string_view(s).substr(1), 8);
  } else if (s.find(':') != std::string::npos) {
    size_t start = 0;
    while (ok) {
      size_t colon = s.find(':', start);
      std::string part = s.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
      __int128 before = v;
      v = 0;
      ok = digits(part, 10);
      v = before * 60 + v;
      if (v > (static_cast<__int128>(1) << 64)) ok = false;
      if (colon == std::string::npos) break;
      start = colon + 1;
    }
  } else {
    ok = digits(s, 10);
  }
  if (!ok) return overflow();
  if (negative) v = -v;
  if (v > std::numeric_limits<int64_t>::max() || v < std::numeric_limits<int64_t>::min()) return overflow();
  return Value::Int(static_cast<int64_t>(v));
}

Value ConstructFloat(const std::string& text) {
  std::string s;
  for (char c : text)
    if (c != '_') s.push_back(c >= 'A' && c <= 'Z' ? static_cast<char>(c + 32) : c);
  double sign = 1.0;
  if (!s.empty() && (s[0] == '-' || s[0] == '+')) {
    if (s[0] == '-') sign = -1.0;
    s.erase(0, 1);
  }
  if (s == ".inf") return Value::Float(sign * std::numeric_limits<double>::infinity());
  if (s == ".nan") return Value::Float(std::numeric_limits<double>::quiet_NaN());
  if (s.find(':') != std::string::npos) {
    // sexagesimal: PyYAML sums float parts times powers of 60
    std::vector<double> parts;
    size_t start = 0;
    while (true) {
      size_t colon = s.find(':', start);
      parts.push_back(ParsePythonFloat(s.substr(start, colon == std::string::npos ? std::string::npos : colon - start)).value_or(0));
      if (colon == std::string::npos) break;
      start = colon + 1;
    }
    double base = 1, value = 0.0;
    for (auto it = parts.rbegin(); it != parts.rend(); ++it) {
      value += *it * base;
      base *= 60;
    }
    return Value::Float(sign * value);
  }
  return Value::Float(sign * ParsePythonFloat(s).value_or(0));
}

// PyYAML's resolution of a plain scalar.
Result<Value> ResolvePlain(const std::string& s, const YAML::Mark& mark) {
  if (s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL") return Value();
  if (s.size() > 200) return Value::Str(s);  // longer than any number or bool word
  if (std::regex_match(s, BoolPattern())) {
    char c = s[0] | 0x20;
    return Value::Bool(c == 'y' || c == 't' || (c == 'o' && (s[1] | 0x20) == 'n'));
  }
  char c = s[0];
  if ((c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.') {
    if (std::regex_match(s, IntPattern())) return ConstructInt(s, mark);
    if (std::regex_match(s, FloatPattern())) return ConstructFloat(s);
  }
  return Value::Str(s);
}

Result<Value> UnitTag(const std::string& tag, const std::string& text, const YAML::Mark& mark) {
  EmptyScope scope;
  auto v = Evaluate(text, scope);
  if (!v.ok()) {
    Error e = std::move(v).error();
    e.message = fmt::format("{}: in {} {}: {}", Where(mark), tag, text, e.message);
    return e;
  }
  double x;
  if (v->IsNumber()) {
    x = v->AsFloat();
  } else if (v->IsStr() && ParsePythonFloat(v->AsStr())) {
    x = *ParsePythonFloat(v->AsStr());
  } else {
    return YamlError(mark, fmt::format("{} {} is not a number", tag, text), Error::Kind::kType);
  }
  if (tag == "!degrees") return Value::Float(x * (std::numbers::pi / 180.0));
  if (tag == "!millimeters") return Value::Float(0.001 * x);
  if (tag == "!foot") return Value::Float(0.3048 * x);
  if (tag == "!inches") return Value::Float(0.0254 * x);
  return Value::Float(x);  // !radians, !meters
}

class Converter {
 public:
  explicit Converter(const Limits& limits) : limits_(limits) {}

  Result<Value> Convert(const YAML::Node& node, int depth) {
    if (depth > limits_.max_depth)
      return YamlError(node.Mark(), fmt::format("nested deeper than the limit of {} levels", limits_.max_depth),
                       Error::Kind::kLimit);
    if (++count_ > limits_.max_items)
      return YamlError(node.Mark(), fmt::format("more than the limit of {} values", limits_.max_items),
                       Error::Kind::kLimit);
    const std::string& tag = node.Tag();
    switch (node.Type()) {
      case YAML::NodeType::Undefined:
      case YAML::NodeType::Null:
        if (tag == "tag:yaml.org,2002:str" || tag == "!") return Value::Str("");
        return Value();
      case YAML::NodeType::Scalar: return Scalar(node, tag);
      case YAML::NodeType::Sequence: {
        std::vector<Value> items;
        for (const auto& child : node) {
          PYEXPR_TRY(v, Convert(child, depth + 1));
          items.push_back(std::move(v));
        }
        return Value::List(std::move(items)).WithAttributeAccess(true);
      }
      case YAML::NodeType::Map: {
        std::vector<Value::Item> merged, own;
        for (const auto& kv : node) {
          if (kv.first.IsScalar() && kv.first.Tag() == "?" && kv.first.Scalar() == "<<") {
            PYEXPR_TRY(m, Merge(kv.second, depth + 1));
            merged.insert(merged.end(), m.begin(), m.end());
            continue;
          }
          PYEXPR_TRY(key, Convert(kv.first, depth + 1));
          if (!Hash(key))
            return YamlError(kv.first.Mark(), fmt::format("a {} cannot be a mapping key", TypeName(key)), Error::Kind::kType);
          PYEXPR_TRY(value, Convert(kv.second, depth + 1));
          own.emplace_back(std::move(key), std::move(value));
        }
        merged.insert(merged.end(), own.begin(), own.end());
        return Value::Dict(std::move(merged), /*attribute_access=*/true);
      }
    }
    return Value();
  }

 private:
  Result<std::vector<Value::Item>> Merge(const YAML::Node& node, int depth) {
    std::vector<YAML::Node> maps;
    if (node.IsMap()) {
      maps.push_back(node);
    } else if (node.IsSequence()) {
      for (const auto& m : node) {
        if (!m.IsMap()) return YamlError(m.Mark(), "a merge key (<<) needs mappings", Error::Kind::kType);
        maps.push_back(m);
      }
    } else {
      return YamlError(node.Mark(), "a merge key (<<) needs a mapping or a list of mappings", Error::Kind::kType);
    }
    std::vector<Value::Item> out;
    // earlier mappings win: add the later ones first
    for (auto it = maps.rbegin(); it != maps.rend(); ++it) {
      PYEXPR_TRY(v, Convert(*it, depth));
      out.insert(out.end(), v.dict_items().begin(), v.dict_items().end());
    }
    return out;
  }

  Result<Value> Scalar(const YAML::Node& node, const std::string& tag) {
    const std::string& s = node.Scalar();
    if (tag == "?") return ResolvePlain(s, node.Mark());
    if (tag == "!" || tag == "tag:yaml.org,2002:str") return Value::Str(s);
    if (tag == "!radians" || tag == "!degrees" || tag == "!meters" || tag == "!millimeters" || tag == "!foot" ||
        tag == "!inches")
      return UnitTag(tag, s, node.Mark());
    if (tag == "tag:yaml.org,2002:int") {
      if (std::regex_match(s, IntPattern())) return ConstructInt(s, node.Mark());
      auto i = ParsePythonInt(s);
      if (i) return Value::Int(*i);
      return YamlError(node.Mark(), fmt::format("'{}' is not an int", s));
    }
    if (tag == "tag:yaml.org,2002:float") {
      if (std::regex_match(s, FloatPattern()) || std::regex_match(s, IntPattern())) return ConstructFloat(s);
      if (auto d = ParsePythonFloat(s)) return Value::Float(*d);
      return YamlError(node.Mark(), fmt::format("'{}' is not a float", s));
    }
    if (tag == "tag:yaml.org,2002:bool") {
      if (std::regex_match(s, BoolPattern())) return ResolvePlain(s, node.Mark());
      return YamlError(node.Mark(), fmt::format("'{}' is not a bool", s));
    }
    if (tag == "tag:yaml.org,2002:null") return Value();
    return YamlError(node.Mark(), fmt::format("no constructor for the tag '{}'", tag), Error::Kind::kUnsupported);
  }

  const Limits& limits_;
  size_t count_ = 0;
};

}  // namespace

Result<Value> LoadYaml(std::string_view text) { return LoadYaml(text, Limits{}); }

Result<Value> LoadYaml(std::string_view text, const Limits& limits) {
  internal::LimitsScope limits_scope(limits);
  std::vector<YAML::Node> docs;
  try {
    docs = YAML::LoadAll(std::string(text));
  } catch (const YAML::Exception& e) {
    return YamlError(e.mark, e.msg, Error::Kind::kSyntax);
  } catch (const std::exception& e) {
    return Fail(Error::Kind::kSyntax, fmt::format("yaml: {}", e.what()));
  }
  if (docs.size() > 1) return YamlError(docs[1].Mark(), "expected one document, found more", Error::Kind::kSyntax);
  if (docs.empty()) return Value();
  try {
    return Converter(limits).Convert(docs[0], 0);
  } catch (const std::exception& e) {
    return Fail(Error::Kind::kValue, fmt::format("yaml: {}", e.what()));
  }
}

}  // namespace mdlc::pyexpr
