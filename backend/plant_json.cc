// plant_json.cc - walks the compiled model in spec order into a JsonWriter.
#include "backend/plant_json.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <variant>

#include "backend/json_writer.h"
#include "backend/kinematics.h"
#include "backend/mass_matrix.h"
#include "ir/shape_parameters.h"

namespace mdlc::backend {

namespace {

// Top-level members and the entries of top-level lists get a line each.
constexpr int kPrettyDepth = 2;

class PlantJsonEmitter {
 public:
  PlantJsonEmitter(const CompiledModel& model, const Eigen::VectorXd& q,
                   const PlantJsonOptions& options)
      : plant_(model.plant),
        scene_(model.scene),
        q_(q),
        options_(options),
        X_WB_(BodyPosesInWorld(model.plant, q)),
        w_(kPrettyDepth) {}

  std::string Emit() {
    w_.BeginObject();
    w_.Key("schema").String("mdlc-plant/1");
    w_.Key("model_instances").BeginArray(JsonWriter::Layout::Compact);
    for (const std::string& name : plant_.model_instances) w_.String(name);
    w_.EndArray();
    w_.Key("bodies").BeginArray();
    for (size_t b = 0; b < plant_.bodies.size(); ++b) {
      if (!plant_.bodies[b].is_world) Body(plant_.bodies[b], X_WB_[b]);
    }
    w_.EndArray();
    w_.Key("joints").BeginArray();
    for (size_t j = 0; j < plant_.joints.size(); ++j) Joint(JointId(j));
    w_.EndArray();
    List("frames", plant_.frames, [&](const PlantFrame& f) { Frame(f); });
    List("geometries", scene_.geometries, [&](const SceneGeometry& g) { Geometry(g); });
    List("actuators", plant_.actuators, [&](const PlantActuator& a) { Actuator(a); });
    List("collision_filters", scene_.collision_filters.Pairs(plant_), [&](const auto& pair) {
      w_.BeginArray().String(BodyName(pair.first)).String(BodyName(pair.second)).EndArray();
    });
    List("constraints", plant_.constraints, [&](const PlantConstraint& c) { Constraint(c); });
    List("cameras", scene_.cameras, [&](const SceneCamera& c) { Camera(c); });
    Dofs();
    List("force_elements", plant_.force_elements,
         [&](const ForceElement& f) { ForceElementEntry(f); });
    w_.Key("gravity");
    Vector(plant_.gravity);
    w_.Key("time_step").Number(plant_.time_step);
    w_.EndObject();
    return w_.Take();
  }

 private:
  template <typename Range, typename Fn>
  void List(std::string_view key, const Range& items, Fn&& entry) {
    w_.Key(key).BeginArray();
    for (const auto& item : items) entry(item);
    w_.EndArray();
  }

  // -- values

  void Vector(const Eigen::Ref<const Eigen::VectorXd>& v) {
    w_.BeginArray(JsonWriter::Layout::Compact);
    for (Eigen::Index i = 0; i < v.size(); ++i) w_.Number(v[i]);
    w_.EndArray();
  }
  void Numbers(std::span<const double> values) {
    w_.BeginArray();
    for (double x : values) w_.Number(x);  // non-finite -> null
    w_.EndArray();
  }
  void Pose(const Transform& X) {
    const Eigen::Quaterniond quat = CanonicalQuaternion(X.R);
    w_.BeginObject();
    w_.Key("p");
    Vector(X.p);
    w_.Key("q").BeginArray().Number(quat.w()).Number(quat.x()).Number(quat.y()).Number(quat.z());
    w_.EndArray().EndObject();
  }
  void OptionalNumber(const std::optional<double>& x) {
    if (x) w_.Number(*x);
    else w_.Null();
  }

  // -- names

  // built as they are written: the plant keeps names unscoped (issue 16)
  std::string Instance(ModelId model) const { return plant_.model_instances[model.index()]; }
  std::string BodyName(BodyId body) const { return plant_.ScopedName(plant_.body(body)); }
  std::string JointName(JointId joint) const { return plant_.ScopedName(plant_.joint(joint)); }
  void NameAndInstance(const std::string& name, ModelId model) {
    w_.Key("name").String(name);
    w_.Key("model_instance").String(Instance(model));
  }

  // -- entities

  void Body(const PlantBody& body, const Transform& X_WB) {
    const Eigen::Matrix3d& I = body.I_BBcm_B;
    w_.BeginObject();
    NameAndInstance(body.name, body.model);
    w_.Key("mass").Number(body.mass);
    w_.Key("com");
    Vector(body.p_BoBcm_B);
    w_.Key("inertia").BeginArray();
    for (double x : {I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2)}) w_.Number(x);
    w_.EndArray();
    w_.Key("X_WB");
    Pose(X_WB);
    if (body.surface_velocity_axis) {
      w_.Key("surface_velocity_axis");
      Vector(*body.surface_velocity_axis);
    }
    if (body.deformable) Deformable(*body.deformable);
    UnnamedFlag(body.unnamed);
    w_.EndObject();
  }

