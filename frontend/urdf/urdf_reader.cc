// urdf_reader.cc - the <robot> element: instance naming, dispatch to the
// element readers, and robot-level materials (URDF-001, URDF-030).
#include <fmt/format.h>

#include <cmath>

#include "frontend/drake_elements.h"
#include "frontend/entity_capacity.h"
#include "frontend/model_naming.h"
#include "frontend/unknown_element.h"
#include "frontend/urdf/urdf_reader_detail.h"

namespace mdlc::frontend {

std::optional<ModelId> ReadUrdf(FileId file, FrontendContext& ctx) {
  std::shared_ptr<const xml::XmlDocument> doc = ParseXml(file, ctx);
  if (!doc) return std::nullopt;
  ReserveEntities(ctx.module, UrdfEntityRoom(*doc));
  urdf::UrdfReader reader(ctx, *doc);
  return reader.Read();
}

}  // namespace mdlc::frontend

namespace mdlc::frontend::urdf {

bool UrdfReader::Ignored(const xml::XmlElement& e) {
  auto v = e.Attribute("drake_ignore");
  return v.present() && v.value == "true";
}

std::optional<ModelId> UrdfReader::Read() {
  xml::XmlElement robot = doc_.Root();
  if (robot.Name() != "robot") {
    diags().Report(DiagKind::WrongRoot, robot.GetLoc(),
                   fmt::format("URDF file must have a <robot> root element (robot tag), found <{}>",
                               robot.Name()));
    return std::nullopt;
  }
  auto name = attrs_.String(robot, "name");
  if (!name || name->empty()) {
    diags().Report(DiagKind::MissingAttribute, robot.GetLoc(),
                   "<robot> is missing required attribute 'name' (the model instance name)");
    if (!ctx_.options.model_name) return std::nullopt;
  }
  if (auto version = robot.Attribute("version"); version.present()) {
    diags().Report(DiagKind::UnsupportedAttribute, version.loc,
                   "attribute 'version' of <robot> is not supported and is ignored");
  }
  attrs_.WarnUnknownAttributes(robot, {"name", "version", "xmlns:xacro"});
  auto model = AddModelInstance(name ? *name : "", robot.GetLoc(), ir::SourceFormat::Urdf, ctx_);
  if (!model) return std::nullopt;
  model_ = *model;

  // materials first: links may use a material defined later in the file.
  // The walk starts at the first one, and a robot without any (as most
  // are) is not walked twice: each child's first touch is a cache miss
  // once the tree outgrows the cache
  for (auto e = robot.Child("material"); e; e = e.NextSibling()) {
    if (e.Name() == "material") ReadRobotMaterial(e);
  }
  for (auto e = robot.FirstChild(); e; e = e.NextSibling()) {
    std::string_view tag = e.Name();
    if (tag == "link") {
      if (!Ignored(e)) ReadLink(e);
    } else if (tag == "joint") {
      if (!Ignored(e)) ReadJoint(e);
    } else if (tag == "frame") {
      ReadFrame(e);
    } else if (tag == "transmission") {
      transmissions_.push_back(e);  // needs the joints, which may come later
    } else if (tag == "material" || tag == "gazebo") {
      // materials were read above; <gazebo> is Gazebo's, silently ignored (URDF-023)
    } else if (tag == "loop_joint") {
      diags().Report(DiagKind::NotImplemented, e.GetLoc(),
                     "loop joints are not supported: the plant must be a tree");
    } else if (tag == "drake:joint") {
      if (!Ignored(e)) ReadDrakeJoint(e);
    } else if (tag == "drake:collision_filter_group" || tag == "drake:linear_bushing_rpy" ||
               tag == "drake:linear_spring_damper" || tag == "drake:ball_constraint" ||
               tag == "drake:distance_constraint" || tag == "drake:tendon_constraint") {
      late_elements_.push_back(e);
    } else if (tag.starts_with("drake:")) {
      diags().Report(DiagKind::UnknownElement, e.GetLoc(),
                     fmt::format("unknown element <{}> in <robot> is ignored", tag));
    } else {
      ReportUnknownElement(diags(), e, "robot",
                           {"link", "joint", "material", "transmission", "gazebo", "frame"});
    }
  }
  for (const auto& e : transmissions_) ReadTransmission(e);
  // model-level drake: elements (EXT-040, EXT-050..054), read last so they
  // may name any link, joint or frame; URDF spells their values in attributes
  const DrakeElementContext drake{module(), attrs_, model_, ValueSpelling::Attribute};
  for (const auto& e : late_elements_) ReadDrakeModelLevelElement(e, drake);
  return model_;
}

std::optional<Eigen::Vector4d> UrdfReader::ReadColor(const xml::XmlElement& material) {
  auto color = material.Child("color");
  if (!color) return std::nullopt;
  auto rgba = attrs_.Doubles(color, "rgba", 4, xml::Need::Required);
  if (!rgba) return std::nullopt;
  for (double v : *rgba) {
    if (v < 0 || v > 1) {
      diags().Report(DiagKind::BadValue, color.Attribute("rgba").loc,
                     fmt::format("color rgba values must be within [0, 1], got '{}'",
                                 color.Attribute("rgba").value));
      return std::nullopt;
    }
  }
  return Eigen::Vector4d((*rgba)[0], (*rgba)[1], (*rgba)[2], (*rgba)[3]);
}

void UrdfReader::ReadRobotMaterial(const xml::XmlElement& e) {
  auto name = attrs_.String(e, "name", xml::Need::Required);
  if (!name) return;
  ir::Material material;
  material.name = module().Intern(*name);
  material.model = model_;
  material.loc = e.GetLoc();
  material.rgba = ReadColor(e);
  if (auto texture = e.Child("texture")) {
    if (auto file = attrs_.String(texture, "filename")) material.texture = std::string(*file);
  }
  auto it = materials_.find(material.name.value);
  if (it != materials_.end()) {
    // identical re-definitions are fine; different ones are an error (URDF-030)
    const ir::Material& first = module()[it->second.id];
    const bool same_color = first.rgba.has_value() == material.rgba.has_value() &&
                            (!first.rgba || first.rgba->isApprox(*material.rgba, 0.0));
    if (!same_color || first.texture != material.texture) {
      diags()
          .Report(DiagKind::MaterialConflict, material.loc,
                  fmt::format("material '{}' is defined again with different values", *name))
          .Note(it->second.loc, "previous definition is here");
    }
    return;
  }
  materials_[material.name.value] = {module().Add(std::move(material)), e.GetLoc()};
}

std::optional<Eigen::Vector4d> UrdfReader::ReadVisualMaterial(const xml::XmlElement& e,
                                                             ir::Geometry& g) {
  auto name = e.Attribute("name");
  auto color = ReadColor(e);
  std::string texture;
  if (auto t = e.Child("texture")) {
    if (auto file = attrs_.String(t, "filename")) texture = std::string(*file);
  }
  if (!name.present()) return color;
  const Symbol symbol = module().Intern(name.value);
  g.material = {symbol, name.loc, {}};
  if (auto it = materials_.find(symbol.value); it != materials_.end()) {
    g.material.id = it->second.id;
    return color ? color : module()[it->second.id].rgba;
  }
  if (!color && texture.empty()) {
    diags().Report(DiagKind::UnknownMaterial, name.loc,
                   fmt::format("material '{}' is not defined at robot level and gives no "
                               "color or texture of its own",
                               name.value));
    return std::nullopt;
  }
  // an inline definition names a new material, usable by later visuals
  ir::Material material;
  material.name = symbol;
  material.model = model_;
  material.loc = e.GetLoc();
  material.rgba = color;
  material.texture = std::move(texture);
  g.material.id = module().Add(std::move(material));
  materials_[symbol.value] = {g.material.id, e.GetLoc()};
  return color;
}

Transform UrdfReader::ReadOrigin(const xml::XmlElement& parent) {
  Transform X;
  auto origin = parent.Child("origin");
  if (!origin) return X;
  if (auto xyz = attrs_.Vector3(origin, "xyz")) X.p = *xyz;
  if (auto rpy = attrs_.Vector3(origin, "rpy")) X.R = RotationFromRpy(*rpy);
  attrs_.WarnUnknownAttributes(origin, {"xyz", "rpy"});
  return X;
}

}  // namespace mdlc::frontend::urdf
