// mjcf_reader_detail.h - what the MJCF frontend's files share (not a public API).
//
// The MJCF frontend reads MuJoCo XML as MuJoCo 3.3's compiler interprets it
// and lowers it into the IR the way Drake's MuJoCo parser lays a model out
// (MJCF-xxx, BEYOND-xxx in features.md). It works in three phases:
//
//   1. Document: the main file and every <include> (expanded lexically, in
//      place, with cycle detection) are parsed; the reader walks the merged
//      element sequence with an explicit stack, never recursing per level.
//   2. Settings and assets: <compiler>, <option>, <size>, <default> classes,
//      <asset> (meshes, materials, textures) from anywhere in the document.
//   3. Lowering: <worldbody> (bodies, joints, geoms, sites, cameras), then the
//      model elements that refer to it: <equality>, <tendon>, <actuator>,
//      <contact>, <keyframe> (mjcf_elements.cc), plus warnings for the
//      elements the plant cannot hold.
//
// Files: mjcf_reader.cc (entry, phases), mjcf_document.cc (includes),
// mjcf_defaults.{h,cc} (classes, attribute lookup, warnings), mjcf_settings.cc
// (compiler, option, other top-level sections), mjcf_orientation.{h,cc}
// (rotation conversions, pure), mjcf_pose.cc (pose attributes of elements),
// mjcf_schema.cc (known attributes per element), mjcf_assets.cc,
// mjcf_replicate.{h,cc} and mjcf_attach.cc (<replicate> and <attach>,
// expanded into a document of their result after <compiler> is read),
// mjcf_body.cc (the worldbody walk, bodies, inertial), mjcf_joint.cc
// (joints and their placement), mjcf_geom.cc (geoms, sites, cameras),
// mjcf_elements*.cc (equality, tendon, actuator, contact, keyframe).
#pragma once

#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include <absl/container/flat_hash_map.h>
#include <absl/container/flat_hash_set.h>

#include "frontend/frontend.h"
#include "frontend/mjcf/mjcf_defaults.h"
#include "frontend/xml/attribute_reader.h"
#include "frontend/xml/xml_document.h"
#include "ir/module.h"

namespace mdlc::frontend::mjcf {

// ---------------------------------------------------------------------------
// Compiler and option settings (MJCF-002..007, BEYOND-006)
// ---------------------------------------------------------------------------

enum class InertiaFromGeom { False, True, Auto };

struct CompilerSettings {
  bool angle_in_degrees = true;  // compiler@angle: degree is MuJoCo's default
  std::string eulerseq = "xyz";  // compiler@eulerseq: 3 of xyzXYZ
  bool autolimits = true;
  InertiaFromGeom inertia_from_geom = InertiaFromGeom::Auto;
  int inertia_group_min = 0, inertia_group_max = 5;  // compiler@inertiagrouprange
  std::string meshdir, texturedir, assetdir;          // as written (relative to the main file)
  bool fitaabb = false;
  bool discard_visual = false;
  bool fusestatic = false;
  bool alignfree = false;  // compiler@alignfree: <freejoint align="auto"> aligns
  ir::MassAdjustments mass_adjustments;  // boundmass, boundinertia, balanceinertia, settotalmass

  /// Radians from a value in the compiler's angle unit.
  double Angle(double v) const;
};

// ---------------------------------------------------------------------------
// The reader's state, shared by every phase
// ---------------------------------------------------------------------------

struct MeshAsset {
  std::string name;
  Loc loc;
  ir::Mesh mesh;  // uri as written, resolved path (meshdir rules, MJCF-006), scale
  ir::MeshInertia inertia = ir::MeshInertia::Legacy;  // mesh@inertia (MuJoCo 3.3: legacy)
  bool used = false;  // a geom names it (resolve-assets checks its file then)
  /// Set: the mesh is left out (made by a plugin, a builtin shape), and why;
  /// the first geom naming it says so (left_out_said), every one is left out.
  std::string left_out;
  bool left_out_said = false;
};

/// The main file and every file its <include>s name (MJCF-001). Documents
/// are never edited: an <include> element stays in its DOM and `Children`
/// splices the included root's children in its place.
struct MjcfDocument {
  std::vector<std::shared_ptr<const xml::XmlDocument>> documents;
  /// <include> node -> root element of the document it names
  std::unordered_map<const void*, xml::XmlElement> includes;

