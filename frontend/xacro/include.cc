// include.cc - <xacro:include> and reading source files into the tree.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <regex>

#include "frontend/xacro/expander.h"
#include "frontend/xml/xml_document.h"

namespace mdlc::xacro {
namespace {

// How deep xacro source may nest elements. Expansion walks the tree
// recursively, as xacro does (which stops near this depth at Python's
// recursion limit); a bound keeps the walk's stack small.
constexpr int kMaxSourceDepth = 1000;

// Copies a parsed element, its attributes and every child node in document
// order into the tree; null when the element nests deeper than
// kMaxSourceDepth, at `*too_deep`.
Node* CopyElement(Tree& tree, const xml::XmlElement& element, int depth, Loc* too_deep) {
  if (depth > kMaxSourceDepth) {
    *too_deep = element.GetLoc();
    return nullptr;
  }
  Node* node = tree.Make(Node::Kind::kElement);
  node->name = std::string(element.Name());
  node->loc = element.GetLoc();
  element.ForEachAttributeName([&](std::string_view name) {
    const xml::XmlAttribute a = element.Attribute(name);
    node->attributes.push_back(Attribute{std::string(name), std::string(a.value), a.loc});
  });
  element.ForEachNode(
      [&](const xml::XmlElement& child) {
        if (too_deep->valid()) return;
        if (Node* copy = CopyElement(tree, child, depth + 1, too_deep)) tree.AppendChild(node, copy);
      },
      [&](const xml::XmlContent& content) {
        Node::Kind kind = content.kind == xml::detail::ContentKind::kComment ? Node::Kind::kComment
                          : content.kind == xml::detail::ContentKind::kCdata ? Node::Kind::kCdata
                                                                             : Node::Kind::kText;
        Node* c = tree.Make(kind);
        c->text = std::string(content.text);
        c->loc = node->loc;
        tree.AppendChild(node, c);
      });
  return node;
}

bool HasGlob(std::string_view spec) { return spec.find_first_of("*[?") != std::string_view::npos; }

// Python's glob of one pattern: '*', '?' and '[...]' within a path part
std::vector<std::string> Glob(const std::string& pattern) {
  namespace fs = std::filesystem;
  std::vector<std::string> matches{""};
  const fs::path p(pattern);
  bool first = true;
  for (const fs::path& part : p) {
    std::vector<std::string> next;
    const std::string piece = part.string();
    for (const std::string& base : matches) {
      const std::string prefix = first ? "" : base;
      if (!HasGlob(piece)) {
        fs::path joined = first ? part : fs::path(prefix) / part;
        if (first || fs::exists(joined)) next.push_back(joined.string());
        continue;
      }
      std::string regex;
      for (size_t i = 0; i < piece.size(); ++i) {
        const char c = piece[i];
        if (c == '*') {
          regex += "[^/]*";
        } else if (c == '?') {
          regex += "[^/]";
        } else if (c == '[') {
          const size_t close = piece.find(']', i + 1);
          if (close == std::string::npos) {
            regex += "\\[";
          } else {
            std::string set = piece.substr(i + 1, close - i - 1);
            if (!set.empty() && set[0] == '!') set[0] = '^';
            regex += "[" + set + "]";
            i = close;
          }
        } else if (std::isalnum(static_cast<unsigned char>(c))) {
          regex += c;
        } else {
          regex += std::string("\\") + c;
        }
      }
      const std::regex re(regex);
      std::error_code ec;
      const fs::path dir = prefix.empty() ? fs::path(".") : fs::path(prefix);
      for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        if (name[0] == '.' && piece[0] != '.') continue;
        if (std::regex_match(name, re)) {
          next.push_back(prefix.empty() ? name : (fs::path(prefix) / name).string());
        }
      }
    }
    matches = std::move(next);
    first = false;
  }
  std::sort(matches.begin(), matches.end());
  return matches;
}

}  // namespace

