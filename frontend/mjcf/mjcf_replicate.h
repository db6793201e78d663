// mjcf_replicate.h - MuJoCo 3's model-building elements <replicate> and
// <attach> (with <asset><model>), expanded into a document of their
// result before the model is read. Private to frontend/mjcf.
//
// The expansion writes a new XmlDocument (xml/document_builder.h) in which
// every <replicate> became `count` <frame>s holding renamed copies of its
// contents and every <attach> a <frame> holding the other model's body
// subtree, its names prefixed. Every element of the result is placed at the
// element it was copied from, so diagnostics about a copy point at the
// original. Elements outside the tree that refer into a replicated or
// attached subtree (<equality>, <tendon>, <actuator>, <contact>, <sensor>)
// are copied and renamed as MuJoCo's mjs_attach does: a copy is kept when
// every name it refers to, renamed, names something in the model.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frontend/mjcf/mjcf_reader_detail.h"
#include "frontend/xml/document_builder.h"

namespace mdlc::frontend::mjcf {

struct Expansion {
  std::shared_ptr<const xml::XmlDocument> document;  // null: nothing to expand
  bool failed = false;                               // a located error was reported
};

/// Expands the <replicate>s and <attach>es under `root` (a model's <mujoco>
/// element, read through r.document) with r.compiler's angle unit and
/// euler sequence. `chain`: the canonical paths of the model files being
/// expanded, outermost first (an attach cycle is an error).
Expansion ExpandReplicateAndAttach(MjcfReader& r, const xml::XmlElement& root,
                                   const std::vector<std::string>& chain);

/// A model an <asset><model> names, loaded and expanded (mjcf_attach.cc).
struct ChildModel {
  std::string name;
  Loc loc;                              // the <model> element
  std::unique_ptr<MjcfReader> reader;   // its documents and compiler settings
  std::shared_ptr<const xml::XmlDocument> expanded;  // its own replicates/attaches
  xml::XmlElement root;                 // the root to read (expanded, or the file's)
  /// Its own <key>s, their qpos split over its joints by name (an unnamed
  /// joint's under an empty name); an attach prefixes both.
  std::vector<MjcfReader::AttachedKey> keys;
  std::vector<xml::XmlElement> Children(const xml::XmlElement& e) const {
    if (expanded) {
      std::vector<xml::XmlElement> out;
      for (auto c = e.FirstChild(); c; c = c.NextSibling()) out.push_back(c);
      return out;
    }
    return reader->Children(e);
  }
};

/// Loads the file of an <asset><model> element (relative to the parent's
/// main directory), its includes and compiler settings, and expands it.
/// Null after a located error (missing file, cycle).
std::unique_ptr<ChildModel> LoadChildModel(MjcfReader& parent, const xml::XmlElement& model,
                                           const std::vector<std::string>& chain);

/// Attribute rewriting while a subtree is copied: the new value, or nullopt
/// to keep the attribute as written.
using Rewrite =
    std::function<std::optional<std::string>(const xml::XmlElement&, const xml::XmlAttribute&)>;
using ChildrenOf = std::function<std::vector<xml::XmlElement>(const xml::XmlElement&)>;

/// Copies `e` and everything below it into `b` (explicit stack), every
/// element at its original location. `skip` elements are left out.
void CopySubtree(xml::XmlDocumentBuilder& b, const xml::XmlElement& e, const ChildrenOf& children,
                 const Rewrite& rewrite);

/// Writes the child model's <default>s and <asset>s, renamed with `prefix`,
/// as top-level elements of the document being built (MuJoCo copies the
/// defaults and assets of an attached model into the parent).
void EmitAttachedDefaultsAndAssets(xml::XmlDocumentBuilder& b, const ChildModel& child,
                                   const std::string& prefix, const CompilerSettings& parent);

/// An attribute of an element of the child model holding angles (euler,
/// axisangle, a hinge or ball joint's range, ref, springref), rewritten
/// from the child's compiler angle unit into `parent`'s; nullopt when it
/// holds none or the units agree. `in_default`: `x` is in a <default>.
std::optional<std::string> ConvertAngles(const ChildModel& child, const CompilerSettings& parent,
                                         const xml::XmlElement& x, const xml::XmlAttribute& a,
                                         bool in_default);

/// The default class the elements of `e` (a body of the child model) use
/// when they name none: the nearest childclass of an enclosing body or
/// frame, else "main".
std::string InheritedChildclass(const ChildModel& child, const xml::XmlElement& e);

}  // namespace mdlc::frontend::mjcf
