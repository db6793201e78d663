// Drake's geometry properties in both spellings, each test run once per
// format (tests/unit/drake_spellings.h): <drake:proximity_properties>
// (EXT-020, EXT-021), visual roles and accepting renderers (EXT-030,
// EXT-031), <drake:declare_convex> (EXT-034), with COMMON-003.
#include "tests/unit/drake_spellings.h"

namespace mdlc::drake_spellings {
namespace {

// -------------------------------------------------- EXT-020, EXT-021: proximity

class DrakeProximityTest : public DrakeSpellingTest {};
MDLC_BOTH_SPELLINGS(DrakeProximityTest);

TEST_P(DrakeProximityTest, EveryChildBecomesItsProperty) {  // EXT-020
  const Format f = format();
  Lowering l(f);
  ASSERT_TRUE(l.Read(ProximityOf(
      "<drake:compliant_hydroelastic/>" + DrakeValue("drake:hydroelastic_modulus", "5e7", f) +
          DrakeValue("drake:mesh_resolution_hint", "0.02", f) +
          DrakeValue("drake:hunt_crossley_dissipation", "1.25", f) +
          DrakeValue("drake:point_contact_stiffness", "1e5", f) +
          DrakeValue("drake:relaxation_time", "0.1", f) +
          DrakeValue("drake:hydroelastic_margin", "0.001", f) +
          DrakeValue("drake:mu_static", "0.8", f) + DrakeValue("drake:mu_dynamic", "0.6", f),
      f)))
      << l.Messages();
  EXPECT_TRUE(l.diags().diagnostics().empty()) << l.Messages();
  ASSERT_EQ(l.module().geometries.size(), 1u);
  const ir::Geometry& g = l.module().geometries[0];
  EXPECT_EQ(g.roles, ir::kProximityRole);
  EXPECT_EQ(std::get<std::string>(Find(g, "hydroelastic/compliance_type")->value), "compliant");
  EXPECT_EQ(Number(g, "hydroelastic/hydroelastic_modulus"), 5e7);
  EXPECT_EQ(Number(g, "hydroelastic/resolution_hint"), 0.02);
  EXPECT_EQ(Number(g, "hydroelastic/margin"), 0.001);
  EXPECT_EQ(Number(g, "material/hunt_crossley_dissipation"), 1.25);
  EXPECT_EQ(Number(g, "material/point_contact_stiffness"), 1e5);
  EXPECT_EQ(Number(g, "material/relaxation_time"), 0.1);
  EXPECT_EQ(Numbers(g, "material/coulomb_friction"), (std::vector<double>{0.8, 0.6}));
  EXPECT_EQ(g.properties.size(), 8u);
}

TEST_P(DrakeProximityTest, RigidHydroelastic) {  // EXT-020
  Lowering l(format());
  ASSERT_TRUE(l.Read(ProximityOf("<drake:rigid_hydroelastic/>", format()))) << l.Messages();
  const ir::Geometry& g = l.module().geometries.at(0);
  ASSERT_EQ(g.properties.size(), 1u);
  EXPECT_EQ(std::get<std::string>(Find(g, "hydroelastic/compliance_type")->value), "rigid");
}

TEST_P(DrakeProximityTest, NoProximityPropertiesMeansNoProperties) {  // EXT-021
  // the plant's default friction applies; it is not listed as a property
  Lowering l(format());
  ASSERT_TRUE(l.Read(BoxCollision("", format()))) << l.Messages();
  EXPECT_TRUE(l.module().geometries.at(0).properties.empty());
  Lowering empty(format());
  ASSERT_TRUE(empty.Read(ProximityOf("", format()))) << empty.Messages();
  EXPECT_TRUE(empty.module().geometries.at(0).properties.empty());
}

TEST_P(DrakeProximityTest, OneFrictionCoefficientGivesBoth) {  // EXT-020, EXT-021
  for (const char* tag : {"drake:mu_dynamic", "drake:mu_static"}) {
    Lowering l(format());
    ASSERT_TRUE(l.Read(ProximityOf(
        DrakeValue(tag, "0.4", format()) + "<drake:rigid_hydroelastic/>", format())))
        << l.Messages();
    const ir::Geometry& g = l.module().geometries.at(0);
    EXPECT_EQ(Numbers(g, "material/coulomb_friction"), (std::vector<double>{0.4, 0.4})) << tag;
    EXPECT_EQ(std::get<std::string>(Find(g, "hydroelastic/compliance_type")->value), "rigid");
    EXPECT_EQ(g.properties.size(), 2u) << tag;
  }
}

TEST_P(DrakeProximityTest, FrictionFollowsCoulombRules) {  // EXT-020
  const Format f = format();
  Lowering negative(f);
  EXPECT_FALSE(negative.Read(ProximityOf(DrakeValue("drake:mu_dynamic", "-0.1", f), f)));
  EXPECT_TRUE(negative.HasDiagnostic(
      DiagKind::BadValue, "the dynamic friction coefficient must not be negative, got -0.1"));
  EXPECT_EQ(negative.diags().error_count(), 1u) << negative.Messages();  // reported once
  EXPECT_TRUE(negative.module().geometries.at(0).properties.empty());

  // Drake's CoulombFriction: dynamic may not exceed static
  Lowering inverted(f);
  EXPECT_FALSE(inverted.Read(ProximityOf(
      DrakeValue("drake:mu_static", "0.2", f) + DrakeValue("drake:mu_dynamic", "0.5", f), f)));
  EXPECT_TRUE(inverted.HasDiagnostic(
      DiagKind::BadValue, "the dynamic friction coefficient (0.5) is greater than the static "
                          "one (0.2)"))
      << inverted.Messages();

  Lowering equal(f);
  EXPECT_TRUE(equal.Read(ProximityOf(
      DrakeValue("drake:mu_static", "0.5", f) + DrakeValue("drake:mu_dynamic", "0.5", f), f)))
      << equal.Messages();
  EXPECT_EQ(Numbers(equal.module().geometries.at(0), "material/coulomb_friction"),
            (std::vector<double>{0.5, 0.5}));
}

TEST_P(DrakeProximityTest, OutOfRangeValuesAreErrors) {  // EXT-020
  const struct {
    const char* tag;
    const char* value;
    const char* message;
  } cases[] = {
      {"drake:relaxation_time", "-1",
       "the relaxation time given by <drake:relaxation_time> must be non-negative, got -1"},
      {"drake:hydroelastic_margin", "-0.1", "hydroelastic margin"},
      {"drake:hunt_crossley_dissipation", "-2", "Hunt-Crossley dissipation"},
      {"drake:point_contact_stiffness", "0", "point contact stiffness"},
      {"drake:point_contact_stiffness", "-1", "point contact stiffness"},
      {"drake:hydroelastic_modulus", "0", "hydroelastic modulus"},
      {"drake:mesh_resolution_hint", "-0.5", "mesh resolution hint"},
      {"drake:mesh_resolution_hint", "0",
       "the mesh resolution hint given by <drake:mesh_resolution_hint> must be positive, got 0"},
  };
  for (const auto& c : cases) {
    Lowering l(format());
    EXPECT_FALSE(l.Read(ProximityOf(DrakeValue(c.tag, c.value, format()), format()))) << c.tag;
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, c.message))
        << c.tag << " " << c.value << "\n" << l.Messages();
    EXPECT_TRUE(l.module().geometries.at(0).properties.empty()) << c.tag;
  }
  // zero is allowed where only negatives are rejected
  Lowering zero(format());
  ASSERT_TRUE(zero.Read(ProximityOf(DrakeValue("drake:relaxation_time", "0", format()) +
                                        DrakeValue("drake:hydroelastic_margin", "0", format()) +
                                        DrakeValue("drake:hunt_crossley_dissipation", "0", format()),
                                    format())))
      << zero.Messages();
  EXPECT_EQ(zero.module().geometries.at(0).properties.size(), 3u);
}

