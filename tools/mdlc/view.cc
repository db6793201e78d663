// view.cc - the page `mdlc view` writes: the model as JSON, three.js and the
// viewer script (viewer/viewer.js), all inside one HTML file.
//
// The model JSON (read only by viewer.js, so it is shaped for it):
//   title, notes[]            what the page should say: what it cannot show, and
//                             what it did with COLLADA meshes not declared Z-up
//   num_positions, joint_order[]            the plant's q layout
//   q0[]                      the configuration the page opens in: the default
//                             positions with --q applied
//   bodies[]   name, scoped_name, model, mass, com, inertia (3x3, row-major),
//              parent, joint (inbound; -1 for the world), level, source
//   joints[]   name, scoped_name, type, parent, child, X_PF, X_CM, axis,
//              q_start, nq, lower[], upper[], default[], pitch, source;
//              curvilinear joints also X_FM (at their default position)
//   frames[]   name, body, X_BF
//   geometries[] name, body, X_BG, shape {type, ...}, roles[], rgba, mesh
//   meshes[]   path, vertices (base64 little-endian Float32 xyz, unscaled),
//              triangles (base64 little-endian Uint32), colors[] (the file's
//              material colours: [first triangle, r, g, b, a] per run)
// File paths (sources, meshes, notes) are relative to the model's folder
// (page_paths.h): the page holds no absolute path of this machine.
// Transforms are {"R": 9 numbers row-major, "p": 3 numbers}, at full
// precision, so the page's forward kinematics reproduce the plant's.
#include "view.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <span>
#include <string_view>

#include "backend/json_writer.h"
#include "ir/module.h"
#include "ir/overloaded.h"
#include "ir/shape_parameters.h"
#include "mdlc/ir.h"
#include "mdlc/kinematics.h"
#include "mdlc/meshes.h"
#include "page_paths.h"

#ifdef MDLC_HAVE_VIEWER
namespace mdlc::tools::viewer {
// generated from three.js and viewer/viewer.js at build time (viewer/embed.cmake)
extern const std::string_view kThreeJs;
extern const std::string_view kOrbitControlsJs;
extern const std::string_view kViewerJs;
}  // namespace mdlc::tools::viewer
#endif

