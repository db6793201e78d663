// SDFormat visuals, collisions, shapes, materials and camera sensors: what
// each element lowers to, what each rule rejects, and what reaches
// plant-json (SDF-040, SDF-041, SDF-043, SDF-044, EXT-020, EXT-021,
// EXT-030..035). The drake: properties that URDF spells the same way are
// tested in both spellings in drake_spellings_test.cc.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "frontend/frontend.h"
#include "tests/unit/sdf_test_util.h"
#include "tests/unit/test_values.h"

namespace mdlc {
namespace {

using testing::AllNamed;
using testing::SdfCompileResult;
using testing::SdfFrontendResult;
using testing::SdfLink;

constexpr uint8_t kVisualRoles = ir::kIllustrationRole | ir::kPerceptionRole;

/// One collision `c` with `geometry` and extra `children`.
std::string Collision(std::string_view geometry, std::string_view children = "") {
  return SdfLink(fmt::format("<collision name='c'><geometry>{}</geometry>{}</collision>", geometry,
                             children));
}
/// One visual `v` with `geometry` and extra `children`.
std::string Visual(std::string_view geometry, std::string_view children = "") {
  return SdfLink(
      fmt::format("<visual name='v'><geometry>{}</geometry>{}</visual>", geometry, children));
}

using testing::Find;
using testing::Numbers;

// -- SDF-040: shapes

TEST(SdfGeometry, EveryShapeLowers) {  // SDF-040, EXT-035
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(SdfLink(R"(
      <collision name='box'><geometry><box><size>1 2 3</size></box></geometry></collision>
      <collision name='sphere'><geometry><sphere><radius>0.5</radius></sphere></geometry></collision>
      <collision name='cylinder'><geometry><cylinder><radius>0.1</radius><length>2</length></cylinder></geometry></collision>
      <collision name='capsule'><geometry><capsule><radius>0.2</radius><length>3</length></capsule></geometry></collision>
      <collision name='ellipsoid'><geometry><ellipsoid><radii>1 2 3</radii></ellipsoid></geometry></collision>
      <collision name='dcapsule'><geometry><drake:capsule><radius>0.3</radius><length>4</length></drake:capsule></geometry></collision>
      <collision name='dellipsoid'><geometry><drake:ellipsoid><a>4</a><b>5</b><c>6</c></drake:ellipsoid></geometry></collision>
      <collision name='plane'><geometry><plane><normal>0 0 1</normal><size>10 10</size></plane></geometry></collision>)")))
      << l.Messages();
  EXPECT_TRUE(l.diags.diagnostics().empty()) << l.Messages();
  ASSERT_EQ(l.module.geometries.size(), 8u);
  auto shape = [&](std::string_view name) { return l.Geometry(name, ir::kProximityRole)->shape; };
  EXPECT_EQ(std::get<ir::Box>(shape("box")).size, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(std::get<ir::Sphere>(shape("sphere")).radius, 0.5);
  EXPECT_EQ(std::get<ir::Cylinder>(shape("cylinder")).radius, 0.1);
  EXPECT_EQ(std::get<ir::Cylinder>(shape("cylinder")).length, 2);
  EXPECT_EQ(std::get<ir::Capsule>(shape("capsule")).radius, 0.2);
  EXPECT_EQ(std::get<ir::Capsule>(shape("capsule")).length, 3);
  const ir::Ellipsoid e = std::get<ir::Ellipsoid>(shape("ellipsoid"));  // a copy: shape() returns a temporary
  EXPECT_EQ(Eigen::Vector3d(e.a, e.b, e.c), Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(std::get<ir::Capsule>(shape("dcapsule")).radius, 0.3);
  EXPECT_EQ(std::get<ir::Capsule>(shape("dcapsule")).length, 4);
  const ir::Ellipsoid de = std::get<ir::Ellipsoid>(shape("dellipsoid"));
  EXPECT_EQ(Eigen::Vector3d(de.a, de.b, de.c), Eigen::Vector3d(4, 5, 6));
  EXPECT_TRUE(std::holds_alternative<ir::HalfSpace>(shape("plane")));
  // the geometry is the link's, by name and by id
  const ir::Geometry* box = l.Geometry("box", ir::kProximityRole);
  EXPECT_EQ(l.module.Text(box->body.name), "a");
  EXPECT_TRUE(box->body.id.valid());
  EXPECT_EQ(box->roles, ir::kProximityRole);
}

TEST(SdfGeometry, MissingSizesTakeLibsdformatDefaults) {  // SDF-040
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(SdfLink(R"(
      <collision name='box'><geometry><box/></geometry></collision>
      <collision name='sphere'><geometry><sphere/></geometry></collision>
      <collision name='capsule'><geometry><capsule/></geometry></collision>)")))
      << l.Messages();
  EXPECT_EQ(std::get<ir::Box>(l.Geometry("box", ir::kProximityRole)->shape).size,
            Eigen::Vector3d(1, 1, 1));
  EXPECT_EQ(std::get<ir::Sphere>(l.Geometry("sphere", ir::kProximityRole)->shape).radius, 1);
  EXPECT_EQ(std::get<ir::Capsule>(l.Geometry("capsule", ir::kProximityRole)->shape).radius, 0.5);
}

TEST(SdfGeometry, DrakeCustomShapesNeedEveryChild) {  // EXT-035
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(SdfLink(R"(
      <collision name='c'><geometry><drake:capsule><radius>1</radius></drake:capsule></geometry></collision>
      <collision name='e'><geometry><drake:ellipsoid><a>1</a><b>1</b></drake:ellipsoid></geometry></collision>)")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::MissingElement, "missing required element <length>"))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::MissingElement, "missing required element <c>"));
  EXPECT_TRUE(l.module.geometries.empty());
}

TEST(SdfGeometry, SizesMustBePositive) {  // SDF-040
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(SdfLink(R"(
      <collision name='b'><geometry><box><size>1 0 1</size></box></geometry></collision>
      <collision name='c'><geometry><cylinder><radius>-1</radius><length>1</length></cylinder></geometry></collision>
      <collision name='e'><geometry><drake:ellipsoid><a>1</a><b>1</b><c>0</c></drake:ellipsoid></geometry></collision>
      <collision name='n'><geometry><sphere><radius>inf</radius></sphere></geometry></collision>
      <collision name='z'><geometry><sphere><radius>0</radius></sphere></geometry></collision>)")));
  EXPECT_EQ(l.Count(DiagKind::BadValue), 3u) << l.Messages();
  EXPECT_EQ(l.Count(DiagKind::NonFinite), 1u) << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "<size> of <box> must hold positive numbers"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "<radius> of <cylinder> must be positive, got -1"));
  // a zero sphere is a point, which Drake allows
  ASSERT_EQ(l.module.geometries.size(), 1u);
  EXPECT_EQ(l.module.Text(l.module.geometries[0].name), "z");
}

TEST(SdfGeometry, EmptyGeometryIsSilentlyNothing) {  // SDF-040
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(SdfLink(R"(
      <collision name='c'><geometry><empty/></geometry></collision>
      <visual name='v'><geometry/></visual>)")))
      << l.Messages();
  EXPECT_TRUE(l.diags.diagnostics().empty()) << l.Messages();
  EXPECT_TRUE(l.module.geometries.empty());
  EXPECT_TRUE(l.module.frame_graph.nodes.size() > 0);
}

TEST(SdfGeometry, HeightmapImagePolylineWarnAndAreSkipped) {  // SDF-040
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(SdfLink(R"(
      <collision name='h'><geometry><heightmap><uri>h.png</uri></heightmap></geometry></collision>
      <visual name='i'><geometry><image><uri>i.png</uri><height>1</height></image></geometry></visual>
      <collision name='p'><geometry><polyline><height>1</height></polyline></geometry></collision>)")))
      << l.Messages();
  EXPECT_EQ(l.Count(DiagKind::UnsupportedElement), 3u) << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement,
                              "element <heightmap> in <geometry> is not supported"));
  EXPECT_TRUE(l.module.geometries.empty());
}

TEST(SdfGeometry, TwoShapesAreAnError) {  // SDF-040
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(Collision("<box/><sphere/>")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadGeometry, "must hold exactly one shape")) << l.Messages();
  ASSERT_EQ(l.module.geometries.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<ir::Box>(l.module.geometries[0].shape));
}

TEST(SdfGeometry, UnknownChildrenFollowSdfRules) {  // SDF-001, SDF-040
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(Collision("<box><size>1 1 1</size><color>1</color></box><cone/>",
                                "<drake:thing/><gz:extra/>")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownSdfElement, "<color> is not an SDFormat element of <box>"))
      << l.Messages();
  // cone is a shape (SDFormat 1.11's), so here it is a second shape
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadGeometry, "must hold exactly one shape, but also holds <cone>"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement, "<drake:thing> in <collision>"));
  EXPECT_EQ(l.diags.diagnostics().size(), 3u) << l.Messages();
}


TEST(SdfGeometry, MeshKeepsItsUriAndScale) {  // SDF-040
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(SdfLink(R"(
      <collision name='c'><geometry><mesh><uri>meshes/part.obj</uri><scale>1 2 3</scale></mesh></geometry></collision>
      <visual name='v'><geometry><mesh><uri> package://pkg/part.dae </uri></mesh></geometry></visual>)")))
      << l.Messages();
  const auto& scaled = std::get<ir::Mesh>(l.Geometry("c", ir::kProximityRole)->shape);
  EXPECT_EQ(scaled.uri, "meshes/part.obj");
  EXPECT_EQ(scaled.scale, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(scaled.uri_loc.line, 4u);
  EXPECT_TRUE(scaled.resolved.empty());  // the resolve-assets pass resolves it
  const auto& mesh = std::get<ir::Mesh>(l.Geometry("v", kVisualRoles)->shape);
  EXPECT_EQ(mesh.uri, "package://pkg/part.dae");
  EXPECT_EQ(mesh.scale, Eigen::Vector3d(1, 1, 1));
  EXPECT_FALSE(mesh.convex);  // <drake:declare_convex>: drake_spellings_test.cc
}

TEST(SdfGeometry, MeshNeedsAUri) {  // SDF-040
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(Collision("<mesh><scale>1 1 1</scale></mesh>")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::MissingElement, "<mesh> is missing its required <uri>"))
      << l.Messages();
  EXPECT_TRUE(l.module.geometries.empty());
}

TEST(SdfGeometry, DeclareConvexOutsideAMeshWarns) {  // EXT-034
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(Collision("<box><drake:declare_convex/></box>"))) << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement, "<drake:declare_convex> in <box>"))
      << l.Messages();
  EXPECT_EQ(l.diags.diagnostics().size(), 1u) << l.Messages();
}

TEST(SdfGeometry, PlaneNormalMustNotBeZero) {  // SDF-040
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(Collision("<plane><normal>0 0 0</normal><size>1 1</size></plane>")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "plane normal must not be zero")) << l.Messages();
}

