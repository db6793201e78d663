// q_flag.cc - the shared --q JOINT=VALUE flag (q_flag.h).
#include "q_flag.h"

#include <fmt/format.h>

#include <cstdlib>

namespace mdlc::cli {

void AddJointPositionsFlag(CLI::App* command, std::vector<std::string>& assignments) {
  command->add_option("--q", assignments, "Set a 1-dof joint's position: JOINT=VALUE (repeatable)")
      ->allow_extra_args(false);
}

bool ParseJointPositions(const std::vector<std::string>& assignments, Options& options) {
  for (const std::string& assignment : assignments) {
    const size_t eq = assignment.rfind('=');
    char* end = nullptr;
    const double value =
        eq == std::string::npos ? 0 : std::strtod(assignment.c_str() + eq + 1, &end);
    if (eq == std::string::npos || end == assignment.c_str() + eq + 1 || *end != '\0') {
      fmt::print(stderr, "mdlc: error: --q expects JOINT=VALUE, got '{}'\n", assignment);
      return false;
    }
    options.model.joint_positions.emplace_back(assignment.substr(0, eq), value);
  }
  return true;
}

}  // namespace mdlc::cli
