// drake: geometry properties and actuator extensions in URDF: what each
// element lowers to, what each rule rejects, and what reaches plant-json
// (EXT-012..014, EXT-020, EXT-021, EXT-030, EXT-031, EXT-033, EXT-060,
// URDF-033). The proximity properties and visual roles that SDFormat spells
// the same way are tested in both spellings in drake_spellings_test.cc.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "backend/plant_json.h"
#include "backend/positions.h"
#include "tests/unit/test_values.h"
#include "tests/unit/urdf_test_util.h"
#include "tools/driver/compiler.h"

namespace mdlc {
namespace {

using testing::Lowered;

/// A robot with one link `a` holding `link_children`.
std::string Link(std::string_view link_children) {
  return fmt::format("<robot name='r'><link name='a'>{}</link></robot>", link_children);
}
/// One collision box with `children` beside its geometry.
std::string UrdfCollision(std::string_view children) {
  return Link(fmt::format("<collision><geometry><box size='1 1 1'/></geometry>{}</collision>",
                          children));
}
/// One visual box with `children` beside its geometry.
std::string UrdfVisual(std::string_view children) {
  return Link(
      fmt::format("<visual><geometry><box size='1 1 1'/></geometry>{}</visual>", children));
}
std::string UrdfProximity(std::string_view children) {
  return UrdfCollision(
      fmt::format("<drake:proximity_properties>{}</drake:proximity_properties>", children));
}

using testing::Find;
using testing::Numbers;

/// Counts diagnostics of `kind` (all must be accounted for by the caller).
size_t Count(const Lowered& l, DiagKind kind) {
  size_t n = 0;
  for (const auto& d : l.diags.diagnostics()) n += d.kind == kind;
  return n;
}

// -- EXT-020: drake:proximity_properties, where URDF's @value differs

TEST(UrdfGeometryProperties, ValueAttributeIsRequiredAndNumeric) {  // EXT-020
  Lowered missing;
  EXPECT_FALSE(missing.Read(UrdfProximity("<drake:mu_dynamic/>")));
  EXPECT_TRUE(missing.HasDiagnostic(DiagKind::MissingAttribute, "'value'"));
  Lowered nan;
  EXPECT_FALSE(nan.Read(UrdfProximity("<drake:hydroelastic_modulus value='nan'/>")));
  EXPECT_TRUE(nan.diags.has_errors());
  nan.ExpectDiagnostic(DiagKind::NonFinite, "must be finite");
  // the number is an attribute in URDF; text content is not read
  Lowered content;
  EXPECT_FALSE(content.Read(UrdfProximity("<drake:mu_dynamic>0.5</drake:mu_dynamic>")));
  EXPECT_TRUE(content.HasDiagnostic(DiagKind::MissingAttribute, "'value'"));
}

TEST(UrdfGeometryProperties, ProximityPropertiesOnAVisualIsUnknown) {  // EXT-020
  Lowered l;
  ASSERT_TRUE(l.Read(UrdfVisual("<drake:proximity_properties/>"))) << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement, "drake:proximity_properties"));
}

// -- URDF-033, EXT-021: legacy drake_compliance

TEST(UrdfGeometryProperties, DrakeComplianceGivesFriction) {  // URDF-033
  Lowered l;
  ASSERT_TRUE(l.Read(UrdfCollision(R"(<drake_compliance>
      <youngs_modulus>1e8</youngs_modulus><dissipation>5</dissipation>
      <static_friction>0.9</static_friction><dynamic_friction>0.5</dynamic_friction>
    </drake_compliance>)")))
      << l.Messages();
  EXPECT_EQ(Count(l, DiagKind::UnsupportedElement), 2u) << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement, "youngs_modulus"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement, "dissipation"));
  EXPECT_EQ(Numbers(l.module.geometries[0], "material/coulomb_friction"),
            (std::vector<double>{0.9, 0.5}));
}

