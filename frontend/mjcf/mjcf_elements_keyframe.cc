// mjcf_elements_keyframe.cc - <keyframe> (MJCF-008).
//
// The rule (the keyframe item of the issue, "keyframe (default positions)"):
// the key named "home" if there is one, else the first <key>, sets the
// model's default configuration. Its qpos is read in MuJoCo's layout over the
// joints in document order (MjcfReader::joint_order) and each slice becomes
// that joint's Joint::default_positions, so the plant's default
// configuration is MuJoCo's state after mj_resetDataKeyframe with that key:
//   hinge, slide  1 value: the joint coordinate itself. The frontend places
//                 the body so that q = ref reproduces the XML pose (X_CM
//                 holds the ref, mjcf_joint.cc), which makes mdlc's
//                 coordinate MuJoCo's qpos; the value is copied as is (in
//                 radians: MuJoCo never converts key values by <compiler
//                 angle>);
//   ball          4 values w x y z: the rotation of the joint's child frame
//                 in its parent frame, which mdlc's ball joint (Drake's
//                 BallRpyJoint, nq = 3) holds as roll-pitch-yaw;
//   free          7 values x y z, w x y z: the body's world pose, which the
//                 quaternion_floating joint holds as [w x y z x y z] (the
//                 body's default_pose follows).
// Quaternions are normalized as MuJoCo's kinematics normalizes them (a zero
// quaternion is the identity). A chosen key without qpos leaves qpos0 (MuJoCo
// fills a key's missing qpos with qpos0), and so do all other keys; qvel,
// act, ctrl, mpos, mquat and time have no place in the plant. Applying the
// key is not reported: the diagnostic engine has no note-level kind for a
// standalone message, and a warning would be noise for every Menagerie model.
// --q still sets joint positions on top of the key.
//
// Constraints that MuJoCo completes at qpos0 (connect, weld, joint coupling)
// are lowered before keyframes, and the qpos0 body poses are computed before
// the key changes any default position, so they still see qpos0.
//
// Every key is checked as MuJoCo 3.3.8's compiler checks it, with the error
// at the attribute: qpos has at most nq values in MuJoCo's layout (free 7,
// ball 4, hinge and slide 1), qvel at most nv (free 6, ball 3, hinge and
// slide 1), ctrl at most one per actuator element. A shorter key is padded
// as MuJoCo 3.3.8 pads it before compiling (mjCModel::ExpandKeyframe, issue
// 62), from the joints as the file writes them, not from the compiled qpos0:
// a hinge or slide gets its ref as written (a hinge's in the file's angle
// unit, unconverted: ref="-30" under angle="degree" pads -30), a ball 1 0 0
// 0 and a free joint 0 0 0, 1 0 0 0 (not its body's pose), as the MuJoCo
// 3.3.8 oracle shows (tests/models/mjcf/oracle/keyframe_short*.xml); qvel,
// act and ctrl are padded with 0 and mocap poses with the bodies' own, none
// of which the plant holds. A longer key is an error, and a chosen key with
// too long a qpos is not applied.
//
// A model attached with <attach> brings its keys (MuJoCo's mjs_attach; the
// attach reads them, mjcf_attach.cc): they follow this model's own keys in
// attach order, a key K named prefix + K (an unnamed one the prefix), its
// values on the attached joints and every other joint at the compiled
// qpos0, not the padding above (MuJoCo's ResolveKeyframes: a hinge's ref in
// radians, a free joint's body pose, a ball the identity), as the oracle
// shows (tests/models/mjcf/oracle/attach_keyframe.xml). A name another key
// has is MuJoCo's repeated-name error.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <absl/container/flat_hash_map.h>
#include <absl/container/flat_hash_set.h>

#include "frontend/mjcf/mjcf_elements.h"

