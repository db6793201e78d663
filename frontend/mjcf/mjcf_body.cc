// mjcf_body.cc - <worldbody>: the body tree (MJCF-020, MJCF-021, MJCF-030,
// MJCF-091, BEYOND-004).
//
// Bodies are lowered in MuJoCo's (and Drake's) order, depth first in
// document order, from an explicit stack: 10,000 nested bodies cost heap,
// not call stack. Each body's children are gathered with the <frame>s they
// sit in folded into a pose and a childclass (MuJoCo 3's <frame>), then
// lowered: inertial, joints (mjcf_joint.cc), geoms, sites, cameras
// (mjcf_geom.cc). Child bodies go back on the stack.
#include <absl/container/inlined_vector.h>
#include <fmt/format.h>

#include <algorithm>

#include "frontend/mjcf/mjcf_lowering.h"

namespace mdlc::frontend::mjcf {
namespace {

/// A body's children, sorted by what they are, frames folded in.
struct BodyItems {
  // a body has a few of each: kept inline, not on the heap
  absl::InlinedVector<BodyItem, 2> inertials, joints, geoms, sites, cameras, bodies;
};

/// <composite> generates bodies, joints and geoms that mdlc does not create:
/// every one gets its own warning saying what is missing from the plant
/// (MJCF-091), not one warning per kind. (<attach> and <replicate> are
/// expanded before the tree is read: mjcf_replicate.h.)
void WarnModelGenerator(MjcfReader& r, const xml::XmlElement& e, std::string_view tag) {
  auto attr = [&](std::string_view name) {
    const xml::XmlAttribute a = e.Attribute(name);
    return a.present() ? std::string(a.value) : std::string("?");
  };
  std::string what;
  if (tag == "composite") {
    long bodies = 1;
    if (auto counts = xml::ParseDoubleList(e.Attribute("count").value)) {
      for (double c : *counts) bodies *= std::max(1L, static_cast<long>(c));
    }
    what = fmt::format(
        "<composite type=\"{}\"> is MuJoCo 2's body-generating macro (MuJoCo 3 replaced it with "
        "<flexcomp> and <replicate>); mdlc does not expand it, so the up to {} bodies it would "
        "generate, with their joints, geoms, tendons and equalities, are missing from the plant",
        attr("type"), bodies);
  }
  r.diags().Report(DiagKind::UnsupportedElement, e.GetLoc(), what);
}

BodyItems Collect(MjcfReader& r, const xml::XmlElement& body, const std::string& childclass,
                  bool is_world) {
  BodyItems items;
  struct Scope {
    std::vector<xml::XmlElement> children;
    size_t next = 0;
    Transform X_BF;
    std::string childclass;
  };
  std::vector<Scope> scopes;
  scopes.push_back({r.Children(body), 0, Transform(), childclass});
  while (!scopes.empty()) {
    Scope& s = scopes.back();
    if (s.next >= s.children.size()) {
      scopes.pop_back();
      continue;
    }
    const xml::XmlElement e = s.children[s.next++];
    const std::string_view tag = e.Name();
    BodyItem item{e, s.X_BF, s.childclass};
    if (tag == "frame") {
      r.CheckAttributes(e, "frame");
      // BEYOND-004: the frame's pose composes onto everything inside it
      auto X = r.ReadPose(Element(e, "frame"));
      std::string cls = s.childclass;
      if (auto cc = e.Attribute("childclass"); cc.present()) {
        if (r.defaults.Has(cc.value)) {
          cls = std::string(cc.value);
        } else {
          r.diags().Report(DiagKind::UnknownReference, cc.loc,
                           fmt::format("unknown default childclass '{}'", cc.value));
        }
      }
      Transform X_BF = s.X_BF * X.value_or(Transform());
      scopes.push_back({r.Children(e), 0, X_BF, std::move(cls)});
    } else if (tag == "inertial") {
      items.inertials.push_back(std::move(item));
    } else if (tag == "joint" || tag == "freejoint") {
      items.joints.push_back(std::move(item));
    } else if (tag == "geom") {
      items.geoms.push_back(std::move(item));
    } else if (tag == "site") {
      items.sites.push_back(std::move(item));
    } else if (tag == "camera") {
      items.cameras.push_back(std::move(item));
    } else if (tag == "body") {
      items.bodies.push_back(std::move(item));
    } else if (tag == "composite") {
      WarnModelGenerator(r, e, tag);
    } else if (tag == "flexcomp") {
      r.LeaveOut(e.GetLoc(), "<flexcomp>", kFlexLeftOut);
    } else if (tag == "plugin") {
      r.LeaveOut(e.GetLoc(), "<plugin> in a body", kPluginLeftOut);
    } else if (tag == "light") {
      r.WarnOnce(e.GetLoc(), DiagKind::UnsupportedElement, is_world ? "worldbody" : "body", tag);
    } else {
      r.WarnOnce(e.GetLoc(), DiagKind::UnknownElement, is_world ? "worldbody" : "body", tag,
                 "is not a MuJoCo element and is ignored (MuJoCo rejects it)",
                 {"body", "geom", "joint", "freejoint", "site", "camera", "inertial", "frame",
                  "light", "composite", "flexcomp", "attach", "replicate", "plugin"});
    }
  }
  return items;
}

/// MJCF-030: <inertial> -> ir::Inertial (nullopt after an error).
std::optional<ir::Inertial> ReadInertial(MjcfReader& r, const xml::XmlElement& e) {
  r.CheckAttributes(e, "inertial");
  const Element in(e, "inertial");
  ir::Inertial inertial;
  inertial.loc = e.GetLoc();
  if (!e.Attribute("mass").present()) {
    r.diags().Report(DiagKind::MissingAttribute, e.GetLoc(),
                     "the <inertial> element must have a 'mass' attribute");
    return std::nullopt;
  }
  if (!e.Attribute("pos").present()) {
    // MuJoCo requires it; Drake (and mdlc) read the COM as the origin
    r.WarnOnce(e.GetLoc(), DiagKind::UnsupportedAttribute, "inertial", "pos",
               "is missing (MuJoCo requires it); the center of mass is the body origin");
  }
  auto mass = r.Number(in, "mass", 0);
  auto pose = r.ReadPose(in);
  if (!mass || !pose) return std::nullopt;
  inertial.mass = *mass;
  inertial.X_BI = *pose;
  const bool diag = e.Attribute("diaginertia").present();
  const bool full = e.Attribute("fullinertia").present();
  if (diag && full) {
    r.diags().Report(DiagKind::BadValue, e.Attribute("fullinertia").loc,
                     "fullinertia and diaginertia cannot both be specified");
    return std::nullopt;
  }
  if (diag) {
    double d[3];
    if (!r.FixedNumbers(in, "diaginertia", d, 3)) return std::nullopt;
    inertial.ixx = d[0];
    inertial.iyy = d[1];
    inertial.izz = d[2];
  } else if (full) {
    for (std::string_view alt : {"quat", "axisangle", "xyaxes", "zaxis", "euler"}) {
      if (e.Attribute(alt).present() && alt != "quat") {
        r.diags().Report(DiagKind::BadValue, e.Attribute(alt).loc,
                         "fullinertia and an inertial orientation cannot both be specified");
        return std::nullopt;
      }
    }
    double f[6];
    if (!r.FixedNumbers(in, "fullinertia", f, 6)) return std::nullopt;
    // the matrix is in the body's axes: MuJoCo ignores quat when fullinertia is given
    inertial.X_BI.R.setIdentity();
    inertial.ixx = f[0];
    inertial.iyy = f[1];
    inertial.izz = f[2];
    inertial.ixy = f[3];
    inertial.ixz = f[4];
    inertial.iyz = f[5];
  } else {
    r.diags().Report(DiagKind::MissingAttribute, e.GetLoc(),
                     "the <inertial> element must have a 'diaginertia' or 'fullinertia' "
                     "attribute");
    return std::nullopt;
  }
  return inertial;
}

/// Geoms, sites and cameras of one body, in document order per kind.
void LowerAttachments(MjcfReader& r, const BodyItems& items, BodyId body, bool is_world,
                      bool mass_from_geometry) {
  int index = 0;
  for (const BodyItem& g : items.geoms) {
    if (LowerGeom(r, g, body, is_world, mass_from_geometry, index)) ++index;
  }
  for (const BodyItem& s : items.sites) LowerSite(r, s, body);
  for (const BodyItem& c : items.cameras) LowerCamera(r, c, body);
}

}  // namespace

void MjcfReader::LowerWorldBody(const xml::XmlElement& worldbody) {
  ir::Module& m = module();
  if (body_order.empty()) {
    body_order.push_back(ir::kWorldBody);
    bodies.Insert(m.Intern("world"), ir::kWorldBody);
  }
  worldbody.ForEachAttributeName([&](std::string_view name) {
    diags().Report(DiagKind::BadValue, worldbody.Attribute(name).loc,
                   fmt::format("the world body cannot have attributes ('{}')", name));
  });

  BodyItems world = Collect(*this, worldbody, "", /*is_world=*/true);
  for (const BodyItem& e : world.inertials) {
    diags().Report(DiagKind::BadValue, e.e.GetLoc(), "the world body cannot have inertia");
  }
  for (const BodyItem& e : world.joints) {
    diags().Report(DiagKind::BadValue, e.e.GetLoc(), "the world body cannot have joints");
  }
  LowerAttachments(*this, world, ir::kWorldBody, /*is_world=*/true, false);

  // per body of this <worldbody>, by its index in m.bodies past `first`:
  // what the inertiafromgeom=false check needs, kept only for that check
  struct Record {
    bool moves = false, has_inertial = false;
    std::vector<uint32_t> welded_children;
    Loc loc;
  };
  const bool check_massless = compiler.inertia_from_geom == InertiaFromGeom::False;
  const uint32_t first = static_cast<uint32_t>(m.bodies.size());
  std::vector<Record> records;  // in body order: deterministic reports
  // the joints' massless in-between bodies get no record of their own
  auto record = [&](uint32_t body) -> Record& {
    const size_t at = body - first;
    if (at >= records.size()) records.resize(at + 1);
    return records[at];
  };

  struct Pending {
    BodyItem item;
    BodyId parent;
    std::string parent_name;
    Transform X_WP0;
    bool parent_is_world;
    bool parent_is_fixed_root = false;  // a joint-less child of the world
  };
  std::vector<Pending> stack;
  for (auto it = world.bodies.rbegin(); it != world.bodies.rend(); ++it) {
    stack.push_back({*it, ir::kWorldBody, "world", Transform(), true});
  }
  while (!stack.empty()) {
    Pending p = std::move(stack.back());
    stack.pop_back();
    const xml::XmlElement e = p.item.e;
    CheckAttributes(e, "body");

    BodyContext b;
    b.e = e;
    b.parent = p.parent;
    const xml::XmlAttribute name_attr = e.Attribute("name");
    // MJCF-020: Drake's default name counts every body of the plant so far
    b.name = name_attr.present() ? std::string(name_attr.value)
                                 : fmt::format("body{}", m.bodies.size());
    std::string childclass = p.item.childclass;
    if (auto cc = e.Attribute("childclass"); cc.present()) {
      if (defaults.Has(cc.value)) {
        childclass = std::string(cc.value);
      } else {
        diags().Report(DiagKind::UnknownReference, cc.loc,
                       fmt::format("unknown default childclass '{}'", cc.value));
      }
    }
    b.X_PB0 = p.item.X_BF * ReadPose(Element(e, "body")).value_or(Transform());
    b.X_WB0 = p.X_WP0 * b.X_PB0;

    BodyItems items = Collect(*this, e, childclass, false);
    b.simple_position = items.bodies.empty() && (p.parent_is_world || p.parent_is_fixed_root);

    ir::Body body;
    body.name = m.Intern(b.name);
    body.unnamed = !name_attr.present();
    body.model = model;
    body.loc = e.GetLoc();
    std::optional<ir::Inertial> inertial;
    if (!items.inertials.empty()) {
      for (size_t i = 1; i < items.inertials.size(); ++i) {
        diags().Report(DiagKind::BadValue, items.inertials[i].e.GetLoc(),
                       "a body can have only one <inertial>");
      }
      inertial = ReadInertial(*this, items.inertials.front().e);
    }
    // MJCF-005, MJCF-031: when MuJoCo computes the mass from geoms
    b.mass_from_geometry = compiler.inertia_from_geom == InertiaFromGeom::True ||
                           (compiler.inertia_from_geom == InertiaFromGeom::Auto &&
                            items.inertials.empty());
    body.inertial = inertial;
    body.mass_from_geometry = b.mass_from_geometry;
    b.body = m.Add(std::move(body));
    b.original = ReadOriginalName(e, b.body, ctx);
    body_order.push_back(b.body);
    if (name_attr.present()) {
      auto [first, inserted] = bodies.Insert(m[b.body].name, b.body);
      if (!inserted) {
        diags()
            .Report(DiagKind::DuplicateName, name_attr.loc,
                    fmt::format("repeated body name '{}'", b.name))
            .Note(m[first].loc, "the first body of that name is here");
      }
    }

    bool mocap = false;
    if (auto mo = Boolean(Element(e, "body"), "mocap", false); mo && *mo) {
      mocap = true;
      if (!p.parent_is_world || !items.joints.empty()) {
        diags().Report(DiagKind::BadValue, e.Attribute("mocap").loc,
                       fmt::format("mocap body '{}' is not a fixed child of world", b.name));
      }
      diags().Report(DiagKind::MocapBody, e.Attribute("mocap").loc,
                     fmt::format("mocap body '{}' is welded to the world at its pose: mocap "
                                 "motion is not modelled",
                                 b.name));
    }
    for (std::string_view a : {"gravcomp", "user"}) WarnUnsupported(e, a);

    LowerJoints(*this, b, items.joints, mocap);
    // issue 62: MuJoCo 3.3.8 aligns a body whose one joint is free and which
    // has no child bodies, when the free joint's align is "true", or "auto"
    // (its default) under compiler@alignfree="true"
    if (items.joints.size() == 1 && items.bodies.empty() && !free_joints.empty() &&
        m[free_joints.back()].child.id == b.body) {
      bool align = compiler.alignfree;
      if (const xml::XmlAttribute a = items.joints.front().e.Attribute("align");
          a.present() && items.joints.front().e.Name() == "freejoint") {
        if (a.value == "true" || a.value == "false") {
          align = a.value == "true";
        } else if (a.value != "auto") {
          diags().Report(DiagKind::BadValue, a.loc,
                         fmt::format("align must be true, false or auto, not '{}'", a.value));
        }
      }
      m[b.body].align_free = align;
    }
    LowerAttachments(*this, items, b.body, false, b.mass_from_geometry);

    if (check_massless) {
      const bool moves = !items.joints.empty();
      if (!moves && !p.parent_is_world) {
        record(p.parent.value).welded_children.push_back(b.body.value);
      }
      Record& rec = record(b.body.value);
      rec.moves = moves;
      rec.has_inertial = !items.inertials.empty();
      rec.loc = e.GetLoc();
    }

    for (auto it = items.bodies.rbegin(); it != items.bodies.rend(); ++it) {
      stack.push_back({*it, b.body, b.name, b.X_WB0, false,
                       p.parent_is_world && items.joints.empty()});
    }
  }

  // MJCF-005: inertiafromgeom=false leaves a body without <inertial>
  // massless; MuJoCo rejects a moving body whose mass is zero, unless a
  // body welded to it (directly or through other welded bodies) has mass.
  if (check_massless) {
    for (size_t index = 0; index < records.size(); ++index) {
      const Record& rec = records[index];
      if (!rec.moves || rec.has_inertial) continue;
      bool found = false;
      std::vector<uint32_t> work = rec.welded_children;
      while (!work.empty() && !found) {
        const Record& child = records[work.back() - first];
        work.pop_back();
        found = child.has_inertial;
        work.insert(work.end(), child.welded_children.begin(), child.welded_children.end());
      }
      if (!found) {
        diags().Report(DiagKind::MissingElement, rec.loc,
                       fmt::format("body '{}' moves but has no <inertial> and "
                                   "inertiafromgeom=false: you must specify an inertia",
                                   m.Text(m.bodies[first + index].name)));
      }
    }
  }
}

}  // namespace mdlc::frontend::mjcf
