// graph.h - `mdlc graph` (issue 15): the kinematic tree or the frames of a
// compiled model as a Graphviz DOT or JSON graph, as urdf_to_graphviz and
// `gz sdf -g` draw them, for every format. Writing DOT needs no Graphviz.
#pragma once

#include <string>

#include "backend/compiled_model.h"

namespace mdlc::tools {

enum class GraphKind { Kinematic, Frames };

/// kinematic: bodies as boxes, one edge per joint (parent -> child) labelled
/// with its name and type; frames: bodies and their frames, each frame an
/// edge to the body it is attached to, labelled with its pose in that body.
std::string FormatGraphDot(const backend::CompiledModel& model, GraphKind kind);
/// The same graph as {"nodes": [...], "edges": [...]}.
std::string FormatGraphJson(const backend::CompiledModel& model, GraphKind kind);

}  // namespace mdlc::tools