  /// Children of `e` in document order with every <include> expanded in place
  /// (nested includes too; an include that failed to load contributes nothing).
  std::vector<xml::XmlElement> Children(const xml::XmlElement& e) const;
};

/// `path` with symbolic links, "." and ".." resolved (as it is when it
/// does not exist): how include and attach chains recognise a file again.
std::string CanonicalPath(const std::string& path);

/// Loads every include reachable from `root` (explicit stack). Reports
/// missing files, unparsable files, cycles and repeated includes at the
/// <include>; returns false after an error.
bool LoadIncludes(const xml::XmlElement& root, const std::string& main_dir, FrontendContext& ctx,
                  MjcfDocument& document);

/// Why the plant leaves out flex objects, plugins and skins (MjcfReader::LeaveOut).
inline constexpr std::string_view kFlexLeftOut =
    "the plant holds rigid bodies, and a flex is a deformable object of vertices that MuJoCo "
    "simulates itself";
inline constexpr std::string_view kPluginLeftOut =
    "a plugin is compiled code that MuJoCo loads and runs, which the plant cannot hold";
inline constexpr std::string_view kSkinLeftOut =
    "a skin is a surface MuJoCo draws over bodies for rendering, which the plant does not hold";

struct MjcfReader {
  MjcfReader(FrontendContext& context, std::string main_directory)
      : ctx(context), attrs(context.diags), main_dir(std::move(main_directory)) {}

  FrontendContext& ctx;
  xml::AttributeReader attrs;
  ModelId model;
  std::string main_dir;  // directory of the main file: includes and assets resolve from here
  MjcfDocument document;
  std::string model_name;  // the instance's name (camera names use it)

  CompilerSettings compiler;
  DefaultClasses defaults;
  std::unordered_map<std::string, MeshAsset> meshes;
  std::unordered_map<std::string, MaterialId> materials;

  // Entities by their MJCF name, as elements refer to them. "world" is the
  // world body. Unnamed entities are not here. Flat tables (one is filled
  // per body, joint, geom and site) keyed by the name's symbol: a named
  // entity's IR name is its MJCF name, interned as the entity was made (a
  // free joint, named after its body, interns its own), so the key costs
  // nothing more, where a string key was copied, hashed and compared per
  // entity. Never iterated, so their order, which varies from run to run,
  // shows nowhere.
  template <typename Id>
  class ByName {
   public:
    /// Adds name -> id unless the name is there; returns the id the name
    /// has and whether it was added.
    std::pair<Id, bool> Insert(Symbol name, Id id) {
      auto [it, inserted] = ids_.emplace(name.value, id);
      return {it->second, inserted};
    }
    /// The entity named `text`; nullopt when none is.
    std::optional<Id> Find(const SymbolTable& symbols, std::string_view text) const {
      const Symbol name = symbols.Find(text);
      if (name.empty() && !text.empty()) return std::nullopt;  // never interned
      auto it = ids_.find(name.value);
      if (it == ids_.end()) return std::nullopt;
      return it->second;
    }

   private:
    absl::flat_hash_map<uint32_t, Id> ids_;
  };
  ByName<BodyId> bodies;
  ByName<JointId> joints;
  ByName<GeometryId> geoms;  // the proximity registration when there is one
  ByName<FrameId> sites;
  /// Every body in document order, world first (keyframe and equality
  /// lookups by index), and each body's MJCF joints in document order.
  std::vector<BodyId> body_order;
  /// Per MJCF joint that sets one: its armature, so an actuator can turn it
  /// into rotor inertia (MJCF-024), and whether one did; an armature no
  /// actuator takes is dropped with a warning at the end.
  struct JointArmature {
    double value = 0;
    Loc loc;
    bool reflected = false;  // an actuator on the joint took it as rotor inertia
  };
  std::unordered_map<uint32_t, JointArmature> joint_armature;  // by JointId index
  /// Every MJCF joint in document order (the qpos layout of keyframes).
  std::vector<JointId> joint_order;
  /// A key of a model attached with <attach>: MuJoCo's mjs_attach adds the
  /// attached model's keys after this model's own, each joint of the
  /// attached subtree at the key's values and every other joint at qpos0
  /// (mjcf_attach.cc, mjcf_elements_keyframe.cc).
  struct AttachedKey {
    std::string name;
    Loc loc;
    bool has_qpos = false;
    /// (joint name, its qpos slice in MuJoCo's layout)
    std::vector<std::pair<std::string, std::vector<double>>> joints;
  };
  std::vector<AttachedKey> attached_keys;
  /// Joint springdamper and actuator dampratio requests, with every joint's
  /// qpos0 and armature (BEYOND-007, BEYOND-008); added to the module at
  /// the end when the file asks for any.
  ir::InertiaScaledGains scaled_gains;

  /// The default class an element uses: its own `class`, else the nearest
  /// enclosing childclass (passed by the caller), else "main". An unknown
  /// class is an error at the attribute.
  int ClassFor(const xml::XmlElement& e, std::string_view childclass);
  Element Resolve(const xml::XmlElement& e, std::string_view kind, std::string_view childclass) {
    return Element(e, kind, ClassFor(e, childclass), defaults);
  }

  /// One warning per (element kind, attribute) the plant cannot hold, as
  /// Drake's parser gives them; unknown attributes get a distinct warning.
  void WarnUnsupported(const xml::XmlElement& e, std::string_view what);

  DiagnosticEngine& diags() { return ctx.diags; }
  ir::Module& module() { return ctx.module; }