TEST(UrdfGeometryProperties, DrakeComplianceNeedsBothCoefficients) {  // URDF-033
  Lowered l;
  EXPECT_FALSE(
      l.Read(UrdfCollision("<drake_compliance><static_friction>0.9</static_friction>"
                           "</drake_compliance>")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::MissingElement, "both static and dynamic"));
  Lowered bad;
  EXPECT_FALSE(
      bad.Read(UrdfCollision("<drake_compliance><static_friction>high</static_friction>"
                             "<dynamic_friction>0.1</dynamic_friction></drake_compliance>")));
  EXPECT_TRUE(bad.HasDiagnostic(DiagKind::BadValue, "must hold a number"));
  Lowered inverted;
  EXPECT_FALSE(
      inverted.Read(UrdfCollision("<drake_compliance><static_friction>0.1</static_friction>"
                                  "<dynamic_friction>0.2</dynamic_friction></drake_compliance>")));
  EXPECT_TRUE(inverted.HasDiagnostic(DiagKind::BadValue, "greater than the static"));
}

TEST(UrdfGeometryProperties, ProximityFrictionBeatsDrakeCompliance) {  // EXT-021
  // in either document order
  for (bool compliance_first : {true, false}) {
    const std::string compliance =
        "<drake_compliance><static_friction>0.9</static_friction>"
        "<dynamic_friction>0.8</dynamic_friction></drake_compliance>";
    const std::string proximity =
        "<drake:proximity_properties><drake:mu_dynamic value='0.3'/>"
        "</drake:proximity_properties>";
    Lowered l;
    ASSERT_TRUE(
        l.Read(UrdfCollision(compliance_first ? compliance + proximity : proximity + compliance)))
        << l.Messages();
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement, "<drake_compliance> is ignored"));
    const ir::Geometry& g = l.module.geometries[0];
    ASSERT_EQ(g.properties.size(), 1u);
    EXPECT_EQ(Numbers(g, "material/coulomb_friction"), (std::vector<double>{0.3, 0.3}));
  }
  // proximity properties without friction leave the friction to drake_compliance
  Lowered l;
  ASSERT_TRUE(l.Read(UrdfCollision(
      "<drake:proximity_properties><drake:rigid_hydroelastic/></drake:proximity_properties>"
      "<drake_compliance><static_friction>0.9</static_friction>"
      "<dynamic_friction>0.8</dynamic_friction></drake_compliance>")))
      << l.Messages();
  EXPECT_TRUE(l.diags.diagnostics().empty()) << l.Messages();
  EXPECT_EQ(Numbers(l.module.geometries[0], "material/coulomb_friction"),
            (std::vector<double>{0.9, 0.8}));
}

// -- EXT-030, EXT-031, EXT-033: visual roles and properties

// URDF takes exactly 'true' and 'false'; SDFormat takes '1' and '0' too
TEST(UrdfGeometryProperties, EnabledIsTrueOrFalseOnly) {  // EXT-030
  Lowered l;
  EXPECT_FALSE(l.Read(UrdfVisual("<drake:perception_properties enabled='1'/>")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "expected 'true' or 'false'")) << l.Messages();
}

TEST(UrdfGeometryProperties, VisualWithNoRoleIsDropped) {  // EXT-030
  Lowered l;
  ASSERT_TRUE(l.Read(Link(R"(
    <visual><geometry><box size='1 1 1'/></geometry>
      <drake:illustration_properties enabled='false'/>
      <drake:perception_properties enabled='false'/></visual>
    <visual><geometry><box size='2 2 2'/></geometry></visual>)")))
      << l.Messages();
  EXPECT_EQ(Count(l, DiagKind::UnsupportedValue), 1u) << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedValue, "geometry is ignored"));
  ASSERT_EQ(l.module.geometries.size(), 1u);
  // the dropped visual does not take the name
  EXPECT_EQ(l.module.Text(l.module.geometries[0].name), "Box");
}