TEST(SdfGeometry, PlaneRotationIsFoldedIntoTheAnchor) {  // SDF-040
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(Collision("<plane><normal>1 0 0</normal><size>1 1</size></plane>",
                               "<pose>1 2 3 0 0 0</pose>")))
      << l.Messages();
  const ir::FrameNode* anchor = nullptr;
  for (const auto& n : l.module.frame_graph.nodes) {
    if (n.target == ir::FrameTarget::Geometry) anchor = &n;
  }
  ASSERT_NE(anchor, nullptr);
  EXPECT_EQ(anchor->target_index, 0u);
  EXPECT_EQ(l.module.Text(anchor->relative_to.name), "a");
  EXPECT_EQ(anchor->X_RN.p, Eigen::Vector3d(1, 2, 3));
  // the half space's +z is the normal; Drake's MakePose picks x = z cross e_y
  EXPECT_TRUE(anchor->X_RN.R.col(2).isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_TRUE(anchor->X_RN.R.col(0).isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_NEAR(anchor->X_RN.R.determinant(), 1, 1e-12);
}

// -- names

TEST(SdfGeometry, NamesAreUniquePerLinkAndKind) {  // SDF-041
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(SdfLink(R"(
      <visual name='x'><geometry><box/></geometry></visual>
      <collision name='x'><geometry><box/></geometry></collision>
      <visual name='x'><geometry><sphere/></geometry></visual>
      <drake:visual name='x'><drake:geometry><drake:sphere/></drake:geometry></drake:visual>
      <collision name='x'><geometry><sphere/></geometry></collision>)")));
  EXPECT_EQ(l.Count(DiagKind::DuplicateName), 3u) << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::DuplicateName,
                              "visual name 'x' is already used by another visual of link 'a'"));
  for (const auto& d : l.diags.diagnostics()) {
    if (d.kind != DiagKind::DuplicateName) continue;
    ASSERT_EQ(d.notes.size(), 1u);
    EXPECT_EQ(d.notes[0].message, "first defined here");
  }
  // the first of each kind is kept
  ASSERT_EQ(l.module.geometries.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<ir::Box>(l.module.geometries[0].shape));
  EXPECT_TRUE(std::holds_alternative<ir::Box>(l.module.geometries[1].shape));
}

