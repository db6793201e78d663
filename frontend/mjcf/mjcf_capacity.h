// mjcf_capacity.h - how many entities an MJCF model's body tree adds, so
// the IR's tables are sized once before it is lowered. Private to frontend/mjcf.
#pragma once

#include <memory>
#include <vector>

#include "frontend/entity_capacity.h"
#include "frontend/xml/xml_document.h"

namespace mdlc::frontend::mjcf {

/// Room for what the model's files (the main file and its includes) can add,
/// from their element counts alone, without a walk over the tree: at
/// 10,000 bodies such a walk found the tree out of the cache and cost as
/// much per body as lowering the body's joints. A body adds one IR body and
/// one joint per joint it has, or a weld when it has none, so both tables
/// get a slot per <body> and per joint, which is never too few. A geom adds
/// up to two geometries (illustration and proximity), a site a frame. Joints
/// and geoms of <default> classes are counted too, which only adds room. A
/// model with <replicate> or <attach> has the document they expand to among
/// its documents (mjcf_replicate.h), so every copy is counted; past the
/// room the tables grow by doubling.
EntityRoom MjcfEntityRoom(const std::vector<std::shared_ptr<const xml::XmlDocument>>& documents);

}  // namespace mdlc::frontend::mjcf