TEST(UrdfGeometryProperties, AcceptingRendererNeedsAName) {  // EXT-031
  Lowered missing;
  EXPECT_FALSE(missing.Read(UrdfVisual("<drake:accepting_renderer/>")));
  EXPECT_TRUE(missing.HasDiagnostic(DiagKind::MissingAttribute, "'name'"));
  Lowered empty;
  EXPECT_FALSE(empty.Read(UrdfVisual("<drake:accepting_renderer name=''/>")));
  EXPECT_TRUE(empty.HasDiagnostic(DiagKind::BadValue, "empty 'name'"));
}

TEST(UrdfGeometryProperties, TextureBecomesDiffuseMap) {  // EXT-033
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'>
    <material name='wood'><texture filename='wood.png'/></material>
    <link name='a'>
      <visual><geometry><box size='1 1 1'/></geometry>
        <material><color rgba='1 1 1 1'/><texture filename='inline.png'/></material></visual>
      <visual><geometry><box size='1 1 1'/></geometry><material name='wood'/></visual>
      <visual><geometry><box size='1 1 1'/></geometry>
        <material name='tiles'><texture filename='tiles.png'/></material></visual>
      <visual><geometry><box size='1 1 1'/></geometry><material name='tiles'/></visual>
      <visual><geometry><box size='1 1 1'/></geometry>
        <material><color rgba='1 0 0 1'/></material></visual>
    </link></robot>)"))
      << l.Messages();
  const auto& g = l.module.geometries;
  ASSERT_EQ(g.size(), 5u);
  auto map = [&](size_t i) -> std::string {
    const ir::Property* p = Find(g[i], "phong/diffuse_map");
    return p ? std::get<std::string>(p->value) : "";
  };
  EXPECT_EQ(map(0), "inline.png");  // an unnamed material's texture
  EXPECT_EQ(map(1), "wood.png");    // from the robot-level material
  EXPECT_EQ(map(2), "tiles.png");   // a material defined inline
  EXPECT_EQ(map(3), "tiles.png");   // ... and used again by name
  EXPECT_EQ(map(4), "");
}

TEST(UrdfGeometryProperties, RepeatedRoleElementsKeepTheFirst) {  // EXT-030
  Lowered l;
  ASSERT_TRUE(
      l.Read(UrdfVisual("<drake:perception_properties enabled='false'/>"
                        "<drake:perception_properties enabled='true'/>")))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement, "only the first one is used"));
  EXPECT_EQ(l.module.geometries[0].roles, ir::kIllustrationRole);
}

// -- EXT-012..014: actuator extensions

std::string Actuated(std::string_view actuator_children) {
  return fmt::format(R"(<robot name='r'><link name='a'/><link name='b'/>
    <joint name='j' type='revolute'><parent link='a'/><child link='b'/>
      <limit effort='10' lower='-1' upper='1'/></joint>
    <transmission><type>transmission_interface/SimpleTransmission</type>
      <joint name='j'/><actuator name='m'>{}</actuator></transmission></robot>)",
                     actuator_children);
}

