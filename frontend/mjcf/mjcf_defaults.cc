// mjcf_defaults.cc - <default> classes (MJCF-011, MJCF-012) and the
// once-per-kind warnings of the frontend.
//
// MuJoCo copies a parent class into each nested class before reading the
// nested class's own elements, so "the nearest class in the chain that writes
// the attribute" is exactly what an element inherits. Element kinds are kept
// apart: a <geom> default applies to geoms only.
#include <fmt/format.h>

#include "frontend/mjcf/mjcf_reader_detail.h"

namespace mdlc::frontend::mjcf {

void DefaultClasses::Read(const xml::XmlElement& top, DiagnosticEngine& diags,
                          const MjcfDocument* document) {
  auto children = [&](const xml::XmlElement& e) {
    if (document) return document->Children(e);
    std::vector<xml::XmlElement> out;
    for (auto c = e.FirstChild(); c; c = c.NextSibling()) out.push_back(c);
    return out;
  };
  if (classes_.empty()) {
    classes_.push_back({"main", -1, {}});
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
        classes_.push_back({std::string(cls.value), 0, {}});
        by_name_.emplace(std::string(cls.value), index);
      }
    } else {
      if (!cls.present()) {
        diags.Report(DiagKind::MissingAttribute, w.e.GetLoc(),
                     "a nested <default> must have a 'class' attribute (only the top-level "
                     "default may omit it)");
        continue;
      }
      if (by_name_.count(std::string(cls.value))) {
        diags.Report(DiagKind::DuplicateName, cls.loc,
                     fmt::format("repeated default class name '{}'", cls.value));
        continue;
      }
      index = static_cast<int>(classes_.size());
      classes_.push_back({std::string(cls.value), w.parent, {}});
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
  return by_name_.count(std::string(class_name)) > 0 || class_name == "main";
}

std::vector<xml::XmlElement> DefaultClasses::Chain(std::string_view class_name,
                                                   std::string_view kind) const {
  std::vector<xml::XmlElement> out;
  auto it = by_name_.find(std::string(class_name));
  int index = it == by_name_.end() ? (classes_.empty() ? -1 : 0) : it->second;
  const std::string key(kind);
  while (index >= 0) {
    const ClassNode& node = classes_[index];
    auto k = node.kinds.find(key);
    if (k != node.kinds.end()) out.push_back(k->second);
    index = node.parent;
  }
  return out;
}

Attribute DefaultClasses::Lookup(std::string_view class_name, std::string_view kind,
                                 std::string_view name) const {
  for (const xml::XmlElement& e : Chain(class_name, kind)) {
    xml::XmlAttribute a = e.Attribute(name);
    if (a.present()) return a;
  }
  return {};
}

const std::vector<xml::XmlElement>& Element::Chain() const {
  if (!chain_) {
    chain_ = defaults_->Chain(class_, kind_);
    for (const xml::XmlElement& d : *chain_) chain_names_ |= d.AttributeNameBits();
  }
  return *chain_;
}

Attribute Element::Own(std::string_view name) const {
  if (!own_names_) own_names_ = e_.AttributeNameBits();
  if (!(*own_names_ & xml::XmlElement::NameBit(name))) return {};
  return e_.Attribute(name);
}

Attribute Element::Get(std::string_view name) const {
  if (xml::XmlAttribute own = Own(name); own.present()) return own;
  const std::vector<xml::XmlElement>& chain = Chain();
  if (!(chain_names_ & xml::XmlElement::NameBit(name))) return {};
  for (const xml::XmlElement& d : chain) {
    xml::XmlAttribute inherited = d.Attribute(name);
    if (inherited.present()) return inherited;
  }
  return {};
}

std::string MjcfReader::ClassFor(const xml::XmlElement& e, std::string_view childclass) {
  const xml::XmlAttribute cls = e.Attribute("class");
  if (cls.present()) {
    if (!defaults.Has(cls.value)) {
      diags().Report(DiagKind::UnknownReference, cls.loc,
                     fmt::format("unknown default class '{}'", cls.value));
      return "main";
    }
    return std::string(cls.value);
  }
  return childclass.empty() ? std::string("main") : std::string(childclass);
}

void MjcfReader::WarnOnce(Loc loc, DiagKind kind, std::string_view element, std::string_view name,
                          std::string_view why) {
  warn_key.assign(element).append(1, '\n').append(name);
  if (!warned.insert(warn_key).second) return;
  const bool is_element = kind == DiagKind::UnsupportedElement || kind == DiagKind::UnknownElement;
  diags().Report(kind, loc,
                 is_element ? fmt::format("element <{}> in <{}> {}", name, element, why)
                            : fmt::format("attribute '{}' of <{}> {}", name, element, why));
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
