// mjcf_replicate.cc - <replicate> and the expansion of <replicate> and
// <attach> into a document of their result (see mjcf_replicate.h).
//
// MuJoCo 3.3 (xml_native_reader.cc, user_model.cc) reads a <replicate> as a
// subtree that it attaches `count` times to the enclosing body with
// mjs_attach and then deletes:
//   - copy i sits in a frame at pos_i and the rotation of i times `euler`
//     (compiler angle unit and eulerseq), where pos_0 = 0 and
//     pos_{i+1} = pos_i + R(i euler) offset;
//   - copy i renames every named element of the subtree (bodies, joints,
//     geoms, sites, cameras, lights, frames; camera and light targets)
//     name + sep + i, i zero-padded to the digits of `count`; a nested
//     replicate is expanded first, so its suffix comes first ("b" in an
//     inner copy 1 of an outer copy 0: "b10");
//   - every element outside the tree (equality, tendon, actuator, contact
//     pair and exclude, sensor) is tried with its own name and every name it
//     refers to suffixed the same way, and kept when all those names exist;
//     once the subtree is deleted, the elements that referred into it go.
// <attach model body prefix> does the same with the other model's subtree,
// prefixing instead (mjcf_attach.cc loads the model). Both are simulated
// here on the names alone, in MuJoCo's order (innermost first, document
// order), then written out. Every walk uses an explicit stack.
#include "frontend/mjcf/mjcf_replicate.h"

#include <absl/container/flat_hash_map.h>
#include <absl/container/flat_hash_set.h>
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "frontend/mjcf/mjcf_orientation.h"
#include "frontend/xml/attribute_reader.h"

namespace mdlc::frontend::mjcf {
namespace {

/// The kind of name a tree element has; empty for elements without one.
std::string_view TreeKind(std::string_view tag) {
  if (tag == "body" || tag == "geom" || tag == "site" || tag == "camera" || tag == "light" ||
      tag == "frame") {
    return tag;
  }
  if (tag == "joint" || tag == "freejoint") return "joint";
  return {};
}

constexpr std::string_view kSections[] = {"equality", "tendon", "actuator", "contact", "sensor"};
bool IsSection(std::string_view tag) {
  return std::find(std::begin(kSections), std::end(kSections), tag) != std::end(kSections);
}

/// The kind of element an attribute of an element outside the tree names;
/// empty when it names none.
std::string RefKind(const xml::XmlElement& e, std::string_view a) {
  if (a == "body1" || a == "body2" || a == "body" || a == "subtree1" || a == "subtree2") {
    return "body";
  }
  if (a == "joint" || a == "joint1" || a == "joint2" || a == "jointinparent") return "joint";
  if (a == "tendon" || a == "tendon1" || a == "tendon2") return "tendon";
  if (a == "site" || a == "site1" || a == "site2" || a == "refsite" || a == "cranksite" ||
      a == "slidersite" || a == "sidesite") {
    return "site";
  }
  if (a == "geom" || a == "geom1" || a == "geom2") return "geom";
  if (a == "actuator") return "actuator";
  if (a == "camera") return "camera";
  if (a == "flex" || a == "flex1" || a == "flex2") return "flex";
  if (a == "objname" || a == "refname") {
    std::string type(e.Attribute(a == "objname" ? "objtype" : "reftype").value);
    if (type == "xbody") type = "body";
    return type.empty() ? std::string("?") : type;
  }
  return {};
}

/// The kind of an outside element's own name.
std::string OwnKind(std::string_view section, std::string_view tag) {
  if (section == "contact") return std::string(tag);  // pair, exclude
  return std::string(section);
}

std::string Key(std::string_view kind, std::string_view name) {
  std::string k;
  k.reserve(kind.size() + 1 + name.size());
  k.append(kind);
  k.push_back('\x1f');
  k.append(name);
  return k;
}

std::string Suffix(std::string_view sep, int count, int i) {
  const std::string digits = std::to_string(i);
  const size_t width = std::to_string(count).size();
  std::string s(sep);
  if (digits.size() < width) s.append(width - digits.size(), '0');
  s += digits;
  return s;
}

struct Name {
  std::string kind, name;
};

/// A replicate, an attach or the worldbody, with the names written
/// directly in it (not in a nested replicate).
struct Node {
  enum Type { kRoot, kReplicate, kAttach } type = kRoot;
  xml::XmlElement e;
  std::vector<Name> own;
  std::vector<int> children;
  uint64_t elements = 0;
  // replicate
  int count = 1;
  std::string sep, childclass;
  std::vector<Transform> frames;
  // attach
  const ChildModel* child = nullptr;
  std::string prefix;
  std::vector<xml::XmlElement> content;  // the child's body, or its worldbody's children
  std::string inherited;                 // the child class they use
  absl::flat_hash_set<std::string> joints;  // the child's names of its joints
  size_t unnamed_joints = 0;
};

/// An element outside the tree: as written in the model (prefix and suffix
/// empty), or a renamed copy.
struct Entry {
  xml::XmlElement e;
  std::string section;
  std::string prefix, suffix;
  bool foreign = false;  // from an attached model
  bool alive = true;
  int info = 0;
  size_t origin = 0;  // the entry as written that this one copies
};
struct EntryInfo {
  std::vector<Name> refs;  // as written
  std::string own_kind, own_name;
};

struct Naming {
  std::string prefix, suffix;
  bool foreign = false;
};

class Expander {
 public:
  Expander(MjcfReader& r, const xml::XmlElement& root, const std::vector<std::string>& chain)
      : r_(r), root_(root), chain_(chain) {}

