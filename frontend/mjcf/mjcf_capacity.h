// mjcf_capacity.h - how many entities an MJCF document's body tree adds, so
// the IR's tables are sized once before it is lowered. Private to frontend/mjcf.
#pragma once

#include "frontend/entity_capacity.h"
#include "frontend/xml/xml_document.h"

namespace mdlc::frontend::mjcf {

/// Counts the <worldbody>s' bodies, joints, geoms and sites under `root`:
/// element counts alone cannot say how many bodies and joints, since a body
/// with no joint still adds a joint (a weld). A body adds
/// one IR body and one joint per joint it has (a weld when it has none; each
/// joint past its first adds a massless body), a geom up to two geometries
/// (illustration and proximity) and a site a frame. A <replicate>'s copies
/// are counted once: the tables still grow by doubling past the room.
EntityRoom MjcfEntityRoom(const xml::XmlElement& root);

}  // namespace mdlc::frontend::mjcf
