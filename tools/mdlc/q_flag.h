// q_flag.h - the --q JOINT=VALUE flag that `mdlc compile` and `mdlc view`
// share: the configuration a command evaluates or shows, one 1-dof joint at
// a time (Options::model.joint_positions).
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "mdlc/mdlc.h"

namespace mdlc::cli {

/// Adds --q (repeatable) to `command`, collecting the assignments as typed.
void AddJointPositionsFlag(CLI::App* command, std::vector<std::string>& assignments);

/// Each JOINT=VALUE into options.model.joint_positions; false, with the malformed
/// one reported on standard error, when one is not JOINT=VALUE.
bool ParseJointPositions(const std::vector<std::string>& assignments, Options& options);

}  // namespace mdlc::cli
