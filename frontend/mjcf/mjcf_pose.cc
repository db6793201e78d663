// mjcf_pose.cc - reading numbers and poses off elements, with default
// classes applied the way MuJoCo applies them (MJCF-010, MJCF-012).
//
// MuJoCo's orientation rule, checked against MuJoCo 3.3: an element starts
// as a copy of its class (quat and the "alternative" orientation both), then
// its own attributes overwrite. The alternative (axisangle, xyaxes, zaxis,
// euler), when any level has one, wins over quat. So an element's own
// alternative wins; else the nearest class's alternative (even over the
// element's own quat); else quat, own or inherited.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <span>

#include "frontend/mjcf/mjcf_orientation.h"
#include "frontend/mjcf/mjcf_reader_detail.h"

namespace mdlc::frontend::mjcf {
namespace {
constexpr std::array<std::string_view, 4> kAlternatives = {"axisangle", "xyaxes", "zaxis",
                                                           "euler"};
constexpr double kDegree = M_PI / 180.0;
}  // namespace

double CompilerSettings::Angle(double v) const { return angle_in_degrees ? v * kDegree : v; }

std::optional<std::vector<double>> MjcfReader::Numbers(const Element& e, std::string_view name,
                                                       size_t n) {
  const Attribute a = e.Get(name);
  if (!a.present()) return std::nullopt;
  return NumbersOf(e, a, name, n);
}

bool MjcfReader::FixedNumbers(const Element& e, std::string_view name, double* out, size_t n) {
  const Attribute a = e.Get(name);
  return a.present() && FixedNumbersOf(e, a, name, out, n);
}

bool MjcfReader::FixedNumbersOf(const Element& e, const Attribute& a, std::string_view name,
                                double* out, size_t n) {
  if (const auto count = xml::ParseDoublesInto(a.value, out, n); count && *count == n) {
    bool finite = true;
    for (size_t i = 0; i < n; ++i) finite = finite && std::isfinite(out[i]);
    if (finite) return true;
  }
  NumbersOf(e, a, name, n);  // says what is wrong
  return false;
}

std::optional<std::vector<double>> MjcfReader::NumbersOf(const Element& e, const Attribute& a,
                                                         std::string_view name, size_t n) {
  auto values = xml::ParseDoubleList(a.value);
  if (!values) {
    diags().Report(DiagKind::BadValue, a.loc,
                   fmt::format("attribute '{}' of <{}>: '{}' is not a list of numbers", name,
                               e.xml().Name(), a.value));
    return std::nullopt;
  }
  if (values->size() != n) {
    diags().Report(DiagKind::BadValue, a.loc,
                   fmt::format("attribute '{}' of <{}> needs {} number{}, found {}", name,
                               e.xml().Name(), n, n == 1 ? "" : "s", values->size()));
    return std::nullopt;
  }
  for (double v : *values) {
    if (!std::isfinite(v)) {
      diags().Report(DiagKind::NonFinite, a.loc,
                     fmt::format("attribute '{}' of <{}> must be finite", name, e.xml().Name()));
      return std::nullopt;
    }
  }
  return values;
}

std::optional<double> MjcfReader::Number(const Element& e, std::string_view name,
                                         double fallback) {
  const Attribute a = e.Get(name);
  if (!a.present()) return fallback;
  double value = 0;
  if (!FixedNumbersOf(e, a, name, &value, 1)) return std::nullopt;
  return value;
}

std::optional<bool> MjcfReader::Boolean(const Element& e, std::string_view name, bool fallback) {
  const Attribute a = e.Get(name);
  if (!a.present()) return fallback;
  if (a.value == "true") return true;
  if (a.value == "false") return false;
  diags().Report(DiagKind::BadValue, a.loc,
                 fmt::format("attribute '{}' of <{}> must be 'true' or 'false', not '{}'", name,
                             e.xml().Name(), a.value));
  return std::nullopt;
}

bool MjcfReader::LayeredNumbers(const Element& e, std::string_view name,
                                std::span<double> values) {
  const size_t n = values.size();
  // MuJoCo overwrites only the values a layer gives; the rest keep the
  // class's (ParseDoublesInto writes the first values only)
  auto apply = [&](const xml::XmlElement& layer) {
    const xml::XmlAttribute a = layer.Attribute(name);
    if (!a.present()) return true;
    const auto count = xml::ParseDoublesInto(a.value, values.data(), n);
    if (count && *count <= n) return true;
    diags().Report(DiagKind::BadValue, a.loc,
                   count ? fmt::format("attribute '{}' of <{}> has too much data: at most {} "
                                       "numbers",
                                       name, layer.Name(), n)
                         : fmt::format("attribute '{}' of <{}>: '{}' is not a list of numbers",
                                       name, layer.Name(), a.value));
    return false;
  };
  // from the root class to the element: the nearest layers are read here;
  // a deeper chain starts from what its far part leaves, which that part
  // works out once (DefaultLayer::Layered)
  std::array<const DefaultLayer*, DefaultLayer::kShortWalk> near;
  size_t num_near = 0;
  const DefaultLayer* far = e.Layers();
  for (; far && num_near < near.size(); far = far->parent()) near[num_near++] = far;
  if (far) {
    const LayeredPrefix& inherited = far->Layered(name, n);
    if (!inherited.ok) {
      // a far layer's text is bad: read them all again, to report it
      std::vector<const DefaultLayer*> chain;
      for (const DefaultLayer* layer = far; layer; layer = layer->parent()) chain.push_back(layer);
      for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        if (!apply((*it)->xml())) return false;
      }
      return false;
    }
    std::copy_n(inherited.values.begin(), inherited.written, values.begin());
  }
  for (size_t i = num_near; i-- > 0;) {
    if (!apply(near[i]->xml())) return false;
  }
  return apply(e.xml());
}

