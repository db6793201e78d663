// reference_rejects.h - the corpus files a reference tool (urdfdom,
// libsdformat 12, MuJoCo 3.3.8) rejects, one table per format, each entry
// recording what mdlc does with the file and why. reference_rejects_test.cc
// runs them all with one test; the tables live in reference_rejects_urdf.cc,
// reference_rejects_sdf.cc and reference_rejects_mjcf.cc.
#pragma once

#include <span>

namespace mdlc::corpus {

struct Expectation {
  const char* path;     // relative to corpus/
  bool accepted;        // does mdlc compile it?
  const char* keyword;  // rejected: a word the error must contain
  const char* why;
  // rejected: the error carries file:line:col and the file is named with a
  // line and column (as the error's location, or in the "in file included
  // from" chain). Only errors about the file itself (its name), raised before
  // it is read, have no line.
  bool located = true;
};

/// An MJCF entry also records MuJoCo 2.2.2's verdict, which the manifest's
/// loads_in_reference column holds for MJCF.
struct MjcfExpectation {
  const char* path;     // relative to corpus/
  bool mujoco222;       // does MuJoCo 2.2.2 load it? (manifest loads_in_reference)
  bool accepted;        // does mdlc compile it?
  const char* keyword;  // rejected: a word the located error must contain
  const char* why;
};

std::span<const Expectation> UrdfReferenceRejects();
std::span<const Expectation> SdfReferenceRejects();
std::span<const MjcfExpectation> MjcfReferenceRejects();

}  // namespace mdlc::corpus