TEST_P(DrakeProximityTest, AValueThatIsNoNumberIsAnError) {  // EXT-020
  Lowering l(format());
  EXPECT_FALSE(l.Read(ProximityOf(DrakeValue("drake:hydroelastic_margin", "x", format()), format())));
  // the message is the reader's of the spelling: URDF's attribute reader, or
  // SDFormat's element text
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, format() == Format::Urdf
                                                      ? "must be numbers"
                                                      : "<drake:hydroelastic_margin> must hold a "
                                                        "number"))
      << l.Messages();
  EXPECT_TRUE(l.module().geometries.at(0).properties.empty());
}

TEST_P(DrakeProximityTest, RigidAndCompliantAreExclusive) {  // EXT-020
  Lowering l(format());
  EXPECT_FALSE(l.Read(
      ProximityOf("<drake:rigid_hydroelastic/><drake:compliant_hydroelastic/>", format())));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "are mutually exclusive")) << l.Messages();
  EXPECT_EQ(Find(l.module().geometries.at(0), "hydroelastic/compliance_type"), nullptr);
}

TEST_P(DrakeProximityTest, ModulusOnRigidIsIgnoredWithAWarning) {  // EXT-020
  Lowering l(format());
  ASSERT_TRUE(l.Read(ProximityOf(
      "<drake:rigid_hydroelastic/>" + DrakeValue("drake:hydroelastic_modulus", "1e7", format()),
      format())))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement, "is ignored on a rigid hydroelastic"));
  const ir::Geometry& g = l.module().geometries.at(0);
  EXPECT_EQ(Find(g, "hydroelastic/hydroelastic_modulus"), nullptr);
  EXPECT_EQ(std::get<std::string>(Find(g, "hydroelastic/compliance_type")->value), "rigid");
}

