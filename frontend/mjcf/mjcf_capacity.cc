// mjcf_capacity.cc - see mjcf_capacity.h.
#include "frontend/mjcf/mjcf_capacity.h"

#include <algorithm>
#include <vector>

namespace mdlc::frontend::mjcf {
namespace {

// elements whose children are more of the body tree
bool HoldsBodyTree(std::string_view name) {
  return name == "body" || name == "frame" || name == "replicate";
}

}  // namespace

EntityRoom MjcfEntityRoom(const xml::XmlElement& root) {
  EntityRoom room;
  size_t geoms = 0;
  // joints of each open <body>, innermost last; the walk follows parent
  // links, so a chain nested 10,000 deep needs no recursion
  std::vector<size_t> open_bodies;
  auto close_body = [&] {
    const size_t joints = std::max<size_t>(1, open_bodies.back());
    open_bodies.pop_back();
    room.bodies += joints;
    room.joints += joints;
  };
  for (xml::XmlElement top = root.FirstChild(); top; top = top.NextSibling()) {
    if (top.Name() != "worldbody") continue;
    xml::XmlElement e = top.FirstChild();
    while (e) {
      const std::string_view name = e.Name();
      if (name == "body") {
        open_bodies.push_back(0);
      } else if (name == "joint" || name == "freejoint") {
        if (!open_bodies.empty()) ++open_bodies.back();
      } else if (name == "geom") {
        ++geoms;
      } else if (name == "site") {
        ++room.frames;
      }
      if (HoldsBodyTree(name) && e.FirstChild()) {
        e = e.FirstChild();
        continue;
      }
      // e is done: close it and every ancestor it is the last child of
      while (true) {
        if (e.Name() == "body") close_body();
        if (xml::XmlElement next = e.NextSibling()) {
          e = next;
          break;
        }
        e = e.Parent();
        if (e.raw() == top.raw()) {
          e = {};
          break;
        }
      }
    }
  }
  room.geometries = 2 * geoms;
  return room;
}

}  // namespace mdlc::frontend::mjcf