TEST(SdfGeometry, SameNameOnTwoLinksIsFine) {  // SDF-041
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(R"(<model name='m'>
      <link name='a'><visual name='v'><geometry><box/></geometry></visual></link>
      <link name='b'><visual name='v'><geometry><box/></geometry></visual></link></model>)"))
      << l.Messages();
  EXPECT_EQ(l.module.geometries.size(), 2u);
}

TEST(SdfGeometry, NamesAreRequiredAndNotReserved) {  // SDF-034, SDF-041
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(SdfLink(R"(
      <visual><geometry><box/></geometry></visual>
      <visual name='__visual__'><geometry><box/></geometry></visual>
      <collision name='a::b'><geometry><box/></geometry></collision>)")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::MissingAttribute, "name")) << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::ReservedName, "visual name '__visual__' is reserved"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::InvalidName, "collision name 'a::b'"));
  EXPECT_TRUE(l.module.geometries.empty());
}

// -- SDF-041: roles and materials

TEST(SdfGeometry, VisualAndCollisionRoles) {  // SDF-041
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(SdfLink(R"(
      <visual name='g'><geometry><box/></geometry></visual>
      <collision name='g'><geometry><box/></geometry></collision>)")))
      << l.Messages();
  ASSERT_EQ(l.module.geometries.size(), 2u);
  EXPECT_EQ(l.module.geometries[0].roles, kVisualRoles);
  EXPECT_EQ(l.module.geometries[1].roles, ir::kProximityRole);
  EXPECT_FALSE(l.module.geometries[0].rgba.has_value());  // no material: renderer default
  EXPECT_TRUE(l.module.geometries[0].properties.empty());
}

TEST(SdfGeometry, MaterialColorsAndTransparency) {  // SDF-041, EXT-033
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(Visual("<box/>", R"(
      <transparency>0.25</transparency>
      <material><diffuse>0.1 0.2 0.3</diffuse><ambient>1 0 0 0.5</ambient>
        <specular>0 1 0</specular><emissive>0 0 1 1</emissive>
        <drake:diffuse_map>textures/wood.png</drake:diffuse_map></material>)")))
      << l.Messages();
  EXPECT_TRUE(l.diags.diagnostics().empty()) << l.Messages();
  const ir::Geometry& g = l.module.geometries.at(0);
  ASSERT_TRUE(g.rgba.has_value());
  EXPECT_EQ(*g.rgba, Eigen::Vector4d(0.1, 0.2, 0.3, 0.75));
  EXPECT_EQ(Numbers(g, "phong/ambient"), std::vector<double>({1, 0, 0, 0.5}));
  EXPECT_EQ(Numbers(g, "phong/specular"), std::vector<double>({0, 1, 0, 1}));
  EXPECT_EQ(Numbers(g, "phong/emissive"), std::vector<double>({0, 0, 1, 1}));
  ASSERT_NE(Find(g, "phong/diffuse_map"), nullptr);
  EXPECT_EQ(std::get<std::string>(Find(g, "phong/diffuse_map")->value), "textures/wood.png");
}

TEST(SdfGeometry, DiffuseAlphaDefaultsToOne) {  // SDF-041
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(Visual("<box/>", "<material><diffuse>1 1 1</diffuse></material>")))
      << l.Messages();
  EXPECT_EQ(*l.module.geometries.at(0).rgba, Eigen::Vector4d(1, 1, 1, 1));
}

TEST(SdfGeometry, BadColorsAndTransparencyAreErrors) {  // SDF-041
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(Visual("<box/>", R"(<transparency>1.5</transparency>
      <material><diffuse>1 1</diffuse><ambient>2 0 0</ambient>
        <drake:diffuse_map> </drake:diffuse_map><script/></material>)")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "<transparency> must be within [0, 1]"))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "<diffuse> must hold a color"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "<ambient> color values must be within [0, 1]"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "<drake:diffuse_map> is empty"));
  // an empty <script> is no error: it is ignored, with a warning
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::IncompleteMaterialScript,
                              "<script> in the material of visual 'v' has no <uri> and <name>"))
      << l.Messages();
  EXPECT_EQ(l.Count(DiagKind::UnsupportedElement), 0u) << l.Messages();
}

// Gazebo-classic materials: libsdformat (and so Drake) rejects a <script>
// without <uri> or <name>; it cannot affect the plant, so mdlc warns once
// and ignores it (a complete script is merely unsupported)
TEST(SdfGeometry, MaterialScriptWithoutUriIsAWarning) {  // SDF-041
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(Visual("<box/>", R"(
      <material><script><name>Gazebo/Red</name></script><diffuse>1 0 0</diffuse></material>)")))
      << l.Messages();
  ASSERT_EQ(l.diags.diagnostics().size(), 1u) << l.Messages();
  l.ExpectDiagnostic(DiagKind::IncompleteMaterialScript, "has no <uri>");
  const Diagnostic& d = l.diags.diagnostics()[0];
  EXPECT_EQ(d.kind, DiagKind::IncompleteMaterialScript);
  EXPECT_EQ(d.severity, Severity::Warning);
  EXPECT_EQ(InfoFor(d.kind).group, "material");
  EXPECT_NE(d.message.find("has no <uri> (or it is empty), which libsdformat rejects; it is "
                           "ignored"),
            std::string::npos)
      << d.message;
  // the rest of the material still counts
  EXPECT_EQ(*l.module.geometries.at(0).rgba, Eigen::Vector4d(1, 0, 0, 1));

  SdfFrontendResult complete;
  ASSERT_TRUE(complete.Read(Visual("<box/>", R"(
      <material><script><uri>file://media/materials/scripts/gazebo.material</uri>
        <name>Gazebo/Red</name></script></material>)")))
      << complete.Messages();
  EXPECT_EQ(complete.Count(DiagKind::IncompleteMaterialScript), 0u);
  EXPECT_EQ(complete.Count(DiagKind::UnsupportedElement), 1u) << complete.Messages();
}

TEST(SdfGeometry, UnsupportedVisualChildrenWarn) {  // SDF-041, SDF-043
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(Visual("<box/>", R"(<cast_shadows>false</cast_shadows>
      <plugin name='p' filename='f'/><meta><layer>1</layer></meta>)")))
      << l.Messages();
  EXPECT_EQ(l.Count(DiagKind::UnsupportedElement), 2u) << l.Messages();  // plugin is silent
  EXPECT_EQ(l.module.geometries.size(), 1u);
}

// -- EXT-030, EXT-031: visual roles

// SDFormat's booleans: '1' and '0' too (URDF takes 'true' and 'false' only)
TEST(SdfGeometry, EnabledTakesSdformatBooleans) {  // EXT-030
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(SdfLink(R"(
      <visual name='p'><geometry><box/></geometry>
        <drake:illustration_properties enabled='0'/></visual>
      <visual name='both'><geometry><box/></geometry>
        <drake:illustration_properties enabled='1'/><drake:perception_properties enabled=' true '/></visual>)")))
      << l.Messages();
  EXPECT_EQ(l.Geometry("p", kVisualRoles)->roles, ir::kPerceptionRole);
  EXPECT_EQ(l.Geometry("both", kVisualRoles)->roles, kVisualRoles);
}

// the name is the element's text, trimmed
TEST(SdfGeometry, AcceptingRendererTextIsTrimmed) {  // EXT-031
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(Visual("<box/>", R"(<drake:accepting_renderer> gl </drake:accepting_renderer>
      <drake:accepting_renderer>
        vtk
      </drake:accepting_renderer>)")))
      << l.Messages();
  const ir::Property* p = Find(l.module.geometries.at(0), "renderer/accepting");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(std::get<std::vector<std::string>>(p->value), std::vector<std::string>({"gl", "vtk"}));
}

TEST(SdfGeometry, AcceptingRendererMustNotBeEmpty) {  // EXT-031
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(Visual("<box/>", "<drake:accepting_renderer/>")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "<drake:accepting_renderer> is empty"))
      << l.Messages();
  EXPECT_EQ(Find(l.module.geometries.at(0), "renderer/accepting"), nullptr);
}

// -- EXT-032: drake:visual

TEST(SdfGeometry, DrakeVisualReadsThePrefixedSubtree) {  // EXT-032
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(SdfLink(R"(
      <drake:visual name='dv'>
        <drake:pose>0 0 1 0 0 0</drake:pose>
        <drake:geometry><drake:box><drake:size>1 2 3</drake:size></drake:box></drake:geometry>
        <drake:material><drake:diffuse>0 1 0 1</drake:diffuse></drake:material>
        <drake:illustration_properties enabled='false'/>
      </drake:visual>)")))
      << l.Messages();
  EXPECT_TRUE(l.diags.diagnostics().empty()) << l.Messages();
  const ir::Geometry* g = l.Geometry("dv", ir::kPerceptionRole);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->roles, ir::kPerceptionRole);
  EXPECT_EQ(std::get<ir::Box>(g->shape).size, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(*g->rgba, Eigen::Vector4d(0, 1, 0, 1));
  const auto& anchor = l.module.frame_graph.nodes.back();
  EXPECT_EQ(anchor.target, ir::FrameTarget::Geometry);
  EXPECT_EQ(anchor.X_RN.p, Eigen::Vector3d(0, 0, 1));
}

TEST(SdfGeometry, DrakeVisualWithAPlainDescendantIsAnError) {  // EXT-032
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(SdfLink(R"(
      <drake:visual name='dv'>
        <drake:geometry><box/></drake:geometry>
      </drake:visual>)")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownSdfElement,
                              "all tags under a drake-namespaced tag must likewise be "
                              "drake-namespaced"))
      << l.Messages();
  EXPECT_TRUE(l.module.geometries.empty());
}

// The check walks the visual's elements in a loop: 100,000 levels of
// drake: elements (within the document depth limit) overflowed the stack
// when it recursed. The plain element at the bottom, and the plain sibling
// after the deep branch, are each found, in document order.
TEST(SdfGeometry, DrakeVisualNestedDeepIsCheckedInDocumentOrder) {  // EXT-032
  constexpr int kDepth = 100000;
  std::string deep;
  for (int i = 0; i < kDepth; ++i) deep += "<drake:x>";
  deep += "<bottom/>";
  for (int i = 0; i < kDepth; ++i) deep += "</drake:x>";
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(SdfLink(
      "<drake:visual name='dv'><drake:geometry><drake:box><drake:size>1 1 1</drake:size>"
      "</drake:box></drake:geometry>" +
      deep + "<after/></drake:visual>")));
  std::vector<std::string> found;
  for (const Diagnostic& d : l.diags.diagnostics()) {
    if (d.kind == DiagKind::UnknownSdfElement) found.push_back(d.message);
  }
  ASSERT_EQ(found.size(), 2u) << l.Messages();
  EXPECT_EQ(found[0],
            "<bottom> in <drake:x>: all tags under a drake-namespaced tag must likewise be "
            "drake-namespaced");
  EXPECT_EQ(found[1],
            "<after> in <drake:visual>: all tags under a drake-namespaced tag must likewise be "
            "drake-namespaced");
  l.ExpectDiagnostic(DiagKind::UnknownSdfElement, "must likewise be drake-namespaced");
  EXPECT_TRUE(l.module.geometries.empty());
}

TEST(SdfGeometry, DrakeVisualWithNoRoleIsSilentlyDropped) {  // EXT-032
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(SdfLink(R"(
      <drake:visual name='dv'>
        <drake:geometry><drake:sphere><drake:radius>1</drake:radius></drake:sphere></drake:geometry>
        <drake:illustration_properties enabled='false'/>
        <drake:perception_properties enabled='false'/>
      </drake:visual>)")))
      << l.Messages();
  EXPECT_TRUE(l.diags.diagnostics().empty()) << l.Messages();
  EXPECT_TRUE(l.module.geometries.empty());
}

// -- EXT-020, EXT-021: collision properties; <drake:proximity_properties>
// in both spellings: drake_spellings_test.cc

TEST(SdfGeometry, OdeMuGivesBothCoefficients) {  // SDF-041, EXT-021
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(Collision(
      "<box/>", "<surface><friction><ode><mu>0.7</mu><mu2>0.2</mu2></ode></friction>"
                "<contact><ode><kp>1</kp></ode></contact></surface>")))
      << l.Messages();
  EXPECT_TRUE(l.diags.diagnostics().empty()) << l.Messages();
  EXPECT_EQ(Numbers(l.module.geometries.at(0), "material/coulomb_friction"),
            std::vector<double>({0.7, 0.7}));
}

TEST(SdfGeometry, NoFrictionGivenMeansNoProperty) {  // EXT-021
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(Collision("<box/>", "<surface><friction><ode/></friction></surface>")))
      << l.Messages();
  EXPECT_TRUE(l.module.geometries.at(0).properties.empty());
}

TEST(SdfGeometry, DrakeFrictionBeatsOdeMu) {  // EXT-021
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(Collision("<box/>", R"(
      <surface><friction><ode><mu>0.9</mu></ode></friction></surface>
      <drake:proximity_properties><drake:mu_static>0.5</drake:mu_static></drake:proximity_properties>)")))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement,
                              "the friction comes from <drake:proximity_properties>"))
      << l.Messages();
  EXPECT_EQ(Numbers(l.module.geometries.at(0), "material/coulomb_friction"),
            std::vector<double>({0.5, 0.5}));
}

TEST(SdfGeometry, NegativeOdeMuIsAnError) {  // SDF-041
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(Collision("<box/>", "<surface><friction><ode><mu>-1</mu></ode></friction></surface>")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "must not be negative")) << l.Messages();
}

TEST(SdfGeometry, CollisionChildren) {  // SDF-041
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(Collision("<box/>", R"(<laser_retro>0</laser_retro>
      <max_contacts>10</max_contacts>)")))
      << l.Messages();
  EXPECT_EQ(l.diags.diagnostics().size(), 1u) << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement, "element <max_contacts>"));
  SdfFrontendResult retro;
  ASSERT_TRUE(retro.Read(Collision("<box/>", "<laser_retro>2</laser_retro>"))) << retro.Messages();
  EXPECT_TRUE(retro.HasDiagnostic(DiagKind::UnsupportedValue, "<laser_retro>"));
}

// -- SDF-043, SDF-044: sensors

TEST(SdfGeometry, CameraSensorBecomesACamera) {  // SDF-044
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(SdfLink(R"(
      <sensor name='cam' type='rgbd_camera'>
        <pose>0 0 1 0 0 0</pose>
        <update_rate>30</update_rate>
        <camera><horizontal_fov>1.5</horizontal_fov>
          <image><width>640</width><height>480</height><format>R8G8B8</format></image>
          <clip><near>0.1</near><far>10</far></clip></camera>
      </sensor>)")))
      << l.Messages();
  EXPECT_TRUE(l.diags.diagnostics().empty()) << l.Messages();
  ASSERT_EQ(l.module.cameras.size(), 1u);
  const ir::Camera& c = l.module.cameras[0];
  EXPECT_EQ(l.module.Text(c.name), "m/cam");
  EXPECT_EQ(c.width, 640);
  EXPECT_EQ(c.height, 480);
  EXPECT_NEAR(c.fov_y, 2 * std::atan(std::tan(0.75) * 480.0 / 640.0), 1e-15);
  EXPECT_EQ(l.module.Text(c.body.name), "a");
  const auto& anchor = l.module.frame_graph.nodes.back();
  EXPECT_EQ(anchor.target, ir::FrameTarget::Camera);
  EXPECT_EQ(anchor.X_RN.p, Eigen::Vector3d(0, 0, 1));
}

TEST(SdfGeometry, CameraDefaultsAreLibsdformats) {  // SDF-044
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(SdfLink("<sensor name='d' type='depth_camera'/>"))) << l.Messages();
  ASSERT_EQ(l.module.cameras.size(), 1u);
  const ir::Camera& c = l.module.cameras[0];
  EXPECT_EQ(c.width, 320);
  EXPECT_EQ(c.height, 240);
  EXPECT_NEAR(c.fov_y, 2 * std::atan(std::tan(1.047 / 2) * 0.75), 1e-15);
}

TEST(SdfGeometry, OtherSensorsWarn) {  // SDF-043
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(SdfLink("<sensor name='i' type='imu'><imu/></sensor>"))) << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement,
                              "sensor 'i' of type 'imu' is not supported"))
      << l.Messages();
  EXPECT_TRUE(l.module.cameras.empty());
}

