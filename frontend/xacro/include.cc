// include.cc - <xacro:include> and reading source files into the tree.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

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
Node* CopyElement(Tree& tree, const xml::XmlElement& element, int depth, Loc* too_deep,
                  FileId file) {
  if (depth > kMaxSourceDepth) {
    *too_deep = element.GetLoc();
    return nullptr;
  }
  Node* node = tree.Make(Node::Kind::kElement);
  node->name = std::string(element.Name());
  node->loc = element.GetLoc();
  node->loc.file = file;
  element.ForEachAttributeName([&](std::string_view name) {
    const xml::XmlAttribute a = element.Attribute(name);
    node->attributes.push_back(
        Attribute{std::string(name), std::string(a.value), Loc{file, a.loc.line, a.loc.column}});
  });
  element.ForEachNode(
      [&](const xml::XmlElement& child) {
        if (too_deep->valid()) return;
        if (Node* copy = CopyElement(tree, child, depth + 1, too_deep, file)) {
          tree.AppendChild(node, copy);
        }
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

// Python's fnmatch of one path part: '*', '?', '[set]', '[!set]' with
// ranges; anything else matches itself. Iterative, with one point to go
// back to for the last '*' (linear in practice, never exponential).
bool PartMatches(std::string_view name, std::string_view pattern) {
  // the length of a [set] at pattern[p] ('[' included), 0 when unclosed
  auto set_length = [&](size_t p) -> size_t {
    size_t q = p + 1;
    if (q < pattern.size() && pattern[q] == '!') ++q;
    if (q < pattern.size() && pattern[q] == ']') ++q;  // a leading ']' is a member
    const size_t close = pattern.find(']', q);
    return close == std::string_view::npos ? 0 : close - p + 1;
  };
  auto in_set = [&](size_t p, size_t length, char c) {
    size_t q = p + 1;
    const bool negated = q < p + length - 1 && pattern[q] == '!';
    if (negated) ++q;
    bool found = false;
    for (const size_t last = p + length - 1; q < last; ++q) {
      if (q + 2 < last && pattern[q + 1] == '-') {
        if (pattern[q] <= c && c <= pattern[q + 2]) found = true;
        q += 2;
      } else if (pattern[q] == c) {
        found = true;
      }
    }
    return found != negated;
  };
  size_t n = 0, p = 0;
  size_t star = std::string_view::npos, star_n = 0;
  while (n < name.size()) {
    if (p < pattern.size() && pattern[p] == '*') {
      star = ++p;
      star_n = n;
      continue;
    }
    if (p < pattern.size()) {
      if (pattern[p] == '[') {
        if (const size_t length = set_length(p)) {
          if (in_set(p, length, name[n])) {
            p += length;
            ++n;
            continue;
          }
        } else if (name[n] == '[') {
          ++p;
          ++n;
          continue;
        }
      } else if (pattern[p] == '?' || pattern[p] == name[n]) {
        ++p;
        ++n;
        continue;
      }
    }
    if (star == std::string_view::npos) return false;
    p = star;
    n = ++star_n;
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

// Python's glob of one pattern, sorted. `budget` bounds the folder entries
// it may look at (a pattern of many '*' parts could walk a whole disk).
std::vector<std::string> Glob(const std::string& pattern, size_t& budget) {
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
      std::error_code ec;
      const fs::path dir = prefix.empty() ? fs::path(".") : fs::path(prefix);
      for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator();
           it.increment(ec)) {
        if (budget == 0) return {};
        --budget;
        const std::string name = it->path().filename().string();
        if (name[0] == '.' && piece[0] != '.') continue;
        if (PartMatches(name, piece)) {
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

Node* Expander::ReadBuffer(FileId file, const std::string* path) {
  xml::ParseOptions options;
  options.keep_blank_text = true;
  options.keep_namespace_declarations = true;
  std::shared_ptr<const xml::XmlDocument> doc =
      xml::XmlDocument::Parse(file, sources_, diags_, options);
  if (!doc) throw ExpansionFailed{};
  // kept for the next inclusion of the same file (its tree is compact)
  if (path) read_files_.emplace(*path, doc);
  return CopyDocument(*doc, file);
}

Node* Expander::CopyDocument(const xml::XmlDocument& doc, FileId file) {
  Loc too_deep;
  Node* root = CopyElement(expansion_->tree, doc.Root(), 1, &too_deep, file);
  if (too_deep.valid()) {
    Fail(too_deep,
         fmt::format("xacro source may nest elements at most {} deep", kMaxSourceDepth),
         DiagKind::LimitExceeded);
  }
  if (file == expansion_->file) {
    for (const auto& [text, after_root] : doc.outside_comments()) {
      (after_root ? expansion_->comments_after_root : expansion_->comments_before_root)
          .emplace_back(text);
    }
  }
  CountNode();
  return root;
}

Node* Expander::ReadFile(const std::string& path, Loc included_from, bool optional) {
  LoadError error;
  // a file included again (by every call of a macro that includes it) is
  // the text already read, included from this place: copied, not parsed
  if (auto read = read_files_.find(path); read != read_files_.end()) {
    const FileId first = read->second->file();
    std::optional<FileId> again = sources_.AddInclusion(first, included_from, &error);
    if (!again) {
      diags_.Report(DiagKind::LimitExceeded, included_from, error.message);
      throw ExpansionFailed{};
    }
    return CopyDocument(*read->second, *again);
  }
  std::optional<FileId> file = sources_.LoadFile(path, included_from, &error);
  if (!file) {
    if (optional && !error.over_limit) return nullptr;
    if (error.over_limit) {
      diags_.Report(DiagKind::LimitExceeded, included_from, error.message);
      throw ExpansionFailed{};
    }
    Fail(included_from, fmt::format("cannot include '{}': {}", path, error.message));
  }
  return ReadBuffer(*file, &path);
}

std::vector<std::string> Expander::IncludeFiles(const std::string& spec, Loc at) {
  const std::string path = AbsoluteFilename(spec);
  if (!HasGlob(path)) return {path};
  constexpr size_t kMaxEntries = 100'000;
  size_t budget = kMaxEntries;
  std::vector<std::string> files = Glob(path, budget);
  if (budget == 0) {
    Fail(at, fmt::format("include pattern '{}' looks at more than {} folder entries; name the "
                         "folders it may search",
                         path, kMaxEntries),
         DiagKind::LimitExceeded);
  }
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
    // the same file however its path is written (dir/../x.xacro, a link)
    std::error_code ec;
    const std::string same = std::filesystem::weakly_canonical(path, ec).string();
    if (std::find(open_files_.begin(), open_files_.end(), same) != open_files_.end()) {
      Fail(a[0]->loc, fmt::format("'{}' includes itself (through the files that include it)", path));
    }
    NoteDependency(path);
    Node* root = ReadFile(path, a[0]->loc, optional);
    if (!root) continue;
    file_stack_.push_back(path);
    open_files_.push_back(same);
    EvalAll(root, *ns_macros, *ns_symbols);
    open_files_.pop_back();
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
