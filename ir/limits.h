// limits.h - the bounds mdlc holds every input to (issue 16).
//
// A model file is untrusted input: a generated dataset, a download, a fuzzer.
// Each limit bounds one way an input could make a compile use unbounded
// memory or time, and each is reported as a located error
// (`[-Wlimits]`, kind limit-exceeded) naming the limit and how to raise it.
// The defaults are far above any real robot model; `mdlc --limit NAME=N` or
// Options::limits changes them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mdlc {

struct Limits {
  /// Bytes of any one file mdlc reads: a model, an included file, a mesh.
  /// At most 2 GiB - 1, the largest buffer libxml2 parses.
  uint64_t file_size = uint64_t{512} << 20;
  /// Bytes of all model files of one compile together (the top file, every
  /// include, every file a directive adds, once per time it is read).
  uint64_t total_size = uint64_t{4} << 30;
  /// Elements in one XML document.
  uint64_t elements = 20'000'000;
  /// Element nesting depth of one XML document.
  uint64_t depth = 1'000'000;
  /// Files included inside included files: an SDFormat <include> chain,
  /// MJCF <include>s, directives adding directives.
  uint64_t include_depth = 100;
  /// Nesting depth of model instances (SDFormat models in models; a
  /// top-level model is 1 deep). The compile is linear in it, but every
  /// output that prints an instance's full name (plant-json, the IR dump,
  /// `mdlc tree`, conversion to URDF or MJCF) grows with its square: 4 GB of
  /// plant-json for a model 10,000 deep, 55 MB for one 1,000 deep.
  uint64_t model_depth = 1'000;
  /// Vertices of one mesh file, counted as read, before vertices at the same
  /// position are merged (an OBJ face's corners may count separately).
  uint64_t mesh_vertices = 20'000'000;
  /// Seconds the mesh reader may take over one mesh file before it is
  /// stopped (it runs in its own process; see passes/mesh/reader_pool.h).
  uint64_t mesh_seconds = 60;
  /// xacro macro calls inside macro calls (a macro calling itself ends here).
  uint64_t macro_depth = 200;
  /// Nodes (elements, text, comments) one xacro expansion may make: a macro
  /// that calls itself twice per level doubles its output at every level.
  uint64_t expansion_nodes = 2'000'000;
};

/// One limit's name (as `--limit` spells it), what it bounds, and its field.
struct LimitInfo {
  std::string_view name;
  std::string_view what;
  uint64_t Limits::*field;
  uint64_t max_value;
};
const std::vector<LimitInfo>& AllLimits();

/// Sets the limit a `NAME=VALUE` setting names (VALUE: a count, or bytes
/// with an optional K, M or G suffix, powers of 1024). Returns a message
/// when the setting is not understood.
std::optional<std::string> SetLimit(Limits& limits, std::string_view setting);

/// "1.5 GiB", "512 MiB", "300 KiB", "12 bytes": for messages.
std::string FormatBytes(uint64_t bytes);

}  // namespace mdlc
