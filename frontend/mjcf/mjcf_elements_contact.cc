// mjcf_elements_contact.cc - <contact> (MJCF-070).
//
// <exclude body1 body2>: the two bodies never collide. It becomes a collision
// filter group holding both bodies that ignores itself, which filters
// exactly that pair (a body is never filtered against itself), so the
// plant's collision_filters gain the one pair Drake's ExcludeBetween adds.
// Missing body1/body2 W (ignored), as Drake; an unknown body E at the name.
//
// <pair geom1 geom2>: MuJoCo's explicit contact pair. The plant already lets
// two proximity geometries collide unless a filter says otherwise, so there
// is nothing to add; the frontend warns where the pair asks for more than the
// plant does: geoms on bodies a joint connects (Drake filters adjacent
// bodies), geoms without a proximity role (contype=conaffinity=0, which
// MuJoCo's pairs still collide), and condim/friction. Unknown geoms W.
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <unordered_set>

#include "frontend/mjcf/mjcf_elements.h"

namespace mdlc::frontend::mjcf {

namespace {

void LowerExclude(ElementsLowering& L, const Element& e, std::unordered_set<std::string>& names) {
  const xml::XmlElement& x = e.xml();
  L.r.attrs.WarnUnknownAttributes(x, {"name", "body1", "body2"});
  const Attribute b1 = e.Get("body1"), b2 = e.Get("body2");
  if (!b1.present() || !b2.present()) {
    L.diags().Report(DiagKind::UnsupportedElement, e.loc(),
                     "<exclude> needs both 'body1' and 'body2'; it is ignored");
    return;
  }
  std::optional<BodyId> body1 = L.FindBody(b1, "exclude");
  std::optional<BodyId> body2 = L.FindBody(b2, "exclude");
  if (!body1 || !body2 || *body1 == *body2) return;

  // a group name unique in the model: the exclude's own name, else synthesized
  std::string name = e.HasOwn("name") ? std::string(x.Attribute("name").value)
                                      : fmt::format("exclude{}", names.size());
  while (!names.insert(name).second) name += "_";

  ir::CollisionFilterGroup g;
  g.name = L.module().Intern(name);
  g.model = L.r.model;
  g.loc = e.loc();
  g.members = {L.BodyRef(*body1, b1.loc), L.BodyRef(*body2, b2.loc)};
  const FilterGroupId self(static_cast<uint32_t>(L.module().filter_groups.size()));
  g.ignored_groups = {{g.name, e.loc(), self}};
  L.module().Add(std::move(g));
}

/// The body pairs a joint of the model connects, gathered on first use:
/// looking through every joint for each <pair> cost pairs x joints.
class JointedBodies {
 public:
  bool Contains(ElementsLowering& L, BodyId a, BodyId b) {
    if (!pairs_) {
      pairs_.emplace();
      for (const ir::Joint& j : L.module().joints) {
        if (j.model != L.r.model) continue;
        std::optional<BodyId> p = L.BodyOf(j.parent), c = L.BodyOf(j.child);
        if (p && c) pairs_->insert(Key(*p, *c));
      }
    }
    return pairs_->count(Key(a, b)) != 0;
  }

 private:
  static uint64_t Key(BodyId a, BodyId b) {
    const auto [lo, hi] = std::minmax(a.value, b.value);
    return (uint64_t{lo} << 32) | hi;
  }
  std::optional<std::unordered_set<uint64_t>> pairs_;
};

void LowerPair(ElementsLowering& L, const Element& e, JointedBodies& jointed) {
  const xml::XmlElement& x = e.xml();
  L.r.attrs.WarnUnknownAttributes(x, {"name", "class", "geom1", "geom2", "condim", "friction",
                                      "solref", "solreffriction", "solimp", "gap", "margin"});
  const Attribute g1 = e.Get("geom1"), g2 = e.Get("geom2");
  if (!g1.present() || !g2.present()) {
    L.diags().Report(DiagKind::UnsupportedElement, e.loc(),
                     "<pair> needs both 'geom1' and 'geom2'; it is ignored");
    return;
  }
  for (const Attribute* g : {&g1, &g2}) {
    if (L.r.geoms.Find(L.module().symbols, g->value)) continue;
    L.diags().Report(DiagKind::IgnoredReference, g->loc,
                     fmt::format("<pair> names {} '{}', which is no geom of the model; the "
                                 "pair is ignored",
                                 g->name, g->value));
    return;
  }
  L.WarnAttribute(e, "pair", "condim");
  L.WarnAttribute(e, "pair", "friction");
  const ir::Geometry& geom1 = L.module()[*L.r.geoms.Find(L.module().symbols, g1.value)];
  const ir::Geometry& geom2 = L.module()[*L.r.geoms.Find(L.module().symbols, g2.value)];
  if (!(geom1.roles & ir::kProximityRole) || !(geom2.roles & ir::kProximityRole)) {
    L.WarnValueOnce("pair/no-proximity", e.loc(),
                    fmt::format("contact pair between geoms {} and {}: a geom without a "
                                "collision role (contype=conaffinity=0) does not collide in "
                                "the plant; the pair is ignored",
                                g1.value, g2.value));
    return;
  }
  std::optional<BodyId> body1 = L.BodyOf(geom1.body), body2 = L.BodyOf(geom2.body);
  if (body1 && body2 && jointed.Contains(L, *body1, *body2)) {
    L.diags().Report(
        DiagKind::UnsupportedValue, e.loc(),
        fmt::format("<pair> of geoms '{}' and '{}' has no effect: their bodies are joined by "
                    "a joint, and the plant filters collisions between such bodies",
                    g1.value, g2.value));
  }
}

}  // namespace

void LowerContact(ElementsLowering& L, const xml::XmlElement& section) {
  std::unordered_set<std::string> names;
  JointedBodies jointed;
  for (const ir::CollisionFilterGroup& g : L.module().filter_groups) {
    if (g.model == L.r.model) names.insert(std::string(L.module().Text(g.name)));
  }
  for (const xml::XmlElement& child : L.r.Children(section)) {
    const std::string_view tag = child.Name();
    if (tag == "exclude") {
      LowerExclude(L, L.r.Resolve(child, "exclude", ""), names);
    } else if (tag == "pair") {
      LowerPair(L, L.r.Resolve(child, "pair", ""), jointed);
    } else {
      L.WarnOnce(fmt::format("contact-unknown/{}", tag), DiagKind::UnknownElement,
                 child.GetLoc(), fmt::format("unknown element <{}> in <contact> is ignored", tag));
    }
  }
}

}  // namespace mdlc::frontend::mjcf
