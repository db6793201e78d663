// model_gen_mjcf.cc - see model_gen_mjcf.h. Keep in step with write_mjcf()
// of gen_models.py.
#include "model_gen_mjcf.h"

#include <algorithm>
#include <utility>

namespace mdlc::bench {
namespace {

constexpr int kMaxIndent = 16;

void AppendQuaternion(std::string& out, const Vec3& rpy) {
  const auto q = QuaternionFromRpy(rpy[0], rpy[1], rpy[2]);
  AppendVector(out, q.data(), 4);
}

void AppendGeom(std::string& out, const std::string& indent, const GeomDraw& g,
                const std::string& name, bool visual) {
  static constexpr const char* kTypes[] = {"box", "sphere", "cylinder", "capsule"};
  out += indent;
  out += "<geom name=\"" + name + "\" type=\"";
  out += kTypes[static_cast<int>(g.kind)];
  out += "\" size=\"";
  if (g.kind == GeomKind::Box) {
    const double half[3] = {g.dims[0] / 2, g.dims[1] / 2, g.dims[2] / 2};
    AppendVector(out, half, 3);
  } else if (g.kind == GeomKind::Sphere) {
    AppendNumber(out, g.dims[0]);
  } else {
    const double size[2] = {g.dims[0], g.dims[1] / 2};  // radius, half-length
    AppendVector(out, size, 2);
  }
  out += "\" pos=\"";
  AppendVector(out, g.xyz.data(), 3);
  out += "\" quat=\"";
  AppendQuaternion(out, g.rpy);
  out += '"';
  if (visual) {
    out += " contype=\"0\" conaffinity=\"0\" group=\"1\" rgba=\"";
    AppendVector(out, g.rgba.data(), 4);
    out += '"';
  } else {
    out += " group=\"3\"";
  }
  out += "/>\n";
}

void AppendBody(std::string& out, const std::string& indent, const LinkDraw& L, int i) {
  const std::string index = std::to_string(i);
  out += indent + "<body name=\"link_" + index + '"';
  if (L.parent >= 0) {
    out += " pos=\"";
    AppendVector(out, L.j_xyz.data(), 3);
    out += "\" quat=\"";
    AppendQuaternion(out, L.j_rpy);
    out += '"';
  }
  out += ">\n";
  const std::string inner = indent + "  ";
  if (L.parent >= 0) {
    out += inner + "<joint name=\"joint_" + index + "\" type=\"hinge\" axis=\"";
    AppendVector(out, L.axis.data(), 3);
    out += "\" limited=\"true\" range=\"";
    AppendNumber(out, L.lower);
    out += ' ';
    AppendNumber(out, L.upper);
    out += "\" damping=\"";
    AppendNumber(out, L.damping);
    out += "\" frictionloss=\"";
    AppendNumber(out, L.friction);
    out += "\"/>\n";
  }
  // the inertia re-expressed from the inertial frame in the body frame
  const Mat3 I = RotateTensor(RotationFromRpy(L.in_rpy[0], L.in_rpy[1], L.in_rpy[2]), L.inertia);
  const double full[6] = {I[0][0], I[1][1], I[2][2], I[0][1], I[0][2], I[1][2]};
  out += inner + "<inertial pos=\"";
  AppendVector(out, L.com.data(), 3);
  out += "\" mass=\"";
  AppendNumber(out, L.mass);
  out += "\" fullinertia=\"";
  AppendVector(out, full, 6);
  out += "\"/>\n";
  AppendGeom(out, inner, L.visual, Numbered("link_", i) + "_visual", /*visual=*/true);
  AppendGeom(out, inner, L.collision, Numbered("link_", i) + "_collision", /*visual=*/false);
}

}  // namespace

std::string GenerateMjcf(Shape shape, int num_links) {
  const std::string name = std::string(ShapeName(shape)) + "_n" + std::to_string(num_links);
  const std::vector<LinkDraw> links = DrawMechanism(shape, num_links);
  std::vector<std::vector<int>> children(links.size());
  for (int i = 1; i < num_links; ++i) children[static_cast<size_t>(links[i].parent)].push_back(i);

  std::string out;
  out.reserve(static_cast<size_t>(num_links) * 900 + 256);
  out += "<mujoco model=\"" + name + "\">\n";
  out += "  <compiler angle=\"radian\"/>\n";
  out += "  <option timestep=\"0.002\"/>\n";
  out += "  <worldbody>\n";
  // depth-first with an explicit stack: a 10,000-deep chain is fine
  struct Item {
    int link, depth;
    bool closing;
  };
  std::vector<Item> stack = {{0, 2, false}};
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    const std::string indent(2 * static_cast<size_t>(std::min(item.depth, kMaxIndent)), ' ');
    if (item.closing) {
      out += indent + "</body>\n";
      continue;
    }
    AppendBody(out, indent, links[static_cast<size_t>(item.link)], item.link);
    stack.push_back({item.link, item.depth, true});
    const auto& kids = children[static_cast<size_t>(item.link)];
    for (auto it = kids.rbegin(); it != kids.rend(); ++it) stack.push_back({*it, item.depth + 1, false});
  }
  out += "  </worldbody>\n</mujoco>\n";
  return out;
}

}  // namespace mdlc::bench
