// stats.cc - see stats.h.
#include "stats.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <map>
#include <set>
#include <variant>

#include "backend/json_writer.h"
#include "backend/kinematics.h"
#include "backend/positions.h"
#include "ir/count_text.h"

namespace mdlc::tools {
namespace {

using backend::Plant;

/// Principal moments non-negative and satisfying the triangle inequality,
/// to a tolerance relative to their size: what a rigid body can have.
bool CouldBePhysical(double mass, const Eigen::Matrix3d& I) {
  if (!(mass >= 0) || !I.allFinite()) return false;
  const Eigen::Vector3d m = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
  const double tolerance = 1e-14 * std::max(1.0, m.cwiseAbs().maxCoeff());
  return m.minCoeff() >= -tolerance && m[0] + m[1] >= m[2] - tolerance;
}

/// What one group of bodies (an instance, or all) adds up to.
struct Totals {
  int bodies = 0;
  double mass = 0;
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();  // sum m p_WBcm
  std::map<std::string, int> joints, geometries, shapes;
  int actuators = 0, constraints = 0, cameras = 0;
  // mesh geometries, the distinct files they name, and their files' sizes
  // summed over the geometries (a file drawn twice counts twice)
  int meshes = 0, unreadable_meshes = 0;
  std::set<std::string> mesh_files;
  size_t vertices = 0, triangles = 0;
  Eigen::Vector3d com() const {
    return mass > 0 ? Eigen::Vector3d(first_moment / mass) : Eigen::Vector3d::Zero();
  }
};

std::string ShapeName(const ir::Shape& shape) { return std::string(ir::ShapeTypeName(shape)); }

/// A mesh geometry and its file's size.
struct MeshUse {
  const backend::SceneGeometry* geometry;
  const ir::Mesh* mesh;
  MeshSize size;
};

class Stats {
 public:
  Stats(const backend::CompiledModel& model, const Result& result)
      : model_(model),
        plant_(model_.plant),
        X_WB_(backend::BodyPosesInWorld(plant_, backend::DefaultPositions(plant_))),
        per_instance_(plant_.model_instances.size()) {
    for (size_t b = 1; b < plant_.bodies.size(); ++b) {
      const auto& body = plant_.bodies[b];
      for (Totals* t : {&per_instance_[body.model.index()], &total_}) {
        ++t->bodies;
        t->mass += body.mass;
        t->first_moment += body.mass * (X_WB_[b] * body.p_BoBcm_B);
      }
    }
    for (const auto& j : plant_.joints) {
      for (Totals* t : {&per_instance_[j.model.index()], &total_}) {
        ++t->joints[std::string(ir::JointTypeName(j.type))];
      }
    }
    for (const auto& g : model_.scene.geometries) {
      for (Totals* t : {&per_instance_[g.model.index()], &total_}) {
        if (g.roles & ir::kProximityRole) ++t->geometries["proximity"];
        if (g.roles & ir::kIllustrationRole) ++t->geometries["illustration"];
        if (g.roles & ir::kPerceptionRole) ++t->geometries["perception"];
        ++t->shapes[ShapeName(g.shape)];
      }
    }
    for (const auto& a : plant_.actuators) {
      ++per_instance_[a.model.index()].actuators;
      ++total_.actuators;
    }
    for (const auto& c : plant_.constraints) {
      ++per_instance_[c.model.index()].constraints;
      ++total_.constraints;
    }
    for (const auto& c : model_.scene.cameras) {
      ++per_instance_[c.model.index()].cameras;
      ++total_.cameras;
    }
    CountMeshes(result);
  }

