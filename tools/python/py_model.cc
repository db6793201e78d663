// py_model.cc - builds the Python view of a compiled model (py_model.h) and
// binds its classes.
#include "py_model.h"

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <variant>

#include "ir/shape_parameters.h"
#include "mdlc/kinematics.h"

namespace mdlc::python {
namespace py = pybind11;

Eigen::Matrix4d Pose::matrix() const {
  Eigen::Matrix4d X = Eigen::Matrix4d::Identity();
  X.topLeftCorner<3, 3>() = R;
  X.topRightCorner<3, 1>() = p;
  return X;
}

Pose MakePose(const Transform& X) {
  const Eigen::Quaterniond quat = CanonicalQuaternion(X.R);
  return Pose{X.p, X.R, Eigen::Vector4d(quat.w(), quat.x(), quat.y(), quat.z())};
}

namespace {

Eigen::VectorXd ToVector(std::span<const double> v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

// plant-json's names: the world body is just "world", every other entity
// "instance::local"
class Names {
 public:
  explicit Names(const backend::Plant& plant) : plant_(plant) {}
  std::string instance(ModelId id) const { return plant_.model_instances[id.index()]; }
  std::string body(BodyId id) const { return plant_.ScopedName(plant_.body(id)); }
  std::string joint(JointId id) const { return plant_.ScopedName(plant_.joint(id)); }

 private:
  const backend::Plant& plant_;
};

std::vector<std::string> RoleNames(uint8_t roles) {
  std::vector<std::string> names;
  ir::ForEachRoleName(roles, [&](std::string_view role) { names.emplace_back(role); });
  return names;
}

// A shape parameter's, a constraint's or a force element's field's value, as
// Python holds it; ids become scoped names, as plant-json writes them
py::object Value(double x, const Names&) { return py::cast(x); }
py::object Value(const Eigen::Vector3d& v, const Names&) { return py::cast(Eigen::Vector3d(v)); }
py::object Value(const std::string& s, const Names&) { return py::cast(s); }
py::object Value(BodyId body, const Names& names) { return py::cast(names.body(body)); }
py::object Value(JointId joint, const Names& names) { return py::cast(names.joint(joint)); }
py::object Value(const Transform& X, const Names&) { return py::cast(MakePose(X)); }
py::object Value(const std::vector<double>& v, const Names&) { return py::cast(ToVector(v)); }
py::object Value(const std::optional<double>& x, const Names&) { return py::cast(x); }
template <typename Entity>
py::dict Fields(const Entity& entity, const Names& names);
// a list of structs, each a dict of its own VisitFields
template <typename Item>
  requires requires(const Item& item) { item.VisitFields([](std::string_view, const auto&) {}); }
py::object Value(const std::vector<Item>& items, const Names& names) {
  py::list list;
  for (const Item& item : items) list.append(Fields(item, names));
  return list;
}
py::object Value(const std::vector<JointId>& joints, const Names& names) {
  py::list list;
  for (JointId j : joints) list.append(names.joint(j));
  return list;
}

// plant-json's parameters (ir/shape_parameters.h), and Python's own extra: a
// mesh's resolved file path
py::dict ShapeParameters(const ir::Shape& shape, const Names& names) {
  py::dict d;
  ir::VisitShapeParameters(shape, [&](std::string_view name, const auto& value) {
    d[py::str(std::string(name))] = Value(value, names);
  });
  if (const auto* mesh = std::get_if<ir::Mesh>(&shape)) d["path"] = mesh->resolved;
  return d;
}

// a constraint's, force element's or deformable body's fields, by its
// VisitFields (backend/plant.h, ir/entities.h)
template <typename Entity>
py::dict Fields(const Entity& entity, const Names& names) {
  py::dict d;
  entity.VisitFields([&](std::string_view name, const auto& value) {
    d[py::str(std::string(name))] = Value(value, names);
  });
  return d;
}

ForceElement MakeForceElement(const backend::Plant& plant, const backend::ForceElement& f,
                              const Names& names) {
  ForceElement out{std::string(backend::ForceElementTypeName(plant, f)), {}};
  std::visit([&](const auto& element) { out.parameters = Fields(element, names); }, f);
  return out;
}

py::dict Properties(const std::vector<ir::Property>& properties) {
  py::dict d;
  for (const ir::Property& p : properties) {
    d[py::str(p.key)] = std::visit([](const auto& v) -> py::object { return py::cast(v); }, p.value);
  }
  return d;
}

// the fields its VisitFields (backend/plant.h) lists, as plant-json writes them
Constraint MakeConstraint(const backend::PlantConstraint& c, const Names& names) {
  Constraint out{std::string(ir::ConstraintTypeName(c.type())), names.instance(c.model), {}};
  std::visit([&](const auto& k) { out.parameters = Fields(k, names); }, c.payload);
  return out;
}

}  // namespace

Model MakeModel(std::shared_ptr<const Result> result, py::list diagnostics) {
  const backend::Plant& plant = result->plant();
  const backend::SceneGraph& scene = result->scene_graph();
  const Names names(plant);
  Model m;
  m.result = result;
  m.diagnostics = std::move(diagnostics);
  m.model_instances = plant.model_instances.ToVector();
  for (size_t i = 0; i < plant.bodies.size(); ++i) {
    const backend::PlantBody& b = plant.bodies[i];
    Body body{b.name, plant.ScopedName(b), names.instance(b.model), b.mass, b.p_BoBcm_B, b.I_BBcm_B,
              b.is_world, b.unnamed, std::nullopt, std::nullopt, static_cast<int>(i)};
    if (b.parent.valid()) body.parent = names.body(b.parent);
    if (b.inbound_joint.valid()) body.joint = names.joint(b.inbound_joint);
    body.surface_velocity_axis = b.surface_velocity_axis;
    if (b.deformable) body.deformable = Fields(*b.deformable, names);
    m.bodies.push_back(std::move(body));
  }
  for (const backend::PlantJoint& j : plant.joints) {
    m.joints.push_back(Joint{j.name, plant.ScopedName(j), names.instance(j.model),
                             std::string(ir::JointTypeName(j.type)), names.body(j.parent),
                             names.body(j.child), MakePose(j.X_PF), MakePose(j.X_CM), j.axis,
                             ToVector(j.lower), ToVector(j.upper), ToVector(j.velocity_lower),
                             ToVector(j.velocity_upper), ToVector(j.effort),
                             ToVector(j.damping), ToVector(j.default_positions),
                             j.screw_thread_pitch, j.unnamed, j.q_start, j.nq, j.v_start, j.nv,
                             ToVector(j.acceleration_lower), ToVector(j.acceleration_upper)});
  }
  for (const backend::PlantFrame& f : plant.frames) {
    m.frames.push_back(
        Frame{f.name, names.instance(f.model), names.body(f.body), MakePose(f.X_BF), f.unnamed});
  }
  for (const backend::SceneGeometry& g : scene.geometries) {
    m.geometries.push_back(Geometry{g.name, names.instance(g.model), names.body(g.body),
                                    MakePose(g.X_BG), RoleNames(g.roles),
                                    std::string(ir::ShapeTypeName(g.shape)),
                                    ShapeParameters(g.shape, names), Properties(g.properties),
                                    g.unnamed});
  }
  for (const backend::PlantActuator& a : plant.actuators) {
    m.actuators.push_back(Actuator{a.name, names.instance(a.model), names.joint(a.joint),
                                   a.effort_limit, a.gear_ratio, a.rotor_inertia, a.kp, a.kd,
                                   a.unnamed});
  }
  for (const backend::PlantConstraint& c : plant.constraints) {
    m.constraints.push_back(MakeConstraint(c, names));
  }
  for (const backend::SceneCamera& c : scene.cameras) {
    m.cameras.push_back(Camera{c.name, names.instance(c.model), names.body(c.body),
                               MakePose(c.X_BC), c.width, c.height, c.fov_y, c.unnamed});
  }
  for (const backend::ForceElement& f : plant.force_elements) {
    m.force_elements.push_back(MakeForceElement(plant, f, names));
  }
  return m;
}

namespace {

// A floating joint's quaternion of zero length is no rotation: normalizing
// it would divide by zero, and taking it as the identity would hide a bug in
// the caller's q. A q of the wrong size is left to the plant's own check.
void CheckQuaternions(const Model& m, const Eigen::VectorXd& q) {
  if (q.size() != m.result->plant().num_positions) return;
  for (const Joint& j : m.joints) {
    if (j.type != "quaternion_floating") continue;
    const double norm = q.segment<4>(j.q_start).norm();
    if (norm == 0 || !std::isfinite(norm)) {
      throw py::value_error(fmt::format(
          "q[{}:{}], the quaternion [w, x, y, z] of joint '{}', {}; a rotation needs a "
          "nonzero finite quaternion (the identity is [1, 0, 0, 0])",
          j.q_start, j.q_start + 4, j.scoped_name, norm == 0 ? "is zero" : "is not finite"));
    }
  }
}

// q defaults to the model's default configuration
Eigen::VectorXd PositionsOr(const Model& m, const std::optional<Eigen::VectorXd>& q) {
  if (!q) return mdlc::DefaultPositions(*m.result);
  CheckQuaternions(m, *q);
  return *q;
}

std::string Number(double x) { return fmt::format("{:.6g}", x); }

std::string Vector(const Eigen::Ref<const Eigen::VectorXd>& v) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) out += (i ? ", " : "") + Number(v[i]);
  return out + "]";
}

// "<mdlc.Kind 'instance::name' details>": the scoped name, as a lookup by
// name (model.bodies['...']) takes it, and what tells entities apart
std::string Repr(const char* kind, const std::string& scoped_name, const std::string& details) {
  return fmt::format("<mdlc.{} '{}'{}{}>", kind, scoped_name, details.empty() ? "" : " ",
                     details);
}
std::string Scoped(const std::string& instance, const std::string& name) {
  return instance.empty() ? name : instance + "::" + name;
}

}  // namespace

