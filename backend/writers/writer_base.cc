// writer_base.cc - see writer_base.h.
#include "backend/writers/writer_base.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>

namespace mdlc::writers {

bool AllEqual(std::span<const double> values) {
  return std::adjacent_find(values.begin(), values.end(), std::not_equal_to<>()) ==
         values.end();
}

WriterBase::WriterBase(const backend::CompiledModel& model, const ir::Module& module,
                       const WriteOptions& options, DiagnosticEngine& diags)
    : plant_(model.plant),
      scene_(model.scene),
      m_(module),
      diags_(diags),
      assets_(options, diags),
      geometries_by_body_(backend::GeometriesByBody(plant_, scene_)),
      cameras_by_body_(backend::CamerasByBody(plant_, scene_)),
      frames_by_body_(backend::FramesByBody(plant_)),
      actuators_by_joint_(backend::ActuatorsByJoint(plant_)),
      couplers_by_follower_(backend::CouplersByFollower(plant_)),
      springs_by_joint_(backend::SpringsByJoint(plant_)) {
  size_t ir_index = 0;
  geometry_locs_.reserve(scene_.geometries.size());
  for (size_t i = 0; i < scene_.geometries.size(); ++i) {
    while (ir_index < m_.geometries.size() && m_.geometries[ir_index].roles == 0) ++ir_index;
    geometry_locs_.push_back(ir_index < m_.geometries.size() ? m_.geometries[ir_index].loc
                                                             : Loc{});
    ++ir_index;
  }
}

const ir::Property* WriterBase::FindProperty(const backend::SceneGeometry& g,
                                             std::string_view key) {
  for (const ir::Property& p : g.properties) {
    if (p.key == key) return &p;
  }
  return nullptr;
}

void WriterBase::ReportAsymmetricLimits(const backend::PlantJoint& j, Loc loc,
                                        std::string_view format) const {
  auto report = [&](std::string_view what, double lower, double upper) {
    if (lower == -upper) return;
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("joint '{}' has {} limits [{}, {}]; {}'s are symmetric, so +-{} "
                              "is written",
                              j.name, what, lower, upper, format, upper));
  };
  report("velocity", j.velocity_lower[0], j.velocity_upper[0]);
  report("acceleration", j.acceleration_lower[0], j.acceleration_upper[0]);
}

void WriterBase::ReportUnwrittenDefaultPositions(const backend::PlantJoint& j, Loc loc,
                                                 std::string_view why) const {
  const ir::DofValues& q = j.default_positions;
  if (std::all_of(q.begin(), q.end(), [](double v) { return v == 0; })) return;
  diags_.Report(DiagKind::Lossy, loc,
                fmt::format("the default position of joint '{}' ({}) is not written ({})", j.name,
                            VectorText(Eigen::Map<const Eigen::VectorXd>(
                                q.data(), static_cast<Eigen::Index>(q.size()))),
                            why));
}

bool WriterBase::IsAppearanceProperty(const ir::Property& p) {
  return p.key.starts_with("phong/") || p.key.starts_with("renderer/") ||
         p.key.starts_with("label/");
}

}  // namespace mdlc::writers
