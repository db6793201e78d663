// named_frames.cc - scoped names first (they are unique), then local ones.
#include "backend/named_frames.h"

#include <string>

namespace mdlc::backend {

namespace {

bool SameFrame(const BodyFixedFrame& a, const BodyFixedFrame& b) {
  return a.body == b.body && a.X_BF.R == b.X_BF.R && a.X_BF.p == b.X_BF.p;
}

/// Adds a candidate; false when it makes the name ambiguous.
bool Offer(FrameLookup& found, const BodyFixedFrame& frame) {
  if (found.status == FrameLookupStatus::Found) return SameFrame(found.frame, frame);
  found = {FrameLookupStatus::Found, frame};
  return true;
}

}  // namespace

FrameLookup FindFrameByName(const Plant& plant, std::string_view name) {
  if (name == "world") return {FrameLookupStatus::Found, {BodyId(size_t{0}), Transform::Identity()}};
  for (int pass = 0; pass < 2; ++pass) {
    const bool scoped = pass == 0;
    // bodies first: a body's name names its own frame, as in Drake, even
    // where a frame of the same name sits on it (an MJCF site named after
    // its body)
    FrameLookup found;
    for (size_t b = 0; b < plant.bodies.size(); ++b) {
      const PlantBody& body = plant.bodies[b];
      if (body.is_world) continue;
      const bool match = scoped ? name.ends_with(body.name) && plant.ScopedName(body) == name
                                : body.name == name;
      if (match && !Offer(found, {BodyId(b), Transform::Identity()})) return {FrameLookupStatus::Ambiguous, {}};
    }
    if (found.status == FrameLookupStatus::Found) return found;
    for (const PlantFrame& frame : plant.frames) {
      const bool match = scoped ? name.ends_with(frame.name) &&
                                      plant.model_instances.Scoped(frame.model, frame.name) == name
                                : frame.name == name;
      if (match && !Offer(found, {frame.body, frame.X_BF})) return {FrameLookupStatus::Ambiguous, {}};
    }
    if (found.status == FrameLookupStatus::Found) return found;
  }
  return {};
}

}  // namespace mdlc::backend
