// sdf_link.cc - <link> (bodies and their frame nodes), <inertial> and
// <frame> (SDF-007, SDF-008, SDF-042, SDF-043).
#include <fmt/format.h>

#include <array>
#include <iterator>

#include "frontend/sdf/sdf_reader_detail.h"

namespace mdlc::frontend::sdf {

void SdfReader::ReadLink(const xml::XmlElement& e, ModelScope& s) {
  auto name = attrs_.String(e, "name", xml::Need::Required);
  if (!name) return;
  attrs_.WarnUnknownAttributes(e, {"name"});
  if (!CheckDefinedName(*name, e.GetLoc(), "link", s.file->version)) return;
  CheckChildren(e,
                {"gravity", "enable_wind", "self_collide", "kinematic", "must_be_base_link",
                 "velocity_decay", "pose", "inertial", "collision", "visual", "sensor",
                 "projector", "audio_sink", "audio_source", "battery", "light",
                 "particle_emitter", "frame", "drake:surface_velocity_axis", "drake:visual",
                 "drake:deformable_properties", "drake:wall_boundary_condition"},
                {});
  const Symbol link_name = module().Intern(*name);

  ir::Body body;
  body.name = link_name;
  body.model = s.model;
  body.loc = e.GetLoc();
  if (auto inertial = e.Child("inertial")) {
    ReadInertial(inertial, body);
  } else {
    // libsdformat's default inertial: 1 kg with unit moments (SDF-007)
    ir::Inertial defaults;
    defaults.loc = e.GetLoc();
    defaults.mass = 1;
    defaults.ixx = defaults.iyy = defaults.izz = 1;
    body.inertial = defaults;
  }
  const BodyId body_id = module().Add(std::move(body));

  ir::FrameNode node;
  node.kind = ir::FrameNodeKind::Link;
  node.name = link_name;
  node.loc = e.GetLoc();
  xml::XmlElement pose = e.Child("pose");
  node.relative_to = RelativeTo(pose);
  if (node.relative_to.empty()) node.relative_to = {s.model_frame_name, e.GetLoc()};
  node.X_RN = ReadPoseValue(pose);
  node.attached_to = {link_name, e.GetLoc()};
  node.target = ir::FrameTarget::Body;
  node.target_index = body_id.value;
  const FrameNodeId node_id = AddNode(s, std::move(node));
  graph()[s.scope].links.push_back(node_id);

  // names are unique per link: the table holds this link's only, so it stays
  // small and in cache however many links the file has
  geometry_names_.clear();
  for (auto child = e.FirstChild(); child; child = child.NextSibling()) {
    std::string_view tag = child.Name();
    if (tag == "visual" || tag == "drake:visual") {
      ReadVisual(child, s, body_id, link_name, node_id);
    } else if (tag == "collision") {
      ReadCollision(child, s, body_id, link_name, node_id);
    } else if (tag == "sensor") {
      ReadSensor(child, s, body_id, link_name, node_id);
    } else if (tag == "frame") {
      // SDFormat 1.5/1.6 allowed frames inside links; they attach to the link
      ReadFrame(child, s);
    } else if (tag == "drake:surface_velocity_axis") {
      if (auto axis = TextVector3(child)) {
        if (axis->norm() < 1e-12) {
          diags().Report(DiagKind::ZeroAxis, child.GetLoc(),
                         "drake:surface_velocity_axis must not be zero");
        } else {
          module()[body_id].surface_velocity_axis = axis->normalized();
        }
      }
    } else if (tag == "gravity" || tag == "kinematic" || tag == "self_collide" ||
               tag == "enable_wind") {
      // unsupported, and only worth a word when set to something else than the default
      const bool default_value = tag == "gravity";
      if (auto v = TextBool(child); v && *v != default_value) {
        diags().Report(DiagKind::UnsupportedElement, child.GetLoc(),
                       fmt::format("element <{}> in <link> is not supported and is ignored",
                                   tag));
      }
    } else if (tag == "velocity_decay") {
      // unsupported, but its numbers must still be numbers (COMMON-007)
      for (auto v = child.FirstChild(); v; v = v.NextSibling()) TextDouble(v);
      diags().Report(DiagKind::UnsupportedElement, child.GetLoc(),
                     "element <velocity_decay> in <link> is not supported and is ignored");
    } else if (tag == "must_be_base_link" || tag == "projector" ||
               tag == "audio_sink" || tag == "audio_source" || tag == "battery" ||
               tag == "light" || tag == "particle_emitter") {
      diags().Report(DiagKind::UnsupportedElement, child.GetLoc(),
                     fmt::format("element <{}> in <link> is not supported and is ignored",
                                 tag));
    }
  }
  if (e.Child("drake:deformable_properties")) ReadDeformableProperties(e, s, body_id);
}

void SdfReader::ReadInertial(const xml::XmlElement& e, ir::Body& body) {
  // one walk over the children, not a search per name (every link has one)
  static constexpr std::string_view kRead[] = {"mass", "pose", "inertia", "fluid_added_mass"};
  static constexpr std::string_view kAlsoKnown[] = {"density", "auto"};
  std::array<xml::XmlElement, std::size(kRead)> first;
  FirstChildrenNamed(e, kRead, first, kAlsoKnown);
  const auto& [mass, pose, inertia, fluid] = first;
  ir::Inertial inertial;
  inertial.loc = e.GetLoc();
  inertial.mass = 1;  // libsdformat's default
  inertial.ixx = inertial.iyy = inertial.izz = 1;
  bool mass_given = false;
  if (mass) {
    if (auto v = TextDouble(mass)) {
      inertial.mass = *v;
      mass_given = true;
    }
  }
  if (auto a = attrs_.Bool(e, "auto"); a && *a) {
    // the inertia-from-collisions pass computes it once the collisions are placed
    double density = 1000;
    if (auto d = ChildDouble(e, "density")) {
      if (*d > 0) {
        density = *d;
      } else {
        diags().Report(DiagKind::BadValue, e.Child("density").GetLoc(),
                       fmt::format("<density> must be positive, got {}", *d));
      }
    }
    body.inertia_from_collisions = density;
    if (mass_given) body.inertia_from_collisions_mass = inertial.mass;
  }
  if (pose) {
    if (ir::NameRef r = RelativeTo(pose); !r.empty()) {
      diags().Report(DiagKind::UnsupportedAttribute, r.loc,
                     "relative_to on an <inertial> pose is not supported: the pose is relative "
                     "to the link");
    }
    inertial.X_BI = ReadPoseValue(pose);
  }
  if (inertia) ReadMoments(inertia, inertial);
  if (fluid) {
    diags().Report(DiagKind::UnsupportedElement, fluid.GetLoc(),
                   "element <fluid_added_mass> in <inertial> is not supported and is ignored");
  }
  body.inertial = inertial;
}

void SdfReader::ReadMoments(const xml::XmlElement& inertia, ir::Inertial& inertial) {
  static constexpr std::string_view kMoments[] = {"ixx", "iyy", "izz", "ixy", "ixz", "iyz"};
  double* const slots[] = {&inertial.ixx, &inertial.iyy, &inertial.izz,
                           &inertial.ixy, &inertial.ixz, &inertial.iyz};
  std::array<xml::XmlElement, std::size(kMoments)> first;
  FirstChildrenNamed(inertia, kMoments, first, {});
  for (size_t k = 0; k < first.size(); ++k) {
    if (!first[k]) continue;
    if (auto v = TextDouble(first[k])) *slots[k] = *v;
  }
}

void SdfReader::ReadFrame(const xml::XmlElement& e, ModelScope& s) {
  auto name = attrs_.String(e, "name", xml::Need::Required);
  if (!name) return;
  attrs_.WarnUnknownAttributes(e, {"name", "attached_to"});
  if (!CheckDefinedName(*name, e.GetLoc(), "frame", s.file->version)) return;
  CheckChildren(e, {"pose"});
  const Symbol frame_name = module().Intern(*name);

  ir::Frame frame;
  frame.name = frame_name;
  frame.model = s.model;
  frame.loc = e.GetLoc();
  const FrameId frame_id = module().Add(std::move(frame));

  ir::FrameNode node;
  node.kind = ir::FrameNodeKind::Frame;
  node.name = frame_name;
  node.loc = e.GetLoc();
  if (auto a = e.Attribute("attached_to"); a.present() && !a.value.empty()) {
    node.attached_to = {module().Intern(a.value), a.loc};
  } else if (e.Parent().Name() == "link") {
    // SDFormat 1.5/1.6: a frame inside a link belongs to the link
    node.attached_to = {module().Intern(e.Parent().Attribute("name").value), e.GetLoc()};
  } else {
    node.attached_to = {s.model_frame_name, e.GetLoc()};
  }
  xml::XmlElement pose = e.Child("pose");
  node.relative_to = RelativeTo(pose);
  if (node.relative_to.empty()) node.relative_to = node.attached_to;
  node.X_RN = ReadPoseValue(pose);
  node.target = ir::FrameTarget::Frame;
  node.target_index = frame_id.value;
  AddNode(s, std::move(node));
}

}  // namespace mdlc::frontend::sdf