TEST(UrdfActuatorExtensions, RotorInertiaGearRatioAndGains) {  // EXT-012, EXT-013, EXT-014
  Lowered l;
  ASSERT_TRUE(l.Read(Actuated(R"(<drake:rotor_inertia value='2e-5'/>
      <drake:gear_ratio value='100'/><drake:controller_gains p='300' d='0'/>)")))
      << l.Messages();
  EXPECT_TRUE(l.diags.diagnostics().empty()) << l.Messages();
  ASSERT_EQ(l.module.actuators.size(), 1u);
  const ir::Actuator& a = l.module.actuators[0];
  EXPECT_EQ(a.rotor_inertia, 2e-5);
  EXPECT_EQ(a.gear_ratio, 100);
  EXPECT_EQ(a.kp, 300);
  EXPECT_EQ(a.kd, 0);
}

TEST(UrdfActuatorExtensions, DefaultsWithoutExtensions) {  // EXT-012..014
  Lowered l;
  ASSERT_TRUE(l.Read(Actuated(""))) << l.Messages();
  const ir::Actuator& a = l.module.actuators[0];
  EXPECT_EQ(a.rotor_inertia, 0);
  EXPECT_EQ(a.gear_ratio, 1);
  EXPECT_FALSE(a.kp.has_value());
  EXPECT_FALSE(a.kd.has_value());
}

TEST(UrdfActuatorExtensions, BadValuesAreErrors) {  // EXT-012, EXT-013, EXT-014
  struct Case {
    const char* xml;
    DiagKind kind;
    const char* message;
  };
  for (const Case& c : std::initializer_list<Case>{
           {"<drake:rotor_inertia/>", DiagKind::MissingAttribute, "'value'"},
           {"<drake:rotor_inertia value='-1'/>", DiagKind::BadValue, "rotor inertia"},
           {"<drake:gear_ratio/>", DiagKind::MissingAttribute, "'value'"},
           {"<drake:gear_ratio value='-2'/>", DiagKind::BadValue, "gear ratio"},
           {"<drake:controller_gains p='1'/>", DiagKind::MissingAttribute, "'d'"},
           {"<drake:controller_gains d='1'/>", DiagKind::MissingAttribute, "'p'"},
           {"<drake:controller_gains p='0' d='1'/>", DiagKind::BadValue, "must be positive"},
           {"<drake:controller_gains p='1' d='-1'/>", DiagKind::BadValue, "non-negative"},
           {"<drake:gear_ratio value='inf'/>", DiagKind::NonFinite, ""},
       }) {
    Lowered l;
    EXPECT_FALSE(l.Read(Actuated(c.xml))) << c.xml;
    EXPECT_TRUE(l.HasDiagnostic(c.kind, c.message)) << c.xml << "\n" << l.Messages();
  }
  // the other gain is not set alone
  Lowered one;
  EXPECT_FALSE(one.Read(Actuated("<drake:controller_gains p='5'/>")));
  one.ExpectDiagnostic(DiagKind::MissingAttribute, "'d'");
  ASSERT_EQ(one.module.actuators.size(), 1u);
  EXPECT_FALSE(one.module.actuators[0].kp.has_value());
}

TEST(UrdfActuatorExtensions, ZeroIsAllowed) {  // EXT-012, EXT-013
  Lowered l;
  ASSERT_TRUE(l.Read(Actuated("<drake:rotor_inertia value='0'/><drake:gear_ratio value='0'/>")))
      << l.Messages();
  EXPECT_EQ(l.module.actuators[0].gear_ratio, 0);
}

TEST(UrdfActuatorExtensions, RepeatsKeepTheFirst) {  // EXT-012
  Lowered l;
  ASSERT_TRUE(l.Read(Actuated(
      "<drake:rotor_inertia value='1'/><drake:rotor_inertia value='2'/>")))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement, "only the first one is used"));
  EXPECT_EQ(l.module.actuators[0].rotor_inertia, 1);
}

TEST(UrdfActuatorExtensions, ExtensionsUnderTheJointAreNotRead) {  // EXT-012
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'/><link name='b'/>
    <joint name='j' type='revolute'><parent link='a'/><child link='b'/>
      <limit effort='10' lower='-1' upper='1'/></joint>
    <transmission><type>SimpleTransmission</type>
      <joint name='j'><drake:gear_ratio value='7'/></joint><actuator name='m'/></transmission>
  </robot>)"))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement, "drake:gear_ratio"));
  EXPECT_EQ(l.module.actuators[0].gear_ratio, 1);
}

// -- EXT-060: drake:surface_velocity_axis

TEST(UrdfSurfaceVelocity, AxisIsNormalizedOntoTheBody) {  // EXT-060
  Lowered l;
  ASSERT_TRUE(l.Read(Link("<drake:surface_velocity_axis axis='0 3 4'/>"))) << l.Messages();
  ASSERT_TRUE(l.Body("a")->surface_velocity_axis.has_value());
  EXPECT_TRUE(l.Body("a")->surface_velocity_axis->isApprox(Eigen::Vector3d(0, 0.6, 0.8)));
  Lowered none;
  ASSERT_TRUE(none.Read(Link("")));
  EXPECT_FALSE(none.Body("a")->surface_velocity_axis.has_value());
}

