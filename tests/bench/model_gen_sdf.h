// model_gen_sdf.h - synthetic SDFormat models for the frame-graph benchmarks
// (bench_sdf_frames.cc).
//
// Three families, each sized by N and written as SDFormat 1.9:
//
//   frame_chain    one model, one link "base", and N <frame>s: frame f1 is
//                  attached to and posed relative to base, frame fi
//                  (i >= 2) attached to and posed relative to f(i-1), each
//                  with a non-trivial pose. Both the attached_to and the
//                  relative_to graph are chains N deep.
//   nested_models  N models nested one inside the other (the top model and
//                  m1 ... m(N-1), XML depth ~N): each has one link "link"
//                  posed relative to __model__, and is posed by its <pose>
//                  relative to its parent model's frame (the default: a
//                  relative_to naming the parent's link is not allowed across
//                  scopes). Each parent joins its link to the child model's
//                  link with a revolute joint (child "m{i}::link"), so the
//                  models form one kinematic chain. Every model that has three
//                  levels below it holds a frame "probe" posed relative to
//                  "m{i+1}::m{i+2}::m{i+3}::link", and the top model a frame
//                  "deep_probe" posed relative to the innermost link through
//                  the whole scoped name "m1::m2::...::m(N-1)::link".
//   sdf_chain      the chain robot of model_gen.h (GenerateUrdf(Chain, N)),
//                  in SDFormat: the same random draws (same seed string), so
//                  the same masses, inertias, geometries, joint origins, axes
//                  and limits. Joint i is posed relative to its parent link
//                  (the URDF joint origin), link i relative to joint i (the
//                  URDF convention), so the relative_to graph is a chain 2N
//                  deep; link_0 is welded to the world.
//   world          a <world> of N one-link models m1 ... mN (a scene of many
//                  small models, issue 16): each model posed in the world,
//                  its link "link" with random mass properties and a box
//                  collision. Its top element is the world "world_nN".
//
// Output is deterministic: same arguments, same bytes.
#pragma once

#include <string>
#include <string_view>

namespace mdlc::bench {

enum class SdfFamily { FrameChain, NestedModels, SdfChain, World };

/// "frame_chain", "nested_models", "sdf_chain", "world".
std::string_view SdfFamilyName(SdfFamily family);

/// The SDFormat text of the `family` model of size `n` (>= 1), with model
/// name "{family}_n{n}".
std::string GenerateSdf(SdfFamily family, int n);

}  // namespace mdlc::bench
