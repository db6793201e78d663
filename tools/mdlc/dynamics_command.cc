// dynamics_command.cc - `mdlc dynamics`: the rigid-body dynamics of a model at
// one state (mdlc/dynamics.h): gravity forces, bias term, the inverse
// dynamics of given accelerations (by default none: the forces that hold the
// model), the forward dynamics of given forces (by default none: free fall),
// the energies and the center of mass, per velocity coordinate.
//
//   mdlc dynamics arm.urdf --q elbow=0.5 --v elbow=1 --tau shoulder=2 [--json]
//
// --q sets a 1-dof joint's position, as `mdlc compile --q` does (an unknown
// joint is the compile's error). --v, --vdot and --tau set one velocity
// coordinate each: a 1-dof joint by name, a coordinate of a joint of several
// by JOINT.COORD with Drake's coordinate names (ball.wx, base.vz, ...).
// Conventions and what is left out (constraints, loops, contact, limits)
// are backend/dynamics.h's.
#include <fmt/format.h>

#include <Eigen/Core>
#include <algorithm>
#include <cstdlib>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "backend/json_writer.h"
#include "ir/scoped_name.h"
#include "mdlc/dynamics.h"
#include "mdlc/kinematics.h"
#include "cli_compile.h"
#include "number_text.h"
#include "q_flag.h"
#include "subcommands.h"

