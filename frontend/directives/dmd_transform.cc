#include "frontend/directives/dmd_transform.h"

#include <fmt/format.h>

#include <numbers>

namespace mdlc::frontend {
namespace {

// Drake's stochastic schema: tags that draw a value at random
bool IsRandomTag(std::string_view tag) {
  return tag == "!Uniform" || tag == "!UniformVector" || tag == "!Gaussian" ||
         tag == "!GaussianVector" || tag == "!UniformDiscrete";
}

bool RejectRandom(YamlSchemaReader& r, const yaml::Node& node, std::string_view what,
                  Loc fallback) {
  const std::string_view tag = YamlSchemaReader::ExplicitTag(node);
  if (!IsRandomTag(tag)) return false;
  r.diags().Report(DiagKind::BadValue, r.LocOf(node, fallback),
                   fmt::format("{} is a random distribution ({}); model directives must be "
                               "deterministic",
                               what, tag));
  return true;
}

// Drake's deterministic wrappers (!Deterministic {value: x} and
// !DeterministicVector {value: [...]}) hold the plain value under `value`.
// Returns the node to read the plain value from, or nullopt after an error.
std::optional<std::pair<yaml::Node, Loc>> Unwrap(YamlSchemaReader& r, const yaml::Node& node,
                                                 std::string_view wrapper, std::string_view what,
                                                 Loc fallback) {
  if (RejectRandom(r, node, what, fallback)) return std::nullopt;
  if (YamlSchemaReader::ExplicitTag(node) != wrapper) return std::pair{node, fallback};
  if (!r.CheckMap(node, what, {"value"}, fallback)) return std::nullopt;
  auto value = r.Get(node, "value");
  if (!value.present()) {
    r.diags().Report(DiagKind::MissingElement, r.LocOf(node, fallback),
                     fmt::format("{} needs 'value'", what));
    return std::nullopt;
  }
  return std::pair{value.value, value.key_loc};
}

std::optional<Eigen::Vector3d> ReadVector(YamlSchemaReader& r, const yaml::Node& node,
                                          std::string_view what, Loc fallback) {
  auto plain = Unwrap(r, node, "!DeterministicVector", what, fallback);
  if (!plain) return std::nullopt;
  return r.Vector3(plain->first, what, plain->second);
}

std::optional<double> ReadScalar(YamlSchemaReader& r, const yaml::Node& node,
                                 std::string_view what, Loc fallback) {
  auto plain = Unwrap(r, node, "!Deterministic", what, fallback);
  if (!plain) return std::nullopt;
  return r.Number(plain->first, what, plain->second);
}

std::optional<Eigen::Matrix3d> ReadRotation(YamlSchemaReader& r, const yaml::Node& node,
                                            Loc fallback) {
  const std::string_view tag = YamlSchemaReader::ExplicitTag(node);
  const Loc loc = r.LocOf(node, fallback);
  constexpr double kDeg = std::numbers::pi / 180;
  if (RejectRandom(r, node, "rotation", fallback)) return std::nullopt;
  if (tag == "!Rpy") {
    if (!r.CheckMap(node, "rotation !Rpy", {"deg"}, fallback)) return std::nullopt;
    auto deg = r.Get(node, "deg");
    if (!deg.present()) return Eigen::Matrix3d::Identity();  // Drake's default: zero angles
    auto rpy = ReadVector(r, deg.value, "rotation !Rpy 'deg'", deg.key_loc);
    if (!rpy) return std::nullopt;
    return RotationFromRpy(*rpy * kDeg);
  }
  if (tag == "!AngleAxis") {
    if (!r.CheckMap(node, "rotation !AngleAxis", {"angle_deg", "axis"}, fallback)) {
      return std::nullopt;
    }
    auto angle_field = r.Get(node, "angle_deg");
    auto axis_field = r.Get(node, "axis");
    std::optional<double> angle = 0.0;
    if (angle_field.present()) {
      angle = ReadScalar(r, angle_field.value, "rotation !AngleAxis 'angle_deg'",
                         angle_field.key_loc);
    }
    std::optional<Eigen::Vector3d> axis = Eigen::Vector3d::UnitZ();
    if (axis_field.present()) {
      axis = ReadVector(r, axis_field.value, "rotation !AngleAxis 'axis'", axis_field.key_loc);
    }
    if (!angle || !axis) return std::nullopt;
    if (axis->norm() == 0) {
      r.diags().Report(DiagKind::BadValue, r.LocOf(axis_field.value, loc),
                       "rotation !AngleAxis 'axis' must not be zero");
      return std::nullopt;
    }
    return RotationAboutAxis(axis->normalized(), *angle * kDeg);
  }
  if (tag == "!Identity" || (tag.empty() && (node.IsNull() || (node.IsMap() && node.size() == 0)))) {
    if (node.IsMap() && !r.CheckMap(node, "rotation !Identity", {}, fallback)) return std::nullopt;
    return Eigen::Matrix3d::Identity();
  }
  if (!tag.empty()) {
    r.diags().Report(DiagKind::BadValue, loc,
                     fmt::format("unknown rotation form '{}'; use !Rpy {{deg: [r, p, y]}} or "
                                 "!AngleAxis {{angle_deg: a, axis: [x, y, z]}}",
                                 tag));
  } else {
    r.diags().Report(DiagKind::BadValue, loc,
                     "rotation needs a tag saying its form: !Rpy {deg: [r, p, y]} or "
                     "!AngleAxis {angle_deg: a, axis: [x, y, z]}");
  }
  return std::nullopt;
}

}  // namespace

std::optional<DirectiveTransform> ReadDirectiveTransform(YamlSchemaReader& r,
                                                         const yaml::Node& node,
                                                         std::string_view what, Loc fallback) {
  DirectiveTransform out;
  out.loc = r.LocOf(node, fallback);
  if (node.IsNull()) return out;  // written but empty: the identity
  const size_t errors_before = r.diags().error_count();
  if (!r.CheckMap(node, what, {"base_frame", "translation", "rotation"}, fallback)) {
    return std::nullopt;
  }
  bool ok = true;
  if (auto base = r.Get(node, "base_frame"); base.present()) {
    auto name = r.String(base.value, fmt::format("{} 'base_frame'", what), base.key_loc);
    ok = ok && name.has_value();
    if (name) out.base_frame = std::move(*name);
  }
  if (auto translation = r.Get(node, "translation"); translation.present()) {
    auto p = ReadVector(r, translation.value, fmt::format("{} 'translation'", what),
                        translation.key_loc);
    ok = ok && p.has_value();
    if (p) out.X.p = *p;
  }
  if (auto rotation = r.Get(node, "rotation"); rotation.present()) {
    auto R = ReadRotation(r, rotation.value, rotation.key_loc);
    ok = ok && R.has_value();
    if (R) out.X.R = *R;
  }
  if (!ok || r.diags().error_count() != errors_before) return std::nullopt;  // e.g. unknown keys
  return out;
}

}  // namespace mdlc::frontend
