// mjcf_capacity.cc - see mjcf_capacity.h.
#include "frontend/mjcf/mjcf_capacity.h"

namespace mdlc::frontend::mjcf {

EntityRoom MjcfEntityRoom(const std::vector<std::shared_ptr<const xml::XmlDocument>>& documents) {
  EntityRoom room;
  for (const auto& doc : documents) {
    const size_t bodies_and_joints =
        doc->CountOf("body") + doc->CountOf("joint") + doc->CountOf("freejoint");
    room.bodies += bodies_and_joints;
    room.joints += bodies_and_joints;
    room.geometries += 2 * doc->CountOf("geom");
    room.frames += doc->CountOf("site");
  }
  return room;
}

}  // namespace mdlc::frontend::mjcf