  // `"unnamed": true` on what the compiler named (plant-json.md); absent
  // otherwise, so that named entities print as before
  void UnnamedFlag(bool unnamed) {
    if (unnamed) w_.Key("unnamed").Bool(true);
  }

  // `bodies[].deformable` (EXT-070), from its VisitFields
  void Deformable(const ir::DeformableProperties& d) {
    w_.Key("deformable").BeginObject();
    Fields(d);
    w_.EndObject();
  }

  void Joint(JointId id) {
    const PlantJoint& joint = plant_.joint(id);
    w_.BeginObject();
    NameAndInstance(joint.name, joint.model);
    w_.Key("type").String(ir::JointTypeName(joint.type));
    w_.Key("parent").String(BodyName(joint.parent));
    w_.Key("child").String(BodyName(joint.child));
    if (joint.nv == 1) {
      // a curvilinear joint moves along its path's tangent at q
      const Eigen::Vector3d axis_F =
          joint.type == ir::JointType::Curvilinear
              ? joint.curvilinear_path.PoseAt(q_[joint.q_start]).R.col(0)
              : joint.axis;
      w_.Key("axis_W");
      Vector(JointFrameInWorld(plant_, X_WB_, id).R * axis_F);
    }
    w_.Key("lower");
    Numbers(joint.lower);
    w_.Key("upper");
    Numbers(joint.upper);
    w_.Key("velocity_limit");
    Numbers(joint.velocity_upper);
    w_.Key("effort_limit");
    Numbers(joint.effort);
    w_.Key("damping");
    Numbers(joint.damping);
    w_.Key("default_positions");
    Numbers(joint.default_positions);
    if (std::any_of(joint.acceleration_upper.begin(), joint.acceleration_upper.end(),
                    [](double x) { return std::isfinite(x); })) {
      w_.Key("acceleration_limit");
      Numbers(joint.acceleration_upper);
    }
    if (joint.type == ir::JointType::Screw) {
      w_.Key("screw_thread_pitch").Number(joint.screw_thread_pitch);
    }
    UnnamedFlag(joint.unnamed);
    w_.EndObject();
  }

  void Frame(const PlantFrame& frame) {
    w_.BeginObject();
    NameAndInstance(frame.name, frame.model);
    w_.Key("body").String(BodyName(frame.body));
    w_.Key("X_BF");
    Pose(frame.X_BF);
    UnnamedFlag(frame.unnamed);
    w_.EndObject();
  }

  void Geometry(const SceneGeometry& g) {
    w_.BeginObject();
    NameAndInstance(g.name, g.model);
    w_.Key("body").String(BodyName(g.body));
    w_.Key("roles").BeginArray();
    ir::ForEachRoleName(g.roles, [&](std::string_view role) { w_.String(role); });
    w_.EndArray();
    w_.Key("shape");
    Shape(g.shape);
    w_.Key("X_WG");
    Pose(X_WB_[g.body.index()] * g.X_BG);
    w_.Key("properties").BeginObject();
    for (const ir::Property& p : g.properties) {
      w_.Key(p.key);
      PropertyValue(p.value);
    }
    w_.EndObject();
    UnnamedFlag(g.unnamed);
    w_.EndObject();
  }

  void Shape(const ir::Shape& shape) {
    w_.BeginObject();
    w_.Key("type").String(ir::ShapeTypeName(shape));
    ir::VisitShapeParameters(shape, [&](std::string_view name, const auto& value) {
      w_.Key(name);
      Value(value);
    });
    w_.EndObject();
  }

  // a member per field of a constraint or force element (its VisitFields)
  template <typename Entity>
  void Fields(const Entity& entity) {
    entity.VisitFields([&](std::string_view name, const auto& value) {
      w_.Key(name);
      Value(value);
    });
  }

