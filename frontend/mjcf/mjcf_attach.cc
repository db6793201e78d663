// mjcf_attach.cc - the models <attach> takes its bodies from (MuJoCo 3.2+:
// <asset><model name file>), and what an attachment brings besides its
// bodies: the model's default classes and assets, renamed with the prefix
// (MuJoCo's mjs_attach copies them into the parent), and its keys, read
// here over its joints and placed by mjcf_replicate.cc's AttachKeys and
// mjcf_elements_keyframe.cc. The expansion itself is mjcf_replicate.cc's.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "frontend/mjcf/mjcf_replicate.h"
#include "frontend/xml/attribute_reader.h"
#include "ir/load_report.h"

namespace mdlc::frontend::mjcf {
namespace {

namespace fs = std::filesystem;

// MuJoCo's qpos width of a joint of the child model (its type resolved
// through the child's defaults)
size_t QposWidth(const ChildModel& child, const xml::XmlElement& x) {
  if (x.Name() == "freejoint") return 7;
  std::string_view type = x.Attribute("type").value;
  if (!x.Attribute("type").present()) {
    std::string cls = InheritedChildclass(child, x);
    if (auto c = x.Attribute("class"); c.present()) cls = std::string(c.value);
    if (child.reader->defaults.Has(cls)) {
      type = child.reader->Resolve(x, "joint", cls).Get("type").value;
    }
  }
  if (type == "free") return 7;
  if (type == "ball") return 4;
  return 1;
}

// The child's joints in MuJoCo's qpos order: a body's joints (those in its
// frames included) in document order, then its child bodies depth first.
void CollectJoints(const ChildModel& child, const xml::XmlElement& body,
                   std::vector<xml::XmlElement>& out) {
  std::vector<xml::XmlElement> bodies;
  std::vector<xml::XmlElement> stack(1, body);
  // joints of `body` through its frames, in document order
  auto walk = [&](auto&& self, const xml::XmlElement& e) -> void {
    for (const auto& c : child.Children(e)) {
      const std::string_view tag = c.Name();
      if (tag == "joint" || tag == "freejoint") out.push_back(c);
      if (tag == "frame") self(self, c);
      if (tag == "body") bodies.push_back(c);
    }
  };
  walk(walk, body);
  for (const auto& b : bodies) CollectJoints(child, b, out);
}

// The child's own keys, their qpos split over its joints. A qpos of other
// than the child's nq values is an error, as MuJoCo 3.3.8's mjs_attach
// makes it (it pads a short key only when it compiles the model itself).
bool ReadChildKeys(ChildModel& child, FrontendContext& ctx) {
  std::vector<xml::XmlElement> joints;
  std::vector<xml::XmlElement> sections;
  for (const auto& top : child.Children(child.root)) {
    if (top.Name() == "worldbody") CollectJoints(child, top, joints);
    if (top.Name() == "keyframe") sections.push_back(top);
  }
  if (sections.empty()) return true;
  std::vector<size_t> width;
  size_t nq = 0;
  for (const auto& j : joints) nq += width.emplace_back(QposWidth(child, j));
  bool ok = true;
  for (const auto& section : sections) {
    for (const auto& key : child.Children(section)) {
      if (key.Name() != "key") continue;  // reported where the child is read, if ever
      MjcfReader::AttachedKey k;
      k.name = std::string(key.Attribute("name").value);
      k.loc = key.GetLoc();
      const xml::XmlAttribute qpos = key.Attribute("qpos");
      if (qpos.present()) {
        auto values = xml::ParseDoubleList(qpos.value);
        if (!values || values->size() != nq) {
          ctx.diags.Report(DiagKind::BadValue, qpos.loc,
                           fmt::format("keyframe '{}' of model '{}' has invalid qpos size, got "
                                       "{}, should be {}: MuJoCo attaches a model's keys only "
                                       "when they hold all of its coordinates",
                                       k.name, child.name, values ? values->size() : 0, nq));
          ok = false;
          continue;
        }
        k.has_qpos = true;
        size_t at = 0;
        for (size_t i = 0; i < joints.size(); ++i) {
          const std::vector<double> slice(values->begin() + at, values->begin() + at + width[i]);
          at += width[i];
          // unnamed joints are held by an empty name, which no attach finds
          k.joints.emplace_back(std::string(joints[i].Attribute("name").value), slice);
        }
      }
      child.keys.push_back(std::move(k));
    }
  }
  return ok;
}

}  // namespace

std::unique_ptr<ChildModel> LoadChildModel(MjcfReader& parent, const xml::XmlElement& model,
                                           const std::vector<std::string>& chain) {
  FrontendContext& ctx = parent.ctx;
  const xml::XmlAttribute file = model.Attribute("file");
  const xml::XmlAttribute name = model.Attribute("name");
  if (!file.present()) {
    ctx.diags.Report(DiagKind::MissingAttribute, model.GetLoc(),
                     "<model> is missing required attribute 'file'");
    return nullptr;
  }
  std::string path(file.value);
  if (!fs::path(path).is_absolute()) path = (fs::path(parent.main_dir) / path).string();
  const std::string canonical = CanonicalPath(path);
  for (const std::string& link : chain) {
    if (CanonicalPath(link) == canonical) {
      ctx.diags.Report(DiagKind::IncludeCycle, file.loc,
                       fmt::format("attach cycle: model '{}' ('{}') attaches from a model that "
                                   "attaches from it",
                                   name.value, file.value));
      return nullptr;
    }
  }
  if (chain.size() > ctx.sources.limits().include_depth) {
    ctx.diags.Report(DiagKind::LimitExceeded, file.loc,
                     fmt::format("models attached inside attached models more than {} deep, the "
                                 "include-depth limit (raise it with --limit include-depth=N)",
                                 ctx.sources.limits().include_depth));
    return nullptr;
  }
  LoadError error;
  auto id = ctx.sources.LoadFile(path, file.loc, &error);
  if (!id) {
    ReportLoadError(ctx.diags, file.loc, error,
                    fmt::format("cannot read the model file '{}'", file.value));
    return nullptr;
  }
  std::shared_ptr<const xml::XmlDocument> doc = ParseXml(*id, ctx);
  if (!doc) return nullptr;
  const xml::XmlElement root = doc->Root();
  if (root.Name() != "mujoco") {
    ctx.diags.Report(DiagKind::WrongRoot, root.GetLoc(),
                     fmt::format("an MJCF file must have a <mujoco> root element, found <{}>",
                                 root.Name()));
    return nullptr;
  }
  auto child = std::make_unique<ChildModel>();
  child->name = std::string(name.present() ? name.value : root.Attribute("model").value);
  child->loc = model.GetLoc();
  const fs::path dir = fs::path(path).parent_path();
  child->reader = std::make_unique<MjcfReader>(ctx, dir.empty() ? std::string(".") : dir.string());
  MjcfReader& r = *child->reader;
  r.document.documents.push_back(doc);
  if (!LoadIncludes(root, r.main_dir, ctx, r.document)) return nullptr;
  const std::vector<xml::XmlElement> top = r.Children(root);
  for (const auto& e : top) {
    if (e.Name() == "compiler") r.ReadCompiler(e);
  }
  // the classes its replicates' childclass names
  for (const auto& e : top) {
    if (e.Name() == "default") r.defaults.Read(e, ctx.diags, &r.document);
  }
  // its angles are converted into this model's unit as they are copied
  // (ConvertAngles); a different euler sequence is not
  if (r.compiler.eulerseq != parent.compiler.eulerseq) {
    ctx.diags.Report(DiagKind::UnsupportedAttribute, model.GetLoc(),
                     fmt::format("model '{}' has compiler eulerseq '{}', other than this model's "
                                 "'{}'; mdlc reads its attached euler angles with '{}'",
                                 name.value, r.compiler.eulerseq, parent.compiler.eulerseq,
                                 parent.compiler.eulerseq));
  }
  std::vector<std::string> inner = chain;
  inner.push_back(canonical);
  Expansion x = ExpandReplicateAndAttach(r, root, inner);
  if (x.failed) return nullptr;
  child->expanded = x.document;
  child->root = x.document ? x.document->Root() : root;
  if (!ReadChildKeys(*child, ctx)) return nullptr;
  return child;
}

std::string InheritedChildclass(const ChildModel& child, const xml::XmlElement& e) {
  for (xml::XmlElement p = e.Parent(); p && p.Name() != "worldbody"; p = p.Parent()) {
    if (auto cc = p.Attribute("childclass"); cc.present()) return std::string(cc.value);
  }
  (void)child;
  return "main";
}

std::optional<std::string> ConvertAngles(const ChildModel& child, const CompilerSettings& parent,
                                         const xml::XmlElement& x, const xml::XmlAttribute& a,
                                         bool in_default) {
  const CompilerSettings& own = child.reader->compiler;
  if (own.angle_in_degrees == parent.angle_in_degrees) return std::nullopt;
  const double k = own.angle_in_degrees ? M_PI / 180 : 180 / M_PI;
  const std::string_view n = a.name;
  size_t first = 0, count = 0;
  if (n == "euler") {
    count = 3;
  } else if (n == "axisangle") {
    first = 3;
    count = 1;
  } else if (x.Name() == "joint" && (n == "range" || n == "ref" || n == "springref")) {
    // hinge and ball joints hold angles: the joint's own type, else its class's
    std::string_view type = x.Attribute("type").value;
    if (!x.Attribute("type").present() && !in_default) {
      std::string cls = InheritedChildclass(child, x);
      if (auto c = x.Attribute("class"); c.present()) cls = std::string(c.value);
      if (child.reader->defaults.Has(cls)) {
        type = child.reader->Resolve(x, "joint", cls).Get("type").value;
      }
    }
    if (type == "slide" || type == "free") return std::nullopt;
    count = n == "range" ? 2 : 1;
  } else {
    return std::nullopt;
  }
  auto values = xml::ParseDoubleList(a.value);
  if (!values || values->size() < first + count) return std::nullopt;  // reported when read
  for (size_t i = first; i < first + count; ++i) (*values)[i] *= k;
  std::string out;
  for (size_t i = 0; i < values->size(); ++i) {
    out += fmt::format("{}{}", i ? " " : "", (*values)[i]);
  }
  return out;
}

void EmitAttachedDefaultsAndAssets(xml::XmlDocumentBuilder& b, const ChildModel& child,
                                   const std::string& prefix, const CompilerSettings& parent) {
  const MjcfReader& r = *child.reader;
  auto children = [&](const xml::XmlElement& e) { return child.Children(e); };
  auto rename = [&](const xml::XmlElement& x,
                    const xml::XmlAttribute& a) -> std::optional<std::string> {
    const std::string_view n = a.name;
    if (auto v = ConvertAngles(child, parent, x, a, true)) return v;
    if (x.Name() == "default" && n == "class") return prefix + std::string(a.value);
    if (n == "class" || n == "mesh" || n == "material" || n == "hfield" ||
        n == "texture") {
      return prefix + std::string(a.value);
    }
    return std::nullopt;
  };
  // one class for the model's top-level defaults: its "main", renamed
  const std::vector<xml::XmlElement> top = child.Children(child.root);
  const std::string main_class = prefix + "main";
  std::vector<xml::XmlElement> defaults;
  for (const auto& e : top) {
    if (e.Name() == "default") defaults.push_back(e);
  }
  const Loc at = defaults.empty() ? child.root.GetLoc() : defaults.front().GetLoc();
  const xml::AttributeSpec cls{"class", main_class, at};
  b.StartElement("default", at, {&cls, 1});
  for (const auto& d : defaults) {
    for (const auto& c : children(d)) CopySubtree(b, c, children, rename);
  }
  b.EndElement();

  // assets: named with the prefix, files resolved where the model is
  auto resolve = [&](std::string_view file, const std::string& dir) {
    fs::path p(file);
    if (p.is_absolute()) return p.lexically_normal().string();
    const fs::path d(dir);
    p = d.is_absolute() ? d / p : fs::absolute(fs::path(r.main_dir)) / d / p;
    return p.lexically_normal().string();
  };
  for (const auto& asset : top) {
    if (asset.Name() != "asset") continue;
    b.StartElement("asset", asset.GetLoc(), {});
    for (const auto& e : children(asset)) {
      const std::string_view tag = e.Name();
      if (tag == "model") continue;  // attached already, inside the model
      std::vector<xml::AttributeSpec> attrs;
      std::vector<std::string> values;
      values.reserve(16);
      bool named = false;
      const std::string& dir = tag == "mesh" || tag == "hfield" || tag == "skin"
                                   ? (!r.compiler.meshdir.empty() ? r.compiler.meshdir
                                                                  : r.compiler.assetdir)
                                   : (!r.compiler.texturedir.empty() ? r.compiler.texturedir
                                                                     : r.compiler.assetdir);
      e.ForEachAttributeName([&](std::string_view n) {
        const xml::XmlAttribute a = e.Attribute(n);
        std::optional<std::string> v;
        if (n == "name") {
          v = prefix + std::string(a.value);
          named = true;
        } else if (n == "file" || n.starts_with("file")) {
          v = resolve(a.value, dir);
        } else if (n == "class" || n == "texture" || n == "material") {
          v = prefix + std::string(a.value);
        }
        if (v) {
          values.push_back(std::move(*v));
          attrs.push_back({a.name, values.back(), a.loc});
        } else {
          attrs.push_back({a.name, a.value, a.loc});
        }
      });
      // MuJoCo names an unnamed mesh (or texture, hfield) after its file
      if (!named) {
        if (auto f = e.Attribute("file"); f.present()) {
          values.push_back(prefix + fs::path(f.value).stem().string());
          attrs.push_back({"name", values.back(), e.GetLoc()});
        }
      }
      b.StartElement(tag, e.GetLoc(), attrs);
      for (const auto& c : children(e)) CopySubtree(b, c, children, rename);
      b.EndElement();
    }
    b.EndElement();
  }
}

}  // namespace mdlc::frontend::mjcf