TEST_P(DrakeProximityTest, SoftHydroelasticIsNoLongerSupported) {  // EXT-020
  Lowering l(format());
  EXPECT_FALSE(l.Read(ProximityOf("<drake:soft_hydroelastic/>", format())));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "<drake:soft_hydroelastic> is no longer supported"))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "drake:compliant_hydroelastic"));
}

TEST_P(DrakeProximityTest, UnknownAndRepeatedChildrenAreReported) {  // EXT-020, COMMON-003
  const Format f = format();
  Lowering l(f);
  ASSERT_TRUE(l.Read(ProximityOf(DrakeValue("drake:mu_dynamic", "0.3", f) +
                                     DrakeValue("drake:mu_dynamic", "0.9", f) +
                                     DrakeValue("drake:mu_dyanmic", "1", f),
                                 f)))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement,
                              "<drake:mu_dynamic> is given more than once in "
                              "<drake:proximity_properties>; only the first one is used"))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement,
                              "unknown element <drake:mu_dyanmic> in <drake:proximity_properties>"));
  EXPECT_EQ(Numbers(l.module().geometries.at(0), "material/coulomb_friction"),
            (std::vector<double>{0.3, 0.3}));

  // a second drake:proximity_properties is ignored, as Drake reads only the first
  Lowering twice(f);
  ASSERT_TRUE(twice.Read(BoxCollision(
      "<drake:proximity_properties>" + DrakeValue("drake:mu_static", "0.7", f) +
          "</drake:proximity_properties><drake:proximity_properties>" +
          DrakeValue("drake:mu_static", "0.1", f) + "</drake:proximity_properties>",
      f)))
      << twice.Messages();
  EXPECT_EQ(twice.Count(DiagKind::UnsupportedElement), 1u) << twice.Messages();
  twice.ExpectDiagnostic(DiagKind::UnsupportedElement, "is given more than once");
  EXPECT_EQ(Numbers(twice.module().geometries.at(0), "material/coulomb_friction"),
            (std::vector<double>{0.7, 0.7}));
}

// Every problem of one <drake:proximity_properties> is reported in one run.
TEST_P(DrakeProximityTest, EveryProblemIsReported) {  // EXT-020
  const Format f = format();
  Lowering l(f);
  EXPECT_FALSE(l.Read(ProximityOf(
      "<drake:rigid_hydroelastic/><drake:compliant_hydroelastic/><drake:soft_hydroelastic/>" +
          DrakeValue("drake:mesh_resolution_hint", "0", f) +
          DrakeValue("drake:relaxation_time", "-1", f) +
          DrakeValue("drake:mu_static", "0.2", f) + DrakeValue("drake:mu_dynamic", "0.3", f) +
          DrakeValue("drake:mu_dynamic", "0.1", f) + DrakeValue("drake:stickiness", "1", f),
      f)));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "are mutually exclusive")) << l.Messages();
  EXPECT_TRUE(
      l.HasDiagnostic(DiagKind::BadValue, "<drake:soft_hydroelastic> is no longer supported"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue,
                              "the mesh resolution hint given by <drake:mesh_resolution_hint> "
                              "must be positive, got 0"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue,
                              "the relaxation time given by <drake:relaxation_time> must be "
                              "non-negative, got -1"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue,
                              "the dynamic friction coefficient (0.3) is greater than the static "
                              "one (0.2)"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement,
                              "<drake:mu_dynamic> is given more than once"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement,
                              "unknown element <drake:stickiness> in <drake:proximity_properties>"));
  // the five errors: exclusive, soft, the hint, the relaxation time, the friction
  EXPECT_EQ(l.diags().error_count(), 5u) << l.Messages();
}

// -------------------------------------------- EXT-030, EXT-031: visual roles

class DrakeVisualRoleTest : public DrakeSpellingTest {};
MDLC_BOTH_SPELLINGS(DrakeVisualRoleTest);

TEST_P(DrakeVisualRoleTest, RolesFollowEnabled) {  // EXT-030
  const struct {
    const char* xml;
    uint8_t roles;
  } cases[] = {
      {"", ir::kIllustrationRole | ir::kPerceptionRole},
      {"<drake:illustration_properties/>", ir::kIllustrationRole | ir::kPerceptionRole},
      {"<drake:perception_properties enabled='true'/>",
       ir::kIllustrationRole | ir::kPerceptionRole},
      {"<drake:illustration_properties enabled='false'/>", ir::kPerceptionRole},
      {"<drake:perception_properties enabled='false'/>", ir::kIllustrationRole},
  };
  for (const auto& c : cases) {
    Lowering l(format());
    ASSERT_TRUE(l.Read(BoxVisual(c.xml, format()))) << c.xml << "\n" << l.Messages();
    EXPECT_TRUE(l.diags().diagnostics().empty()) << c.xml << "\n" << l.Messages();
    ASSERT_EQ(l.module().geometries.size(), 1u);
    EXPECT_EQ(l.module().geometries[0].roles, c.roles) << c.xml;
  }
}

