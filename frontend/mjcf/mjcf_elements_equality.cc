// mjcf_elements_equality.cc - <equality> (MJCF-080, BEYOND-003).
//
//   connect  -> ball constraint. Body form (body1 + anchor [+ body2, default
//               world]): P is the anchor in body1; Q is the same point in
//               body2 at qpos0, as MuJoCo's mj_setConst and Drake's
//               AddBallConstraint (p_BQ omitted) both complete it. Site form
//               (site1 + site2): P and Q are the two sites.
//   weld     -> weld constraint. MuJoCo's weld holds body1's point `relpose
//               pos` on body2's point `anchor`, and body1's orientation times
//               `relpose quat` on body2's: X_AP = relpose, X_BQ = (anchor, I).
//               When the relpose quaternion is all zeros (its default),
//               MuJoCo 3 uses the relative pose at qpos0 instead. Site form:
//               the two site frames coincide.
//   joint    -> coupler: MuJoCo holds q1 - ref1 = c0 + c1 (q2 - ref2) + ...
//               so joint1 follows joint2 with gear c1 and offset
//               c0 + ref1 - c1 ref2: Drake's joint0 is MJCF's joint1, its
//               joint1 MJCF's joint2. Without joint2, joint1 is held at
//               ref1 + c0: a tendon constraint with equal bounds on it alone.
//   distance -> (MuJoCo 2.x, removed in 2.2.2) distance constraint between
//               the geoms' centers; sphere radii are added to the distance.
//   tendon, flex -> W, ignored.
// `active="false"`: MuJoCo compiles the constraint but starts it disabled;
// Drake's constraints start enabled, so it is left out (W). solref and
// solimp are solver settings, silently ignored (as Drake does). The
// "equality" default class supplies `active` only: MuJoCo reads no other
// equality attribute from defaults.
#include <fmt/format.h>

#include <Eigen/Geometry>

#include "frontend/mjcf/mjcf_elements.h"

namespace mdlc::frontend::mjcf {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

class EqualityLowering {
 public:
  EqualityLowering(ElementsLowering& L, const Element& e) : L_(L), e_(e), x_(e.xml()) {}

  void Lower() {
    const std::string_view tag = x_.Name();
    if (tag == "connect") {
      Known({"name", "class", "body1", "body2", "anchor", "site1", "site2", "active", "solref",
             "solimp"});
      if (Active()) Connect();
    } else if (tag == "weld") {
      Known({"name", "class", "body1", "body2", "relpose", "anchor", "site1", "site2", "active",
             "solref", "solimp", "torquescale"});
      if (Active()) Weld();
    } else if (tag == "joint") {
      Known({"name", "class", "joint1", "joint2", "polycoef", "active", "solref", "solimp"});
      if (Active()) Joint();
    } else if (tag == "distance") {
      Known({"name", "class", "geom1", "geom2", "distance", "active", "solref", "solimp"});
      if (Active()) Distance();
    } else if (tag == "tendon" || tag == "flex") {
      L_.WarnOnce(fmt::format("equality/{}", tag), DiagKind::UnsupportedElement, e_.loc(),
                  fmt::format("<equality><{}> is not supported by the plant and is ignored",
                              tag));
    } else {
      L_.WarnOnce(fmt::format("equality-unknown/{}", tag), DiagKind::UnknownElement, e_.loc(),
                  fmt::format("unknown element <{}> in <equality> is ignored", tag));
    }
  }

 private:
  void Known(std::initializer_list<std::string_view> names) {
    L_.r.attrs.WarnUnknownAttributes(x_, names);
  }

  // false when the constraint starts disabled (and is left out)
  bool Active() {
    const Attribute a = e_.Get("active");
    std::optional<bool> active = L_.Bool(a);
    if (!active || *active) return true;
    L_.WarnOnce("equality/active", DiagKind::UnsupportedValue, a.loc,
                fmt::format("<{}> active=\"false\": MuJoCo starts this constraint disabled; the "
                            "plant's constraints start enabled, so it is left out",
                            x_.Name()));
    return false;
  }

  /// Adds the constraint `payload`, located at this element.
  void Add(ir::ConstraintPayload payload) {
    L_.module().Add(ir::Constraint{L_.r.model, e_.loc(), std::move(payload)});
  }