  Expansion Run();

 private:
  DiagnosticEngine& diags() { return r_.diags(); }
  bool ReadReplicate(const xml::XmlElement& e, Node& n);
  bool ReadAttach(const xml::XmlElement& e, Node& n);
  void AttachKeys(const Node& n, bool in_replicate);
  const ChildModel* Model(const xml::XmlElement& attach, std::string_view name);
  bool CheckSize();
  void AddEntries(const std::vector<xml::XmlElement>& top, const ChildModel* child,
                  const std::string& prefix);
  void Simulate();
  void CopyEntries(const std::string& prefix, const std::string& suffix, size_t from, size_t to,
                   bool foreign);
  bool Resolves(const Entry& c, const std::string& prefix, const std::string& suffix) const;
  void AddName(const std::string& k) { ++names_[k]; }
  void RemoveName(const std::string& k) {
    auto it = names_.find(k);
    if (it != names_.end() && --it->second <= 0) names_.erase(it);
  }
  std::shared_ptr<const xml::XmlDocument> Write();
  void WriteWorldbody(xml::XmlDocumentBuilder& b, const xml::XmlElement& wb,
                      const std::vector<xml::XmlElement>& top);
  void WriteEntry(xml::XmlDocumentBuilder& b, const Entry& entry);

  MjcfReader& r_;
  xml::XmlElement root_;
  const std::vector<std::string>& chain_;
  bool failed_ = false;
  std::vector<Node> nodes_;
  absl::flat_hash_map<const void*, int> node_of_;
  std::vector<Entry> entries_;
  std::vector<EntryInfo> infos_;
  absl::flat_hash_map<const void*, size_t> original_entry_;
  absl::flat_hash_map<std::string, int> names_;
  // models of <asset><model>, loaded when an attach first names them
  absl::flat_hash_map<std::string, xml::XmlElement> model_assets_;
  absl::flat_hash_map<std::string, std::unique_ptr<ChildModel>> models_;
  std::vector<std::pair<const ChildModel*, std::string>> attached_;  // (model, prefix), once
  absl::flat_hash_set<const ChildModel*> nested_keys_taken_;  // see AttachKeys
};

bool Expander::ReadReplicate(const xml::XmlElement& e, Node& n) {
  // outside MuJoCo's schema: MuJoCo reads these and ignores any other
  e.ForEachAttributeName([&](std::string_view name) {
    for (std::string_view known : {"count", "offset", "euler", "sep", "childclass"}) {
      if (name == known) return;
    }
    diags().Report(DiagKind::UnknownAttribute, e.Attribute(name).loc,
                   fmt::format("'{}' is not an attribute of <replicate> and is ignored (MuJoCo "
                               "ignores it too)",
                               name));
  });
  const xml::XmlAttribute count = e.Attribute("count");
  if (!count.present()) {
    diags().Report(DiagKind::MissingAttribute, e.GetLoc(),
                   "<replicate> is missing required attribute 'count'");
    return false;
  }
  auto c = xml::ParseDoubleList(count.value);
  if (!c || c->size() != 1 || (*c)[0] != std::floor((*c)[0]) || (*c)[0] < 1 || (*c)[0] > 2e9) {
    diags().Report(DiagKind::BadValue, count.loc,
                   fmt::format("replicate count '{}' is not a positive integer", count.value));
    return false;
  }
  n.count = static_cast<int>((*c)[0]);
  double offset[3] = {0, 0, 0}, euler[3] = {0, 0, 0};
  for (auto [name, out] : {std::pair{"offset", offset}, std::pair{"euler", euler}}) {
    const xml::XmlAttribute a = e.Attribute(name);
    if (!a.present()) continue;
    auto v = xml::ParseDoubleList(a.value);
    if (!v || v->size() != 3) {
      diags().Report(DiagKind::BadValue, a.loc,
                     fmt::format("replicate {} '{}' must be 3 numbers", name, a.value));
      return false;
    }
    std::copy(v->begin(), v->end(), out);
  }
  n.sep = std::string(e.Attribute("sep").value);
  // its childclass is checked where the frame that stands for each copy is
  // read (the defaults are read from the expanded document)
  n.childclass = std::string(e.Attribute("childclass").value);
  // MuJoCo resolves i times the euler angles anew for each copy (for
  // precision) and moves the position by the offset turned by that rotation
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();
  const Eigen::Vector3d d(offset[0], offset[1], offset[2]);
  for (int i = 0; i < n.count; ++i) {
    const Eigen::Vector3d angles(r_.compiler.Angle(i * euler[0]), r_.compiler.Angle(i * euler[1]),
                                 r_.compiler.Angle(i * euler[2]));
    RotationOrError R = RotationFromEuler(angles, r_.compiler.eulerseq);
    if (auto* why = std::get_if<std::string>(&R)) {
      diags().Report(DiagKind::BadValue, e.GetLoc(), fmt::format("replicate euler: {}", *why));
      return false;
    }
    const Eigen::Matrix3d& rot = std::get<Eigen::Matrix3d>(R);
    n.frames.push_back({rot, pos});
    pos += rot * d;
    if (n.frames.size() > 4096 && static_cast<uint64_t>(n.count) > r_.ctx.sources.limits().elements) {
      break;  // too many anyway: CheckSize reports it
    }
  }
  return true;
}

// MuJoCo's mjs_attach stores the attached model's keys by joint (named
// with the prefix: a key K becomes prefix + K, an unnamed one the prefix
// itself) and adds them after this model's own keys, in attach order, the
// joints outside the attached subtree at qpos0. Keys the child took from
// its own attaches follow, under their names (MuJoCo does not prefix them
// again) and only the first time the child is attached (MuJoCo clears
// them then).
void Expander::AttachKeys(const Node& n, bool in_replicate) {
  const ChildModel& c = *n.child;
  const bool nested = nested_keys_taken_.insert(&c).second;
  const std::vector<MjcfReader::AttachedKey> none;
  const std::vector<MjcfReader::AttachedKey>& inner = nested ? c.reader->attached_keys : none;
  if (c.keys.empty() && inner.empty()) return;
  if (in_replicate) {
    diags().Report(DiagKind::UnsupportedElement, n.e.GetLoc(),
                   fmt::format("the keyframes of model '{}' are not attached: MuJoCo adds each "
                               "to this model, but mdlc does not attach keys inside a "
                               "<replicate>; it leaves them out",
                               c.name));
    return;
  }
  bool values = false;
  auto add = [&](const MjcfReader::AttachedKey& k, std::string name) {
    MjcfReader::AttachedKey out{std::move(name), k.loc, k.has_qpos, {}};
    for (const auto& [joint, q] : k.joints) {
      if (!joint.empty() && n.joints.contains(joint)) out.joints.emplace_back(n.prefix + joint, q);
    }
    values |= k.has_qpos;
    r_.attached_keys.push_back(std::move(out));
  };
  for (const auto& k : c.keys) add(k, n.prefix + k.name);
  for (const auto& k : inner) add(k, k.name);
  if (values && n.unnamed_joints > 0) {
    diags().Report(DiagKind::UnsupportedElement, n.e.GetLoc(),
                   fmt::format("the attached keyframes of model '{}' leave its {} unnamed "
                               "joint{} at qpos0: mdlc finds an attached key's joints by "
                               "name, where MuJoCo sets them to the key's values",
                               c.name, n.unnamed_joints, n.unnamed_joints == 1 ? "" : "s"));
  }
}

const ChildModel* Expander::Model(const xml::XmlElement& attach, std::string_view name) {
  if (auto it = models_.find(std::string(name)); it != models_.end()) return it->second.get();
  auto asset = model_assets_.find(std::string(name));
  if (asset == model_assets_.end()) {
    diags().Report(DiagKind::UnknownReference, attach.Attribute("model").loc,
                   fmt::format("<attach> names model '{}', which no <asset><model> defines", name));
    return nullptr;
  }
  std::unique_ptr<ChildModel> child = LoadChildModel(r_, asset->second, chain_);
  const ChildModel* out = child.get();
  models_.emplace(std::string(name), std::move(child));
  return out;
}

bool Expander::ReadAttach(const xml::XmlElement& e, Node& n) {
  r_.CheckAttributes(e, "attach");
  const xml::XmlAttribute model = e.Attribute("model");
  const xml::XmlAttribute prefix = e.Attribute("prefix");
  if (!model.present() || !prefix.present()) {
    diags().Report(DiagKind::MissingAttribute, e.GetLoc(),
                   fmt::format("<attach> is missing required attribute '{}'",
                               model.present() ? "prefix" : "model"));
    return false;
  }
  n.child = Model(e, model.value);
  if (!n.child) return false;
  n.prefix = std::string(prefix.value);
  const xml::XmlAttribute body = e.Attribute("body");
  std::vector<xml::XmlElement> stack;
  for (const auto& top : n.child->Children(n.child->root)) {
    if (top.Name() == "worldbody") {
      if (!body.present()) {
        for (const auto& c : n.child->Children(top)) n.content.push_back(c);
      } else {
        stack.push_back(top);
      }
    }
  }
  while (!stack.empty() && n.content.empty()) {
    const xml::XmlElement x = stack.back();
    stack.pop_back();
    for (const auto& c : n.child->Children(x)) {
      if (c.Name() == "body" && c.Attribute("name").value == body.value) {
        n.content.push_back(c);
        break;
      }
      if (c.Name() == "body" || c.Name() == "frame") stack.push_back(c);
    }
  }
  if (body.present() && n.content.empty()) {
    diags()
        .Report(DiagKind::UnknownReference, body.loc,
                fmt::format("model '{}' has no body '{}' to attach", model.value, body.value))
        .Note(n.child->loc, "the model is defined here");
    return false;
  }
  n.inherited = n.content.empty() || !body.present() ? std::string("main")
                                                      : InheritedChildclass(*n.child, n.content[0]);
  // the names the attached subtree brings, prefixed
  std::vector<xml::XmlElement> walk(n.content.rbegin(), n.content.rend());
  while (!walk.empty()) {
    const xml::XmlElement x = walk.back();
    walk.pop_back();
    ++n.elements;
    const std::string_view kind = TreeKind(x.Name());
    if (!kind.empty()) {
      if (auto nm = x.Attribute("name"); nm.present() && !nm.value.empty()) {
        n.own.push_back({std::string(kind), n.prefix + std::string(nm.value)});
      }
    }
    if (x.Name() == "joint" || x.Name() == "freejoint") {
      if (auto nm = x.Attribute("name"); nm.present() && !nm.value.empty()) {
        n.joints.insert(std::string(nm.value));
      } else {
        ++n.unnamed_joints;
      }
    }
    for (const auto& c : n.child->Children(x)) walk.push_back(c);
  }
  bool seen = false;
  for (const auto& [m, p] : attached_) seen |= (m == n.child && p == n.prefix);
  if (!seen) attached_.emplace_back(n.child, n.prefix);
  return true;
}

/// The elements a replicate expands to, innermost first: a located error
/// once one is over the elements limit (nested count=1000 replicates would
/// otherwise make a billion).
bool Expander::CheckSize() {
  const uint64_t limit = r_.ctx.sources.limits().elements;
  std::vector<uint64_t> total(nodes_.size(), 0);
  for (size_t i = nodes_.size(); i-- > 0;) {  // children are made after their parent
    Node& n = nodes_[i];
    uint64_t sum = n.elements + (n.type == Node::kReplicate ? 1 : 0);
    for (int c : n.children) sum = std::min(limit + 1, sum + total[c]);
    const uint64_t count = n.type == Node::kReplicate ? static_cast<uint64_t>(n.count) : 1;
    total[i] = sum > (limit + 1) / count ? limit + 1 : sum * count;
    if (total[i] > limit && n.type == Node::kReplicate) {
      diags().Report(DiagKind::LimitExceeded, n.e.GetLoc(),
                     fmt::format("<replicate count=\"{}\"> expands to more than {} elements, the "
                                 "elements limit (raise it with --limit elements=N)",
                                 n.count, limit));
      return false;
    }
  }
  return true;
}

void Expander::AddEntries(const std::vector<xml::XmlElement>& top, const ChildModel* child,
                          const std::string& prefix) {
  for (const auto& section : top) {
    if (!IsSection(section.Name())) continue;
    const auto items = child ? child->Children(section) : r_.Children(section);
    for (const auto& item : items) {
      EntryInfo info;
      info.own_kind = OwnKind(section.Name(), item.Name());
      info.own_name = std::string(item.Attribute("name").value);
      std::vector<xml::XmlElement> walk{item};
      while (!walk.empty()) {
        const xml::XmlElement x = walk.back();
        walk.pop_back();
        x.ForEachAttributeName([&](std::string_view a) {
          std::string kind = RefKind(x, a);
          if (!kind.empty()) info.refs.push_back({kind, std::string(x.Attribute(a).value)});
        });
        for (auto c = x.FirstChild(); c; c = c.NextSibling()) walk.push_back(c);
      }
      Entry entry{item, std::string(section.Name()), prefix, "", child != nullptr, true,
                  static_cast<int>(infos_.size()), entries_.size()};
      infos_.push_back(std::move(info));
      if (!child) {
        original_entry_[item.raw()] = entries_.size();
        entries_.push_back(std::move(entry));
        const EntryInfo& in = infos_.back();
        if (!in.own_name.empty()) AddName(Key(in.own_kind, in.own_name));
      } else if (Resolves(entry, prefix, "")) {
        const EntryInfo& in = infos_.back();
        if (!in.own_name.empty()) AddName(Key(in.own_kind, prefix + in.own_name));
        entries_.push_back(std::move(entry));
      }
    }
  }
}

bool Expander::Resolves(const Entry& c, const std::string& prefix,
                        const std::string& suffix) const {
  for (const Name& ref : infos_[c.info].refs) {
    if (ref.name.empty()) continue;
    if (!names_.contains(Key(ref.kind, prefix + ref.name + suffix))) return false;
  }
  return true;
}

/// Copies of the entries [from, to) with `suffix` appended, kept when every
/// name they refer to exists (MuJoCo's CopyList on a self-attach).
void Expander::CopyEntries(const std::string&, const std::string& suffix, size_t from, size_t to,
                           bool) {
  for (size_t j = from; j < to; ++j) {
    if (!entries_[j].alive) continue;
    Entry copy = entries_[j];
    copy.suffix = entries_[j].suffix + suffix;
    if (!Resolves(copy, copy.prefix, copy.suffix)) continue;
    const EntryInfo& in = infos_[copy.info];
    if (!in.own_name.empty()) AddName(Key(in.own_kind, copy.prefix + in.own_name + copy.suffix));
    entries_.push_back(std::move(copy));
  }
}

void Expander::Simulate() {
  // post-order over the nodes, children in document order
  std::vector<std::vector<Name>> result(nodes_.size());
  struct Visit {
    int node;
    size_t next = 0;
  };
  std::vector<Visit> stack{{0}};
  for (const Name& n : nodes_[0].own) AddName(Key(n.kind, n.name));
  while (!stack.empty()) {
    Visit& v = stack.back();
    Node& n = nodes_[v.node];
    if (v.next < n.children.size()) {
      const int c = n.children[v.next++];
      if (nodes_[c].type == Node::kReplicate) {
        for (const Name& x : nodes_[c].own) AddName(Key(x.kind, x.name));
      }
      stack.push_back({c});
      continue;
    }
    const int id = v.node;
    stack.pop_back();
    if (n.type == Node::kRoot) continue;
    std::vector<Name> names = std::move(n.own);
    for (int c : n.children) {
      for (Name& x : result[c]) names.push_back(std::move(x));
      result[c] = {};
    }
    if (n.type == Node::kAttach) {
      for (const Name& x : names) AddName(Key(x.kind, x.name));
      std::vector<xml::XmlElement> top = n.child->Children(n.child->root);
      AddEntries(top, n.child, n.prefix);
      result[id] = std::move(names);
      continue;
    }
    std::vector<Name> out;
    for (int i = 0; i < n.count; ++i) {
      const std::string s = Suffix(n.sep, n.count, i);
      for (const Name& x : names) {
        out.push_back({x.kind, x.name + s});
        AddName(Key(x.kind, out.back().name));
      }
      CopyEntries("", s, 0, entries_.size(), false);
    }
    // the subtree itself is deleted, and what referred into it
    absl::flat_hash_set<std::string> deleted;
    for (const Name& x : names) {
      deleted.insert(Key(x.kind, x.name));
      RemoveName(Key(x.kind, x.name));
    }
    for (Entry& entry : entries_) {
      if (!entry.alive) continue;
      const EntryInfo& in = infos_[entry.info];
      for (const Name& ref : in.refs) {
        const std::string k = Key(ref.kind, entry.prefix + ref.name + entry.suffix);
        if (deleted.contains(k) && !names_.contains(k)) {
          entry.alive = false;
          if (!in.own_name.empty()) {
            RemoveName(Key(in.own_kind, entry.prefix + in.own_name + entry.suffix));
          }
          break;
        }
      }
    }
    result[id] = std::move(out);
  }
  // MuJoCo drops, without a word, an element that referred into a
  // replicated subtree when no copy of it names only existing elements
  std::vector<bool> survives(entries_.size(), false);
  for (const Entry& entry : entries_) {
    if (entry.alive) survives[entry.origin] = true;
  }
  for (size_t i = 0; i < entries_.size(); ++i) {
    const Entry& entry = entries_[i];
    if (entry.origin != i || entry.foreign || survives[i]) continue;
    diags().Report(DiagKind::UnsupportedElement, entry.e.GetLoc(),
                   fmt::format("<{}> refers to an element inside a <replicate> and to names no "
                               "copy has (each copy renames all it refers to with the copy's "
                               "suffix); MuJoCo drops it with the replicated original, and so "
                               "does mdlc",
                               entry.e.Name()));
  }
}

void Expander::WriteEntry(xml::XmlDocumentBuilder& b, const Entry& entry) {
  const std::string& p = entry.prefix;
  const std::string& s = entry.suffix;
  const bool foreign = entry.foreign;
  const void* top = entry.e.raw();
  CopySubtree(
      b, entry.e, [](const xml::XmlElement& x) {
        std::vector<xml::XmlElement> out;
        for (auto c = x.FirstChild(); c; c = c.NextSibling()) out.push_back(c);
        return out;
      },
      [&](const xml::XmlElement& x, const xml::XmlAttribute& a) -> std::optional<std::string> {
        if (p.empty() && s.empty()) return std::nullopt;
        if (a.value.empty()) return std::nullopt;
        if ((a.name == "name" && x.raw() == top) || !RefKind(x, a.name).empty()) {
          if (a.name == "objname" || a.name == "refname" || a.name == "name" ||
              !RefKind(x, a.name).empty()) {
            return p + std::string(a.value) + s;
          }
        }
        if (foreign && (a.name == "class" || a.name == "material")) {
          return p + std::string(a.value);
        }
        return std::nullopt;
      });
}

void Expander::WriteWorldbody(xml::XmlDocumentBuilder& b, const xml::XmlElement& wb,
                              const std::vector<xml::XmlElement>& top) {
  std::vector<Naming> namings{{}};
  struct Item {
    enum Kind { kOpen, kClose, kFrame } kind;
    xml::XmlElement e;
    int naming = 0;
    const ChildModel* source = nullptr;
    Transform X;
    std::string childclass;
  };
  std::vector<Item> stack;
  auto children = [&](const xml::XmlElement& e, const ChildModel* source) {
    return source ? source->Children(e) : r_.Children(e);
  };
  auto push_children = [&](const std::vector<xml::XmlElement>& kids, int naming,
                           const ChildModel* source) {
    for (auto it = kids.rbegin(); it != kids.rend(); ++it) {
      stack.push_back({Item::kOpen, *it, naming, source, {}, {}});
    }
  };
  std::vector<xml::AttributeSpec> attrs;
  std::vector<std::string> values;
  std::vector<xml::AttributeSpec> world_attrs;
  wb.ForEachAttributeName([&](std::string_view name) {
    const xml::XmlAttribute a = wb.Attribute(name);
    world_attrs.push_back({a.name, a.value, a.loc});
  });
  b.StartElement("worldbody", wb.GetLoc(), world_attrs);
  std::vector<xml::XmlElement> all;
  for (const auto& t : top) {
    if (t.Name() != "worldbody") continue;
    for (const auto& c : r_.Children(t)) all.push_back(c);
  }
  push_children(all, 0, nullptr);
  while (!stack.empty()) {
    Item item = std::move(stack.back());
    stack.pop_back();
    if (item.kind == Item::kClose) {
      b.EndElement();
      continue;
    }
    const Loc loc = item.e.GetLoc();
    if (item.kind == Item::kFrame) {
      values.clear();
      attrs.clear();
      values.reserve(3);
      if (item.X.p != Eigen::Vector3d::Zero() || !item.X.R.isIdentity()) {
        const Eigen::Quaterniond q(item.X.R);
        values.push_back(fmt::format("{} {} {}", item.X.p.x(), item.X.p.y(), item.X.p.z()));
        values.push_back(fmt::format("{} {} {} {}", q.w(), q.x(), q.y(), q.z()));
        attrs.push_back({"pos", values[0], loc});
        attrs.push_back({"quat", values[1], loc});
      }
      if (!item.childclass.empty()) {
        const xml::XmlAttribute cc = item.e.Attribute("childclass");
        attrs.push_back({"childclass", item.childclass, cc.present() ? cc.loc : loc});
      }
      b.StartElement("frame", loc, attrs);
      continue;
    }
    const std::string_view tag = item.e.Name();
    if (item.source == nullptr && (tag == "replicate" || tag == "attach")) {
      auto it = node_of_.find(item.e.raw());
      if (it == node_of_.end()) continue;
      const Node& n = nodes_[it->second];
      const Naming outer = namings[item.naming];
      if (n.type == Node::kAttach) {
        namings.push_back({n.prefix + outer.prefix, outer.suffix, true});
        const int k = static_cast<int>(namings.size()) - 1;
        stack.push_back({Item::kClose, item.e});
        push_children(n.content, k, n.child);
        stack.push_back({Item::kFrame, item.e, 0, nullptr, {}, n.prefix + n.inherited});
        continue;
      }
      for (int i = n.count; i-- > 0;) {
        namings.push_back({outer.prefix, Suffix(n.sep, n.count, i) + outer.suffix, outer.foreign});
        const int k = static_cast<int>(namings.size()) - 1;
        stack.push_back({Item::kClose, item.e});
        push_children(r_.Children(item.e), k, nullptr);
        stack.push_back({Item::kFrame, item.e, 0, nullptr, n.frames[i], n.childclass});
      }
      continue;
    }
    const Naming& naming = namings[item.naming];
    const bool tree = !TreeKind(tag).empty();
    values.clear();
    attrs.clear();
    std::vector<std::pair<std::string_view, size_t>> renamed;
    item.e.ForEachAttributeName([&](std::string_view name) {
      const xml::XmlAttribute a = item.e.Attribute(name);
      std::optional<std::string> v;
      if (item.source) v = ConvertAngles(*item.source, r_.compiler, item.e, a, false);
      if (!v && !a.value.empty() && (!naming.prefix.empty() || !naming.suffix.empty())) {
        if ((tree && name == "name") || ((tag == "camera" || tag == "light") && name == "target")) {
          v = naming.prefix + std::string(a.value) + naming.suffix;
        } else if (naming.foreign &&
                   ((name == "class" || name == "childclass") ||
                    name == "mesh" || name == "material" || name == "hfield")) {
          v = naming.prefix + std::string(a.value);
        }
      }
      if (v) {
        renamed.push_back({name, values.size()});
        values.push_back(std::move(*v));
      }
      attrs.push_back({a.name, a.value, a.loc});
    });
    for (auto [name, index] : renamed) {
      for (auto& spec : attrs) {
        if (spec.name == name) spec.value = values[index];
      }
    }
    b.StartElement(tag, loc, attrs);
    stack.push_back({Item::kClose, item.e});
    if (tag == "body" || tag == "frame") push_children(children(item.e, item.source), item.naming,
                                                       item.source);
    else push_children(children(item.e, item.source), item.naming, item.source);
  }
  b.EndElement();
}

std::shared_ptr<const xml::XmlDocument> Expander::Write() {
  const std::vector<xml::XmlElement> top = r_.Children(root_);
  xml::XmlDocumentBuilder b(root_.GetLoc().file, r_.ctx.sources);
  auto copy_as_is = [&](const xml::XmlElement& e) {
    CopySubtree(
        b, e, [&](const xml::XmlElement& x) { return r_.Children(x); },
        [](const xml::XmlElement&, const xml::XmlAttribute&) { return std::nullopt; });
  };
  auto element_attrs = [](const xml::XmlElement& e) {
    std::vector<xml::AttributeSpec> attrs;
    e.ForEachAttributeName([&](std::string_view name) {
      const xml::XmlAttribute a = e.Attribute(name);
      attrs.push_back({a.name, a.value, a.loc});
    });
    return attrs;
  };
  absl::flat_hash_map<std::string_view, size_t> last_section;
  for (size_t i = 0; i < top.size(); ++i) {
    if (IsSection(top[i].Name())) last_section[top[i].Name()] = i;
  }
  auto write_copies = [&](std::string_view section) {
    for (const Entry& entry : entries_) {
      if (!entry.alive || entry.section != section) continue;
      if (!entry.foreign && entry.suffix.empty()) continue;  // written in place
      WriteEntry(b, entry);
    }
  };
  b.StartElement(root_.Name(), root_.GetLoc(), element_attrs(root_));
  bool wrote_world = false;
  for (size_t i = 0; i < top.size(); ++i) {
    const xml::XmlElement& e = top[i];
    const std::string_view tag = e.Name();
    if (tag == "worldbody") {
      // MuJoCo reads every <worldbody> into the one world body: the first
      // holds them all, so unnamed geoms are numbered as MuJoCo does
      if (!wrote_world) WriteWorldbody(b, e, top);
      wrote_world = true;
    } else if (tag == "asset") {
      b.StartElement(tag, e.GetLoc(), element_attrs(e));
      for (const auto& c : r_.Children(e)) {
        if (c.Name() != "model") copy_as_is(c);
      }
      b.EndElement();
    } else if (IsSection(tag)) {
      b.StartElement(tag, e.GetLoc(), element_attrs(e));
      for (const auto& c : r_.Children(e)) {
        auto it = original_entry_.find(c.raw());
        if (it == original_entry_.end() || entries_[it->second].alive) copy_as_is(c);
      }
      if (last_section[tag] == i) write_copies(tag);
      b.EndElement();
    } else {
      copy_as_is(e);
    }
  }
  // sections only attached models have
  for (std::string_view section : kSections) {
    if (last_section.contains(section)) continue;
    const Entry* first = nullptr;
    for (const Entry& entry : entries_) {
      if (entry.alive && entry.section == section && (entry.foreign || !entry.suffix.empty())) {
        first = &entry;
        break;
      }
    }
    if (!first) continue;
    b.StartElement(section, first->e.Parent().GetLoc(), {});
    write_copies(section);
    b.EndElement();
  }
  for (const auto& [child, prefix] : attached_) EmitAttachedDefaultsAndAssets(b, *child, prefix, r_.compiler);
  b.EndElement();
  return b.Finish();
}

Expansion Expander::Run() {
  const std::vector<xml::XmlElement> top = r_.Children(root_);
  for (const auto& section : top) {
    if (section.Name() != "asset") continue;
    for (const auto& m : r_.Children(section)) {
      if (m.Name() != "model") continue;
      r_.CheckAttributes(m, "model");
      const xml::XmlAttribute name = m.Attribute("name");
      if (name.present()) {
        model_assets_.emplace(std::string(name.value), m);
        continue;
      }
      // without a name, the model is known by its file's <mujoco model>
      std::unique_ptr<ChildModel> child = LoadChildModel(r_, m, chain_);
      if (!child) {
        failed_ = true;
        continue;
      }
      std::string key = child->name;
      models_.emplace(std::move(key), std::move(child));
    }
  }
  // the nodes: the worldbody, each replicate and attach in document order
  nodes_.push_back({});
  struct Work {
    xml::XmlElement e;
    int node;
  };
  std::vector<Work> stack;
  for (auto it = top.rbegin(); it != top.rend(); ++it) {
    if (it->Name() != "worldbody") continue;
    const auto kids = r_.Children(*it);
    for (auto k = kids.rbegin(); k != kids.rend(); ++k) stack.push_back({*k, 0});
  }
  while (!stack.empty()) {
    const Work w = stack.back();
    stack.pop_back();
    const std::string_view tag = w.e.Name();
    if (tag == "replicate" || tag == "attach") {
      Node n;
      n.type = tag == "replicate" ? Node::kReplicate : Node::kAttach;
      n.e = w.e;
      if (!(tag == "replicate" ? ReadReplicate(w.e, n) : ReadAttach(w.e, n))) {
        failed_ = true;
        continue;
      }
      if (tag == "attach") AttachKeys(n, w.node != 0);
      const int id = static_cast<int>(nodes_.size());
      nodes_[w.node].children.push_back(id);
      node_of_[w.e.raw()] = id;
      nodes_.push_back(std::move(n));
      if (tag == "replicate") {
        const auto kids = r_.Children(w.e);
        for (auto k = kids.rbegin(); k != kids.rend(); ++k) stack.push_back({*k, id});
      }
      continue;
    }
    Node& n = nodes_[w.node];
    ++n.elements;
    const std::string_view kind = TreeKind(tag);
    if (!kind.empty()) {
      if (auto nm = w.e.Attribute("name"); nm.present() && !nm.value.empty()) {
        n.own.push_back({std::string(kind), std::string(nm.value)});
      }
    }
    if (tag == "body" || tag == "frame") {
      const auto kids = r_.Children(w.e);
      for (auto k = kids.rbegin(); k != kids.rend(); ++k) stack.push_back({*k, w.node});
    } else {
      n.elements += 4;  // a leaf's children (plugin config) are few
    }
  }
  if (failed_ || !CheckSize()) return {nullptr, true};
  AddEntries(top, nullptr, "");
  Simulate();
  auto doc = Write();
  if (!doc) return {nullptr, true};
  return {std::move(doc), false};
}

}  // namespace

void CopySubtree(xml::XmlDocumentBuilder& b, const xml::XmlElement& e, const ChildrenOf& children,
                 const Rewrite& rewrite) {
  struct Item {
    xml::XmlElement e;
    bool close;
  };
  std::vector<Item> stack{{e, false}};
  std::vector<xml::AttributeSpec> attrs;
  std::vector<std::string> values;
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    if (item.close) {
      b.EndElement();
      continue;
    }
    attrs.clear();
    values.clear();
    std::vector<std::pair<size_t, size_t>> renamed;
    item.e.ForEachAttributeName([&](std::string_view name) {
      const xml::XmlAttribute a = item.e.Attribute(name);
      if (auto v = rewrite(item.e, a)) {
        renamed.push_back({attrs.size(), values.size()});
        values.push_back(std::move(*v));
      }
      attrs.push_back({a.name, a.value, a.loc});
    });
    for (auto [at, index] : renamed) attrs[at].value = values[index];
    b.StartElement(item.e.Name(), item.e.GetLoc(), attrs);
    stack.push_back({item.e, true});
    const auto kids = children(item.e);
    for (auto it = kids.rbegin(); it != kids.rend(); ++it) stack.push_back({*it, false});
  }
}

Expansion ExpandReplicateAndAttach(MjcfReader& r, const xml::XmlElement& root,
                                   const std::vector<std::string>& chain) {
  uint64_t found = 0;
  for (const auto& doc : r.document.documents) {
    found += doc->CountOf("replicate") + doc->CountOf("attach");
  }
  if (found == 0) return {};
  return Expander(r, root, chain).Run();
}

}  // namespace mdlc::frontend::mjcf
