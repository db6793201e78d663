// tree.cc - `mdlc tree`: the kinematic tree of each model instance, as
// check_urdf prints it for URDF, for every format (issue 15).
#include "tree.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>
#include <variant>

#include "backend/entity_index.h"
#include "backend/json_writer.h"
#include "number_text.h"

namespace mdlc::tools {
namespace {

using backend::EntityIndex;
using backend::Plant;
using backend::PlantJoint;
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string Limits(const PlantJoint& j) {
  std::string out;
  for (int k = 0; k < j.nv; ++k) {
    if (j.lower[k] == -kInf && j.upper[k] == kInf) continue;
    out += fmt::format("{}[{}, {}]", out.empty() ? "" : " ", Number(j.lower[k]),
                       Number(j.upper[k]));
  }
  return out;
}

/// The couplers that make joint `id` follow another: "mimics 'x' (2 q + 0.1)".
std::string Couplers(const Plant& plant, const EntityIndex& couplers_by_follower, JointId id) {
  std::string out;
  for (uint32_t c : couplers_by_follower[id.index()]) {
    const auto* k = std::get_if<backend::CouplerConstraint>(&plant.constraints[c].payload);
    out += fmt::format(", mimics '{}' ({} q {} {})", plant.ScopedName(plant.joint(k->joint1)),
                       Number(k->gear_ratio), k->offset < 0 ? "-" : "+",
                       Number(std::abs(k->offset)));
  }
  return out;
}

class TreePrinter {
 public:
  explicit TreePrinter(const backend::CompiledModel& model)
      : plant_(model.plant),
        children_(plant_.bodies.size()),
        // what each model instance holds, indexed once: a world of N
        // models would otherwise scan every body N times
        bodies_by_model_(backend::BodiesByModel(plant_)),
        joints_by_model_(backend::JointsByModel(plant_)),
        frames_by_model_(backend::FramesByModel(plant_)),
        couplers_by_follower_(backend::CouplersByFollower(plant_)) {
    for (size_t b = 1; b < plant_.bodies.size(); ++b) {
      const auto& body = plant_.bodies[b];
      if (body.parent.valid()) children_[body.parent.index()].push_back(BodyId(b));
    }
  }

  std::string Text() {
    std::string out;
    for (size_t m = 0; m < plant_.model_instances.size(); ++m) {
      std::vector<BodyId> roots;  // this instance's bodies whose parent is elsewhere
      int bodies = 0, dofs = 0;
      for (uint32_t b : bodies_by_model_[m]) {
        const auto& body = plant_.bodies[b];
        ++bodies;
        if (!body.parent.valid() || plant_.body(body.parent).model.index() != m) {
          roots.push_back(BodyId(b));
        }
      }
      for (uint32_t j : joints_by_model_[m]) dofs += plant_.joints[j].nv;
      if (bodies == 0) continue;
      out += fmt::format("model instance '{}': {} bod{}, {} dof{}\n", plant_.model_instances[m],
                         bodies, bodies == 1 ? "y" : "ies", dofs, dofs == 1 ? "" : "s");
      for (BodyId root : roots) {
        const auto& body = plant_.body(root);
        const std::string parent =
            body.parent.valid() ? plant_.ScopedName(plant_.body(body.parent)) : "nothing";
        out += fmt::format("  {} (on {})\n", Describe(root), parent);
        Children(root, "  ", out);
      }
      for (uint32_t i : frames_by_model_[m]) {
        const auto& f = plant_.frames[i];
        if (f.unnamed) continue;
        // a body of the frame's own instance by its local name (names that
        // repeat the instance's full name grow with its nesting depth)
        const auto& body = plant_.body(f.body);
        out += fmt::format("  frame '{}' on {}\n", f.name,
                           body.model.index() == m ? body.name : plant_.ScopedName(body));
      }
    }
    return out;
  }

