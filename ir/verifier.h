// verifier.h - structural invariants of the IR, checked between passes.
//
// A failure is a bug in mdlc (a frontend or pass broke an invariant), not in
// the user's file; it is reported as an internal error naming the entity.
// What must hold depends on how far the pipeline has come.
#pragma once

#include "ir/diagnostics.h"
#include "ir/module.h"

namespace mdlc::ir {

enum class VerifyLevel {
  Raw,       // after frontends: ids in range, names present
  Resolved,  // + every reference resolved to an id
  Tree,      // + every non-world body has exactly one inboard joint
  Named,     // + names unique where Drake needs them: bodies, frames, joints,
             //   actuators and cameras in their model instance, geometries
             //   in their body and role
};

/// Returns true when every invariant of `level` holds.
bool VerifyModule(const Module& module, VerifyLevel level, DiagnosticEngine& diags);

}  // namespace mdlc::ir
