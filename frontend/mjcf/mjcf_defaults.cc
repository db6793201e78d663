// mjcf_defaults.cc - <default> classes (MJCF-011, MJCF-012), the layers an
// element inherits (mjcf_defaults.h), and the once-per-kind warnings of the
// frontend.
#include <algorithm>

#include <fmt/format.h>

#include "frontend/mjcf/mjcf_reader_detail.h"
#include "ir/scoped_name.h"

namespace mdlc::frontend::mjcf {
namespace {

// The tables' string keys are looked up without a copy; the installed absl
// hashes its own string_view type, not std::string_view.
absl::string_view Key(std::string_view text) { return {text.data(), text.size()}; }

}  // namespace

void DefaultClasses::Read(const xml::XmlElement& top, DiagnosticEngine& diags,
                          const MjcfDocument* document) {
  auto children = [&](const xml::XmlElement& e) {
    if (document) return document->Children(e);
    std::vector<xml::XmlElement> out;
    for (auto c = e.FirstChild(); c; c = c.NextSibling()) out.push_back(c);
    return out;
  };
  // layers are worked out from the classes as all <default>s leave them
  layers_.clear();
  for (ClassNode& node : classes_) node.layers.clear();
  if (classes_.empty()) {
    classes_.push_back({"main", -1, {}, {}});
    by_name_.emplace("main", 0);
  }
  struct Work {
    xml::XmlElement e;
    int parent;  // -1: the top-level <default>
  };
  std::vector<Work> stack{{top, -1}};
  while (!stack.empty()) {
    Work w = stack.back();
    stack.pop_back();
    const xml::XmlAttribute cls = w.e.Attribute("class");
    int index = 0;
    if (w.parent < 0) {
      // top level: class "main" (the name is optional there)
      if (cls.present() && cls.value != "main") {
        index = static_cast<int>(classes_.size());
        classes_.push_back({std::string(cls.value), 0, {}, {}});
        by_name_.emplace(std::string(cls.value), index);
      }
    } else {
      if (!cls.present()) {
        diags.Report(DiagKind::MissingAttribute, w.e.GetLoc(),
                     "a nested <default> must have a 'class' attribute (only the top-level "
                     "default may omit it)");
        continue;
      }
      if (by_name_.contains(Key(cls.value))) {
        diags.Report(DiagKind::DuplicateName, cls.loc,
                     fmt::format("repeated default class name '{}'", cls.value));
        continue;
      }
      index = static_cast<int>(classes_.size());
      classes_.push_back({std::string(cls.value), w.parent, {}, {}});
      by_name_.emplace(std::string(cls.value), index);
    }
    std::vector<Work> nested;
    for (const xml::XmlElement& c : children(w.e)) {
      if (c.Name() == "default") {
        nested.push_back({c, index});
      } else {
        // a later element of the same kind in one class replaces the earlier
        classes_[index].kinds[std::string(c.Name())] = c;
      }
    }
    for (auto it = nested.rbegin(); it != nested.rend(); ++it) stack.push_back(*it);
  }
}

bool DefaultClasses::Has(std::string_view class_name) const {
  return class_name == "main" || by_name_.contains(Key(class_name));
}

int DefaultClasses::IndexOf(std::string_view class_name) const {
  auto it = by_name_.find(Key(class_name));
  return it == by_name_.end() ? 0 : it->second;
}

const DefaultLayer* DefaultClasses::Layers(int class_index, std::string_view kind) const {
  if (class_index < 0 || class_index >= static_cast<int>(classes_.size())) return nullptr;
  // up to the nearest class that knows its answer; each class passed on the
  // way gets its own, root side first, so each (class, kind) is worked once
  std::vector<int> unknown;
  const DefaultLayer* above = nullptr;
  for (int c = class_index; c >= 0; c = classes_[c].parent) {
    if (auto it = classes_[c].layers.find(Key(kind)); it != classes_[c].layers.end()) {
      above = it->second;
      break;
    }
    unknown.push_back(c);
  }
  for (auto c = unknown.rbegin(); c != unknown.rend(); ++c) {
    const ClassNode& node = classes_[*c];
    if (auto k = node.kinds.find(Key(kind)); k != node.kinds.end()) {
      above = &layers_.emplace_back(k->second, above);
    }
    node.layers.emplace(std::string(kind), above);
  }
  return above;
}

Inherited DefaultLayer::Find(std::string_view name) const {
  const uint64_t bit = xml::XmlElement::NameBit(name);
  int up = 0;
  for (const DefaultLayer* layer = this; layer; layer = layer->parent_, ++up) {
    if (!(layer->chain_names_ & bit)) return {};
    if (up == kShortWalk) {
      Inherited far = layer->FindRemembered(name, bit);
      far.level += up;
      return far;
    }
    if (Attribute a = layer->e_.Attribute(name); a.present()) return {a, up};
  }
  return {};
}

Inherited DefaultLayer::FindRemembered(std::string_view name, uint64_t bit) const {
  // up to the layer that answers (writes the name, or remembers the
  // answer), or past the last that could; the layers passed on the way
  // remember the answer too
  std::vector<const DefaultLayer*> passed;
  Inherited answer;  // relative to the layer the walk stopped at
  for (const DefaultLayer* layer = this; layer; layer = layer->parent_) {
    if (!(layer->chain_names_ & bit)) break;
    if (auto it = layer->found_.find(Key(name)); it != layer->found_.end()) {
      answer = it->second;
      break;
    }
    if (Attribute a = layer->e_.Attribute(name); a.present()) {
      answer = {a, 0};
      layer->found_.emplace(std::string(name), answer);
      break;
    }
    passed.push_back(layer);
  }
  for (auto layer = passed.rbegin(); layer != passed.rend(); ++layer) {
    if (answer.attribute.present()) ++answer.level;
    (*layer)->found_.emplace(std::string(name), answer);
  }
  return answer;
}

const LayeredPrefix& DefaultLayer::Layered(std::string_view name, size_t n) const {
  std::pair<std::string, size_t> key(name, n);
  if (auto it = layered_.find(key); it != layered_.end()) return it->second;
  // down from the nearest layer above that remembers its values (or the
  // root), each layer on the way remembering what it leaves
  std::vector<const DefaultLayer*> unknown{this};
  LayeredPrefix values{std::vector<double>(n, 0.0), 0, true};
  for (const DefaultLayer* layer = parent_; layer; layer = layer->parent_) {
    if (auto it = layer->layered_.find(key); it != layer->layered_.end()) {
      values = it->second;
      break;
    }
    unknown.push_back(layer);
  }
  for (auto layer = unknown.rbegin(); layer != unknown.rend(); ++layer) {
    const Attribute a = (*layer)->e_.Attribute(name);
    if (a.present() && values.ok) {
      const auto count = xml::ParseDoublesInto(a.value, values.values.data(), n);
      if (count && *count <= n) {
        values.written = std::max(values.written, *count);
      } else {
        values.ok = false;  // the reader walks the layers again to say where
      }
    }
    (*layer)->layered_.emplace(key, values);
  }
  return layered_.at(key);
}

const DefaultLayer* Element::Layers() const {
  if (!layers_known_) {
    layers_ = defaults_ ? defaults_->Layers(class_index_, kind_) : nullptr;
    layers_known_ = true;
  }
  return layers_;
}

Attribute Element::Own(std::string_view name) const {
  if (!own_names_known_) {
    own_names_ = e_.AttributeNameBits();
    own_names_known_ = true;
  }
  if (!(own_names_ & xml::XmlElement::NameBit(name))) return {};
  return e_.Attribute(name);
}

Attribute Element::Get(std::string_view name) const {
  if (Attribute own = Own(name); own.present()) return own;
  const DefaultLayer* layers = Layers();
  return layers ? layers->Find(name).attribute : Attribute{};
}

int MjcfReader::ClassFor(const xml::XmlElement& e, std::string_view childclass) {
  const xml::XmlAttribute cls = e.Attribute("class");
  if (cls.present()) {
    if (!defaults.Has(cls.value)) {
      diags().Report(DiagKind::UnknownReference, cls.loc,
                     fmt::format("unknown default class '{}'", cls.value));
      return defaults.IndexOf("main");
    }
    return defaults.IndexOf(cls.value);
  }
  return defaults.IndexOf(childclass.empty() ? std::string_view("main") : childclass);
}

void MjcfReader::WarnOnce(Loc loc, DiagKind kind, std::string_view element, std::string_view name,
                          std::string_view why, std::initializer_list<std::string_view> known) {
  warn_key.assign(element).append(1, '\n').append(name);
  if (!warned.insert(warn_key).second) return;
  const bool is_element = kind == DiagKind::UnsupportedElement || kind == DiagKind::UnknownElement;
  auto diag = diags().Report(kind, loc,
                             is_element
                                 ? fmt::format("element <{}> in <{}> {}", name, element, why)
                                 : fmt::format("attribute '{}' of <{}> {}", name, element, why));
  if (auto best = ir::ClosestName(name, std::vector(known))) {
    diag.Note(loc, is_element ? fmt::format("did you mean <{}>?", *best)
                              : fmt::format("did you mean '{}'?", *best));
  }
}

void MjcfReader::CheckDefaultAttributes(const xml::XmlElement& top) {
  // issue 62: a misspelt attribute in a class is as silent in the model as
  // one on the element itself, so it gets the same warning (and, like it,
  // is ignored). Elements whose kind the schema does not list are left to
  // the sections that read them.
  std::vector<xml::XmlElement> work{top};
  while (!work.empty()) {
    const xml::XmlElement d = work.back();
    work.pop_back();
    CheckAttributes(d, "default");
    // the class's own elements in document order, then its nested classes
    std::vector<xml::XmlElement> nested;
    for (const xml::XmlElement& c : Children(d)) {
      if (c.Name() == "default") {
        nested.push_back(c);
      } else {
        CheckAttributes(c, c.Name());
      }
    }
    work.insert(work.end(), nested.rbegin(), nested.rend());
  }
}

void MjcfReader::LeaveOut(Loc loc, std::string_view construct, std::string_view why) {
  warn_key.assign("left out\n").append(construct);
  if (!warned.insert(warn_key).second) return;
  diags().Report(DiagKind::UnsupportedElement, loc,
                 fmt::format("{} is left out of the plant, here and everywhere else in this "
                             "file: {}",
                             construct, why));
}

void MjcfReader::WarnUnsupported(const xml::XmlElement& e, std::string_view what) {
  const xml::XmlAttribute a = e.Attribute(what);
  if (a.present()) {
    WarnOnce(a.loc, DiagKind::UnsupportedAttribute, e.Name(), what);
    return;
  }
  for (auto c = e.FirstChild(); c; c = c.NextSibling()) {
    if (c.Name() == what) {
      WarnOnce(c.GetLoc(), DiagKind::UnsupportedElement, e.Name(), what);
      return;
    }
  }
}

}  // namespace mdlc::frontend::mjcf