Node* Expander::ReadBuffer(FileId file) {
  xml::ParseOptions options;
  options.keep_blank_text = true;
  options.keep_namespace_declarations = true;
  std::unique_ptr<xml::XmlDocument> doc = xml::XmlDocument::Parse(file, sources_, diags_, options);
  if (!doc) throw ExpansionFailed{};
  Loc too_deep;
  Node* root = CopyElement(expansion_->tree, doc->Root(), 1, &too_deep);
  if (too_deep.valid()) {
    Fail(too_deep,
         fmt::format("xacro source may nest elements at most {} deep", kMaxSourceDepth),
         DiagKind::LimitExceeded);
  }
  if (file == expansion_->file) {
    for (const auto& [text, after_root] : doc->outside_comments()) {
      (after_root ? expansion_->comments_after_root : expansion_->comments_before_root)
          .emplace_back(text);
    }
  }
  CountNode();
  return root;
}

Node* Expander::ReadFile(const std::string& path, Loc included_from, bool optional) {
  LoadError error;
  std::optional<FileId> file = sources_.LoadFile(path, included_from, &error);
  if (!file) {
    if (optional && !error.over_limit) return nullptr;
    if (error.over_limit) {
      diags_.Report(DiagKind::LimitExceeded, included_from, error.message);
      throw ExpansionFailed{};
    }
    Fail(included_from, fmt::format("cannot include '{}': {}", path, error.message));
  }
  return ReadBuffer(*file);
}

std::vector<std::string> Expander::IncludeFiles(const std::string& spec, Loc at) {
  const std::string path = AbsoluteFilename(spec);
  if (!HasGlob(path)) return {path};
  std::vector<std::string> files = Glob(path);
  if (files.empty()) Warn(at, fmt::format("include pattern '{}' matches no file", path));
  return files;
}

void Expander::Include(Node* node, MacroTable& macros, SymbolTable& symbols) {
  const auto a = CheckAttributes(node, {"filename"}, {"ns", "optional"});
  MacroTable* ns_macros = &macros;
  SymbolTable* ns_symbols = &symbols;
  if (a[1]) {
    const std::string space = EvalString(a[1]->value, symbols, a[1]->loc);
    ns_macros = macros.AddNamespace(space);
    scopes_.push_back(std::make_unique<SymbolTable>(&symbols, /*is_namespace=*/true));
    ns_symbols = scopes_.back().get();
    Symbol symbol;
    symbol.kind = Symbol::Kind::kNamespace;
    symbol.space = ns_symbols;
    symbol.defined_at = a[1]->loc;
    symbols.Set(space, std::move(symbol));
  }
  bool optional = false;
  if (a[2]) optional = ConditionValue(pyexpr::Value::Str(a[2]->value), a[2]->value, a[2]->loc);
  if (node->FirstElementChild()) {
    Warn(node->FirstElementChild()->loc, "elements inside <xacro:include> are ignored");
  }
  const std::string spec = EvalString(a[0]->value, symbols, a[0]->loc);
  std::vector<Node*> included;
  for (const std::string& path : IncludeFiles(spec, a[0]->loc)) {
    if (std::find(file_stack_.begin(), file_stack_.end(), path) != file_stack_.end()) {
      Fail(a[0]->loc, fmt::format("'{}' includes itself (through the files that include it)", path));
    }
    if (dependency_seen_.try_emplace(path, true).second) expansion_->dependencies.push_back(path);
    Node* root = ReadFile(path, a[0]->loc, optional);
    if (!root) continue;
    file_stack_.push_back(path);
    EvalAll(root, *ns_macros, *ns_symbols);
    file_stack_.pop_back();
    included.push_back(root);
    LiftNamespaces(node->parent(), *root);
  }
  RemovePreviousComments(node);
  for (Node* root : included) {
    while (Node* child = root->first_child()) expansion_->tree.InsertBefore(node, child);
  }
  expansion_->tree.Replace(node, nullptr, false);
}

}  // namespace mdlc::xacro