namespace mdlc::tools {

namespace {

using backend::JsonWriter;

std::string Base64(std::string_view bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const uint32_t n = (uint8_t(bytes[i]) << 16) | (uint8_t(bytes[i + 1]) << 8) |
                       uint8_t(bytes[i + 2]);
    for (int shift : {18, 12, 6, 0}) out += kDigits[(n >> shift) & 63];
  }
  if (i < bytes.size()) {
    uint32_t n = uint8_t(bytes[i]) << 16;
    if (i + 1 < bytes.size()) n |= uint8_t(bytes[i + 1]) << 8;
    out += kDigits[(n >> 18) & 63];
    out += kDigits[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(n >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

/// Plain numbers as little-endian bytes, the layout of a JS typed array on
/// every platform a browser runs on.
template <typename T>
void AppendLittleEndian(std::string& out, T value) {
  static_assert(std::endian::native == std::endian::little, "big-endian hosts are not supported");
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

void Vector(JsonWriter& w, const Eigen::Vector3d& v) {
  w.BeginArray().Number(v.x()).Number(v.y()).Number(v.z()).EndArray();
}

void Pose(JsonWriter& w, const Transform& X) {
  w.BeginObject().Key("R").BeginArray();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) w.Number(X.R(r, c));
  }
  w.EndArray().Key("p");
  Vector(w, X.p);
  w.EndObject();
}

void Numbers(JsonWriter& w, std::span<const double> values) {
  w.BeginArray();
  for (double x : values) w.Number(x);
  w.EndArray();
}

std::string Where(const Result& result, const PagePaths& paths, Loc loc) {
  if (!loc.valid()) return "";
  return fmt::format("{}:{}:{}", paths.Show(result.sources().Path(loc.file)), loc.line,
                     loc.column);
}

/// A mesh's URI as the page shows it: a file path or file:// URI as a path
/// relative to the model's folder, any other URI (package://) as written.
std::string ShownUri(const std::string& uri, const PagePaths& paths) {
  if (uri.starts_with("file://")) return paths.Show(uri.substr(7));
  if (uri.starts_with("/")) return paths.Show(uri);
  return uri;
}

// The shape's parameters as plant-json writes them (ir/shape_parameters.h),
// but a mesh's uri as the page shows it; then the page's own extra, a mesh's
// index in `meshes` (-1: not shown).
void Shape(JsonWriter& w, const ir::Shape& shape, int mesh, const PagePaths& paths) {
  w.BeginObject().Key("type").String(ir::ShapeTypeName(shape));
  ir::VisitShapeParameters(shape, ir::Overloaded{
                                      [&](std::string_view name, double x) { w.Key(name).Number(x); },
                                      [&](std::string_view name, const Eigen::Vector3d& v) {
                                        w.Key(name);
                                        Vector(w, v);
                                      },
                                      [&](std::string_view name, const std::string& uri) {
                                        w.Key(name).String(ShownUri(uri, paths));
                                      },
                                  });
  if (std::holds_alternative<ir::Mesh>(shape)) w.Key("mesh").Int(mesh);
  w.EndObject();
}

/// "phong/diffuse" when the geometry has one (illustration and perception
/// geometries with a colour).
std::optional<std::vector<double>> Diffuse(const backend::SceneGeometry& g) {
  for (const ir::Property& p : g.properties) {
    if (p.key != "phong/diffuse") continue;
    if (const auto* rgba = std::get_if<std::vector<double>>(&p.value); rgba && rgba->size() == 4) {
      return *rgba;
    }
  }
  return std::nullopt;
}

/// Keeps the page's text out of the HTML parser's way: "</script" (any case)
/// would end the script element it sits in, so no "</" is left. In JSON and
/// in JavaScript strings, regular expressions and comments "<\/" reads as
/// "</". (This and EscapeHtml are unused in a build without the viewer.)
[[maybe_unused]] std::string EscapeForScript(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') {
      out += "<\\/";
      ++i;
    } else {
      out += text[i];
    }
  }
  return out;
}

[[maybe_unused]] std::string EscapeHtml(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

bool ViewerAvailable() {
#ifdef MDLC_HAVE_VIEWER
  return true;
#else
  return false;
#endif
}

std::string ViewModelJson(const Result& result, const std::string& title,
                          const std::string& model_file) {
  const PagePaths paths(model_file);
  const backend::Plant& plant = result.plant();
  const backend::SceneGraph& scene = result.scene_graph();
  const ir::Module& module = IrModule(result);
  JsonWriter w(2);
  std::vector<std::string> notes;
  w.BeginObject();
  w.Key("title").String(title);
  w.Key("num_positions").Int(plant.num_positions);
  w.Key("model_instances").BeginArray();
  for (const std::string& name : plant.model_instances) w.String(name);
  w.EndArray();
  w.Key("joint_order").BeginArray(JsonWriter::Layout::Compact);
  for (JointId id : plant.joint_order) w.Int(id.index());
  w.EndArray();
  const Eigen::VectorXd q0 = DefaultPositions(result);
  w.Key("q0");
  Numbers(w, std::span<const double>(q0.data(), static_cast<size_t>(q0.size())));

  w.Key("bodies").BeginArray();
  for (size_t b = 0; b < plant.bodies.size(); ++b) {
    const backend::PlantBody& body = plant.bodies[b];
    w.BeginObject();
    w.Key("name").String(body.name).Key("scoped_name").String(plant.ScopedName(body));
    w.Key("model").Int(body.model.index());
    w.Key("mass").Number(body.mass).Key("com");
    Vector(w, body.p_BoBcm_B);
    w.Key("inertia").BeginArray();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) w.Number(body.I_BBcm_B(r, c));
    }
    w.EndArray();
    w.Key("parent").Int(body.parent.valid() ? body.parent.index() : -1);
    w.Key("joint").Int(body.inbound_joint.valid() ? body.inbound_joint.index() : -1);
    w.Key("level").Int(body.level);
    w.Key("source").String(b < module.bodies.size() ? Where(result, paths, module.bodies[b].loc) : "");
    w.EndObject();
  }
  w.EndArray();