TEST(SdfGeometry, BadCameraValuesAreErrors) {  // SDF-044
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(SdfLink(R"(
      <sensor name='a' type='camera'><camera><horizontal_fov>4</horizontal_fov></camera></sensor>
      <sensor name='b' type='camera'><camera><image><width>0</width></image></camera></sensor>
      <sensor name='b' type='camera'/>)")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "<horizontal_fov> must be within (0, pi)"))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "<width> must be a positive whole number"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::DuplicateName, "sensor name 'b'"));
  EXPECT_TRUE(l.module.cameras.empty());
}

// -- end to end: SDF -> passes -> plant-json

TEST(SdfGeometryEndToEnd, PosesRolesAndPropertiesReachPlantJson) {
  // SDF-040, SDF-041, SDF-044, EXT-020, EXT-021, EXT-030, EXT-031, EXT-033
  SdfCompileResult c(R"(<model name='m'>
    <link name='base'>
      <pose>0 0 1 0 0 0</pose>
      <collision name='floor'><pose>0 0 -1 0 0 0</pose>
        <geometry><plane><normal>0 1 0</normal><size>5 5</size></plane></geometry>
        <surface><friction><ode><mu>0.6</mu></ode></friction></surface></collision>
      <collision name='pad'><geometry><box><size>1 1 0.1</size></box></geometry>
        <drake:proximity_properties>
          <drake:compliant_hydroelastic/><drake:hydroelastic_modulus>1e7</drake:hydroelastic_modulus>
          <drake:mu_static>0.8</drake:mu_static><drake:mu_dynamic>0.6</drake:mu_dynamic>
          <drake:relaxation_time>0.1</drake:relaxation_time>
        </drake:proximity_properties></collision>
      <visual name='pad'><pose relative_to='tool'>0 0 0 0 0 0</pose>
        <geometry><sphere><radius>0.1</radius></sphere></geometry>
        <material><diffuse>0 0 1</diffuse><drake:diffuse_map>blue.png</drake:diffuse_map></material>
        <transparency>0.5</transparency>
        <drake:illustration_properties enabled='false'/>
        <drake:accepting_renderer>vtk</drake:accepting_renderer>
        <drake:accepting_renderer>gl</drake:accepting_renderer></visual>
      <sensor name='eye' type='camera'><pose>1 0 0 0 0 0</pose>
        <camera><horizontal_fov>1.2</horizontal_fov><image><width>100</width><height>50</height></image></camera>
      </sensor>
    </link>
    <frame name='tool' attached_to='base'><pose>0.5 0 0 0 0 0</pose></frame>
    <joint name='weld' type='fixed'><parent>world</parent><child>base</child></joint>
  </model>)");
  ASSERT_TRUE(c.ok()) << c.Messages();
  const nlohmann::json json = c.PlantJson();

  auto pads = AllNamed(json["geometries"], "pad");
  ASSERT_EQ(pads.size(), 2u);
  const nlohmann::json& pad_collision = pads[0]["roles"] == nlohmann::json({"proximity"}) ? pads[0] : pads[1];
  const nlohmann::json& pad_visual = pads[0]["roles"] == nlohmann::json({"proximity"}) ? pads[1] : pads[0];
  EXPECT_EQ(pad_collision["body"], "m::base");
  EXPECT_EQ(pad_collision["properties"], nlohmann::json::parse(R"({
      "hydroelastic/compliance_type": "compliant",
      "hydroelastic/hydroelastic_modulus": 1e7,
      "material/coulomb_friction": [0.8, 0.6],
      "material/relaxation_time": 0.1})"));
  EXPECT_EQ(pad_visual["roles"], nlohmann::json({"perception"}));
  EXPECT_EQ(pad_visual["properties"], nlohmann::json::parse(R"({
      "phong/diffuse": [0, 0, 1, 0.5],
      "phong/diffuse_map": "blue.png",
      "renderer/accepting": ["gl", "vtk"]})"));
  // the visual sits at the frame 'tool' (relative_to)
  EXPECT_EQ(pad_visual["X_WG"]["p"], nlohmann::json({0.5, 0, 1}));

  auto floors = AllNamed(json["geometries"], "floor");
  ASSERT_EQ(floors.size(), 1u);
  const nlohmann::json& floor = floors[0];
  EXPECT_EQ(floor["shape"]["type"], "half_space");
  EXPECT_EQ(floor["properties"], nlohmann::json::parse(R"({"material/coulomb_friction": [0.6, 0.6]})"));
  // +z of the half space is the normal (0 1 0), at the link's origin shifted by the pose
  const auto q = floor["X_WG"]["q"].get<std::vector<double>>();
  const Eigen::Quaterniond R_WG(q[0], q[1], q[2], q[3]);
  EXPECT_TRUE((R_WG * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
  const auto p = floor["X_WG"]["p"].get<std::vector<double>>();
  EXPECT_NEAR(p[2], 0, 1e-12);

  ASSERT_EQ(json["cameras"].size(), 1u);
  const nlohmann::json& eye = json["cameras"][0];
  EXPECT_EQ(eye["name"], "m/eye");
  EXPECT_EQ(eye["body"], "m::base");
  EXPECT_EQ(eye["width"], 100);
  EXPECT_EQ(eye["height"], 50);
  EXPECT_NEAR(eye["fov_y"].get<double>(), 2 * std::atan(std::tan(0.6) * 0.5), 1e-15);
  EXPECT_EQ(eye["X_BC"]["p"], nlohmann::json({1, 0, 0}));
  // Drake's camera frame looks along +z: the sensor's +x
  const auto qc = eye["X_BC"]["q"].get<std::vector<double>>();
  const Eigen::Quaterniond R_BC(qc[0], qc[1], qc[2], qc[3]);
  EXPECT_TRUE((R_BC * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitX(), 1e-12));
}

TEST(SdfGeometryEndToEnd, RelativeMeshUriResolvesBesideTheFile) {  // SDF-040, COMMON-010
  SdfCompileResult c(R"(<model name='m'><link name='a'>
      <visual name='v'><geometry><mesh><uri>part.obj</uri><scale>2 2 2</scale></mesh></geometry></visual>
    </link></model>)",
                     {{"part.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"}});
  ASSERT_TRUE(c.ok()) << c.Messages();
  const auto& g = c.compilation().module.geometries.at(0);
  const auto& mesh = std::get<ir::Mesh>(g.shape);
  EXPECT_TRUE(mesh.resolved.ends_with("/part.obj")) << mesh.resolved;
  EXPECT_EQ(c.PlantJson()["geometries"][0]["shape"]["type"], "mesh");
}

/// The same geometry written in URDF and SDFormat dumps the same properties.
TEST(SdfGeometryEndToEnd, PropertiesMatchTheUrdfPath) {  // EXT-020, EXT-031, SDF-041
  const std::string sdf = R"(<model name='r'><link name='a'>
      <collision name='c'><geometry><box><size>1 1 1</size></box></geometry>
        <drake:proximity_properties>
          <drake:rigid_hydroelastic/><drake:mesh_resolution_hint>0.1</drake:mesh_resolution_hint>
          <drake:hunt_crossley_dissipation>2</drake:hunt_crossley_dissipation>
          <drake:point_contact_stiffness>3e4</drake:point_contact_stiffness>
          <drake:hydroelastic_margin>0.01</drake:hydroelastic_margin>
          <drake:mu_static>0.9</drake:mu_static>
        </drake:proximity_properties></collision>
      <visual name='v'><geometry><box><size>1 1 1</size></box></geometry>
        <material><diffuse>0.5 0.5 0.5 1</diffuse></material>
        <drake:accepting_renderer>x</drake:accepting_renderer></visual>
    </link></model>)";
  const std::string urdf = R"(<robot name='r'><link name='a'>
      <collision name='c'><geometry><box size='1 1 1'/></geometry>
        <drake:proximity_properties>
          <drake:rigid_hydroelastic/><drake:mesh_resolution_hint value='0.1'/>
          <drake:hunt_crossley_dissipation value='2'/>
          <drake:point_contact_stiffness value='3e4'/>
          <drake:hydroelastic_margin value='0.01'/>
          <drake:mu_static value='0.9'/>
        </drake:proximity_properties></collision>
      <visual name='v'><geometry><box size='1 1 1'/></geometry>
        <material><color rgba='0.5 0.5 0.5 1'/></material>
        <drake:accepting_renderer name='x'/></visual>
    </link></robot>)";
  SdfCompileResult from_sdf(sdf);
  ASSERT_TRUE(from_sdf.ok()) << from_sdf.Messages();
  Compilation from_urdf;
  frontend::FrontendContext ctx{from_urdf.sources, from_urdf.diags, from_urdf.module,
                                from_urdf.options.frontend};
  frontend::ReadUrdf(from_urdf.sources.AddBuffer("r.urdf", urdf), ctx);
  ASSERT_TRUE(from_urdf.RunPasses());
  ASSERT_TRUE(from_urdf.RunBackend());
  const auto urdf_json = nlohmann::json::parse(backend::EmitPlantJson(
      *from_urdf.model, backend::DefaultPositions(from_urdf.model->plant)));
  const auto sdf_json = from_sdf.PlantJson();
  for (std::string_view name : {"c", "v"}) {
    auto s = AllNamed(sdf_json["geometries"], name);
    auto u = AllNamed(urdf_json["geometries"], name);
    ASSERT_EQ(s.size(), 1u);
    ASSERT_EQ(u.size(), 1u);
    EXPECT_EQ(s[0]["properties"], u[0]["properties"]) << name;
    EXPECT_EQ(s[0]["roles"], u[0]["roles"]) << name;
    EXPECT_EQ(s[0]["shape"], u[0]["shape"]) << name;
  }
}

}  // namespace
}  // namespace mdlc
