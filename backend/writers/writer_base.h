// writer_base.h - what the URDF, SDFormat and MJCF writers share: the
// compiled model they read, where each of its entities came from (the
// location a -Wlossy warning points at), the XML being written and the
// asset files it names.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "backend/compiled_model.h"
#include "backend/entity_index.h"
#include "backend/writers/asset_paths.h"
#include "backend/writers/names.h"
#include "backend/writers/writer.h"
#include "backend/writers/xml_out.h"
#include "ir/diagnostics.h"
#include "ir/module.h"

namespace mdlc::writers {

using backend::EntityIndex;

/// Whether every value is the same (a joint's per-coordinate damping or
/// limits, which some formats hold once).
bool AllEqual(std::span<const double> values);

class WriterBase {
 protected:
  WriterBase(const backend::CompiledModel& model, const ir::Module& module,
             const WriteOptions& options, DiagnosticEngine& diags);

  // Source locations. Plant entity i is IR entity i (backend/plant.h); what
  // the compiler made beyond the IR's tables has no location.
  Loc BodyLoc(BodyId body) const { return At(m_.bodies, body.index()); }
  Loc JointLoc(JointId joint) const { return At(m_.joints, joint.index()); }
  Loc FrameLoc(size_t frame) const { return At(m_.frames, frame); }
  Loc ModelLoc(size_t model) const { return At(m_.models, model); }
  Loc ActuatorLoc(size_t actuator) const { return At(m_.actuators, actuator); }
  Loc ConstraintLoc(size_t constraint) const { return At(m_.constraints, constraint); }
  Loc ForceElementLoc(size_t element) const { return At(m_.force_elements, element); }
  Loc CameraLoc(size_t camera) const { return At(m_.cameras, camera); }
  /// Scene geometry i's location: the scene's geometries are the IR's that
  /// have a role, in order.
  Loc GeometryLoc(size_t geometry) const {
    return geometry < geometry_locs_.size() ? geometry_locs_[geometry] : Loc{};
  }

  /// The property `key` of `g`, or null.
  static const ir::Property* FindProperty(const backend::SceneGeometry& g, std::string_view key);
  /// Whether a property is the visual's (phong/, renderer/, label/), not proximity's.
  static bool IsAppearanceProperty(const ir::Property& p);
  /// Warns (-Wlossy) that a 1-dof joint's velocity or acceleration limits
  /// are not symmetric, as `format`'s are, so +-upper is written.
  void ReportAsymmetricLimits(const backend::PlantJoint& j, Loc loc,
                              std::string_view format) const;
  /// Warns (-Wlossy) that a joint's nonzero default positions are not
  /// written, saying `why` (the target holds none).
  void ReportUnwrittenDefaultPositions(const backend::PlantJoint& j, Loc loc,
                                       std::string_view why) const;
  static bool IsFloating(const backend::PlantJoint& j) {
    return j.type == ir::JointType::QuaternionFloating || j.type == ir::JointType::RpyFloating;
  }

  const backend::Plant& plant_;
  const backend::SceneGraph& scene_;
  const ir::Module& m_;
  DiagnosticEngine& diags_;
  AssetPaths assets_;
  XmlOut out_;
  // what belongs to each body and joint, so that writing one costs only
  // what it holds (entity_index.h)
  const EntityIndex geometries_by_body_, cameras_by_body_, frames_by_body_;
  const EntityIndex actuators_by_joint_;
  const EntityIndex couplers_by_follower_;  // constraints: a coupler's joint0
  const EntityIndex springs_by_joint_;      // force elements: joint springs

 private:
  template <typename Table>
  static Loc At(const Table& table, size_t i) {
    return i < table.size() ? table[i].loc : Loc{};
  }

  std::vector<Loc> geometry_locs_;
};

/// The base of the writers whose format has one namespace for the whole
/// file (URDF, MJCF): every entity's name goes through FlatNames.
class FlatWriterBase : public WriterBase {
 protected:
  FlatWriterBase(const backend::CompiledModel& model, const ir::Module& module,
                 const WriteOptions& options, DiagnosticEngine& diags)
      : WriterBase(model, module, options, diags), names_(plant_) {}

  std::string Named(ModelId model, std::string_view name) const {
    return names_.Named(model, name);
  }
  /// Round-trip metadata inside the element just opened, after its
  /// attributes: the entity's instance and name when the file does not say
  /// them (names.h, ir/syntax/original_name_comment.h); `written` is the name
  /// in the file.
  void OriginalName(ModelId model, std::string_view name, std::string_view written) {
    if (auto comment = names_.OriginalNameComment(model, name, written)) out_.Comment(*comment);
  }
  /// A body's name in the file; the world body is "world".
  std::string BodyName(BodyId body) const {
    if (body.index() == 0) return "world";
    const backend::PlantBody& b = plant_.body(body);
    return Named(b.model, b.name);
  }
  std::string JointName(JointId joint) const {
    const backend::PlantJoint& j = plant_.joint(joint);
    return Named(j.model, j.name);
  }

  FlatNames names_;
};

}  // namespace mdlc::writers