  // body1/body2 of the body form; nullopt after an error
  std::optional<std::pair<BodyId, BodyId>> Bodies() {
    const Attribute b1 = e_.Get("body1"), b2 = e_.Get("body2");
    std::optional<BodyId> body1 = L_.FindBody(b1, x_.Name());
    std::optional<BodyId> body2 =
        b2.present() ? L_.FindBody(b2, x_.Name()) : std::optional<BodyId>(ir::kWorldBody);
    if (!body1 || !body2) return std::nullopt;
    if (*body1 == *body2) {
      L_.diags().Report(DiagKind::BadValue, b2.present() ? b2.loc : b1.loc,
                        fmt::format("<{}> connects body '{}' to itself", x_.Name(), b1.value));
      return std::nullopt;
    }
    return std::make_pair(*body1, *body2);
  }

  // site1/site2 of the site form: (body, X_BS) each
  struct SitePair {
    BodyId body1, body2;
    Transform X_B1S1, X_B2S2;
  };
  std::optional<SitePair> Sites() {
    const Attribute s1 = e_.Get("site1"), s2 = e_.Get("site2");
    if (!s1.present() || !s2.present()) {
      L_.diags().Report(DiagKind::MissingAttribute, e_.loc(),
                        fmt::format("<{}> must give body1 or both site1 and site2", x_.Name()));
      return std::nullopt;
    }
    std::optional<FrameId> f1 = L_.FindSite(s1, x_.Name());
    std::optional<FrameId> f2 = L_.FindSite(s2, x_.Name());
    if (!f1 || !f2) return std::nullopt;
    const ir::Frame& site1 = L_.module()[*f1];
    const ir::Frame& site2 = L_.module()[*f2];
    std::optional<BodyId> body1 = L_.BodyOf(site1.body), body2 = L_.BodyOf(site2.body);
    if (!body1 || !body2) return std::nullopt;
    if (*body1 == *body2) {
      L_.diags().Report(DiagKind::BadValue, s2.loc,
                        fmt::format("<{}>: sites '{}' and '{}' are on the same body", x_.Name(),
                                    s1.value, s2.value));
      return std::nullopt;
    }
    return SitePair{*body1, *body2, site1.X_BF, site2.X_BF};
  }

  // both body1 and site1 given: Drake's parser rejects the ambiguity (MJCF-080)
  bool BothForms() {
    if (!(e_.Get("body1").present() && e_.Get("site1").present())) return false;
    L_.diags().Report(DiagKind::BadValue, e_.Get("site1").loc,
                      fmt::format("<{}> must specify either body1 and anchor OR site1 and "
                                  "site2, but not both",
                                  x_.Name()));
    return true;
  }

  void Connect() {
    if (BothForms()) return;
    ir::BallConstraint c;
    if (e_.Get("body1").present()) {
      const Attribute anchor_attr = e_.Get("anchor");
      if (!anchor_attr.present()) {
        L_.diags().Report(DiagKind::MissingAttribute, e_.loc(),
                          "connect specified body1 but does not have the required anchor "
                          "attribute");
        return;
      }
      auto anchor = L_.Doubles(anchor_attr, 3);
      auto bodies = Bodies();
      if (!anchor || !bodies) return;
      const Eigen::Vector3d p_AP((*anchor)[0], (*anchor)[1], (*anchor)[2]);
      // Q: where P is, in body2's frame, at qpos0
      const Transform& X_WA = L_.PoseAtQpos0(bodies->first);
      const Transform& X_WB = L_.PoseAtQpos0(bodies->second);
      c.body_A = L_.BodyRef(bodies->first, e_.Get("body1").loc);
      c.body_B = L_.BodyRef(bodies->second, e_.Get("body2").present() ? e_.Get("body2").loc
                                                                      : e_.loc());
      c.p_AP = p_AP;
      c.p_BQ = X_WB.inverse() * (X_WA * p_AP);
    } else {
      auto sites = Sites();
      if (!sites) return;
      c.body_A = L_.BodyRef(sites->body1, e_.Get("site1").loc);
      c.body_B = L_.BodyRef(sites->body2, e_.Get("site2").loc);
      c.p_AP = sites->X_B1S1.p;
      c.p_BQ = sites->X_B2S2.p;
    }
    Add(std::move(c));
  }