std::optional<std::vector<int>> MjcfReader::Integers(const Element& e, std::string_view name,
                                                     size_t n) {
  const Attribute a = e.Get(name);
  if (!a.present()) return std::nullopt;
  const auto values = NumbersOf(e, a, name, n);
  if (!values) return std::nullopt;
  std::vector<int> out;
  for (double v : *values) {
    // casting a double outside int's range is undefined: check first
    constexpr double kMin = std::numeric_limits<int>::min(), kMax = std::numeric_limits<int>::max();
    if (!(v == std::floor(v) && v >= kMin && v <= kMax)) {
      diags().Report(DiagKind::BadValue, a.loc,
                     fmt::format("attribute '{}' of <{}> must be whole numbers from {} to {}, "
                                 "not '{}'",
                                 name, e.xml().Name(), std::numeric_limits<int>::min(),
                                 std::numeric_limits<int>::max(), a.value));
      return std::nullopt;
    }
    out.push_back(static_cast<int>(v));
  }
  return out;
}

std::optional<int> MjcfReader::Integer(const Element& e, std::string_view name, int fallback) {
  const Attribute a = e.Get(name);
  if (!a.present()) return fallback;
  // a plain whole number, as nearly every integer attribute is written, is
  // read as one (integer from_chars is inline; the double reader is not)
  int whole = 0;
  const char* const end = a.value.data() + a.value.size();
  if (const auto [stop, ec] = std::from_chars(a.value.data(), end, whole);
      ec == std::errc() && stop == end) {
    return whole;
  }
  // other spellings of a whole number ("1.0", "1e1", " 3 "), without a
  // list; Integers says what is wrong otherwise
  constexpr double kMin = std::numeric_limits<int>::min(), kMax = std::numeric_limits<int>::max();
  double value = 0;
  if (const auto count = xml::ParseDoublesInto(a.value, &value, 1);
      count && *count == 1 && value == std::floor(value) && value >= kMin && value <= kMax) {
    return static_cast<int>(value);
  }
  const auto v = Integers(e, name, 1);
  if (!v) return std::nullopt;
  return (*v)[0];
}

