// model_gen.cc - see model_gen.h. Mirrors build() and write_urdf() of
// gen_models.py; keep the two in step when either changes.
#include "model_gen.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>

namespace mdlc::bench {
namespace {

void AppendOrigin(std::string& out, const char* indent, const Vec3& xyz, const Vec3& rpy) {
  out += indent;
  out += "<origin xyz=\"";
  AppendVector(out, xyz.data(), 3);
  out += "\" rpy=\"";
  AppendVector(out, rpy.data(), 3);
  out += "\"/>\n";
}

void AppendShape(std::string& out, const GeomDraw& g) {
  out += "        ";
  if (g.kind == GeomKind::Box) {
    out += "<box size=\"";
    AppendVector(out, g.dims.data(), 3);
    out += "\"/>\n";
  } else if (g.kind == GeomKind::Sphere) {
    out += "<sphere radius=\"";
    AppendNumber(out, g.dims[0]);
    out += "\"/>\n";
  } else {
    // URDF has no capsule: the script writes it as a cylinder of the same size
    out += "<cylinder radius=\"";
    AppendNumber(out, g.dims[0]);
    out += "\" length=\"";
    AppendNumber(out, g.dims[1]);
    out += "\"/>\n";
  }
}

void AppendGeometry(std::string& out, const GeomDraw& g, int link, bool visual) {
  const std::string index = std::to_string(link);
  out += visual ? "    <visual name=\"link_" : "    <collision name=\"link_";
  out += index;
  out += visual ? "_visual\">\n" : "_collision\">\n";
  AppendOrigin(out, "      ", g.xyz, g.rpy);
  out += "      <geometry>\n";
  AppendShape(out, g);
  out += "      </geometry>\n";
  if (visual) {
    out += "      <material name=\"material_" + index + "\">\n";
    out += "        <color rgba=\"";
    AppendVector(out, g.rgba.data(), 4);
    out += "\"/>\n      </material>\n    </visual>\n";
  } else {
    out += "    </collision>\n";
  }
}

}  // namespace

std::string GenerateUrdf(Shape shape, int num_links) {
  const std::string name = std::string(ShapeName(shape)) + "_n" + std::to_string(num_links);
  std::string out;
  out.reserve(static_cast<size_t>(num_links) * 1250 + 256);
  out += "<?xml version=\"1.0\"?>\n<robot name=\"" + name + "\">\n";
  out += "  <link name=\"world\"/>\n";
  out += "  <joint name=\"world_weld\" type=\"fixed\">\n";
  out += "    <parent link=\"world\"/>\n";
  out += "    <child link=\"link_0\"/>\n";
  out += "  </joint>\n";
  const std::vector<LinkDraw> links = DrawMechanism(shape, num_links);
  for (int i = 0; i < num_links; ++i) {
    const LinkDraw& L = links[static_cast<size_t>(i)];
    const std::string index = std::to_string(i);
    const int parent = L.parent;
    const double mass = L.mass;
    const Vec3& com = L.com;
    const Vec3& in_rpy = L.in_rpy;
    const Mat3& I = L.inertia;
    const GeomDraw& visual = L.visual;
    const GeomDraw& collision = L.collision;
    const Vec3& j_xyz = L.j_xyz;
    const Vec3& j_rpy = L.j_rpy;
    const Vec3& axis = L.axis;
    const double limits[4] = {L.lower, L.upper, L.effort, L.velocity};
    const double damping = L.damping, friction = L.friction;

    out += "  <link name=\"link_" + index + "\">\n";
    out += "    <inertial>\n";
    AppendOrigin(out, "      ", com, in_rpy);
    out += "      <mass value=\"";
    AppendNumber(out, mass);
    out += "\"/>\n";
    const double tensor[6] = {I[0][0], I[0][1], I[0][2], I[1][1], I[1][2], I[2][2]};
    static constexpr const char* kTensorNames[6] = {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"};
    out += "      <inertia";
    for (int k = 0; k < 6; ++k) {
      out += ' ';
      out += kTensorNames[k];
      out += "=\"";
      AppendNumber(out, tensor[k]);
      out += '"';
    }
    out += "/>\n    </inertial>\n";
    AppendGeometry(out, visual, i, /*visual=*/true);
    AppendGeometry(out, collision, i, /*visual=*/false);
    out += "  </link>\n";
    if (parent < 0) continue;
    out += "  <joint name=\"joint_" + index + "\" type=\"revolute\">\n";
    AppendOrigin(out, "    ", j_xyz, j_rpy);
    out += "    <parent link=\"link_" + std::to_string(parent) + "\"/>\n";
    out += "    <child link=\"link_" + index + "\"/>\n";
    out += "    <axis xyz=\"";
    AppendVector(out, axis.data(), 3);
    out += "\"/>\n    <limit";
    static constexpr const char* kLimitNames[4] = {"lower", "upper", "effort", "velocity"};
    for (int k = 0; k < 4; ++k) {
      out += ' ';
      out += kLimitNames[k];
      out += "=\"";
      AppendNumber(out, limits[k]);
      out += '"';
    }
    out += "/>\n    <dynamics damping=\"";
    AppendNumber(out, damping);
    out += "\" friction=\"";
    AppendNumber(out, friction);
    out += "\"/>\n  </joint>\n";
  }
  out += "</robot>\n";
  return out;
}

}  // namespace mdlc::bench
