// ids.h - strongly typed 32-bit indices into the IR's entity tables.
//
// Id<BodyTag> and Id<JointTag> are different types, so a joint id can never be
// used to index bodies. An id default-constructs to "invalid".
#pragma once

#include <cstdint>
#include <functional>

namespace mdlc {

template <typename Tag>
struct Id {
  uint32_t value = UINT32_MAX;
  constexpr Id() = default;
  constexpr explicit Id(uint32_t v) : value(v) {}
  constexpr explicit Id(size_t v) : value(static_cast<uint32_t>(v)) {}
  constexpr bool valid() const { return value != UINT32_MAX; }
  constexpr size_t index() const { return value; }
  friend constexpr bool operator==(Id, Id) = default;
  friend constexpr auto operator<=>(Id, Id) = default;
};

struct ModelTag;
struct BodyTag;
struct FrameTag;
struct JointTag;
struct GeometryTag;
struct MaterialTag;
struct ActuatorTag;
struct ConstraintTag;
struct ForceElementTag;
struct FilterGroupTag;
struct CameraTag;

using ModelId = Id<ModelTag>;
using BodyId = Id<BodyTag>;
using FrameId = Id<FrameTag>;
using JointId = Id<JointTag>;
using GeometryId = Id<GeometryTag>;
using MaterialId = Id<MaterialTag>;
using ActuatorId = Id<ActuatorTag>;
using ConstraintId = Id<ConstraintTag>;
using ForceElementId = Id<ForceElementTag>;
using FilterGroupId = Id<FilterGroupTag>;
using CameraId = Id<CameraTag>;

}  // namespace mdlc

template <typename Tag>
struct std::hash<mdlc::Id<Tag>> {
  size_t operator()(mdlc::Id<Tag> id) const { return id.value; }
};