std::optional<Transform> MjcfReader::ReadPose(const Element& e) {
  Transform X;
  bool ok = true;
  if (const Attribute pos_attribute = e.Get("pos"); pos_attribute.present()) {
    Eigen::Vector3d pos;
    if (FixedNumbersOf(e, pos_attribute, "pos", pos.data(), 3)) {
      X.p = pos;
    } else {
      ok = false;
    }
  }

  // more than one orientation written on the element itself: MJCF-010
  std::array<xml::XmlAttribute, 5> own_storage;  // no allocation per pose
  size_t own_count = 0;
  for (std::string_view name : {"quat", "axisangle", "xyaxes", "zaxis", "euler"}) {
    if (xml::XmlAttribute a = e.Own(name); a.present()) own_storage[own_count++] = a;
  }
  const std::span<const xml::XmlAttribute> own(own_storage.data(), own_count);
  if (own.size() > 1) {
    auto diag = diags().Report(DiagKind::BadValue, own[1].loc,
                               fmt::format("<{}> has more than one orientation: at most one of "
                                           "quat, axisangle, xyaxes, zaxis, euler",
                                           e.xml().Name()));
    diag.Note(own[0].loc, fmt::format("'{}' is given here", own[0].name));
    return std::nullopt;
  }

  // the nearest level (element, then classes) with an alternative wins;
  // the element's own attributes are in `own` already
  std::string_view alt_name;
  for (const xml::XmlAttribute& a : own) {
    if (a.name != "quat") alt_name = a.name;
  }
  if (const DefaultLayer* classes = e.Layers(); alt_name.empty() && classes) {
    int nearest = std::numeric_limits<int>::max();
    for (std::string_view alt : kAlternatives) {
      // strictly nearer: within one layer the first alternative listed wins
      if (const Inherited found = classes->Find(alt);
          found.attribute.present() && found.level < nearest) {
        nearest = found.level;
        alt_name = alt;
      }
    }
  }

  RotationOrError R = Eigen::Matrix3d(Eigen::Matrix3d::Identity());
  std::string_view used = alt_name;
  std::array<double, 6> v;  // the largest orientation: xyaxes
  if (alt_name == "axisangle") {
    if (!FixedNumbers(e, "axisangle", v.data(), 4)) return std::nullopt;
    R = RotationFromAxisAngle({v[0], v[1], v[2]}, compiler.Angle(v[3]));
  } else if (alt_name == "xyaxes") {
    if (!FixedNumbers(e, "xyaxes", v.data(), 6)) return std::nullopt;
    R = RotationFromXYAxes({v[0], v[1], v[2]}, {v[3], v[4], v[5]});
  } else if (alt_name == "zaxis") {
    if (!FixedNumbers(e, "zaxis", v.data(), 3)) return std::nullopt;
    R = RotationFromZAxis({v[0], v[1], v[2]});
  } else if (alt_name == "euler") {
    if (!FixedNumbers(e, "euler", v.data(), 3)) return std::nullopt;
    R = RotationFromEuler({compiler.Angle(v[0]), compiler.Angle(v[1]), compiler.Angle(v[2])},
                          compiler.eulerseq);
  } else if (const Attribute quat = e.Get("quat"); quat.present()) {
    used = "quat";
    if (!FixedNumbersOf(e, quat, "quat", v.data(), 4)) return std::nullopt;
    R = RotationFromQuat(v[0], v[1], v[2], v[3]);
  }
  if (auto* error = std::get_if<std::string>(&R)) {
    diags().Report(DiagKind::BadValue, e.Get(used).loc,
                   fmt::format("attribute '{}' of <{}>: {}", used, e.xml().Name(), *error));
    return std::nullopt;
  }
  X.R = std::get<Eigen::Matrix3d>(R);
  if (!ok) return std::nullopt;
  return X;
}

}  // namespace mdlc::frontend::mjcf