  w.Key("joints").BeginArray();
  for (size_t j = 0; j < plant.joints.size(); ++j) {
    const backend::PlantJoint& joint = plant.joints[j];
    w.BeginObject();
    w.Key("name").String(joint.name).Key("scoped_name").String(plant.ScopedName(joint));
    w.Key("type").String(ir::JointTypeName(joint.type));
    w.Key("parent").Int(joint.parent.index()).Key("child").Int(joint.child.index());
    w.Key("X_PF");
    Pose(w, joint.X_PF);
    w.Key("X_CM");
    Pose(w, joint.X_CM);
    w.Key("axis");
    Vector(w, joint.axis);
    w.Key("q_start").Int(joint.q_start).Key("nq").Int(joint.nq);
    w.Key("lower");
    Numbers(w, joint.lower);
    w.Key("upper");
    Numbers(w, joint.upper);
    w.Key("default");
    Numbers(w, joint.default_positions);
    w.Key("pitch").Number(joint.screw_thread_pitch);
    w.Key("source").String(j < module.joints.size() ? Where(result, paths, module.joints[j].loc) : "");
    if (joint.type == ir::JointType::Curvilinear) {
      // the page does not follow the path; it shows the joint where it rests
      w.Key("X_FM");
      Pose(w, joint.curvilinear_path.PoseAt(joint.default_positions.empty()
                                                ? 0.0
                                                : joint.default_positions[0]));
      notes.push_back(fmt::format("curvilinear joint '{}' is shown at its default position, "
                                  "not moving with its slider",
                                  plant.ScopedName(joint)));
    }
    w.EndObject();
  }
  w.EndArray();

  w.Key("frames").BeginArray();
  for (const backend::PlantFrame& frame : plant.frames) {
    w.BeginObject().Key("name").String(frame.name).Key("body").Int(frame.body.index());
    w.Key("X_BF");
    Pose(w, frame.X_BF);
    w.EndObject();
  }
  w.EndArray();

  // meshes once per file, read as the compile reads them (in parallel);
  // geometries name them by index
  std::vector<std::string> mesh_paths;
  std::map<std::string, int> mesh_index;  // resolved path -> index in `meshes`; -1: none
  for (const backend::SceneGeometry& g : scene.geometries) {
    const auto* m = std::get_if<ir::Mesh>(&g.shape);
    if (m && !m->resolved.empty() && mesh_index.try_emplace(m->resolved, -1).second) {
      mesh_paths.push_back(m->resolved);
    }
  }
  std::string axes_note;
  std::vector<MeshTriangles> read = ReadMeshes(result, mesh_paths, &axes_note);
  if (!axes_note.empty()) notes.push_back(axes_note);
  std::vector<std::pair<std::string, const MeshTriangles*>> meshes;
  for (size_t i = 0; i < mesh_paths.size(); ++i) {
    if (!read[i].ok()) continue;
    mesh_index[mesh_paths[i]] = static_cast<int>(meshes.size());
    meshes.emplace_back(mesh_paths[i], &read[i]);
  }
  std::set<std::string> unshown;  // each mesh's note once
  w.Key("geometries").BeginArray();
  for (const backend::SceneGeometry& g : scene.geometries) {
    int mesh = -1;
    if (const auto* m = std::get_if<ir::Mesh>(&g.shape)) {
      if (auto it = mesh_index.find(m->resolved); it != mesh_index.end()) mesh = it->second;
      if (mesh < 0 && unshown.insert(m->resolved.empty() ? m->uri : m->resolved).second) {
        const auto at = std::find(mesh_paths.begin(), mesh_paths.end(), m->resolved);
        notes.push_back(fmt::format("mesh '{}' is not shown: {}", ShownUri(m->uri, paths),
                                    at == mesh_paths.end() ? "it was not found"
                                                           : read[at - mesh_paths.begin()].error));
      }
    }
    w.BeginObject();
    w.Key("name").String(g.name).Key("body").Int(g.body.index());
    w.Key("X_BG");
    Pose(w, g.X_BG);
    w.Key("shape");
    Shape(w, g.shape, mesh, paths);
    w.Key("roles").BeginArray(JsonWriter::Layout::Compact);
    ir::ForEachRoleName(g.roles, [&](std::string_view role) { w.String(role); });
    w.EndArray();
    if (auto rgba = Diffuse(g)) {
      w.Key("rgba");
      Numbers(w, *rgba);
    }
    w.EndObject();
  }
  w.EndArray();

  w.Key("meshes").BeginArray();
  for (const auto& [path, m] : meshes) {
    std::string vertices, triangles;
    for (const Eigen::Vector3d& v : m->vertices) {
      for (int k = 0; k < 3; ++k) AppendLittleEndian(vertices, static_cast<float>(v[k]));
    }
    for (const Eigen::Vector3i& t : m->triangles) {
      for (int k = 0; k < 3; ++k) AppendLittleEndian(triangles, static_cast<uint32_t>(t[k]));
    }
    w.BeginObject().Key("path").String(paths.Show(path));
    w.Key("vertices").String(Base64(vertices)).Key("triangles").String(Base64(triangles));
    w.Key("colors").BeginArray();
    for (const MeshColor& c : m->colors) {
      w.BeginArray(JsonWriter::Layout::Compact).Int(static_cast<int64_t>(c.first_triangle));
      for (int k = 0; k < 4; ++k) w.Number(c.rgba[k]);
      w.EndArray();
    }
    w.EndArray();
    w.EndObject();
  }
  w.EndArray();

