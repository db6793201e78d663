// option_names.cc - see mdlc/option_names.h.
#include "mdlc/option_names.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <set>
#include <unordered_set>

#include "ir/scoped_name.h"
#include "ir/diagnostics.h"
#include "mdlc/pass_list.h"

namespace mdlc {
namespace {

// "; did you mean 'joint'?" when a known name is a typo away, else
// `otherwise` (where to find the names)
std::string Suggestion(std::string_view wanted, const std::vector<std::string_view>& known,
                       std::string_view otherwise) {
  if (auto best = ir::ClosestName(wanted, known)) return fmt::format("; did you mean '{}'?", *best);
  return std::string(otherwise);
}

std::string Listed(const std::vector<std::string_view>& names) {
  return fmt::format("{}", fmt::join(names, ", "));
}

bool Contains(const std::vector<std::string_view>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// a value of a fixed few words, e.g. --mesh-reader's
std::optional<std::string> CheckChoice(std::string_view text, std::string_view where,
                                       const std::vector<std::string_view>& choices) {
  if (Contains(choices, text)) return std::nullopt;
  return fmt::format("unknown value '{}' for {}{}", text, where,
                     Suggestion(text, choices,
                                fmt::format("; expected '{}'", fmt::join(choices, "' or '"))));
}

}  // namespace

const std::vector<std::string_view>& WarningGroupNames() {
  static const std::vector<std::string_view> names = [] {
    std::set<std::string_view> groups;
    for (const DiagKindInfo& kind : AllDiagKindInfo()) groups.insert(kind.group);
    return std::vector<std::string_view>(groups.begin(), groups.end());
  }();
  return names;
}

const std::vector<std::string_view>& PassNames() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> out;
    for (const PassListing& pass : PassList()) out.push_back(pass.name);
    return out;
  }();
  return names;
}

std::optional<std::string> ApplyWarningFlag(DiagnosticPolicy& policy, std::string_view flag,
                                            std::string_view where) {
  if (flag.empty()) return fmt::format("{} needs a value", where);
  if (flag == "error") {
    policy.warnings_as_errors = true;
    return std::nullopt;
  }
  std::string_view group = flag;
  std::unordered_set<std::string>* set = nullptr;  // none: -WGROUP, enabled as by default
  if (flag.starts_with("error=")) {
    group = flag.substr(6);
    set = &policy.error_groups;
  } else if (flag.starts_with("no-")) {
    group = flag.substr(3);
    set = &policy.disabled_groups;
  }
  if (!Contains(WarningGroupNames(), group)) {
    // a misspelt group would otherwise silence or promote nothing, silently
    return fmt::format("unknown warning group '{}' in {}{}", group, where,
                       Suggestion(group, WarningGroupNames(),
                                  "; mdlc --list-warnings lists the groups"));
  }
  if (set) set->insert(std::string(group));
  return std::nullopt;
}

std::optional<std::string> CheckPassName(std::string_view name, std::string_view where) {
  if (Contains(PassNames(), name)) return std::nullopt;
  return fmt::format("unknown pass '{}' in {}{}", name, where,
                     Suggestion(name, PassNames(), "; mdlc --list-passes lists the passes"));
}

std::optional<std::string> ApplyLimitSetting(Limits& limits, std::string_view setting,
                                             std::string_view where) {
  const std::string_view name = setting.substr(0, setting.find('='));
  std::vector<std::string_view> known;
  for (const LimitInfo& l : AllLimits()) known.push_back(l.name);
  if (setting.find('=') != std::string_view::npos && !Contains(known, name)) {
    return fmt::format("unknown limit '{}' in {}{}", name, where,
                       Suggestion(name, known, "; the limits are " + Listed(known)));
  }
  if (auto problem = SetLimit(limits, setting)) return fmt::format("{}: {}", where, *problem);
  return std::nullopt;
}

std::optional<std::string> ParseMeshReader(std::string_view text, std::string_view where,
                                           MeshReader& reader) {
  if (auto problem = CheckChoice(text, where, {"process", "in-process"})) return problem;
  reader = text == "in-process" ? MeshReader::InProcess : MeshReader::Process;
  return std::nullopt;
}

std::optional<std::string> ParseColladaUpAxis(std::string_view text, std::string_view where,
                                              ColladaUpAxis& axis) {
  if (auto problem = CheckChoice(text, where, {"as-written", "apply"})) return problem;
  axis = text == "apply" ? ColladaUpAxis::Apply : ColladaUpAxis::AsWritten;
  return std::nullopt;
}

const std::vector<OptionName>& CompileOptionNames() {
  static const std::vector<OptionName> names = {
      {"auto_rename", "--auto-rename"},
      {"cache_dir", "--cache-dir"},
      {"collada_up_axis", "--collada-up-axis"},
      {"disabled_warnings", "-Wno-GROUP"},
      {"error_warnings", "-Werror=GROUP"},
      {"fixed_base", "--fixed-base"},
      {"joint_positions", "--q"},
      {"limits", "--limit"},
      {"max_errors", "--max-errors"},
      {"mesh_reader", "--mesh-reader"},
      {"model_name", "--model-name"},
      {"package_paths", "--package-path"},
      {"packages", "--package"},
      {"strict", "--strict"},
      {"use_ros_package_path", ""},  // the command line always does
      {"warnings", "-W"},
      {"xacro_args", "NAME:=VALUE"},
  };
  return names;
}

std::optional<std::string> CheckOptionKeyword(std::string_view keyword,
                                              std::string_view function) {
  std::vector<std::string_view> known;
  for (const OptionName& o : CompileOptionNames()) known.push_back(o.keyword);
  if (Contains(known, keyword)) return std::nullopt;
  return fmt::format("unknown keyword '{}' for {}{}", keyword, function,
                     Suggestion(keyword, known, "; the keywords are " + Listed(known)));
}

}  // namespace mdlc
