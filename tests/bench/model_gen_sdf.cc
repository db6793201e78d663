// model_gen_sdf.cc - see model_gen_sdf.h. The random source, number
// formatting and the chain robot's draws repeat model_gen.cc's (whose helpers
// are file-local): keep sdf_chain in step with GenerateUrdf(Shape::Chain, N)
// so that the two files describe the same robot.
#include "model_gen_sdf.h"

#include "mechanism.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>

namespace mdlc::bench {
namespace {

constexpr double kPi = std::numbers::pi;
// <pose [relative_to="R"]>x y z r p y</pose>
void AppendPose(std::string& out, std::string_view indent, const Vec3& xyz, const Vec3& rpy,
                std::string_view relative_to = {}) {
  out += indent;
  out += "<pose";
  if (!relative_to.empty()) {
    out += " relative_to=\"";
    out += relative_to;
    out += '"';
  }
  out += '>';
  AppendVector(out, xyz.data(), 3);
  out += ' ';
  AppendVector(out, rpy.data(), 3);
  out += "</pose>\n";
}

void AppendElement(std::string& out, std::string_view tag, double value) {
  out += '<';
  out += tag;
  out += '>';
  AppendNumber(out, value);
  out += "</";
  out += tag;
  out += '>';
}

// <inertial> with a diagonal-free inertia tensor
void AppendInertial(std::string& out, std::string_view indent, double mass, const Vec3& com,
                    const Vec3& rpy, const double (&tensor)[6]) {
  static constexpr const char* kNames[6] = {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"};
  out += indent;
  out += "<inertial>\n";
  AppendPose(out, std::string(indent) + "  ", com, rpy);
  out += indent;
  out += "  ";
  AppendElement(out, "mass", mass);
  out += '\n';
  out += indent;
  out += "  <inertia>";
  for (int k = 0; k < 6; ++k) AppendElement(out, kNames[k], tensor[k]);
  out += "</inertia>\n";
  out += indent;
  out += "</inertial>\n";
}

Vec3 SmallOffset(Rng& rng) {
  return {rng.Uniform(-0.1, 0.1), rng.Uniform(-0.1, 0.1), rng.Uniform(0.02, 0.2)};
}
Vec3 SmallRotation(Rng& rng) {
  return {rng.Uniform(-0.6, 0.6), rng.Uniform(-0.6, 0.6), rng.Uniform(-kPi, kPi)};
}

// a link's mass properties: principal moments of a box, turned by a rotation
void AppendRandomInertial(std::string& out, std::string_view indent, Rng& rng) {
  const double mass = rng.Uniform(0.3, 5.0);
  const Vec3 com = {rng.Uniform(-0.03, 0.03), rng.Uniform(-0.03, 0.03), rng.Uniform(0.0, 0.12)};
  const double a = rng.Uniform(0.05, 0.3), b = rng.Uniform(0.05, 0.3), c = rng.Uniform(0.05, 0.3);
  const Vec3 principal = {mass * (b * b + c * c) / 12, mass * (a * a + c * c) / 12,
                          mass * (a * a + b * b) / 12};
  const Vec3 q_rpy = {rng.Uniform(-kPi, kPi), rng.Uniform(-1.5, 1.5), rng.Uniform(-kPi, kPi)};
  const Mat3 I = RotateDiagonal(RotationFromRpy(q_rpy[0], q_rpy[1], q_rpy[2]), principal);
  const double tensor[6] = {I[0][0], I[0][1], I[0][2], I[1][1], I[1][2], I[2][2]};
  AppendInertial(out, indent, mass, com, {0, 0, 0}, tensor);
}

void AppendHeader(std::string& out, const std::string& name) {
  out += "<?xml version=\"1.0\"?>\n<sdf version=\"1.9\">\n  <model name=\"" + name + "\">\n";
}

// ---------------------------------------------------------------- frame_chain

std::string FrameChain(const std::string& name, int n) {
  Rng rng(Fnv1a(name + "/20240611"));
  std::string out;
  out.reserve(static_cast<size_t>(n) * 150 + 1024);
  AppendHeader(out, name);
  out += "    <link name=\"base\">\n";
  AppendRandomInertial(out, "      ", rng);
  out += "    </link>\n";
  std::string previous = "base";
  for (int i = 1; i <= n; ++i) {
    const std::string frame = Numbered("f", i);
    const Vec3 xyz = SmallOffset(rng), rpy = SmallRotation(rng);
    out += "    <frame name=\"" + frame + "\" attached_to=\"" + previous + "\">\n";
    AppendPose(out, "      ", xyz, rpy, previous);
    out += "    </frame>\n";
    previous = frame;
  }
  out += "  </model>\n</sdf>\n";
  return out;
}

// ---------------------------------------------------------------- nested_models

std::string NestedModels(const std::string& name, int n) {
  Rng rng(Fnv1a(name + "/20240611"));
  std::string out;
  // the deep_probe name is ~7 bytes per level; the indentation is capped
  out.reserve(static_cast<size_t>(n) * 900 + 1024);
  AppendHeader(out, name);
  auto model_name = [](int level) { return Numbered("m", level); };
  // level 0 is the top model, level i >= 1 is model m{i}
  for (int level = 0; level < n; ++level) {
    const std::string indent(2 * std::min(level, 20) + 4, ' ');
    if (level > 0) {
      out += std::string(indent.size() - 2, ' ') + "<model name=\"" + model_name(level) + "\">\n";
      // relative to the parent model's frame (the default)
      AppendPose(out, indent, SmallOffset(rng), SmallRotation(rng));
    }
    out += indent + "<link name=\"link\">\n";
    AppendPose(out, indent + "  ", SmallOffset(rng), SmallRotation(rng), "__model__");
    AppendRandomInertial(out, indent + "  ", rng);
    out += indent + "</link>\n";
    if (level + 1 < n) {
      // the joint to the next level's link, by its scoped name
      Vec3 axis = {rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1)};
      double norm = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
      if (norm < 1e-3) {
        axis = {0, 0, 1};
        norm = 1;
      }
      for (double& v : axis) v /= norm;
      out += indent + "<joint name=\"j" + std::to_string(level + 1) + "\" type=\"revolute\">\n";
      out += indent + "  <parent>link</parent>\n";
      out += indent + "  <child>" + model_name(level + 1) + "::link</child>\n";
      out += indent + "  <axis><xyz>";
      AppendVector(out, axis.data(), 3);
      out += "</xyz><limit><lower>-2</lower><upper>2</upper></limit></axis>\n";
      out += indent + "</joint>\n";
    }
    if (level + 3 < n) {
      // three levels down, by a scoped name
      const std::string target = model_name(level + 1) + "::" + model_name(level + 2) +
                                 "::" + model_name(level + 3) + "::link";
      out += indent + "<frame name=\"probe\" attached_to=\"link\">\n";
      AppendPose(out, indent + "  ", SmallOffset(rng), SmallRotation(rng), target);
      out += indent + "</frame>\n";
    }
    if (level == 0 && n > 1) {
      // the innermost link, through every level
      std::string target;
      for (int k = 1; k < n; ++k) target += model_name(k) + "::";
      target += "link";
      out += indent + "<frame name=\"deep_probe\" attached_to=\"link\">\n";
      AppendPose(out, indent + "  ", SmallOffset(rng), SmallRotation(rng), target);
      out += indent + "</frame>\n";
    }
  }
  for (int level = n - 1; level > 0; --level) {
    out += std::string(2 * std::min(level, 20) + 2, ' ') + "</model>\n";
  }
  out += "  </model>\n</sdf>\n";
  return out;
}

// ---------------------------------------------------------------- sdf_chain

void AppendGeometry(std::string& out, const GeomDraw& g, int link, bool visual) {
  const std::string index = std::to_string(link);
  out += visual ? "      <visual name=\"link_" : "      <collision name=\"link_";
  out += index;
  out += visual ? "_visual\">\n" : "_collision\">\n";
  AppendPose(out, "        ", g.xyz, g.rpy);
  out += "        <geometry>";
  if (g.kind == GeomKind::Box) {
    out += "<box><size>";
    AppendVector(out, g.dims.data(), 3);
    out += "</size></box>";
  } else if (g.kind == GeomKind::Sphere) {
    out += "<sphere>";
    AppendElement(out, "radius", g.dims[0]);
    out += "</sphere>";
  } else {
    // a cylinder for the capsule too, as the URDF file has it
    out += "<cylinder>";
    AppendElement(out, "radius", g.dims[0]);
    AppendElement(out, "length", g.dims[1]);
    out += "</cylinder>";
  }
  out += "</geometry>\n";
  if (visual) {
    out += "        <material><diffuse>";
    AppendVector(out, g.rgba.data(), 4);
    out += "</diffuse></material>\n      </visual>\n";
  } else {
    out += "      </collision>\n";
  }
}

std::string SdfChain(const std::string& name, int n) {
  // the URDF chain's draws: the same robot
  const std::vector<LinkDraw> links = DrawMechanism(Shape::Chain, n);
  std::string out;
  out.reserve(static_cast<size_t>(n) * 1700 + 1024);
  AppendHeader(out, name);
  for (int i = 0; i < n; ++i) {
    const LinkDraw& L = links[static_cast<size_t>(i)];
    const std::string index = std::to_string(i);
    const int parent = L.parent;
    const Mat3& I = L.inertia;
    const double limits[4] = {L.lower, L.upper, L.effort, L.velocity};

    if (parent >= 0) {
      // the URDF joint origin: relative to the parent link
      out += "    <joint name=\"joint_" + index + "\" type=\"revolute\">\n";
      AppendPose(out, "      ", L.j_xyz, L.j_rpy, Numbered("link_", parent));
      out += "      <parent>link_" + std::to_string(parent) + "</parent>\n";
      out += "      <child>link_" + index + "</child>\n";
      out += "      <axis>\n        <xyz>";
      AppendVector(out, L.axis.data(), 3);
      out += "</xyz>\n        <limit>";
      AppendElement(out, "lower", limits[0]);
      AppendElement(out, "upper", limits[1]);
      AppendElement(out, "effort", limits[2]);
      AppendElement(out, "velocity", limits[3]);
      out += "</limit>\n        <dynamics>";
      AppendElement(out, "damping", L.damping);
      AppendElement(out, "friction", L.friction);
      out += "</dynamics>\n      </axis>\n    </joint>\n";
    }
    out += "    <link name=\"link_" + index + "\">\n";
    if (parent >= 0) {
      out += "      <pose relative_to=\"joint_" + index + "\">0 0 0 0 0 0</pose>\n";
    }
    const double tensor[6] = {I[0][0], I[0][1], I[0][2], I[1][1], I[1][2], I[2][2]};
    AppendInertial(out, "      ", L.mass, L.com, L.in_rpy, tensor);
    AppendGeometry(out, L.visual, i, /*visual=*/true);
    AppendGeometry(out, L.collision, i, /*visual=*/false);
    out += "    </link>\n";
  }
  out += "    <joint name=\"world_weld\" type=\"fixed\">\n";
  out += "      <parent>world</parent>\n      <child>link_0</child>\n    </joint>\n";
  out += "  </model>\n</sdf>\n";
  return out;
}

// ---------------------------------------------------------------- world

std::string World(const std::string& name, int n) {
  Rng rng(Fnv1a(name + "/20240611"));
  std::string out;
  out.reserve(static_cast<size_t>(n) * 700 + 1024);
  out += "<?xml version=\"1.0\"?>\n<sdf version=\"1.9\">\n  <world name=\"" + name + "\">\n";
  for (int i = 1; i <= n; ++i) {
    out += "    <model name=\"" + Numbered("m", i) + "\">\n";
    // spread over a grid so the models do not overlap
    const Vec3 xyz = {static_cast<double>(i % 100), static_cast<double>(i / 100 % 100),
                      static_cast<double>(i / 10000) + rng.Uniform(0.1, 0.5)};
    AppendPose(out, "      ", xyz, SmallRotation(rng));
    out += "      <link name=\"link\">\n";
    AppendRandomInertial(out, "        ", rng);
    const Vec3 size = {rng.Uniform(0.05, 0.3), rng.Uniform(0.05, 0.3), rng.Uniform(0.05, 0.3)};
    out += "        <collision name=\"box\"><geometry><box><size>";
    AppendVector(out, size.data(), 3);
    out += "</size></box></geometry></collision>\n";
    out += "      </link>\n    </model>\n";
  }
  out += "  </world>\n</sdf>\n";
  return out;
}

}  // namespace

std::string_view SdfFamilyName(SdfFamily family) {
  switch (family) {
    case SdfFamily::FrameChain:
      return "frame_chain";
    case SdfFamily::NestedModels:
      return "nested_models";
    case SdfFamily::SdfChain:
      return "sdf_chain";
    case SdfFamily::World:
      return "world";
  }
  return "?";
}

std::string GenerateSdf(SdfFamily family, int n) {
  const std::string name = std::string(SdfFamilyName(family)) + "_n" + std::to_string(n);
  switch (family) {
    case SdfFamily::FrameChain:
      return FrameChain(name, n);
    case SdfFamily::NestedModels:
      return NestedModels(name, n);
    case SdfFamily::SdfChain:
      return SdfChain(name, n);
    case SdfFamily::World:
      return World(name, n);
  }
  return {};
}

}  // namespace mdlc::bench
