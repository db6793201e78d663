// dart_model_loader.h - reads a URDF or SDFormat file into DART 6.12
// skeletons for the dynamics oracle (dart_dynamics_oracle_test.cc).
//
// DART is given the file with its <visual> and <collision> elements removed:
// dynamics needs no geometry, and DART's shape classes abort on degenerate
// shapes (a zero sphere radius) that a compiler must accept. DART's
// SdfParser reads SDFormat 1.4-1.6 only; a newer file that uses none of
// what changed since (pose relative_to, frames, expressed_in, nested models,
// includes, degrees) means the same as 1.6 and is read as 1.6. Two gaps of
// the SdfParser are filled as libsdformat would: a 1.4 axis is marked as in
// the model frame (use_parent_model_frame), and a static model's free links
// are welded where they are. A file DART cannot read gets a reason instead
// of skeletons.
#pragma once

#include <dart/dynamics/Skeleton.hpp>
#include <dart/simulation/World.hpp>
#include <string>
#include <vector>

namespace mdlc::oracle {

struct DartModel {
  std::vector<dart::dynamics::SkeletonPtr> skeletons;
  dart::simulation::WorldPtr world;  // owns the skeletons of an SDFormat world
  std::string skip_reason;           // set when DART cannot read the file
  std::string note;                  // how the text was adapted for DART
  std::string log;                   // what DART printed while reading
};

/// Loads `path` (.urdf with DartLoader; .sdf/.world with SdfParser). URDF
/// links without <inertial> get mass 0 (the URDF spec's, and mdlc's, value)
/// instead of DART's default of 1.
DartModel LoadDartModel(const std::string& path);

/// Why reading `path` kills DART's process ("" when it does not): DART 6.12
/// asserts or dereferences a null element on some inputs (an <axis> without
/// <xyz>, ...). Tried in a child process; call it while the process has no
/// other threads.
std::string DartCrashesOn(const std::string& path);

/// `text` without the elements named `name` (<name ...>...</name> or
/// <name .../>); exposed for its self-test.
std::string StripElements(const std::string& text, const std::string& name);

}  // namespace mdlc::oracle