  std::string Json() {
    backend::JsonWriter w(2);
    w.BeginObject();
    w.Key("bodies").BeginArray();
    for (size_t b = 1; b < plant_.bodies.size(); ++b) {
      const auto& body = plant_.bodies[b];
      w.BeginObject(backend::JsonWriter::Layout::Compact);
      w.Key("name").String(plant_.ScopedName(body));
      w.Key("model_instance").String(plant_.model_instances[body.model.index()]);
      w.Key("parent").String(
          body.parent.valid() ? plant_.ScopedName(plant_.body(body.parent)) : std::string());
      if (body.inbound_joint.valid()) {
        const PlantJoint& j = plant_.joint(body.inbound_joint);
        w.Key("joint").String(plant_.ScopedName(j));
        w.Key("type").String(ir::JointTypeName(j.type));
        w.Key("dofs").Int(j.nv);
      }
      w.EndObject();
    }
    w.EndArray();
    w.Key("dofs").Int(plant_.num_velocities);
    w.EndObject();
    return w.Take() + "\n";
  }

 private:
  std::string Describe(BodyId id) const {
    const auto& body = plant_.body(id);
    if (!body.inbound_joint.valid()) return fmt::format("{}", plant_.ScopedName(body));
    const PlantJoint& j = plant_.joint(body.inbound_joint);
    std::string joint = fmt::format("{} joint '{}'", ir::JointTypeName(j.type), j.name);
    if (j.nv == 1 && j.type != ir::JointType::Weld) {
      joint += fmt::format(", axis [{} {} {}]", Number(j.axis.x()), Number(j.axis.y()),
                           Number(j.axis.z()));
    }
    if (const std::string limits = Limits(j); !limits.empty()) joint += ", limits " + limits;
    joint += Couplers(plant_, couplers_by_follower_, body.inbound_joint);
    return fmt::format("{} <- {}", body.name, joint);
  }

  /// A body of another instance, where this instance's tree reaches it: one
  /// line naming it; its own instance's tree (printed on its own) goes on.
  std::string DescribeElsewhere(BodyId id) const {
    const auto& body = plant_.body(id);
    return fmt::format("{} of model instance '{}'", body.name,
                       plant_.model_instances[body.model.index()]);
  }

  // depth-first, without recursion (a chain may be thousands deep); past
  // kMaxDrawnDepth levels the branch lines give way to the depth in numbers.
  // Only `root`'s own instance is expanded: each instance's tree would
  // otherwise repeat every instance nested below it, and a model nested N
  // deep would print N^2/2 lines.
  static constexpr size_t kMaxDrawnDepth = 32;
  void Children(BodyId root, const std::string& indent, std::string& out) {
    const ModelId instance = plant_.body(root).model;
    struct Item {
      BodyId body;
      std::string prefix;  // the drawn branches above this body
      size_t depth;
      bool last;
    };
    std::vector<Item> stack;
    auto push_children = [&](BodyId parent, const std::string& prefix, size_t depth) {
      const auto& kids = children_[parent.index()];
      for (size_t i = kids.size(); i-- > 0;) {
        stack.push_back({kids[i], prefix, depth, i + 1 == kids.size()});
      }
    };
    push_children(root, indent, 1);
    while (!stack.empty()) {
      Item item = std::move(stack.back());
      stack.pop_back();
      const bool elsewhere = plant_.body(item.body).model != instance;
      const std::string line = elsewhere ? DescribeElsewhere(item.body) : Describe(item.body);
      if (item.depth <= kMaxDrawnDepth) {
        out += fmt::format("{}{}{}\n", item.prefix, item.last ? "└─ " : "├─ ", line);
      } else {
        out += fmt::format("{}[depth {}] {}\n", item.prefix, item.depth, line);
      }
      if (elsewhere) continue;
      const std::string prefix = item.depth < kMaxDrawnDepth
                                     ? item.prefix + (item.last ? "   " : "│  ")
                                     : item.prefix;
      push_children(item.body, prefix, item.depth + 1);
    }
  }

  const Plant& plant_;
  std::vector<std::vector<BodyId>> children_;
  const EntityIndex bodies_by_model_, joints_by_model_, frames_by_model_, couplers_by_follower_;
};

}  // namespace

std::string FormatTree(const backend::CompiledModel& model) { return TreePrinter(model).Text(); }
std::string FormatTreeJson(const backend::CompiledModel& model) {
  return TreePrinter(model).Json();
}

}  // namespace mdlc::tools
