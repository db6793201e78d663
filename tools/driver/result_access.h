// result_access.h - what the driver's free functions of a Result (the public
// kinematics.h, convert.h, meshes.h, ir.h) read of the compile behind it.
// Internal: Result keeps its Compilation private to everyone else.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "mdlc/mdlc.h"
#include "tools/driver/compiler.h"

namespace mdlc {

class ResultAccess {
 public:
  static const Compilation& compilation(const Result& result) { return *result.compilation_; }
  /// Options::model.joint_positions, which DefaultPositions applies.
  static const std::vector<std::pair<std::string, double>>& joint_positions(
      const Result& result) {
    return result.joint_positions_;
  }
};

}  // namespace mdlc
