// inertia_scaled_gains.h - the MJCF gains MuJoCo's compiler derives from the
// joint-space inertia at the reference configuration qpos0
// (ir::InertiaScaledGains; BEYOND-007, BEYOND-008), computed on the plant.
//
// Per model that asks for any, as MuJoCo 3.3.8 computes them (its
// mj_setConst, then the springdamper step of its compiler):
//   - M = the plant's mass matrix restricted to the model's joints, at the
//     model's qpos0 (hinges and slides at `ref`, ball joints at identity;
//     other models' joints at their default positions), plus each joint's
//     armature on its dofs' diagonal;
//   - springdamper: w_k = (M^-1)_kk for each dof k of the joint, except a
//     slide on a "simple" body whose inertia frame is its body frame (COM
//     within 1e-6 of the origin, products of inertia at most 1e-6 of the
//     largest moment), where w_k = 1 / the body's mass; then I = n / sum
//     w_k over the joint's n dofs, damping = 2 I / timeconst on every dof,
//     and a joint spring (hinges, slides) of stiffness
//     I / (timeconst dampratio)^2 about springref, added to the plant's
//     force elements;
//   - dampratio: m = M_kk / gear^2 for the actuator's dof k (0 when gear^2
//     is at most 1e-15), kd = 2 dampratio sqrt(kp m).
// MuJoCo's 1e-15 floor (mjMINVAL) guards every denominator.
#pragma once

#include "backend/plant.h"
#include "ir/diagnostics.h"
#include "ir/module.h"

namespace mdlc::backend {

/// Applies every request of module.inertia_scaled_gains to `plant`, built
/// from `module`: joint damping, joint springs and actuator kd. A model whose
/// M at qpos0 is singular (a Cholesky pivot below 1e-12 of its diagonal
/// entry; MuJoCo would divide by about 0) is an error at its first
/// springdamper (its springdampers are not applied); false after an error.
bool ApplyInertiaScaledGains(const ir::Module& module, Plant& plant, DiagnosticEngine& diags);

}  // namespace mdlc::backend