  w.Key("notes").BeginArray();
  // a reader's error names the file it could not read by its full path
  for (const std::string& note : notes) w.String(paths.Scrub(note, mesh_paths));
  w.EndArray();
  w.EndObject();
  return w.Take();
}

std::string ViewPage(const Result& result, const std::string& title,
                     const std::string& model_file) {
#ifdef MDLC_HAVE_VIEWER
  // three.js and OrbitControls travel as base64 text: the viewer turns them
  // into module URLs of their own (blob:), which file:// pages may import
  return fmt::format(
      R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>{title} - mdlc view</title>
<script>
// every error the page meets, for the reader and for tests (before any other script runs)
window.mdlcErrors = [];
function mdlcReport(text) {{
  window.mdlcErrors.push(text);
  const pre = document.getElementById('mdlc-errors');
  if (pre) {{ pre.textContent = window.mdlcErrors.join('\n'); pre.hidden = false; }}
}}
addEventListener('error', (e) => mdlcReport('error: ' + e.message));
addEventListener('unhandledrejection', (e) => mdlcReport('error: ' + e.reason));
const mdlcConsoleError = console.error;
console.error = (...args) => {{ mdlcReport('console.error: ' + args.join(' ')); mdlcConsoleError(...args); }};
</script>
<style>
html, body {{ margin: 0; height: 100%; font: 13px/1.35 system-ui, sans-serif; color: #222; }}
body {{ display: flex; }}
#side {{ width: 330px; overflow: auto; padding: 8px 10px; box-sizing: border-box;
         border-right: 1px solid #ccc; background: #f7f7f7; }}
#view {{ flex: 1; position: relative; min-width: 0; }}
#view canvas {{ display: block; }}
h1 {{ font-size: 15px; margin: 0 0 6px; }} h2 {{ font-size: 13px; margin: 10px 0 4px; }}
.note {{ color: #8a5a00; }} .slider {{ display: grid; grid-template-columns: minmax(0, 1fr) 110px 48px;
  gap: 4px; align-items: center; }} .slider span {{ overflow: hidden; text-overflow: ellipsis; }}
#tree ul {{ list-style: none; padding-left: 12px; margin: 0; }}
#tree .body {{ cursor: pointer; }} #tree .body.selected {{ background: #ffe28a; }}
#tree .joint {{ color: #666; }} #toggles {{ display: flex; flex-wrap: wrap; gap: 2px 10px; }} #toggles label {{ white-space: nowrap; }}
/* the selection floats over the 3D view, so it is in sight however long the tree */
#selection {{ position: absolute; top: 8px; right: 8px; z-index: 1; max-width: min(480px, 70%);
  max-height: calc(100% - 16px); overflow: auto; box-sizing: border-box; padding: 4px 8px;
  background: rgba(255, 255, 255, 0.9); border: 1px solid #ccc; }}
#selection h2 {{ margin: 2px 0 4px; }}
#info {{ white-space: pre; font-family: monospace; font-size: 11px; }}
.slider .clamped {{ color: #a33; }}
</style>
</head>
<body>
<div id="side">
<h1>{title}</h1>
<pre id="mdlc-errors" class="note" hidden></pre>
<div id="notes"></div>
<h2>Show</h2>
<div id="toggles"></div>
<h2>Joints</h2>
<div id="sliders"></div>
<h2>Kinematic tree</h2>
<div id="tree"></div>
</div>
<div id="view">
<div id="selection"><h2>Selected body</h2><div id="info">click a body in the tree or the view</div></div>
</div>
<script type="application/json" id="mdlc-model">{model}</script>
<script type="text/plain" id="mdlc-three">{three}</script>
<script type="text/plain" id="mdlc-orbit-controls">{orbit}</script>
<script type="module">
{viewer}
</script>
</body>
</html>
)",
      fmt::arg("title", EscapeHtml(title)),
      fmt::arg("model", EscapeForScript(ViewModelJson(result, title, model_file))),
      fmt::arg("three", Base64(viewer::kThreeJs)),
      fmt::arg("orbit", Base64(viewer::kOrbitControlsJs)),
      fmt::arg("viewer", EscapeForScript(viewer::kViewerJs)));
#else
  (void)result;
  (void)title;
  (void)model_file;
  return "";
#endif
}

}  // namespace mdlc::tools
