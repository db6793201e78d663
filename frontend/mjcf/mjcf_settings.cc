// mjcf_settings.cc - <compiler>, <option> and the top-level sections the
// plant has no place for (MJCF-002..008, BEYOND-006).
//
// Settings are read before any body: MuJoCo applies compiler@angle (say) to
// every element wherever the <compiler> stands in the file.
#include <fmt/format.h>

#include "frontend/mjcf/mjcf_orientation.h"
#include "frontend/mjcf/mjcf_reader_detail.h"

namespace mdlc::frontend::mjcf {
namespace {
// MJCF-007: option attributes Drake warns about; the solver-only rest are silent
constexpr std::string_view kWarnedOptions[] = {"wind",   "magnetic", "density",
                                               "viscosity", "integrator", "cone",
                                               "actuatorgroupdisable"};
}  // namespace

void MjcfReader::ReadCompiler(const xml::XmlElement& e) {
  CheckAttributes(e, "compiler");
  const Element c(e, "compiler");

  if (auto v = Boolean(c, "autolimits", compiler.autolimits)) compiler.autolimits = *v;
  if (auto a = e.Attribute("angle"); a.present()) {
    if (a.value == "degree" || a.value == "radian") {
      compiler.angle_in_degrees = a.value == "degree";
    } else {
      diags().Report(DiagKind::BadValue, a.loc,
                     fmt::format("compiler angle must be 'degree' or 'radian', not '{}'; it stays "
                                 "'{}'",
                                 a.value, compiler.angle_in_degrees ? "degree" : "radian"))
          ;
    }
  }
  if (auto a = e.Attribute("eulerseq"); a.present()) {
    if (IsValidEulerSequence(a.value)) {
      compiler.eulerseq = std::string(a.value);
    } else {
      diags().Report(DiagKind::BadValue, a.loc,
                     fmt::format("illegal eulerseq '{}': exactly three characters of x, y, z, X, "
                                 "Y, Z",
                                 a.value));
    }
  }
  if (auto a = e.Attribute("coordinate"); a.present() && a.value != "local") {
    diags().Report(DiagKind::BadValue, a.loc,
                   fmt::format("compiler coordinate='{}' is not supported: global coordinates "
                               "were removed in MuJoCo 2.3.3",
                               a.value));
  }
  // assetdir sets meshdir and texturedir; the specific ones win (MJCF-006)
  if (auto a = e.Attribute("assetdir"); a.present()) compiler.assetdir = std::string(a.value);
  if (auto a = e.Attribute("meshdir"); a.present()) compiler.meshdir = std::string(a.value);
  if (auto a = e.Attribute("texturedir"); a.present()) compiler.texturedir = std::string(a.value);
  if (auto a = e.Attribute("inertiafromgeom"); a.present()) {
    if (a.value == "true") compiler.inertia_from_geom = InertiaFromGeom::True;
    else if (a.value == "false") compiler.inertia_from_geom = InertiaFromGeom::False;
    else if (a.value == "auto") compiler.inertia_from_geom = InertiaFromGeom::Auto;
    else {
      diags().Report(DiagKind::BadValue, a.loc,
                     fmt::format("inertiafromgeom must be true, false or auto, not '{}'", a.value));
    }
  }
  if (e.Attribute("inertiagrouprange").present()) {
    if (auto v = Integers(c, "inertiagrouprange", 2)) {
      compiler.inertia_group_min = (*v)[0];
      compiler.inertia_group_max = (*v)[1];
    }
  }
  ir::MassAdjustments& m = compiler.mass_adjustments;
  if (auto v = Number(c, "boundmass", m.bound_mass)) m.bound_mass = *v;
  if (auto v = Number(c, "boundinertia", m.bound_inertia)) m.bound_inertia = *v;
  if (auto v = Boolean(c, "balanceinertia", m.balance_inertia)) m.balance_inertia = *v;
  if (e.Attribute("settotalmass").present()) {
    // MuJoCo: a value <= 0 (its default is -1) disables the rescaling
    if (auto v = Number(c, "settotalmass", -1)) {
      m.total_mass = *v > 0 ? std::optional<double>(*v) : std::nullopt;
    }
  }
  if (auto v = Boolean(c, "fitaabb", compiler.fitaabb)) compiler.fitaabb = *v;
  if (auto v = Boolean(c, "discardvisual", compiler.discard_visual)) compiler.discard_visual = *v;
  if (auto v = Boolean(c, "fusestatic", false); v && *v) {
    compiler.fusestatic = true;
    WarnOnce(e.Attribute("fusestatic").loc, DiagKind::UnsupportedAttribute, "compiler",
             "fusestatic", "is not applied: static bodies are kept as welded bodies");
  }
  if (auto v = Boolean(c, "alignfree", false)) compiler.alignfree = *v;
  for (std::string_view name : {"strippath", "saveinertial"}) {
    if (e.Attribute(name).present()) WarnUnsupported(e, name);
  }
  // usethread: a MuJoCo runtime setting, silently ignored
  for (auto child = e.FirstChild(); child; child = child.NextSibling()) {
    if (child.Name() == "lengthrange") {
      WarnOnce(child.GetLoc(), DiagKind::UnsupportedElement, "compiler", "lengthrange");
    } else {
      WarnOnce(child.GetLoc(), DiagKind::UnknownElement, "compiler", child.Name(),
               "is not a MuJoCo element here and is ignored");
    }
  }
}

void MjcfReader::ReadOption(const xml::XmlElement& e) {
  CheckAttributes(e, "option");
  const Element o(e, "option");
  if (e.Attribute("gravity").present()) {
    if (auto g = Numbers(o, "gravity", 3)) module().gravity = Eigen::Vector3d((*g)[0], (*g)[1], (*g)[2]);
  }
  if (e.Attribute("timestep").present()) {
    if (auto t = Number(o, "timestep", 0)) {
      if (*t < 0) {
        diags().Report(DiagKind::BadValue, e.Attribute("timestep").loc,
                       "option timestep must not be negative");
      } else {
        module().time_step = *t;  // BEYOND-006
      }
    }
  }
  for (std::string_view name : kWarnedOptions) {
    if (e.Attribute(name).present()) WarnUnsupported(e, name);
  }
  for (auto child = e.FirstChild(); child; child = child.NextSibling()) {
    if (child.Name() == "flag") {
      WarnOnce(child.GetLoc(), DiagKind::UnsupportedElement, "option", "flag");
    } else {
      WarnOnce(child.GetLoc(), DiagKind::UnknownElement, "option", child.Name(),
               "is not a MuJoCo element here and is ignored");
    }
  }
}

void MjcfReader::ReadOtherTopLevel(const xml::XmlElement& e) {
  const std::string_view tag = e.Name();
  if (tag == "size") {
    CheckAttributes(e, "size");  // MuJoCo's memory sizes: nothing for the plant (S)
  } else if (tag == "custom") {
    // user data for MuJoCo programs (S)
  } else if (tag == "extension") {
    // plugin declarations and their instances
    for (const xml::XmlElement& c : Children(e)) {
      if (c.Name() == "plugin") LeaveOut(c.GetLoc(), "<plugin> in <extension>", kPluginLeftOut);
    }
  } else if (tag == "deformable") {
    for (const xml::XmlElement& c : Children(e)) {
      if (c.Name() == "flex") {
        LeaveOut(c.GetLoc(), "<flex>", kFlexLeftOut);
      } else if (c.Name() == "skin") {
        LeaveOut(c.GetLoc(), "<skin>", kSkinLeftOut);
      } else {
        WarnOnce(c.GetLoc(), DiagKind::UnknownElement, "deformable", c.Name(),
                 "is not a MuJoCo element here and is ignored");
      }
    }
  } else if (tag == "statistic" || tag == "visual" || tag == "sensor") {
    if (tag == "statistic") CheckAttributes(e, "statistic");
    WarnOnce(e.GetLoc(), DiagKind::UnsupportedElement, "mujoco", tag);
  } else {
    WarnOnce(e.GetLoc(), DiagKind::UnknownElement, "mujoco", tag,
             "is not a MuJoCo element and is ignored (MuJoCo rejects it)");
  }
}

}  // namespace mdlc::frontend::mjcf