TEST(UrdfSurfaceVelocity, BadAxesAreErrors) {  // EXT-060
  struct Case {
    const char* xml;
    DiagKind kind;
    const char* message;
  };
  for (const Case& c : std::initializer_list<Case>{
           {"<drake:surface_velocity_axis/>", DiagKind::MissingAttribute, "'axis'"},
           {"<drake:surface_velocity_axis axis='0 0 0'/>", DiagKind::BadValue, "non-zero length"},
           {"<drake:surface_velocity_axis axis='1 0'/>", DiagKind::BadValue, "3 values"},
           {"<drake:surface_velocity_axis axis='nan 0 1'/>", DiagKind::NonFinite, "finite"},
       }) {
    Lowered l;
    EXPECT_FALSE(l.Read(Link(c.xml))) << c.xml;
    l.ExpectDiagnostic(c.kind, c.message);
    EXPECT_FALSE(l.Body("a")->surface_velocity_axis.has_value());
  }
}

TEST(UrdfSurfaceVelocity, OnTheWorldLinkIsIgnored) {  // EXT-060
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='world'>
      <drake:surface_velocity_axis axis='1 0 0'/></link></robot>)"))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement, "'world' link"));
  EXPECT_FALSE(l.module.bodies[0].surface_velocity_axis.has_value());
}

TEST(UrdfSurfaceVelocity, RepeatKeepsTheFirst) {  // EXT-060
  Lowered l;
  ASSERT_TRUE(l.Read(Link("<drake:surface_velocity_axis axis='1 0 0'/>"
                          "<drake:surface_velocity_axis axis='0 1 0'/>")))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement, "only the"));
  EXPECT_EQ(*l.Body("a")->surface_velocity_axis, Eigen::Vector3d(1, 0, 0));
}

// -- end to end: URDF -> Compilation -> plant-json

