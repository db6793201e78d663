// sdf_values.cc - SDFormat values written as element text: numbers, vectors,
// booleans and poses (SDF-003). Each reader reports its own problem at the
// element and returns nullopt, so callers skip what they could not read.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include "frontend/sdf/sdf_reader_detail.h"
#include "frontend/xml/trim.h"

namespace mdlc::frontend::sdf {

std::optional<std::string> SdfReader::ChildText(const xml::XmlElement& parent,
                                                std::string_view name, xml::Need need) {
  xml::XmlElement child = parent.Child(name);
  if (!child) {
    if (need == xml::Need::Required) {
      diags().Report(DiagKind::MissingElement, parent.GetLoc(),
                     fmt::format("<{}> is missing required element <{}>", parent.Name(), name));
    }
    return std::nullopt;
  }
  std::string storage;
  return std::string(xml::Trim(child.TextView(storage)));
}

std::optional<double> SdfReader::LeadingNumber(const xml::XmlElement& e, std::string_view text) {
  // libsdformat reads the leading number and drops the rest; real models
  // rely on it ("2.35"" with a stray quote), so take the number, and warn
  std::string_view trimmed = xml::Trim(text);
  std::string copy(trimmed);
  char* end = nullptr;
  const double prefix = copy.empty() ? 0 : std::strtod(copy.c_str(), &end);
  if (end && end != copy.c_str()) {
    diags().Report(DiagKind::TrailingText, e.GetLoc(),
                   fmt::format("<{}> holds '{}': the text after the number {} is ignored",
                               e.Name(), trimmed, std::string_view(copy.c_str(), end - copy.c_str())));
    return prefix;
  }
  diags().Report(DiagKind::BadValue, e.GetLoc(),
                 fmt::format("<{}> must hold a number, found '{}'", e.Name(), trimmed));
  return std::nullopt;
}

std::optional<double> SdfReader::TextDouble(const xml::XmlElement& e, xml::Finite finite) {
  std::string storage;
  const std::string_view text = e.TextView(storage);
  std::optional<double> parsed = xml::ParseDouble(text);
  if (!parsed) parsed = LeadingNumber(e, text);
  if (!parsed) return std::nullopt;
  // returned as a plain double: an optional kept in memory and copied out
  // whole is written in two parts and read in one, which stalls the load
  const double value = *parsed;
  if (finite == xml::Finite::Required && !std::isfinite(value)) {
    diags().Report(DiagKind::NonFinite, e.GetLoc(),
                   fmt::format("<{}> must be finite, found '{}'", e.Name(), xml::Trim(text)));
    return std::nullopt;
  }
  return value;
}

std::optional<double> SdfReader::ChildDouble(const xml::XmlElement& parent, std::string_view name,
                                             xml::Need need, xml::Finite finite) {
  xml::XmlElement child = parent.Child(name);
  if (!child) {
    if (need == xml::Need::Required) {
      diags().Report(DiagKind::MissingElement, parent.GetLoc(),
                     fmt::format("<{}> is missing required element <{}>", parent.Name(), name));
    }
    return std::nullopt;
  }
  return TextDouble(child, finite);
}

std::optional<std::vector<double>> SdfReader::TextDoubles(const xml::XmlElement& e, size_t count,
                                                          xml::Finite finite) {
  std::string storage;
  const std::string_view text = e.TextView(storage);
  auto values = xml::ParseDoubleList(text);
  if (!values || values->size() != count) {
    diags().Report(DiagKind::BadValue, e.GetLoc(),
                   fmt::format("<{}> must hold {} numbers, found '{}'", e.Name(), count,
                               xml::Trim(text)));
    return std::nullopt;
  }
  if (finite == xml::Finite::Required) {
    for (double v : *values) {
      if (!std::isfinite(v)) {
        diags().Report(DiagKind::NonFinite, e.GetLoc(),
                       fmt::format("<{}> must hold finite numbers, found '{}'", e.Name(),
                                   xml::Trim(text)));
        return std::nullopt;
      }
    }
  }
  return values;
}

std::optional<Eigen::Vector3d> SdfReader::TextVector3(const xml::XmlElement& e) {
  // read in place, as nearly every vector is well formed; TextDoubles says
  // what is wrong with the others
  std::string storage;
  Eigen::Vector3d v;
  if (const auto count = xml::ParseDoublesInto(e.TextView(storage), v.data(), 3);
      count && *count == 3 && v.allFinite()) {
    return v;
  }
  auto values = TextDoubles(e, 3);
  if (!values) return std::nullopt;
  return Eigen::Vector3d((*values)[0], (*values)[1], (*values)[2]);
}

std::optional<Eigen::Vector3d> SdfReader::ChildVector3(const xml::XmlElement& parent,
                                                       std::string_view name, xml::Need need) {
  xml::XmlElement child = parent.Child(name);
  if (!child) {
    if (need == xml::Need::Required) {
      diags().Report(DiagKind::MissingElement, parent.GetLoc(),
                     fmt::format("<{}> is missing required element <{}>", parent.Name(), name));
    }
    return std::nullopt;
  }
  return TextVector3(child);
}

std::optional<bool> SdfReader::TextBool(const xml::XmlElement& e) {
  std::string text(xml::Trim(e.Text()));
  if (text == "true" || text == "1") return true;
  if (text == "false" || text == "0") return false;
  diags().Report(DiagKind::BadValue, e.GetLoc(),
                 fmt::format("<{}> must be true, false, 1 or 0, found '{}'", e.Name(), text));
  return std::nullopt;
}

std::optional<bool> SdfReader::ChildBool(const xml::XmlElement& parent, std::string_view name) {
  xml::XmlElement child = parent.Child(name);
  if (!child) return std::nullopt;
  return TextBool(child);
}

ir::NameRef SdfReader::RelativeTo(const xml::XmlElement& pose) {
  if (!pose) return {};
  xml::XmlAttribute a = pose.Attribute("relative_to");
  if (!a.present() || a.value.empty()) {
    // SDFormat 1.4 to 1.6 spelled it `frame`; an empty one means the default
    a = pose.Attribute("frame");
    if (!a.present() || a.value.empty()) return {};
  }
  return {module().Intern(a.value), a.loc};
}

Transform SdfReader::ReadPoseValue(const xml::XmlElement& pose) {
  if (!pose) return Transform::Identity();
  bool degrees = false;
  std::string_view format = "euler_rpy";
  if (pose.AttributeNameBits() != 0) {  // most poses have no attributes
    attrs_.WarnUnknownAttributes(pose, {"relative_to", "frame", "rotation_format", "degrees"});
    if (auto d = attrs_.Bool(pose, "degrees")) degrees = *d;
    if (auto f = attrs_.String(pose, "rotation_format")) format = *f;
  }
  std::string storage;
  const std::string_view text = pose.TextView(storage);
  if (xml::Trim(text).empty()) return Transform::Identity();
  std::array<double, 7> v;  // x y z and a quaternion, or x y z roll pitch yaw
  const auto count = xml::ParseDoublesInto(text, v.data(), v.size());
  const size_t want = format == "quat_xyzw" ? 7 : 6;
  if (format != "euler_rpy" && format != "quat_xyzw") {
    diags().Report(DiagKind::BadValue, pose.Attribute("rotation_format").loc,
                   fmt::format("rotation_format must be 'euler_rpy' or 'quat_xyzw', found '{}'",
                               format));
    return Transform::Identity();
  }
  if (!count || *count != want) {
    diags().Report(DiagKind::BadValue, pose.GetLoc(),
                   fmt::format("<pose> must hold {} numbers ({}), found '{}'", want,
                               want == 7 ? "x y z qx qy qz qw" : "x y z roll pitch yaw",
                               xml::Trim(text)));
    return Transform::Identity();
  }
  for (size_t i = 0; i < want; ++i) {
    if (!std::isfinite(v[i])) {
      diags().Report(DiagKind::NonFinite, pose.GetLoc(),
                     fmt::format("<pose> must hold finite numbers, found '{}'", xml::Trim(text)));
      return Transform::Identity();
    }
  }
  Transform X;
  X.p = Eigen::Vector3d(v[0], v[1], v[2]);
  if (want == 7) {
    Eigen::Quaterniond q(v[6], v[3], v[4], v[5]);  // file order x y z w
    if (q.norm() < 1e-12) {
      diags().Report(DiagKind::BadValue, pose.GetLoc(), "<pose> quaternion must not be zero");
      return Transform::Identity();
    }
    X.R = q.normalized().toRotationMatrix();
  } else {
    const double scale = degrees ? std::numbers::pi / 180.0 : 1.0;
    X.R = RotationFromRpy(Eigen::Vector3d(v[3], v[4], v[5]) * scale);
  }
  return X;
}

}  // namespace mdlc::frontend::sdf