  std::string Text() const {
    std::string out;
    for (size_t b = 1; b < plant_.bodies.size(); ++b) {
      const auto& body = plant_.bodies[b];
      const Eigen::Matrix3d& I = body.I_BBcm_B;
      out += fmt::format(
          "body {}: mass {} kg, com [{} {} {}], inertia about com [ixx {} iyy {} izz {} ixy {} "
          "ixz {} iyz {}]{}\n",
          plant_.ScopedName(body), body.mass, body.p_BoBcm_B.x(), body.p_BoBcm_B.y(),
          body.p_BoBcm_B.z(), I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2),
          CouldBePhysical(body.mass, I) ? "" : "  (not physically valid)");
    }
    for (const MeshUse& use : meshes_) {
      out += fmt::format("mesh {} on {}: {}: ", use.geometry->name, BodyName(*use.geometry),
                         use.mesh->resolved);
      out += use.size.ok() ? fmt::format("{}, {}\n",
                                         ir::CountOf(use.size.vertices, "vertex", "vertices"),
                                         ir::CountOf(use.size.triangles, "triangle"))
                           : fmt::format("not readable ({})\n", use.size.error);
    }
    for (size_t m = 0; m < per_instance_.size(); ++m) {
      if (per_instance_[m].bodies == 0) continue;
      out += Summary(fmt::format("model instance '{}'", plant_.model_instances[m]),
                     per_instance_[m]);
    }
    out += Summary("total", total_);
    return out;
  }

  std::string Json() const {
    backend::JsonWriter w(2);
    w.BeginObject();
    w.Key("bodies").BeginArray();
    for (size_t b = 1; b < plant_.bodies.size(); ++b) {
      const auto& body = plant_.bodies[b];
      w.BeginObject(backend::JsonWriter::Layout::Compact);
      w.Key("name").String(plant_.ScopedName(body));
      w.Key("mass").Number(body.mass);
      w.Key("com").BeginArray(backend::JsonWriter::Layout::Compact);
      for (int k = 0; k < 3; ++k) w.Number(body.p_BoBcm_B[k]);
      w.EndArray();
      w.Key("inertia").BeginArray(backend::JsonWriter::Layout::Compact);
      const Eigen::Matrix3d& I = body.I_BBcm_B;
      for (double v : {I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2)}) w.Number(v);
      w.EndArray();
      w.Key("physically_valid").Bool(CouldBePhysical(body.mass, I));
      w.EndObject();
    }
    w.EndArray();
    w.Key("meshes").BeginArray();
    for (const MeshUse& use : meshes_) {
      w.BeginObject(backend::JsonWriter::Layout::Compact);
      w.Key("geometry").String(use.geometry->name);
      w.Key("body").String(BodyName(*use.geometry));
      w.Key("uri").String(use.mesh->uri);
      w.Key("file").String(use.mesh->resolved);
      if (use.size.ok()) {
        w.Key("vertices").Int(static_cast<int64_t>(use.size.vertices));
        w.Key("triangles").Int(static_cast<int64_t>(use.size.triangles));
      } else {
        w.Key("error").String(use.size.error);
      }
      w.EndObject();
    }
    w.EndArray();
    w.Key("model_instances").BeginArray();
    for (size_t m = 0; m < per_instance_.size(); ++m) {
      if (per_instance_[m].bodies == 0) continue;
      JsonTotals(w, plant_.model_instances[m], per_instance_[m]);
    }
    w.EndArray();
    w.Key("total");
    JsonTotals(w, "", total_);
    w.EndObject();
    return w.Take() + "\n";
  }

 private:
  std::string BodyName(const backend::SceneGeometry& g) const {
    return plant_.ScopedName(plant_.bodies[g.body.index()]);
  }

  /// The size of every mesh geometry's file, read in parallel where the
  /// compile did not read it already.
  void CountMeshes(const Result& result) {
    std::vector<std::string> paths;
    for (const auto& g : model_.scene.geometries) {
      if (const auto* mesh = std::get_if<ir::Mesh>(&g.shape)) {
        meshes_.push_back({&g, mesh, {}});
        paths.push_back(mesh->resolved);
      }
    }
    const std::vector<MeshSize> sizes = MeshSizes(result, paths);
    for (size_t i = 0; i < meshes_.size(); ++i) {
      MeshUse& use = meshes_[i];
      use.size = sizes[i];
      // a model printed as far as it compiled keeps meshes it did not find
      if (use.mesh->resolved.empty()) use.size.error = "not found";
      for (Totals* t : {&per_instance_[use.geometry->model.index()], &total_}) {
        ++t->meshes;
        t->mesh_files.insert(use.mesh->resolved);
        t->vertices += use.size.vertices;
        t->triangles += use.size.triangles;
        if (!use.size.ok()) ++t->unreadable_meshes;
      }
    }
  }