namespace mdlc::cli {
namespace {

struct DynamicsFlags {
  CompileFlags compile;
  std::string output;
  std::vector<std::string> q, v, vdot, tau;  // as typed: JOINT=VALUE
  bool joint_damping = false;
  bool force_elements = false;
};

// -- naming coordinates: "instance::joint" for a joint of one coordinate,
// "instance::joint.wx" (Drake's suffixes) for one of several

std::vector<std::string_view> PositionSuffixes(ir::JointType type) {
  switch (type) {
    case ir::JointType::Ball: return {"qx", "qy", "qz"};
    case ir::JointType::Universal: return {"qx", "qy"};
    case ir::JointType::Planar: return {"x", "y", "qz"};
    case ir::JointType::QuaternionFloating: return {"qw", "qx", "qy", "qz", "x", "y", "z"};
    case ir::JointType::RpyFloating: return {"qx", "qy", "qz", "x", "y", "z"};
    default: return {};
  }
}

std::vector<std::string_view> VelocitySuffixes(ir::JointType type) {
  switch (type) {
    case ir::JointType::Ball: return {"wx", "wy", "wz"};
    case ir::JointType::Universal: return {"wx", "wy"};
    case ir::JointType::Planar: return {"vx", "vy", "wz"};
    case ir::JointType::QuaternionFloating:
    case ir::JointType::RpyFloating: return {"wx", "wy", "wz", "vx", "vy", "vz"};
    default: return {};
  }
}

struct Coordinate {
  std::string scoped, local;  // "arm::ball.wx", "ball.wx"
};

// One name per coordinate, in q order (positions) or v order (velocities).
std::vector<Coordinate> CoordinateNames(const backend::Plant& plant, bool positions) {
  std::vector<Coordinate> names(positions ? plant.num_positions : plant.num_velocities);
  for (JointId id : plant.joint_order) {
    const backend::PlantJoint& joint = plant.joint(id);
    const int start = positions ? joint.q_start : joint.v_start;
    const int count = positions ? joint.nq : joint.nv;
    const auto suffixes = positions ? PositionSuffixes(joint.type) : VelocitySuffixes(joint.type);
    for (int i = 0; i < count; ++i) {
      const std::string suffix =
          count == 1 ? ""
          : static_cast<int>(suffixes.size()) == count ? "." + std::string(suffixes[i])
                                                       : fmt::format("[{}]", i);
      names[start + i] = {plant.ScopedName(joint) + suffix, joint.name + suffix};
    }
  }
  return names;
}

// -- reading --v, --vdot, --tau

struct Assignment {
  std::string name;
  double value = 0;
};

// NAME=VALUE each; nullopt, reported, when one is not
std::optional<std::vector<Assignment>> ParseAssignments(const std::vector<std::string>& typed,
                                                        const char* flag) {
  std::vector<Assignment> out;
  for (const std::string& assignment : typed) {
    const size_t eq = assignment.rfind('=');
    char* end = nullptr;
    const double value =
        eq == std::string::npos ? 0 : std::strtod(assignment.c_str() + eq + 1, &end);
    if (eq == std::string::npos || eq == 0 || end == assignment.c_str() + eq + 1 || *end != '\0') {
      fmt::print(stderr, "mdlc: error: {} expects JOINT=VALUE, got '{}'\n", flag, assignment);
      return std::nullopt;
    }
    out.push_back({assignment.substr(0, eq), value});
  }
  return out;
}

// The index of the coordinate `name` names, scoped or (when only one
// coordinate has it) local; nullopt, reported, when none or several do.
std::optional<int> FindCoordinate(const std::vector<Coordinate>& coordinates,
                                  const std::string& name, const char* flag) {
  std::vector<int> local;
  for (size_t i = 0; i < coordinates.size(); ++i) {
    if (coordinates[i].scoped == name) return static_cast<int>(i);
    if (coordinates[i].local == name) local.push_back(static_cast<int>(i));
  }
  if (local.size() == 1) return local.front();
  if (local.size() > 1) {
    fmt::print(stderr,
               "mdlc: error: {}: {} velocity coordinates are named '{}'; give the scoped "
               "name ('{}', ...)\n",
               flag, local.size(), name, coordinates[local.front()].scoped);
    return std::nullopt;
  }
  std::vector<std::string_view> candidates;
  for (const Coordinate& c : coordinates) {
    candidates.push_back(c.scoped);
    candidates.push_back(c.local);
  }
  const std::optional<std::string> closest = ir::ClosestName(name, candidates);
  fmt::print(stderr, "mdlc: error: {}: no velocity coordinate named '{}'{}\n", flag, name,
             closest              ? fmt::format("; did you mean '{}'?", *closest)
             : coordinates.empty() ? std::string("; the model has no velocities")
                                   : std::string());
  return std::nullopt;
}

// A vector of nv set by a flag's assignments, zero elsewhere
std::optional<Eigen::VectorXd> VelocityVector(const std::vector<Coordinate>& coordinates,
                                              const std::vector<Assignment>& assignments,
                                              const char* flag) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(coordinates.size()));
  for (const Assignment& a : assignments) {
    const std::optional<int> i = FindCoordinate(coordinates, a.name, flag);
    if (!i) return std::nullopt;
    x[*i] = a.value;
  }
  return x;
}

// -- what is computed, and its two printings

struct Dynamics {
  std::vector<Coordinate> positions, velocities;
  Eigen::VectorXd q, v, vdot, tau;
  Eigen::VectorXd gravity_forces, bias_term, inverse_dynamics;
  std::optional<Eigen::VectorXd> forward_dynamics;  // none when M is singular
  double kinetic_energy = 0, potential_energy = 0;
  std::optional<backend::CenterOfMass> center_of_mass;  // none without mass
  std::vector<std::string> problems;                    // why one is none
};

Dynamics Compute(const Result& result, Dynamics d, const DynamicsOptions& options) {
  d.gravity_forces = GravityForces(result, d.q);
  d.bias_term = BiasTerm(result, d.q, d.v);
  d.inverse_dynamics = InverseDynamics(result, d.q, d.v, d.vdot, options);
  d.kinetic_energy = KineticEnergy(result, d.q, d.v, options);
  d.potential_energy = PotentialEnergy(result, d.q, options);
  try {
    d.forward_dynamics = ForwardDynamics(result, d.q, d.v, d.tau, options);
  } catch (const std::domain_error& e) {
    d.problems.push_back(fmt::format("forward dynamics: {}", e.what()));
  }
  try {
    d.center_of_mass = CenterOfMass(result, d.q, d.v);
  } catch (const std::domain_error& e) {
    d.problems.push_back(fmt::format("center of mass: {}", e.what()));
  }
  return d;
}

