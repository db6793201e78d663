// drake_elements.h - the model-level drake: elements of URDF and SDFormat,
// one implementation for both formats: collision filter groups (EXT-040),
// force elements (EXT-050 linear_bushing_rpy, EXT-051 linear_spring_damper)
// and constraints (EXT-052 ball, EXT-053 distance, EXT-054 tendon).
//
// The formats differ only in where a child writes its value or name
// (ValueSpelling, see drake_child_reader.h). Read after every link, joint and
// frame of the model, so they may name any of them. These readers lower
// syntax only: every name becomes a Ref (the name and where it is written)
// that the resolve-names pass resolves within the model instance; rules that
// need the resolved entities (group definitions, COMMON-050; distinct bodies;
// single-dof tendon joints) are the check-model-elements pass's. Values are
// checked here, as Drake's parsers and MultibodyPlant do.
#pragma once

#include "frontend/drake_child_reader.h"
#include "frontend/xml/attribute_reader.h"
#include "frontend/xml/xml_document.h"
#include "ir/module.h"

namespace mdlc::frontend {

/// Where the elements go and how their values are spelled.
struct DrakeElementContext {
  ir::Module& module;
  xml::AttributeReader& attrs;
  ModelId model;
  ValueSpelling spelling;
};

/// <drake:collision_filter_group name [ignore]> with <drake:member> (a link),
/// <drake:member_group> and <drake:ignored_collision_filter_group> (EXT-040).
void ReadDrakeCollisionFilterGroup(const xml::XmlElement& e, const DrakeElementContext& ctx);
/// <drake:linear_bushing_rpy> (EXT-050).
void ReadDrakeLinearBushing(const xml::XmlElement& e, const DrakeElementContext& ctx);
/// <drake:linear_spring_damper> (EXT-051).
void ReadDrakeLinearSpringDamper(const xml::XmlElement& e, const DrakeElementContext& ctx);
/// <drake:ball_constraint> (EXT-052).
void ReadDrakeBallConstraint(const xml::XmlElement& e, const DrakeElementContext& ctx);
/// <drake:distance_constraint> (EXT-053).
void ReadDrakeDistanceConstraint(const xml::XmlElement& e, const DrakeElementContext& ctx);
/// <drake:tendon_constraint> (EXT-054).
void ReadDrakeTendonConstraint(const xml::XmlElement& e, const DrakeElementContext& ctx);

/// Reads `e` when it is one of the elements above; false when it is not
/// (nothing is reported then).
bool ReadDrakeModelLevelElement(const xml::XmlElement& e, const DrakeElementContext& ctx);

}  // namespace mdlc::frontend