  void Weld() {
    if (BothForms()) return;
    const Attribute torquescale = e_.Get("torquescale");
    if (auto ts = L_.Double(torquescale); ts && *ts != 1) {
      L_.WarnOnce("weld/torquescale", DiagKind::UnsupportedAttribute, torquescale.loc,
                  "<weld> torquescale is not supported by the plant's weld constraint and is "
                  "ignored");
    }
    ir::WeldConstraint c;
    if (e_.Get("body1").present()) {
      auto bodies = Bodies();
      // anchor: on body2, default its origin
      std::optional<std::vector<double>> anchor_values = L_.Doubles(e_.Get("anchor"), 3);
      std::optional<std::vector<double>> relpose = L_.Doubles(e_.Get("relpose"), 7);
      if (!bodies || (e_.Get("relpose").present() && !relpose) ||
          (e_.Get("anchor").present() && !anchor_values)) {
        return;
      }
      const Eigen::Vector3d anchor =
          anchor_values ? Eigen::Vector3d(anchor_values->data()) : Eigen::Vector3d::Zero();
      c.body_A = L_.BodyRef(bodies->first, e_.Get("body1").loc);
      c.body_B = L_.BodyRef(bodies->second, e_.Get("body2").present() ? e_.Get("body2").loc
                                                                      : e_.loc());
      c.X_BQ = Transform::FromTranslation(anchor);
      const bool given = relpose && ((*relpose)[3] != 0 || (*relpose)[4] != 0 ||
                                     (*relpose)[5] != 0 || (*relpose)[6] != 0);
      if (given) {
        Eigen::Quaterniond q((*relpose)[3], (*relpose)[4], (*relpose)[5], (*relpose)[6]);
        c.X_AP = {q.normalized().toRotationMatrix(),
                  Eigen::Vector3d((*relpose)[0], (*relpose)[1], (*relpose)[2])};
      } else {
        // the relative pose at qpos0: X_AP = X_AW * X_WB * X_BQ
        c.X_AP = L_.PoseAtQpos0(bodies->first).inverse() * L_.PoseAtQpos0(bodies->second) *
                 c.X_BQ;
      }
    } else {
      auto sites = Sites();
      if (!sites) return;
      c.body_A = L_.BodyRef(sites->body1, e_.Get("site1").loc);
      c.body_B = L_.BodyRef(sites->body2, e_.Get("site2").loc);
      c.X_AP = sites->X_B1S1;
      c.X_BQ = sites->X_B2S2;
    }
    Add(std::move(c));
  }

  void Joint() {
    const Attribute j1 = e_.Get("joint1"), j2 = e_.Get("joint2");
    if (!j1.present()) {
      L_.diags().Report(DiagKind::MissingAttribute, e_.loc(),
                        "<equality><joint> needs the attribute 'joint1'");
      return;
    }
    // polycoef: up to 5 numbers over MuJoCo's default "0 1 0 0 0"
    std::vector<double> poly = {0, 1, 0, 0, 0};
    const Attribute pc = e_.Get("polycoef");
    if (pc.present()) {
      auto given = L_.Doubles(pc, 5, /*at_most=*/true);
      if (!given) return;
      std::copy(given->begin(), given->end(), poly.begin());
    }
    std::optional<JointId> joint1 = L_.FindJoint(j1, "joint");
    std::optional<JointId> joint2 =
        j2.present() ? L_.FindJoint(j2, "joint") : std::optional<JointId>();
    if (!joint1 || (j2.present() && !joint2)) return;
    for (auto [id, attr] : {std::pair{joint1, j1}, std::pair{joint2, j2}}) {
      if (!id) continue;
      const ir::JointType t = L_.module()[*id].type;
      if (t != ir::JointType::Revolute && t != ir::JointType::Prismatic) {
        L_.diags().Report(DiagKind::BadValue, attr.loc,
                          fmt::format("only hinge and slide joints can be in a joint equality; "
                                      "'{}' is not one",
                                      attr.value));
        return;
      }
    }
    if (joint2 && *joint1 == *joint2) {
      L_.diags().Report(DiagKind::BadValue, j2.loc,
                        fmt::format("joint '{}' is repeated in the joint equality", j1.value));
      return;
    }
    if (poly[2] != 0 || poly[3] != 0 || poly[4] != 0) {
      L_.WarnOnce("equality/joint/polycoef", DiagKind::UnsupportedValue, pc.loc,
                  "<equality><joint> polycoef: only the linear part (first two coefficients) "
                  "is kept; the higher-order terms are ignored");
    }
    const double ref1 = L_.JointQpos0(*joint1);
    if (joint2) {
      const double ref2 = L_.JointQpos0(*joint2);
      ir::CouplerConstraint c;
      // Drake's coupler orientation: joint0 (MJCF's joint1) follows joint1
      c.joint0 = L_.JointRef(*joint1, j1.loc);
      c.joint1 = L_.JointRef(*joint2, j2.loc);
      c.gear_ratio = poly[1];
      c.offset = poly[0] + ref1 - poly[1] * ref2;
      Add(std::move(c));
    } else {
      // joint1 held at ref1 + c0: 1 * q1 - (ref1 + c0) in [0, 0]
      ir::TendonConstraint c;
      c.joints = {L_.JointRef(*joint1, j1.loc)};
      c.a = {1.0};
      c.offset = -(ref1 + poly[0]);
      c.lower = c.upper = 0;
      c.stiffness = kInf;
      c.damping = 0;
      Add(std::move(c));
    }
  }