// six significant digits, and -0 (gravity's force on a coordinate it does
// not move) as 0
std::string Number(double x) { return tools::Number(x == 0 ? 0.0 : x); }

std::string Vector3(const Eigen::Vector3d& p) {
  return fmt::format("[{} {} {}]", Number(p.x()), Number(p.y()), Number(p.z()));
}

std::string Text(const Dynamics& d, const Result& result) {
  const backend::Plant& plant = result.plant();
  std::string out = fmt::format("nq {}, nv {}, gravity {} m/s^2\n", plant.num_positions,
                                plant.num_velocities, Vector3(plant.gravity));
  size_t width = 10;  // "coordinate"
  for (const Coordinate& c : d.positions) width = std::max(width, c.scoped.size());
  for (const Coordinate& c : d.velocities) width = std::max(width, c.scoped.size());
  out += "positions q:\n";
  for (size_t i = 0; i < d.positions.size(); ++i) {
    out += fmt::format("  {:<{}}  {}\n", d.positions[i].scoped, width, Number(d.q[i]));
  }
  // one row per velocity coordinate: the inputs, then what was computed
  out += "per velocity coordinate: v, vdot and tau as given; tau_g, the gravity forces;\n"
         "C(q,v)v, the bias term; inverse tau, the tau that gives vdot; forward vdot, the vdot\n"
         "that tau gives:\n";
  out += fmt::format("  {:<{}}  {:>12} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12}\n", "coordinate",
                     width, "v", "vdot", "tau", "tau_g", "C(q,v)v", "inverse tau",
                     "forward vdot");
  for (size_t i = 0; i < d.velocities.size(); ++i) {
    out += fmt::format(
        "  {:<{}}  {:>12} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12}\n", d.velocities[i].scoped,
        width, Number(d.v[i]), Number(d.vdot[i]), Number(d.tau[i]),
        Number(d.gravity_forces[i]), Number(d.bias_term[i]),
        Number(d.inverse_dynamics[i]),
        d.forward_dynamics ? Number((*d.forward_dynamics)[i]) : std::string("-"));
  }
  out += fmt::format("kinetic energy: {} J\npotential energy: {} J\n",
                     Number(d.kinetic_energy), Number(d.potential_energy));
  if (d.center_of_mass) {
    out += fmt::format("center of mass: mass {} kg, position {}, velocity {}\n",
                       Number(d.center_of_mass->mass), Vector3(d.center_of_mass->position),
                       Vector3(d.center_of_mass->velocity));
  } else {
    out += "center of mass: none\n";
  }
  return out;
}

void Array(backend::JsonWriter& w, const char* key, const Eigen::VectorXd& x) {
  w.Key(key).BeginArray(backend::JsonWriter::Layout::Compact);
  for (double value : x) w.Number(value);
  w.EndArray();
}

void Names(backend::JsonWriter& w, const char* key, const std::vector<Coordinate>& names) {
  w.Key(key).BeginArray(backend::JsonWriter::Layout::Compact);
  for (const Coordinate& c : names) w.String(c.scoped);
  w.EndArray();
}

std::string Json(const Dynamics& d) {
  backend::JsonWriter w(1);
  w.BeginObject();
  Names(w, "positions", d.positions);
  Names(w, "velocities", d.velocities);
  Array(w, "q", d.q);
  Array(w, "v", d.v);
  Array(w, "vdot", d.vdot);
  Array(w, "tau", d.tau);
  Array(w, "gravity_forces", d.gravity_forces);
  Array(w, "bias_term", d.bias_term);
  Array(w, "inverse_dynamics", d.inverse_dynamics);
  if (d.forward_dynamics) {
    Array(w, "forward_dynamics", *d.forward_dynamics);
  } else {
    w.Key("forward_dynamics").Null();
  }
  w.Key("kinetic_energy").Number(d.kinetic_energy);
  w.Key("potential_energy").Number(d.potential_energy);
  w.Key("center_of_mass");
  if (d.center_of_mass) {
    w.BeginObject(backend::JsonWriter::Layout::Compact);
    w.Key("mass").Number(d.center_of_mass->mass);
    Array(w, "position", d.center_of_mass->position);
    Array(w, "velocity", d.center_of_mass->velocity);
    w.EndObject();
  } else {
    w.Null();
  }
  w.EndObject();
  return w.Take() + "\n";
}