TEST(UrdfGeometryPropertiesEndToEnd, PropertiesRolesAndActuatorsReachPlantJson) {
  // EXT-012..014, EXT-020, EXT-021, EXT-030, EXT-031, EXT-033, EXT-060, URDF-033
  Compilation c;
  frontend::FrontendContext ctx{c.sources, c.diags, c.module, c.options.frontend};
  frontend::ReadUrdf(c.sources.AddBuffer("e2e.urdf", R"(<robot name='r'>
    <link name='base'>
      <inertial><mass value='2'/><inertia ixx='1' iyy='1' izz='1' ixy='0' ixz='0' iyz='0'/></inertial>
      <drake:surface_velocity_axis axis='0 0 -2'/>
      <collision name='pad'><geometry><box size='1 1 0.1'/></geometry>
        <drake:proximity_properties>
          <drake:compliant_hydroelastic/><drake:hydroelastic_modulus value='1e7'/>
          <drake:mu_static value='0.8'/><drake:mu_dynamic value='0.6'/>
          <drake:relaxation_time value='0.1'/>
        </drake:proximity_properties></collision>
      <collision name='legacy'><geometry><sphere radius='0.1'/></geometry>
        <drake_compliance><static_friction>0.5</static_friction>
          <dynamic_friction>0.4</dynamic_friction></drake_compliance></collision>
      <visual name='look'><geometry><sphere radius='0.1'/></geometry>
        <material><color rgba='0 0 1 1'/><texture filename='blue.png'/></material>
        <drake:illustration_properties enabled='false'/>
        <drake:accepting_renderer name='vtk'/><drake:accepting_renderer name='gl'/></visual>
      <visual name='hidden'><geometry><sphere radius='0.1'/></geometry>
        <drake:illustration_properties enabled='false'/>
        <drake:perception_properties enabled='false'/></visual>
    </link>
    <link name='arm'>
      <inertial><mass value='1'/><inertia ixx='0.1' iyy='0.1' izz='0.1' ixy='0' ixz='0' iyz='0'/></inertial>
    </link>
    <link name='finger'>
      <inertial><mass value='0.1'/><inertia ixx='0.01' iyy='0.01' izz='0.01' ixy='0' ixz='0' iyz='0'/></inertial>
    </link>
    <joint name='weld' type='fixed'><parent link='world'/><child link='base'/></joint>
    <joint name='shoulder' type='revolute'><parent link='base'/><child link='arm'/>
      <axis xyz='0 0 1'/><limit effort='50' lower='-1' upper='1'/></joint>
    <joint name='slide' type='prismatic'><parent link='arm'/><child link='finger'/>
      <limit effort='5' lower='0' upper='0.1'/></joint>
    <transmission><type>transmission_interface/SimpleTransmission</type>
      <joint name='shoulder'/><actuator name='shoulder_motor'>
        <drake:rotor_inertia value='3e-4'/><drake:gear_ratio value='100'/>
        <drake:controller_gains p='250' d='12.5'/></actuator></transmission>
    <transmission><type>transmission_interface/SimpleTransmission</type>
      <joint name='slide'/><actuator name='slide_motor'/></transmission>
  </robot>)"),
                     ctx);
  ASSERT_FALSE(c.diags.has_errors());
  ASSERT_TRUE(c.RunPasses());
  ASSERT_TRUE(c.RunBackend());
  const nlohmann::json json = nlohmann::json::parse(
      backend::EmitPlantJson(*c.model, backend::DefaultPositions(c.model->plant)));

  std::map<std::string, nlohmann::json> geometries;
  for (const auto& g : json["geometries"]) geometries[g["name"].get<std::string>()] = g;
  ASSERT_EQ(geometries.size(), 3u);  // 'hidden' has no role and is dropped
  EXPECT_EQ(geometries.count("hidden"), 0u);

  const nlohmann::json& pad = geometries["pad"];
  EXPECT_EQ(pad["roles"], nlohmann::json({"proximity"}));
  EXPECT_EQ(pad["properties"], nlohmann::json::parse(R"({
      "hydroelastic/compliance_type": "compliant",
      "hydroelastic/hydroelastic_modulus": 1e7,
      "material/coulomb_friction": [0.8, 0.6],
      "material/relaxation_time": 0.1})"));
  EXPECT_EQ(geometries["legacy"]["properties"],
            nlohmann::json::parse(R"({"material/coulomb_friction": [0.5, 0.4]})"));

  const nlohmann::json& look = geometries["look"];
  EXPECT_EQ(look["roles"], nlohmann::json({"perception"}));
  EXPECT_EQ(look["properties"], nlohmann::json::parse(R"({
      "phong/diffuse": [0, 0, 1, 1],
      "phong/diffuse_map": "blue.png",
      "renderer/accepting": ["gl", "vtk"]})"));

  std::map<std::string, nlohmann::json> actuators;
  for (const auto& a : json["actuators"]) actuators[a["name"].get<std::string>()] = a;
  const nlohmann::json& motor = actuators["shoulder_motor"];
  EXPECT_EQ(motor["gear_ratio"], 100);
  EXPECT_EQ(motor["rotor_inertia"], 3e-4);
  EXPECT_EQ(motor["kp"], 250);
  EXPECT_EQ(motor["kd"], 12.5);
  const nlohmann::json& slide = actuators["slide_motor"];
  EXPECT_EQ(slide["gear_ratio"], 1);
  EXPECT_EQ(slide["rotor_inertia"], 0);
  EXPECT_TRUE(slide["kp"].is_null());
  EXPECT_TRUE(slide["kd"].is_null());

  // reflected inertia per dof: gear_ratio^2 * rotor_inertia
  ASSERT_EQ(json["dofs"].size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const std::string dof = json["dofs"][i];
    const double expected = dof == "r::shoulder" ? 100.0 * 100.0 * 3e-4 : 0.0;
    EXPECT_DOUBLE_EQ(json["reflected_inertia"][i].get<double>(), expected) << dof;
  }

  for (const auto& body : json["bodies"]) {
    if (body["name"] == "base") {
      EXPECT_EQ(body["surface_velocity_axis"], nlohmann::json({0, 0, -1}));
    } else {
      EXPECT_FALSE(body.contains("surface_velocity_axis")) << body["name"];
    }
  }
}

}  // namespace
}  // namespace mdlc