TEST_P(DrakeVisualRoleTest, InvalidEnabledIsAnError) {  // EXT-030
  for (const char* value : {"no", "maybe", "False", ""}) {
    Lowering l(format());
    EXPECT_FALSE(l.Read(BoxVisual(
        fmt::format("<drake:perception_properties enabled='{}'/>", value), format())))
        << value;
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue,
                                fmt::format("invalid value '{}' for attribute 'enabled' of "
                                            "<drake:perception_properties>: expected 'true' or "
                                            "'false'",
                                            value)))
        << value << "\n" << l.Messages();
  }
}

TEST_P(DrakeVisualRoleTest, VisualWithNoRoleIsDroppedWithAWarning) {  // EXT-030
  Lowering l(format());
  ASSERT_TRUE(l.Read(BoxVisual("<drake:illustration_properties enabled='false'/>"
                               "<drake:perception_properties enabled='false'/>",
                               format())))
      << l.Messages();
  EXPECT_EQ(l.Count(DiagKind::UnsupportedValue), 1u) << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedValue,
                              "visual geometry 'v' in link 'a' has both its illustration and "
                              "perception properties disabled; the geometry is ignored"))
      << l.Messages();
  EXPECT_TRUE(l.module().geometries.empty());
}

TEST_P(DrakeVisualRoleTest, AcceptingRenderersAreASortedSet) {  // EXT-031
  const Format f = format();
  Lowering l(f);
  ASSERT_TRUE(l.Read(BoxVisual(DrakeName("drake:accepting_renderer", "vtk", f) +
                                   DrakeName("drake:accepting_renderer", "gl", f) +
                                   DrakeName("drake:accepting_renderer", "vtk", f),
                               f)))
      << l.Messages();
  const ir::Property* p = Find(l.module().geometries.at(0), "renderer/accepting");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(std::get<std::vector<std::string>>(p->value), (std::vector<std::string>{"gl", "vtk"}));
}

TEST_P(DrakeVisualRoleTest, AcceptingRendererWithoutPerceptionIsIgnored) {  // EXT-031
  const std::string off = "<drake:perception_properties enabled='false'/>";
  const std::string vtk = DrakeName("drake:accepting_renderer", "vtk", format());
  for (const std::string& xml : {off + vtk, vtk + off}) {  // in either order
    Lowering l(format());
    ASSERT_TRUE(l.Read(BoxVisual(xml, format()))) << l.Messages();
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement,
                                "<drake:accepting_renderer> is ignored: the perception role of "
                                "this visual is disabled"))
        << xml << "\n" << l.Messages();
    EXPECT_EQ(Find(l.module().geometries.at(0), "renderer/accepting"), nullptr);
    EXPECT_EQ(l.module().geometries.at(0).roles, ir::kIllustrationRole);
  }
}

// ----------------------------------------------------- EXT-034: declare_convex

class DrakeConvexTest : public DrakeSpellingTest {};
MDLC_BOTH_SPELLINGS(DrakeConvexTest);

TEST_P(DrakeConvexTest, DeclareConvexMakesTheMeshConvex) {  // EXT-034
  // URDF writes <drake:declare_convex/> beside the <mesh>, SDFormat in it
  Lowering l(format());
  ASSERT_TRUE(l.Read(OneLink(
      format() == Format::Urdf
          ? "<collision name='c'><geometry><mesh filename='part.obj' scale='1 2 3'/>"
            "<drake:declare_convex/></geometry></collision>"
          : "<collision name='c'><geometry><mesh><uri>part.obj</uri><scale>1 2 3</scale>"
            "<drake:declare_convex/></mesh></geometry></collision>",
      format())))
      << l.Messages();
  ASSERT_EQ(l.module().geometries.size(), 1u);
  const ir::Geometry& g = l.module().geometries[0];
  const auto& mesh = std::get<ir::Mesh>(g.shape);
  EXPECT_TRUE(mesh.convex);
  EXPECT_EQ(ir::ShapeTypeName(g.shape), "convex");
  EXPECT_EQ(mesh.uri, "part.obj");
  EXPECT_EQ(mesh.scale, Eigen::Vector3d(1, 2, 3));
}

}  // namespace
}  // namespace mdlc::drake_spellings