  // a shape parameter's, a constraint's or a force element's field's value
  // (their VisitShapeParameters and VisitFields)
  void Value(double x) { w_.Number(x); }
  void Value(const Eigen::Vector3d& v) { Vector(v); }
  void Value(const std::string& s) { w_.String(s); }
  void Value(BodyId body) { w_.String(BodyName(body)); }
  void Value(JointId joint) { w_.String(JointName(joint)); }
  void Value(const Transform& X) { Pose(X); }
  void Value(const std::vector<double>& values) { Numbers(values); }
  void Value(const std::optional<double>& x) { OptionalNumber(x); }
  // a list of structs, each an object of its own VisitFields
  template <typename Item>
    requires requires(const Item& item) { item.VisitFields([](std::string_view, const auto&) {}); }
  void Value(const std::vector<Item>& items) {
    w_.BeginArray();
    for (const Item& item : items) {
      w_.BeginObject();
      Fields(item);
      w_.EndObject();
    }
    w_.EndArray();
  }
  void Value(const std::vector<JointId>& joints) {
    w_.BeginArray();
    for (JointId j : joints) w_.String(JointName(j));
    w_.EndArray();
  }

  void PropertyValue(const ir::PropertyValue& value) {
    std::visit(
        [&](const auto& v) {
          using V = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<V, bool>) {
            w_.Bool(v);
          } else if constexpr (std::is_same_v<V, double>) {
            w_.Number(v);
          } else if constexpr (std::is_same_v<V, std::string>) {
            w_.String(v);
          } else if constexpr (std::is_same_v<V, std::vector<double>>) {
            Numbers(v);
          } else {
            w_.BeginArray();
            for (const std::string& s : v) w_.String(s);
            w_.EndArray();
          }
        },
        value);
  }

  void Actuator(const PlantActuator& a) {
    w_.BeginObject();
    NameAndInstance(a.name, a.model);
    w_.Key("joint").String(JointName(a.joint));
    w_.Key("effort_limit").Number(a.effort_limit);
    w_.Key("gear_ratio").Number(a.gear_ratio);
    w_.Key("rotor_inertia").Number(a.rotor_inertia);
    w_.Key("kp");
    OptionalNumber(a.kp);
    w_.Key("kd");
    OptionalNumber(a.kd);
    UnnamedFlag(a.unnamed);
    w_.EndObject();
  }

  // its fields come from its VisitFields (plant.h)
  void Constraint(const PlantConstraint& c) {
    w_.BeginObject();
    w_.Key("type").String(ir::ConstraintTypeName(c.type()));
    w_.Key("model_instance").String(Instance(c.model));
    std::visit([&](const auto& k) { Fields(k); }, c.payload);
    w_.EndObject();
  }

  void Camera(const SceneCamera& c) {
    w_.BeginObject();
    NameAndInstance(c.name, c.model);
    w_.Key("body").String(BodyName(c.body));
    w_.Key("X_BC");
    Pose(c.X_BC);
    w_.Key("width").Int(c.width);
    w_.Key("height").Int(c.height);
    w_.Key("fov_y").Number(c.fov_y);
    UnnamedFlag(c.unnamed);
    w_.EndObject();
  }

  // its fields come from its VisitFields (plant.h)
  void ForceElementEntry(const ForceElement& f) {
    w_.BeginObject();
    w_.Key("type").String(ForceElementTypeName(plant_, f));
    std::visit([&](const auto& element) { Fields(element); }, f);
    w_.EndObject();
  }

  /// dofs, and (for at most mass_matrix_max_dofs of them, unless forced)
  /// mass_matrix and reflected_inertia.
  void Dofs() {
    std::vector<JointId> dofs;
    for (JointId j : plant_.joint_order) {
      if (plant_.joint(j).nv == 1) dofs.push_back(j);
    }
    List("dofs", dofs, [&](JointId j) { w_.String(JointName(j)); });
    if (dofs.size() > options_.mass_matrix_max_dofs && !options_.force_mass_matrix) return;

    const Eigen::MatrixXd M = CalcMassMatrix(plant_, q_, dofs);
    w_.Key("mass_matrix").BeginArray();
    for (Eigen::Index r = 0; r < M.rows(); ++r) Vector(M.row(r).transpose());
    w_.EndArray();

    // gear_ratio^2 * rotor_inertia of the actuators on each dof
    std::vector<double> reflected(plant_.joints.size(), 0.0);
    for (const PlantActuator& a : plant_.actuators) {
      reflected[a.joint.index()] += a.gear_ratio * a.gear_ratio * a.rotor_inertia;
    }
    List("reflected_inertia", dofs, [&](JointId j) { w_.Number(reflected[j.index()]); });
  }

  const Plant& plant_;
  const SceneGraph& scene_;
  const Eigen::VectorXd& q_;
  const PlantJsonOptions& options_;
  const std::vector<Transform> X_WB_;
  JsonWriter w_;
};

}  // namespace

std::string EmitPlantJson(const CompiledModel& model, const Eigen::VectorXd& q,
                          const PlantJsonOptions& options) {
  return PlantJsonEmitter(model, q, options).Emit();
}

}  // namespace mdlc::backend
