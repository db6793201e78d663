// mjcf_schema.cc - the attributes MuJoCo 3.3's schema allows on the
// elements this frontend reads. MuJoCo rejects any other attribute; mdlc
// warns (UnknownAttribute: most likely a misspelling) and goes on.
#include <fmt/format.h>

#include <initializer_list>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <absl/container/flat_hash_map.h>
#include <absl/container/flat_hash_set.h>

#include "frontend/mjcf/mjcf_reader_detail.h"
#include "ir/scoped_name.h"

namespace mdlc::frontend::mjcf {
namespace {

using List = std::vector<std::string_view>;

// The schema as written: read once, into KnownAttributes' sets.
std::unordered_map<std::string_view, List> SchemaLists() {
  return {
      {"mujoco", {"model"}},
      {"compiler",
       {"autolimits", "boundmass", "boundinertia", "settotalmass", "balanceinertia", "strippath",
        "coordinate", "angle", "fitaabb", "eulerseq", "meshdir", "texturedir", "discardvisual",
        "usethread", "fusestatic", "inertiafromgeom", "inertiagrouprange", "saveinertial",
        "assetdir", "alignfree"}},
      {"option",
       {"timestep", "impratio", "tolerance", "ls_tolerance", "noslip_tolerance", "ccd_tolerance",
        "gravity", "wind", "magnetic", "density", "viscosity", "o_margin", "o_solref",
        "o_solimp", "o_friction", "integrator", "cone", "jacobian", "solver", "iterations",
        "ls_iterations", "noslip_iterations", "ccd_iterations", "sdf_iterations",
        "sdf_initpoints", "actuatorgroupdisable", "apirate", "collision", "mpr_iterations",
        "mpr_tolerance"}},
      {"size",
       {"memory", "njmax", "nconmax", "nstack", "nuserdata", "nkey", "nuser_body", "nuser_jnt",
        "nuser_geom", "nuser_site", "nuser_cam", "nuser_tendon", "nuser_actuator",
        "nuser_sensor"}},
      {"statistic", {"meaninertia", "meanmass", "meansize", "extent", "center"}},
      {"default", {"class"}},
      {"body",
       {"name", "childclass", "pos", "quat", "mocap", "axisangle", "xyaxes", "zaxis", "euler",
        "gravcomp", "user"}},
      {"frame", {"name", "childclass", "pos", "quat", "axisangle", "xyaxes", "zaxis", "euler"}},
      {"attach", {"model", "body", "prefix"}},
      {"model", {"name", "file", "content_type"}},
      {"inertial",
       {"pos", "quat", "mass", "diaginertia", "axisangle", "xyaxes", "zaxis", "euler",
        "fullinertia"}},
      {"joint",
       {"name", "class", "type", "group", "pos", "axis", "springdamper", "limited",
        "actuatorfrclimited", "solreflimit", "solimplimit", "solreffriction", "solimpfriction",
        "stiffness", "range", "actuatorfrcrange", "actuatorgravcomp", "margin", "ref",
        "springref", "armature", "damping", "frictionloss", "user"}},
      {"freejoint", {"name", "group", "align"}},
      {"geom",
       {"name", "class", "type", "contype", "conaffinity", "condim", "group", "priority", "size",
        "material", "friction", "mass", "density", "shellinertia", "solmix", "solref", "solimp",
        "margin", "gap", "fromto", "pos", "quat", "axisangle", "xyaxes", "zaxis", "euler",
        "hfield", "mesh", "fitscale", "rgba", "fluidshape", "fluidcoef", "user"}},
      {"site",
       {"name", "class", "type", "group", "pos", "quat", "material", "size", "fromto",
        "axisangle", "xyaxes", "zaxis", "euler", "rgba", "user"}},
      {"camera",
       {"name", "class", "orthographic", "fovy", "ipd", "resolution", "pos", "quat",
        "axisangle", "xyaxes", "zaxis", "euler", "mode", "target", "focal", "focalpixel",
        "principal", "principalpixel", "sensorsize", "user"}},
      {"mesh",
       {"name", "class", "content_type", "file", "vertex", "normal", "texcoord", "face",
        "refpos", "refquat", "scale", "smoothnormal", "maxhullvert", "inertia", "builtin",
        "params", "material"}},
      {"material",
       {"name", "class", "texture", "texrepeat", "texuniform", "emission", "specular",
        "shininess", "reflectance", "metallic", "roughness", "rgba"}},
  };
}

// The schema as hash sets, built once: every element checks each of its
// attributes, and a geom's list alone is dozens of names long.
using KnownSet = absl::flat_hash_set<std::string_view>;
const absl::flat_hash_map<std::string_view, KnownSet>& KnownAttributes() {
  static const auto known = [] {
    absl::flat_hash_map<std::string_view, KnownSet> sets;
    for (const auto& [kind, names] : SchemaLists()) sets[kind] = KnownSet(names.begin(), names.end());
    return sets;
  }();
  return known;
}

// The names of an element's attributes in the schema's order, for a
// suggestion that does not depend on a hash set's order.
const List& OrderedAttributes(std::string_view schema_kind) {
  static const auto lists = SchemaLists();
  return lists.at(schema_kind);
}

}  // namespace

void MjcfReader::CheckAttributes(const xml::XmlElement& e, std::string_view schema_kind) {
  const auto& schema = KnownAttributes();
  auto it = schema.find(schema_kind);
  if (it == schema.end()) return;
  const KnownSet& known = it->second;
  // attribute locations: look each name up again (names are few)
  std::vector<std::string_view> unknown;
  e.ForEachAttributeName([&](std::string_view name) {
    auto [verdict, first_time] = known_attribute_names.try_emplace({&known, name.data()});
    if (first_time) {
      // names in other tools' namespaces are theirs to check
      verdict->second = name.find(':') != std::string_view::npos || known.contains(name);
    }
    if (!verdict->second) unknown.push_back(name);
  });
  for (std::string_view name : unknown) {
    const Loc loc = e.Attribute(name).loc;
    auto diag = diags().Report(DiagKind::UnknownAttribute, loc,
                               fmt::format("'{}' is not an attribute of <{}> in MuJoCo's schema "
                                           "and is ignored (MuJoCo rejects it)",
                                           name, e.Name()));
    if (auto best = ir::ClosestName(name, OrderedAttributes(schema_kind))) {
      diag.Note(loc, fmt::format("did you mean '{}'?", *best));
    }
  }
}

}  // namespace mdlc::frontend::mjcf