  // MuJoCo 2.x: the geoms' surface distance; between geom centers here, which
  // is exact for two spheres once their radii are added
  void Distance() {
    const Attribute g1 = e_.Get("geom1"), g2 = e_.Get("geom2");
    if (!g1.present() || !g2.present()) {
      L_.diags().Report(DiagKind::MissingAttribute, e_.loc(),
                        "<equality><distance> needs the attributes 'geom1' and 'geom2'");
      return;
    }
    L_.WarnOnce("equality/distance-version", DiagKind::UnsupportedValue, e_.loc(),
                "<equality><distance> was removed in MuJoCo 2.2.2; it is read with MuJoCo 2.x "
                "semantics");
    std::optional<GeometryId> id1 = L_.FindGeom(g1, "distance");
    std::optional<GeometryId> id2 = L_.FindGeom(g2, "distance");
    double distance = 0;
    if (auto d = L_.Double(e_.Get("distance"))) distance = *d;
    if (!id1 || !id2) return;
    const ir::Geometry& geom1 = L_.module()[*id1];
    const ir::Geometry& geom2 = L_.module()[*id2];
    std::optional<BodyId> body1 = L_.BodyOf(geom1.body), body2 = L_.BodyOf(geom2.body);
    if (!body1 || !body2) return;
    if (*body1 == *body2) {
      L_.diags().Report(DiagKind::BadValue, g2.loc,
                        "<equality><distance>: the two geoms are on the same body");
      return;
    }
    for (const ir::Geometry* g : {&geom1, &geom2}) {
      if (const auto* s = std::get_if<ir::Sphere>(&g->shape)) {
        distance += s->radius;
      } else {
        L_.WarnOnce("equality/distance-shape", DiagKind::UnsupportedValue, e_.loc(),
                    "<equality><distance> on a geom that is not a sphere: the distance is "
                    "held between the geoms' centers");
      }
    }
    if (distance <= 0) {
      L_.diags().Report(DiagKind::BadValue, e_.loc(),
                        fmt::format("<equality><distance>: the distance between the geoms' "
                                    "centers would be {}; it must be positive",
                                    distance));
      return;
    }
    ir::DistanceConstraint c;
    c.body_A = L_.BodyRef(*body1, g1.loc);
    c.body_B = L_.BodyRef(*body2, g2.loc);
    c.p_AP = geom1.X_BG.p;
    c.p_BQ = geom2.X_BG.p;
    c.distance = distance;
    c.stiffness = kInf;  // rigid, as MuJoCo's equality (solref ignored)
    c.damping = 0;
    Add(std::move(c));
  }

  ElementsLowering& L_;
  const Element& e_;
  xml::XmlElement x_;
};

}  // namespace

void LowerEquality(ElementsLowering& L, const xml::XmlElement& section) {
  L.r.attrs.WarnUnknownAttributes(section, {});
  for (const xml::XmlElement& child : L.r.Children(section)) {
    const Element e = L.r.Resolve(child, "equality", "");
    EqualityLowering(L, e).Lower();
  }
}

}  // namespace mdlc::frontend::mjcf
