// warning_groups.cc - see warning_groups.h.
#include "warning_groups.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <utility>

#include "ir/diagnostics.h"

namespace mdlc::cli {
namespace {

// One line per group, alphabetical. A group added to diagnostic_kinds.def
// needs its line here (warning_groups_test checks every group has one).
constexpr std::pair<std::string_view, std::string_view> kDescriptions[] = {
    {"actuator", "actuators and transmissions that cannot be built as written"},
    {"driver", "the compile itself: too many errors, so the rest were not reported"},
    {"frames", "SDFormat frames: cycles, and joints of a static model"},
    {"geometry", "shapes and mesh files: bad sizes, unreadable or open meshes"},
    {"include", "included files: cycles and files included twice"},
    {"inertia", "mass and inertia that are not physical, or were ignored"},
    {"internal", "a broken invariant of mdlc's own (a bug in mdlc; please report it)"},
    {"io", "files that cannot be read, and files of no format mdlc knows"},
    {"joint", "joints: zero axes, floating joints, limits that contradict themselves"},
    {"limits", "an input over one of the --limit limits (file size, elements, depth, ...)"},
    {"lossy", "convert: what the target format cannot hold, dropped or approximated"},
    {"material", "materials: unknown names, conflicting definitions, partial scripts"},
    {"mesh-axes", "what was done with a COLLADA file's declared up axis"},
    {"mesh-reader", "mesh files read inside mdlc because the mesh reader program is missing"},
    {"missing-asset", "a file the plant does not need (a visual-only mesh) that does not exist"},
    {"names", "names: duplicates, renames, unknown references, packages found twice"},
    {"schema", "elements and attributes a format requires, and values it does not allow"},
    {"security", "XML entity declarations, refused"},
    {"syntax", "XML and YAML syntax, empty files, text after a value"},
    {"topology", "the kinematic tree: loops, links with two parents, self-joints"},
    {"unimplemented", "elements mdlc does not build yet"},
    {"unknown", "elements and attributes the format does not define (often a misspelling)"},
    {"unsupported", "elements and attributes the format defines that the plant does not hold"},
    {"uri", "URIs in a non-standard form that mdlc reads anyway"},
    {"xacro", "xacro expansion: errors, warnings and the model's own messages"},
};

struct GroupFacts {
  bool has_warnings_or_notes = false;
};

// every group of the .def, and whether any of its kinds can be silenced
std::map<std::string_view, GroupFacts> GroupsInDefinitions() {
  std::map<std::string_view, GroupFacts> groups;
  for (const DiagKindInfo& kind : AllDiagKindInfo()) {
    groups[kind.group].has_warnings_or_notes |= kind.default_severity != Severity::Error;
  }
  return groups;
}

}  // namespace

std::vector<WarningGroup> WarningGroups() {
  std::vector<WarningGroup> out;
  for (const auto& [name, facts] : GroupsInDefinitions()) {
    std::string_view description;
    for (const auto& [known, text] : kDescriptions) {
      if (known == name) description = text;
    }
    out.push_back({name, description, !facts.has_warnings_or_notes});
  }
  return out;
}

std::string ListWarningGroups() {
  std::string out =
      "Diagnostic groups. -Wno-GROUP silences a group's warnings and notes, -Werror=GROUP\n"
      "makes its warnings errors, -Werror makes every warning an error; errors cannot be\n"
      "silenced. Each diagnostic names its group: [-Wgroup].\n";
  const std::vector<WarningGroup> groups = WarningGroups();
  size_t width = 0;
  for (const WarningGroup& g : groups) width = std::max(width, g.name.size());
  for (const WarningGroup& g : groups) {
    out += fmt::format("  {:<{}}  {}{}\n", g.name, width, g.description,
                       g.errors_only ? " (errors only)" : "");
  }
  return out;
}

}  // namespace mdlc::cli