void BindModel(py::module_& m) {
  py::class_<Pose>(m, "Pose", "A pose X_AB: p (3), R (3x3), q = [w, x, y, z] (w >= 0)")
      .def_readonly("p", &Pose::p)
      .def_readonly("R", &Pose::R)
      .def_readonly("q", &Pose::q)
      .def_property_readonly("matrix", &Pose::matrix, "The 4x4 homogeneous transform")
      .def("__repr__", [](const Pose& p) {
        return "<mdlc.Pose p=" + Vector(p.p) + " q=" + Vector(p.q) + ">";
      });

  py::class_<Body>(m, "Body")
      .def_readonly("name", &Body::name)
      .def_readonly("scoped_name", &Body::scoped_name)
      .def_readonly("model_instance", &Body::model_instance)
      .def_readonly("mass", &Body::mass)
      .def_readonly("com", &Body::com, "Center of mass in the body frame")
      .def_readonly("inertia", &Body::inertia, "Rotational inertia about the center of mass, in B")
      .def_readonly("is_world", &Body::is_world)
      .def_readonly("unnamed", &Body::unnamed)
      .def_readonly("parent", &Body::parent)
      .def_readonly("joint", &Body::joint, "The joint whose child this body is")
      .def_readonly("surface_velocity_axis", &Body::surface_velocity_axis,
                    "The axis a conveyor-like surface moves along, in B (None: it does not)")
      .def_readonly("deformable", &Body::deformable,
                    "A deformable link's properties, as plant-json's bodies[].deformable (None: "
                    "a rigid body)")
      .def_readonly("index", &Body::index, "Its index in Model.bodies and body_poses()")
      .def("__repr__", [](const Body& b) {
        return Repr("Body", b.scoped_name,
                    fmt::format("index={} mass={}{}", b.index, Number(b.mass),
                                b.joint ? " joint '" + *b.joint + "'" : ""));
      });

  py::class_<Joint>(m, "Joint")
      .def_readonly("name", &Joint::name)
      .def_readonly("scoped_name", &Joint::scoped_name)
      .def_readonly("model_instance", &Joint::model_instance)
      .def_readonly("type", &Joint::type)
      .def_readonly("parent", &Joint::parent)
      .def_readonly("child", &Joint::child)
      .def_readonly("X_PF", &Joint::X_PF)
      .def_readonly("X_CM", &Joint::X_CM)
      .def_readonly("axis", &Joint::axis)
      .def_readonly("lower", &Joint::lower)
      .def_readonly("upper", &Joint::upper)
      .def_readonly("velocity_lower", &Joint::velocity_lower)
      .def_readonly("velocity_upper", &Joint::velocity_upper)
      .def_readonly("acceleration_lower", &Joint::acceleration_lower)
      .def_readonly("acceleration_upper", &Joint::acceleration_upper)
      .def_readonly("effort", &Joint::effort)
      .def_readonly("damping", &Joint::damping)
      .def_readonly("default_positions", &Joint::default_positions)
      .def_readonly("screw_thread_pitch", &Joint::screw_thread_pitch)
      .def_readonly("unnamed", &Joint::unnamed)
      .def_readonly("q_start", &Joint::q_start)
      .def_readonly("nq", &Joint::nq)
      .def_readonly("v_start", &Joint::v_start)
      .def_readonly("nv", &Joint::nv)
      .def("__repr__", [](const Joint& j) {
        // where its positions are in q: plant.joints are in the plant's
        // joint order, not in q order
        const std::string q = j.nq == 0   ? "no q"
                              : j.nq == 1 ? fmt::format("q[{}]", j.q_start)
                                          : fmt::format("q[{}:{}]", j.q_start, j.q_start + j.nq);
        return Repr("Joint", j.scoped_name,
                    fmt::format("{} {} {} -> {}", j.type, q, j.parent, j.child));
      });

  py::class_<Frame>(m, "Frame")
      .def_readonly("name", &Frame::name)
      .def_readonly("model_instance", &Frame::model_instance)
      .def_readonly("body", &Frame::body)
      .def_readonly("X_BF", &Frame::X_BF)
      .def_readonly("unnamed", &Frame::unnamed)
      .def("__repr__", [](const Frame& f) {
        return Repr("Frame", Scoped(f.model_instance, f.name), "on '" + f.body + "'");
      });

  py::class_<Geometry>(m, "Geometry")
      .def_readonly("name", &Geometry::name)
      .def_readonly("model_instance", &Geometry::model_instance)
      .def_readonly("body", &Geometry::body)
      .def_readonly("X_BG", &Geometry::X_BG)
      .def_readonly("roles", &Geometry::roles)
      .def_readonly("shape", &Geometry::shape)
      .def_readonly("shape_parameters", &Geometry::shape_parameters)
      .def_readonly("properties", &Geometry::properties)
      .def_readonly("unnamed", &Geometry::unnamed)
      .def("__repr__", [](const Geometry& g) {
        std::string roles;
        for (const std::string& r : g.roles) roles += (roles.empty() ? "" : ",") + r;
        return Repr("Geometry", Scoped(g.model_instance, g.name),
                    fmt::format("{} on '{}' ({})", g.shape, g.body, roles));
      });

  py::class_<Actuator>(m, "Actuator")
      .def_readonly("name", &Actuator::name)
      .def_readonly("model_instance", &Actuator::model_instance)
      .def_readonly("joint", &Actuator::joint)
      .def_readonly("effort_limit", &Actuator::effort_limit)
      .def_readonly("gear_ratio", &Actuator::gear_ratio)
      .def_readonly("rotor_inertia", &Actuator::rotor_inertia)
      .def_readonly("kp", &Actuator::kp)
      .def_readonly("kd", &Actuator::kd)
      .def_readonly("unnamed", &Actuator::unnamed)
      .def("__repr__", [](const Actuator& a) {
        return Repr("Actuator", Scoped(a.model_instance, a.name),
                    fmt::format("on '{}' effort_limit={}", a.joint, Number(a.effort_limit)));
      });

  py::class_<Constraint>(m, "Constraint")
      .def_readonly("type", &Constraint::type)
      .def_readonly("model_instance", &Constraint::model_instance)
      .def_readonly("parameters", &Constraint::parameters)
      .def("__repr__", [](const Constraint& c) {
        return "<mdlc.Constraint " + c.type + " in '" + c.model_instance + "'>";
      });

  py::class_<ForceElement>(m, "ForceElement")
      .def_readonly("type", &ForceElement::type)
      .def_readonly("parameters", &ForceElement::parameters)
      .def("__repr__", [](const ForceElement& f) { return "<mdlc.ForceElement " + f.type + ">"; });

  py::class_<Camera>(m, "Camera")
      .def_readonly("name", &Camera::name)
      .def_readonly("model_instance", &Camera::model_instance)
      .def_readonly("body", &Camera::body)
      .def_readonly("X_BC", &Camera::X_BC)
      .def_readonly("width", &Camera::width)
      .def_readonly("height", &Camera::height)
      .def_readonly("fov_y", &Camera::fov_y)
      .def_readonly("unnamed", &Camera::unnamed)
      .def("__repr__", [](const Camera& c) {
        return Repr("Camera", Scoped(c.model_instance, c.name),
                    fmt::format("on '{}' {}x{}", c.body, c.width, c.height));
      });

  py::class_<Model>(m, "Model", "A compiled model: the plant, its scene graph and cameras")
      .def_readonly("model_instances", &Model::model_instances)
      .def_readonly("bodies", &Model::bodies, "Every body, by index; bodies[0] is the world")
      .def_readonly("joints", &Model::joints,
                    "Every joint, in the plant's joint order (as plant-json lists them); "
                    "each joint's q_start and nq say where its positions are in q")
      .def_readonly("frames", &Model::frames)
      .def_readonly("geometries", &Model::geometries)
      .def_readonly("actuators", &Model::actuators)
      .def_readonly("constraints", &Model::constraints)
      .def_readonly("cameras", &Model::cameras)
      .def_readonly("force_elements", &Model::force_elements,
                    "Springs, dampers and bushings, as plant-json lists them")
      .def_readonly("diagnostics", &Model::diagnostics, "Warnings the compile reported")
      .def_property_readonly("num_positions",
                             [](const Model& m) { return m.result->plant().num_positions; })
      .def_property_readonly("num_velocities",
                             [](const Model& m) { return m.result->plant().num_velocities; })
      .def_property_readonly(
          "gravity", [](const Model& m) { return Eigen::Vector3d(m.result->plant().gravity); })
      .def_property_readonly("time_step",
                             [](const Model& m) { return m.result->plant().time_step; })
      .def("default_positions", [](const Model& m) { return mdlc::DefaultPositions(*m.result); },
           "Each joint's default position (and the compile's joint_positions), in q order")
      .def(
          "mass_matrix",
          [](const Model& m, const std::optional<Eigen::VectorXd>& q) {
            return mdlc::MassMatrix(*m.result, PositionsOr(m, q));
          },
          py::arg("q") = py::none(),
          "The nv x nv mass matrix M(q) (default: at default_positions())")
      .def(
          "body_poses",
          [](const Model& m, const std::optional<Eigen::VectorXd>& q) {
            std::vector<Pose> poses;
            for (const Transform& X : mdlc::BodyPoses(*m.result, PositionsOr(m, q))) {
              poses.push_back(MakePose(X));
            }
            return poses;
          },
          py::arg("q") = py::none(), "X_WB of every body at q, indexed like bodies")
      .def(
          "collision_filtered",
          [](const Model& m, size_t a, size_t b) {
            const size_t n = m.bodies.size();
            if (a >= n || b >= n) {
              throw py::index_error("body index out of range: the model has " +
                                    std::to_string(n) + " bodies");
            }
            return m.result->scene_graph().collision_filters.Filtered(BodyId(a), BodyId(b));
          },
          py::arg("a"), py::arg("b"),
          "Whether the collisions of bodies a and b (indices into bodies) are filtered out")
      .def(
          "collision_filters",
          [](const Model& m) {
            std::vector<std::pair<std::string, std::string>> pairs;
            for (const auto& [a, b] :
                 m.result->scene_graph().collision_filters.Pairs(m.result->plant())) {
              pairs.emplace_back(m.bodies[a.index()].scoped_name, m.bodies[b.index()].scoped_name);
            }
            return pairs;
          },
          "Every filtered body pair by scoped name, as plant-json lists them (as many as the "
          "pairs: a welded composite of N bodies gives N(N-1)/2; collision_filtered answers "
          "one pair)")
      .def(
          "to_json",
          [](const Model& m, const std::optional<Eigen::VectorXd>& q, bool full_mass_matrix) {
            backend::PlantJsonOptions options;
            options.force_mass_matrix = full_mass_matrix;
            return mdlc::PlantJson(*m.result, PositionsOr(m, q), options);
          },
          py::arg("q") = py::none(), py::arg("full_mass_matrix") = false,
          "plant-json (schema mdlc-plant/1) at q")
      .def("__repr__", [](const Model& m) {
        const backend::Plant& plant = m.result->plant();
        // the instances that hold a body: the world's own is no model
        std::vector<std::string> instances;
        for (const Body& b : m.bodies) {
          if (b.is_world) continue;
          if (std::find(instances.begin(), instances.end(), b.model_instance) == instances.end()) {
            instances.push_back(b.model_instance);
          }
        }
        const auto count = [](size_t n, const char* one, const char* many) {
          return fmt::format("{} {}", n, n == 1 ? one : many);
        };
        return fmt::format("<mdlc.Model '{}': {}, {}, {}, nq={} nv={}>",
                           fmt::join(instances, ", "), count(m.bodies.size() - 1, "body", "bodies"),
                           count(m.joints.size(), "joint", "joints"),
                           count(m.geometries.size(), "geometry", "geometries"),
                           plant.num_positions, plant.num_velocities);
      });
}

}  // namespace mdlc::python
