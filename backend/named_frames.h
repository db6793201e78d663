// named_frames.h - finding a body or a frame by the name plant-json gives it.
//
// A name is "world", a body's or a frame's scoped name ("instance::name"),
// or a local name that exactly one body or frame carries. A body's name
// names the body's own frame even when a frame of the same name exists (an
// MJCF site named after its body); frames with one name that are the same
// frame count once.
#pragma once

#include <string_view>

#include "backend/dynamics.h"
#include "backend/plant.h"

namespace mdlc::backend {

enum class FrameLookupStatus { Found, NotFound, Ambiguous };
struct FrameLookup {
  FrameLookupStatus status = FrameLookupStatus::NotFound;
  BodyFixedFrame frame;  // valid when Found
};

FrameLookup FindFrameByName(const Plant& plant, std::string_view name);

}  // namespace mdlc::backend
