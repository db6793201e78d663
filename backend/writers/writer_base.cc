// writer_base.cc - see writer_base.h.
#include "backend/writers/writer_base.h"

#include <fmt/format.h>

#include <algorithm>
#include <variant>

namespace mdlc::writers {

WriterBase::WriterBase(const backend::CompiledModel& model, const ir::Module& module,
                       const WriteOptions& options, DiagnosticEngine& diags)
    : plant_(model.plant),
      scene_(model.scene),
      m_(module),
      diags_(diags),
      assets_(options, diags),
      geometries_by_body_(plant_.bodies.size(), scene_.geometries.size(),
                          [&](size_t i) { return scene_.geometries[i].body.index(); }),
      cameras_by_body_(plant_.bodies.size(), scene_.cameras.size(),
                       [&](size_t i) { return scene_.cameras[i].body.index(); }),
      frames_by_body_(plant_.bodies.size(), plant_.frames.size(),
                      [&](size_t i) { return plant_.frames[i].body.index(); }),
      actuators_by_joint_(plant_.joints.size(), plant_.actuators.size(),
                          [&](size_t i) { return plant_.actuators[i].joint.index(); }),
      couplers_by_follower_(plant_.joints.size(), plant_.constraints.size(),
                            [&](size_t i) -> int64_t {
                              const auto* c = std::get_if<backend::CouplerConstraint>(
                                  &plant_.constraints[i].payload);
                              return c ? int64_t(c->joint0.index()) : EntityIndex::kNoKey;
                            }),
      springs_by_joint_(plant_.joints.size(), plant_.force_elements.size(),
                        [&](size_t i) -> int64_t {
                          const auto* s =
                              std::get_if<backend::JointSpring>(&plant_.force_elements[i]);
                          return s ? int64_t(s->joint.index()) : EntityIndex::kNoKey;
                        }) {
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
