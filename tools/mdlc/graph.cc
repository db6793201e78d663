// graph.cc - see graph.h.
#include "graph.h"

#include <fmt/format.h>

#include "backend/json_writer.h"
#include "number_text.h"

namespace mdlc::tools {
namespace {

struct Node {
  std::string id, label, shape;
};
struct Edge {
  std::string from, to, label, style;
};
struct Graph {
  std::vector<Node> nodes;
  std::vector<Edge> edges;
};

std::string Pose(const Transform& X) {
  const Eigen::Vector3d rpy = RpyFromRotation(X.R);
  return fmt::format("xyz [{} {} {}] rpy [{} {} {}]", Number(X.p.x()), Number(X.p.y()),
                     Number(X.p.z()), Number(rpy.x()), Number(rpy.y()), Number(rpy.z()));
}

Graph Build(const backend::CompiledModel& model, GraphKind kind) {
  const backend::Plant& plant = model.plant;
  Graph g;
  for (const auto& b : plant.bodies) {
    g.nodes.push_back({plant.ScopedName(b), plant.ScopedName(b), "box"});
  }
  if (kind == GraphKind::Kinematic) {
    for (const auto& j : plant.joints) {
      g.edges.push_back({plant.ScopedName(plant.body(j.parent)),
                         plant.ScopedName(plant.body(j.child)),
                         fmt::format("{}\n{}", plant.ScopedName(j), ir::JointTypeName(j.type)),
                         j.type == ir::JointType::Weld ? "dashed" : "solid"});
    }
    return g;
  }
  for (const auto& f : plant.frames) {
    const std::string id = fmt::format("{}::{}", plant.model_instances[f.model.index()], f.name);
    g.nodes.push_back({id, id, "ellipse"});
    g.edges.push_back({plant.ScopedName(plant.body(f.body)), id, Pose(f.X_BF), "solid"});
  }
  // the joints' frames F and M, each fixed on its body
  for (const auto& j : plant.joints) {
    const std::string F = plant.ScopedName(j) + " (F)", M = plant.ScopedName(j) + " (M)";
    g.nodes.push_back({F, F, "ellipse"});
    g.nodes.push_back({M, M, "ellipse"});
    g.edges.push_back({plant.ScopedName(plant.body(j.parent)), F, Pose(j.X_PF), "solid"});
    g.edges.push_back({plant.ScopedName(plant.body(j.child)), M, Pose(j.X_CM), "solid"});
    g.edges.push_back({F, M, std::string(ir::JointTypeName(j.type)), "dashed"});
  }
  return g;
}

/// A DOT string literal: quotes and backslashes escaped, newlines as \n.
std::string Quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::string FormatGraphDot(const backend::CompiledModel& model, GraphKind kind) {
  const Graph g = Build(model, kind);
  std::string out = fmt::format("digraph {} {{\n  rankdir=TB;\n",
                                kind == GraphKind::Kinematic ? "kinematic" : "frames");
  for (const Node& n : g.nodes) {
    out += fmt::format("  {} [label={}, shape={}];\n", Quoted(n.id), Quoted(n.label), n.shape);
  }
  for (const Edge& e : g.edges) {
    out += fmt::format("  {} -> {} [label={}, style={}];\n", Quoted(e.from), Quoted(e.to),
                       Quoted(e.label), e.style);
  }
  return out + "}\n";
}

std::string FormatGraphJson(const backend::CompiledModel& model, GraphKind kind) {
  const Graph g = Build(model, kind);
  backend::JsonWriter w(2);
  w.BeginObject();
  w.Key("nodes").BeginArray();
  for (const Node& n : g.nodes) {
    w.BeginObject(backend::JsonWriter::Layout::Compact);
    w.Key("id").String(n.id);
    w.Key("kind").String(n.shape == "box" ? "body" : "frame");
    w.EndObject();
  }
  w.EndArray();
  w.Key("edges").BeginArray();
  for (const Edge& e : g.edges) {
    w.BeginObject(backend::JsonWriter::Layout::Compact);
    w.Key("from").String(e.from);
    w.Key("to").String(e.to);
    w.Key("label").String(e.label);
    w.EndObject();
  }
  w.EndArray();
  w.EndObject();
  return w.Take() + "\n";
}

}  // namespace mdlc::tools