  static std::string MeshCounts(const Totals& t) {
    if (t.meshes == 0) return "none";
    return fmt::format("{} geometr{} of {} file{}, {} vertices, {} triangles{}", t.meshes,
                       t.meshes == 1 ? "y" : "ies", t.mesh_files.size(),
                       t.mesh_files.size() == 1 ? "" : "s", t.vertices, t.triangles,
                       t.unreadable_meshes
                           ? fmt::format(" ({} not readable)", t.unreadable_meshes)
                           : "");
  }

  static std::string Counts(const std::map<std::string, int>& counts) {
    std::string out;
    for (const auto& [name, n] : counts) out += fmt::format("{}{} {}", out.empty() ? "" : ", ", n, name);
    return out.empty() ? "none" : out;
  }

  std::string Summary(const std::string& what, const Totals& t) const {
    const Eigen::Vector3d com = t.com();
    return fmt::format(
        "{}: {}, mass {} kg, com in world [{} {} {}]\n  joints: {}\n  geometries: {} "
        "(shapes: {})\n  meshes: {}\n  actuators {}, constraints {}, cameras {}\n",
        what, ir::CountOf(t.bodies, "body", "bodies"), t.mass, com.x(), com.y(), com.z(),
        Counts(t.joints), Counts(t.geometries),
        Counts(t.shapes), MeshCounts(t), t.actuators, t.constraints, t.cameras);
  }

  static void JsonCounts(backend::JsonWriter& w, const std::map<std::string, int>& counts) {
    w.BeginObject(backend::JsonWriter::Layout::Compact);
    for (const auto& [name, n] : counts) w.Key(name).Int(n);
    w.EndObject();
  }

  void JsonTotals(backend::JsonWriter& w, const std::string& name, const Totals& t) const {
    w.BeginObject();
    if (!name.empty()) w.Key("name").String(name);
    w.Key("bodies").Int(t.bodies);
    w.Key("mass").Number(t.mass);
    const Eigen::Vector3d com = t.com();
    w.Key("com_in_world").BeginArray(backend::JsonWriter::Layout::Compact);
    for (int k = 0; k < 3; ++k) w.Number(com[k]);
    w.EndArray();
    w.Key("joints");
    JsonCounts(w, t.joints);
    w.Key("geometries");
    JsonCounts(w, t.geometries);
    w.Key("shapes");
    JsonCounts(w, t.shapes);
    w.Key("meshes").BeginObject(backend::JsonWriter::Layout::Compact);
    w.Key("geometries").Int(t.meshes);
    w.Key("files").Int(static_cast<int64_t>(t.mesh_files.size()));
    w.Key("vertices").Int(static_cast<int64_t>(t.vertices));
    w.Key("triangles").Int(static_cast<int64_t>(t.triangles));
    w.Key("not_readable").Int(t.unreadable_meshes);
    w.EndObject();
    w.Key("actuators").Int(t.actuators);
    w.Key("constraints").Int(t.constraints);
    w.Key("cameras").Int(t.cameras);
    w.EndObject();
  }

  const backend::CompiledModel& model_;
  const Plant& plant_;
  std::vector<Transform> X_WB_;
  std::vector<Totals> per_instance_;
  Totals total_;
  std::vector<MeshUse> meshes_;
};

}  // namespace

std::string FormatStats(const backend::CompiledModel& model, const Result& result) {
  return Stats(model, result).Text();
}
std::string FormatStatsJson(const backend::CompiledModel& model, const Result& result) {
  return Stats(model, result).Json();
}

}  // namespace mdlc::tools