  /// Children of `e` with includes expanded (MjcfDocument::Children).
  std::vector<xml::XmlElement> Children(const xml::XmlElement& e) const {
    return document.Children(e);
  }

  // --- mjcf_defaults.cc ---
  /// One warning per (element kind, name): an attribute or child element
  /// MuJoCo knows that the plant cannot hold (`why` says what happens). For
  /// a name MuJoCo does not know, `known` lists the ones it does, and a note
  /// suggests the closest (<gemo>: did you mean <geom>?).
  void WarnOnce(Loc loc, DiagKind kind, std::string_view element, std::string_view name,
                std::string_view why = "is not supported and is ignored",
                std::initializer_list<std::string_view> known = {});
  /// One warning per construct and file for what the plant cannot hold
  /// (flex, skins, spatial tendons, plugins, sdf geoms; issue 62): "<flex>
  /// is left out of the plant, here and everywhere else in this file: `why`".
  void LeaveOut(Loc loc, std::string_view construct, std::string_view why);
  /// Warns about attributes of `e` outside MuJoCo's schema for it (a
  /// misspelling, most likely; MuJoCo itself rejects them).
  void CheckAttributes(const xml::XmlElement& e, std::string_view schema_kind);
  /// CheckAttributes for a top-level <default>, its nested classes and the
  /// element defaults in them (<default><joint dampnig="5"/>).
  void CheckDefaultAttributes(const xml::XmlElement& top);
  // CheckAttributes' verdicts by (schema set, attribute name pointer):
  // libxml2 interns names, so each distinct name is hashed as a string once
  // per kind, not once per element (the reader holds its documents, so no
  // pointer is reused for another name while the table lives)
  absl::flat_hash_map<std::pair<const void*, const void*>, bool> known_attribute_names;
  // "element\nname" already warned about; the key is built in warn_key, whose
  // buffer is reused: WarnOnce runs for every element that repeats a warning
  absl::flat_hash_set<std::string> warned;
  std::string warn_key;

  // --- mjcf_pose.cc ---
  /// pos + orientation of an element (MJCF-010) with MuJoCo's default rule:
  /// the element's own alternative orientation (axisangle, xyaxes, zaxis,
  /// euler) wins, then the nearest class's, then quat (own, then class).
  /// Reports bad values and more than one orientation on the element.
  std::optional<Transform> ReadPose(const Element& e);
  /// A vector attribute of up to `values.size()` numbers that MuJoCo
  /// overwrites element by element (geom@size, geom@friction): `values`
  /// holds the starting numbers, and each layer from the root class to the
  /// element overwrites those it gives. False after an error.
  bool LayeredNumbers(const Element& e, std::string_view name, std::span<double> values);
  /// A number (own or default); `fallback` when absent; nullopt after an error.
  std::optional<double> Number(const Element& e, std::string_view name, double fallback);
  /// Exactly `n` numbers (own or default); nullopt when absent or bad.
  std::optional<std::vector<double>> Numbers(const Element& e, std::string_view name, size_t n);
  /// An integer attribute (own or default): a whole number within int's
  /// range, as MuJoCo reads contype, group or a camera's resolution;
  /// `fallback` when absent; nullopt after an error.
  std::optional<int> Integer(const Element& e, std::string_view name, int fallback);
  /// Exactly `n` integers (own or default); nullopt when absent or bad.
  std::optional<std::vector<int>> Integers(const Element& e, std::string_view name, size_t n);
  /// Exactly `n` numbers into `out`, without a list (poses and vectors of a
  /// known size); false when absent or bad (bad is reported).
  bool FixedNumbers(const Element& e, std::string_view name, double* out, size_t n);
  bool FixedNumbersOf(const Element& e, const Attribute& a, std::string_view name, double* out,
                      size_t n);
  /// Numbers() of an attribute already looked up (`a.present()`).
  std::optional<std::vector<double>> NumbersOf(const Element& e, const Attribute& a,
                                               std::string_view name, size_t n);
  /// MuJoCo's booleans: "true"/"false" only.
  std::optional<bool> Boolean(const Element& e, std::string_view name, bool fallback);

  // --- mjcf_settings.cc ---
  void ReadCompiler(const xml::XmlElement& e);
  void ReadOption(const xml::XmlElement& e);
  void ReadOtherTopLevel(const xml::XmlElement& e);

  // --- mjcf_assets.cc ---
  void ReadAsset(const xml::XmlElement& e);

  // --- mjcf_body.cc ---
  void LowerWorldBody(const xml::XmlElement& worldbody);
  /// Free joints are named after their body once every joint exists (Drake
  /// names floating joints at Finalize, prefixing '_' on a clash).
  std::vector<JointId> free_joints;
  int num_cameras = 0;
};

/// Phase 3b: <equality>, <tendon>, <actuator>, <contact>, <keyframe> under
/// `root` (the merged document's top-level elements, in order).
void LowerModelElements(MjcfReader& reader, const std::vector<xml::XmlElement>& top_level);

}  // namespace mdlc::frontend::mjcf