namespace mdlc::frontend::mjcf {

namespace {

// MuJoCo's qpos and qvel widths of a plant joint that an MJCF joint became
size_t QposWidth(ir::JointType t) {
  switch (t) {
    case ir::JointType::QuaternionFloating: return 7;
    case ir::JointType::Ball: return 4;
    case ir::JointType::Weld: return 0;
    default: return 1;
  }
}
size_t QvelWidth(ir::JointType t) {
  switch (t) {
    case ir::JointType::QuaternionFloating: return 6;
    case ir::JointType::Ball: return 3;
    case ir::JointType::Weld: return 0;
    default: return 1;
  }
}

// A MuJoCo quaternion [w x y z], normalized as mj_kinematics does (identity
// when it is too small to normalize)
Eigen::Quaterniond KeyQuaternion(const double* wxyz) {
  Eigen::Quaterniond q(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
  if (q.norm() < 1e-15) return Eigen::Quaterniond::Identity();
  return q.normalized();
}

class Keyframes {
 public:
  explicit Keyframes(ElementsLowering& L) : L_(L) {
    for (JointId j : L_.r.joint_order) {
      nq_ += QposWidth(L_.module()[j].type);
      nv_ += QvelWidth(L_.module()[j].type);
    }
  }

  /// Checks one key; its qpos when it has one of the right size.
  std::optional<std::vector<double>> Check(const xml::XmlElement& key) {
    L_.r.attrs.WarnUnknownAttributes(
        key, {"name", "time", "qpos", "qvel", "act", "mpos", "mquat", "ctrl"});
    std::optional<std::vector<double>> qpos = CheckSize(key, "qpos", nq_);
    CheckSize(key, "qvel", nv_);
    CheckSize(key, "ctrl", L_.actuator_elements);
    for (const char* attr : {"act", "mpos", "mquat"}) L_.AnyDoubles(key.Attribute(attr));
    L_.Double(key.Attribute("time"));
    return qpos;
  }

  /// An attached key's qpos in MuJoCo's layout: its joints at its values,
  /// every other joint at the compiled qpos0 (MuJoCo's ResolveKeyframes
  /// fills them from mjModel's qpos0: a hinge's ref in radians, a free
  /// joint's body pose), read before any key is applied.
  std::vector<double> Attached(const MjcfReader::AttachedKey& key) {
    const ir::Module& m = L_.module();
    absl::flat_hash_map<uint32_t, const std::vector<double>*> values;
    for (const auto& [name, q] : key.joints) {
      if (std::optional<JointId> id = L_.r.joints.Find(m.symbols, name)) {
        values[id->index()] = &q;
      }
    }
    std::vector<double> qpos;
    qpos.reserve(nq_);
    for (JointId id : L_.r.joint_order) {
      const ir::Joint& j = m[id];
      const size_t w = QposWidth(j.type);
      auto it = values.find(id.index());
      if (it != values.end() && it->second->size() == w) {
        qpos.insert(qpos.end(), it->second->begin(), it->second->end());
        continue;
      }
      const auto& p = j.default_positions;
      switch (j.type) {
        case ir::JointType::QuaternionFloating:
          if (p.size() == 7) {
            qpos.insert(qpos.end(), {p[4], p[5], p[6], p[0], p[1], p[2], p[3]});
          } else {
            qpos.insert(qpos.end(), {0, 0, 0, 1, 0, 0, 0});
          }
          break;
        case ir::JointType::Ball: qpos.insert(qpos.end(), {1, 0, 0, 0}); break;
        case ir::JointType::Weld: break;
        default: qpos.push_back(p.empty() ? 0.0 : p[0]); break;  // hinge, slide
      }
    }
    return qpos;
  }

  /// The key's qpos (at most nq values, padded as MuJoCo pads it) becomes
  /// every joint's default positions.
  void Apply(const std::vector<double>& key) {
    ir::Module& m = L_.module();
    const std::vector<double> qpos = Padded(key);
    size_t at = 0;
    for (JointId id : L_.r.joint_order) {
      ir::Joint& j = m[id];
      const double* q = qpos.data() + at;
      at += QposWidth(j.type);
      switch (j.type) {
        case ir::JointType::QuaternionFloating: {
          const Eigen::Quaterniond quat = KeyQuaternion(q + 3);
          j.default_positions = {quat.w(), quat.x(), quat.y(), quat.z(), q[0], q[1], q[2]};
          if (std::optional<BodyId> body = L_.BodyOf(j.child)) {
            m[*body].default_pose = Transform{quat.toRotationMatrix(), Eigen::Vector3d(q[0], q[1], q[2])};
            // an aligned body's qpos places its aligned frame
            m[*body].aligned_default_pose = m[*body].align_free;
          }
          break;
        }
        case ir::JointType::Ball: {
          const Eigen::Vector3d rpy = RpyFromRotation(KeyQuaternion(q).toRotationMatrix());
          j.default_positions = {rpy.x(), rpy.y(), rpy.z()};
          break;
        }
        case ir::JointType::Weld: break;
        default: j.default_positions = {q[0]}; break;  // hinge, slide
      }
    }
  }

 private:
  /// `key` followed by MuJoCo 3.3.8's padding in its layout: free 0 0 0,
  /// 1 0 0 0, ball 1 0 0 0, hinge and slide the ref as written (the frontend
  /// holds a hinge's in radians: back to degrees under angle="degree").
  std::vector<double> Padded(const std::vector<double>& key) const {
    std::vector<double> pad;
    pad.reserve(nq_);
    const double to_file_unit = L_.r.compiler.angle_in_degrees ? 180 / M_PI : 1.0;
    for (JointId id : L_.r.joint_order) {
      const ir::Joint& j = L_.module()[id];
      const double ref = j.default_positions.empty() ? 0.0 : j.default_positions[0];
      switch (j.type) {
        case ir::JointType::QuaternionFloating: pad.insert(pad.end(), {0, 0, 0, 1, 0, 0, 0}); break;
        case ir::JointType::Ball: pad.insert(pad.end(), {1, 0, 0, 0}); break;
        case ir::JointType::Weld: break;
        case ir::JointType::Revolute: pad.push_back(ref * to_file_unit); break;
        default: pad.push_back(ref); break;  // slide
      }
    }
    std::copy(key.begin(), key.end(), pad.begin());
    return pad;
  }

  std::optional<std::vector<double>> CheckSize(const xml::XmlElement& key, const char* attr,
                                               size_t expected) {
    const Attribute a = key.Attribute(attr);
    std::optional<std::vector<double>> v = L_.AnyDoubles(a);
    if (!v || v->size() <= expected) return v;  // a shorter one is padded
    const Attribute name = key.Attribute("name");
    L_.diags().Report(DiagKind::BadValue, a.loc,
                      fmt::format("keyframe '{}': invalid {} size, expected {}, got {}",
                                  name.present() ? name.value : "", attr, expected, v->size()));
    return std::nullopt;
  }

  ElementsLowering& L_;
  size_t nq_ = 0, nv_ = 0;
};

}  // namespace

void LowerKeyframes(ElementsLowering& L, const std::vector<xml::XmlElement>& sections) {
  Keyframes keys(L);
  // checked: whether a key was seen; qpos: its qpos when present and valid
  bool have_first = false, have_home = false;
  std::optional<std::vector<double>> first, home;
  for (const xml::XmlElement& section : sections) {
    for (const xml::XmlElement& key : L.r.Children(section)) {
      if (key.Name() != "key") {
        L.WarnOnce(fmt::format("keyframe-unknown/{}", key.Name()), DiagKind::UnknownElement,
                   key.GetLoc(),
                   fmt::format("unknown element <{}> in <keyframe> is ignored", key.Name()));
        continue;
      }
      std::optional<std::vector<double>> qpos = keys.Check(key);
      if (!have_first) {
        have_first = true;
        first = qpos;
      }
      if (!have_home && key.Attribute("name").value == "home") {
        have_home = true;
        home = std::move(qpos);
      }
    }
  }
  // the keys of attached models follow this model's own (mjs_attach); a
  // name they share with another key is MuJoCo's "repeated name" error
  absl::flat_hash_set<std::string> names;
  for (const xml::XmlElement& section : sections) {
    for (const xml::XmlElement& key : L.r.Children(section)) {
      if (key.Name() == "key" && !key.Attribute("name").value.empty()) {
        names.insert(std::string(key.Attribute("name").value));
      }
    }
  }
  for (const MjcfReader::AttachedKey& key : L.r.attached_keys) {
    if (!key.name.empty() && !names.insert(key.name).second) {
      L.diags().Report(DiagKind::DuplicateName, key.loc,
                       fmt::format("repeated name '{}' in key: an attached model's key takes "
                                   "the attach prefix and its own name, which another key has",
                                   key.name));
      continue;
    }
    std::optional<std::vector<double>> qpos;
    if (key.has_qpos) qpos = keys.Attached(key);
    if (!have_first) {
      have_first = true;
      first = qpos;
    }
    if (!have_home && key.name == "home") {
      have_home = true;
      home = std::move(qpos);
    }
  }
  const std::optional<std::vector<double>>& chosen = have_home ? home : first;
  if (!chosen) return;  // no key, a key without qpos, or a wrong-size qpos (reported)
  // body poses at qpos0 (connect and weld) are MuJoCo's, before the key
  L.PoseAtQpos0(ir::kWorldBody);
  keys.Apply(*chosen);
}

}  // namespace mdlc::frontend::mjcf