int Run(const DynamicsFlags& flags) {
  Options joint_positions;
  if (!ParseJointPositions(flags.q, joint_positions)) return 2;
  const auto v = ParseAssignments(flags.v, "--v");
  const auto vdot = v ? ParseAssignments(flags.vdot, "--vdot") : std::nullopt;
  const auto tau = vdot ? ParseAssignments(flags.tau, "--tau") : std::nullopt;
  if (!tau) return 2;

  CompileSetup setup;
  setup.adjust = [&](Options& options) {
    options.model.joint_positions = joint_positions.model.joint_positions;
  };
  const CliCompile compiled = CompileForCli(flags.compile, setup);
  if (compiled.status) return compiled.status;
  const Result& result = *compiled.result;

  Dynamics d;
  d.positions = CoordinateNames(result.plant(), true);
  d.velocities = CoordinateNames(result.plant(), false);
  d.q = DefaultPositions(result);
  const auto v_values = VelocityVector(d.velocities, *v, "--v");
  const auto vdot_values = VelocityVector(d.velocities, *vdot, "--vdot");
  const auto tau_values = VelocityVector(d.velocities, *tau, "--tau");
  if (!v_values || !vdot_values || !tau_values) return 1;
  d.v = *v_values;
  d.vdot = *vdot_values;
  d.tau = *tau_values;

  DynamicsOptions options;
  options.joint_damping = flags.joint_damping;
  options.force_elements = flags.force_elements;
  try {
    d = Compute(result, std::move(d), options);
  } catch (const std::exception& e) {  // a force element whose force is undefined here
    fmt::print(stderr, "mdlc: error: {}\n", e.what());
    return 1;
  }
  const int written = WriteOutput(
      flags.output, flags.compile.output_format == "json" ? Json(d) : Text(d, result));
  for (const std::string& problem : d.problems) fmt::print(stderr, "mdlc: error: {}\n", problem);
  return written ? written : d.problems.empty() ? 0 : 1;
}

}  // namespace

Subcommand AddDynamicsCommand(CLI::App& app) {
  auto flags = std::make_shared<DynamicsFlags>();
  CLI::App* command = app.add_subcommand(
      "dynamics",
      "Print gravity forces, bias term, inverse and forward dynamics, energy and center of "
      "mass at one state");
  flags->compile.output_formats = {"text", "json"};
  AddCompileFlags(command, flags->compile);
  AddJsonAlias(command, flags->compile);
  command->add_option("-o,--output", flags->output, "Write the output here instead of stdout");
  AddJointPositionsFlag(command, flags->q);
  const char* coordinate = "JOINT=VALUE, or JOINT.COORD=VALUE for a joint of several (repeatable)";
  command->add_option("--v", flags->v, fmt::format("Set a velocity: {}", coordinate))
      ->allow_extra_args(false);
  command
      ->add_option("--vdot", flags->vdot,
                   fmt::format("Set an acceleration for inverse dynamics: {}", coordinate))
      ->allow_extra_args(false);
  command
      ->add_option("--tau", flags->tau,
                   fmt::format("Set a generalized force for forward dynamics: {}", coordinate))
      ->allow_extra_args(false);
  command->add_flag("--joint-damping", flags->joint_damping,
                    "Include the joints' viscous damping (-d v)");
  command->add_flag("--force-elements", flags->force_elements,
                    "Include joint springs, linear spring-dampers and bushings");
  return {command, [flags] { return Run(*flags); }};
}

}  // namespace mdlc::cli
