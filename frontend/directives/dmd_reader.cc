// dmd_reader.cc - the Model Directives frontend (DMD-001..DMD-062).
//
// A .dmd.yaml file composes a scene: it loads models with the other
// frontends (add_model), makes empty instances to hold namespaces
// (add_model_instance), declares collision filter groups, and records frames,
// welds and default poses for the apply-directives pass (which needs every
// model's frames resolved first). add_directives processes another file in a
// namespace; that recursion runs on an explicit stack, so any depth of
// nesting is fine, and a file that is already being processed is a cycle.
//
// Names: inside add_directives with model_namespace `ns`, every name a
// directive writes gets `ns::` prepended, except `world` (DMD-060).
#include <fmt/format.h>

#include <filesystem>
#include <utility>

#include "frontend/directives/dmd_transform.h"
#include "frontend/directives/yaml_schema.h"
#include "frontend/frontend.h"
#include "frontend/xacro/xacro.h"
#include "frontend/model_naming.h"
#include "ir/assets/package_map.h"
#include "ir/load_report.h"
#include "ir/scoped_name.h"

namespace mdlc::frontend {
namespace {

namespace fs = std::filesystem;


// DmdScopedNameJoin: the namespace applies to every name but `world`
std::string InNamespace(std::string_view ns, std::string_view name) {
  if (name == "world") return std::string(name);
  return ir::JoinScopedName(ns, name);
}

// One directives file being processed: where it is, its directives and the
// next one to run.
struct OpenFile {
  FileId file;
  std::string canonical_path;
  std::unique_ptr<yaml::Document> document;  // owns `directives`
  yaml::Node directives;
  size_t next = 0;
  std::string ns;
};

class DirectivesReader {
 public:
  explicit DirectivesReader(FrontendContext& ctx) : ctx_(ctx) {}

  bool Run(FileId root);

 private:
  ir::Module& module() { return ctx_.module; }
  DiagnosticEngine& diags() { return ctx_.diags; }
  const assets::PackageMap& packages() const { return ctx_.packages; }

  // Loads and checks the top level of a directives file; pushes it.
  bool Open(FileId file, std::string ns);
  void RunDirective(YamlSchemaReader& r, const yaml::Node& directive, const std::string& ns);

  void AddModel(YamlSchemaReader& r, const yaml::Node& node, Loc loc, const std::string& ns);
  void AddModelInstanceDirective(YamlSchemaReader& r, const yaml::Node& node, Loc loc,
                                 const std::string& ns);
  void AddFrame(YamlSchemaReader& r, const yaml::Node& node, Loc loc, const std::string& ns);
  void AddWeld(YamlSchemaReader& r, const yaml::Node& node, Loc loc, const std::string& ns);
  void AddCollisionFilterGroup(YamlSchemaReader& r, const yaml::Node& node, Loc loc,
                               const std::string& ns);
  void AddDirectives(YamlSchemaReader& r, const yaml::Node& node, Loc loc, const std::string& ns);

  // A required, non-empty string field (DMD-010, DMD-020, DMD-030, ...).
  std::optional<LocatedString> RequiredName(YamlSchemaReader& r, const yaml::Node& node,
                                            std::string_view directive, std::string_view key,
                                            Loc loc);
  // A file reference: a URI or an absolute path (DMD-002), resolved.
  std::optional<std::string> ResolveFile(const LocatedString& file);
  // Reads a resolved file, noting where it was named (for "included from").
  std::optional<FileId> Load(const std::string& path, Loc referenced_at);
  std::optional<ModelId> FindModel(std::string_view name) const {
    return FindModelInstance(ctx_.module, name);
  }
  ir::DirectiveFrameName FrameName(const std::string& ns, const LocatedString& name) {
    return {module().Intern(InNamespace(ns, name.text)), name.loc};
  }
  void Record(ir::SceneEdit::Variant edit) {
    module().scene_edits.push_back(
        ir::SceneEdit{std::move(edit), static_cast<uint32_t>(module().models.size())});
  }

  FrontendContext& ctx_;
  std::vector<OpenFile> stack_;
};

bool DirectivesReader::Run(FileId root) {
  const size_t errors_before = diags().error_count();
  if (!Open(root, "")) return false;
  while (!stack_.empty()) {
    OpenFile& top = stack_.back();
    if (top.next == top.directives.size()) {
      stack_.pop_back();
      continue;
    }
    // the document outlives the directive: a pushed file moves only its owner
    const yaml::Node directive = top.directives[top.next++];
    YamlSchemaReader r(top.file, diags());
    // a copy: RunDirective may push a file and invalidate `top`
    const std::string ns = top.ns;
    RunDirective(r, directive, ns);
  }
  return diags().error_count() == errors_before;
}

bool DirectivesReader::Open(FileId file, std::string ns) {
  YamlSchemaReader r(file, diags());
  const Loc start{file, 1, 1};
  std::unique_ptr<yaml::Document> doc = r.Parse(ctx_.sources.Contents(file));
  if (!doc) return false;
  const yaml::Node root = doc->root();
  if (root.IsNull()) {
    diags().Report(DiagKind::EmptyFile, start, "the model directives file is empty");
    return false;
  }
  const size_t errors_before = diags().error_count();
  if (!r.CheckMap(root, "a model directives file", {"directives"}, start) ||
      diags().error_count() != errors_before) {
    return false;
  }
  auto directives = r.Get(root, "directives");
  if (!directives.present() || directives.value.IsNull()) {
    diags().Report(DiagKind::MissingElement, directives.present() ? directives.key_loc : start,
                   "a model directives file needs a 'directives' list");
    return false;
  }
  if (!directives.value.IsSequence()) {
    diags().Report(DiagKind::BadValue, r.LocOf(directives.value, directives.key_loc),
                   "'directives' must be a list of directives");
    return false;
  }
  std::error_code ec;
  std::string canonical = fs::weakly_canonical(ctx_.sources.Path(file), ec).string();
  stack_.push_back(
      OpenFile{file, std::move(canonical), std::move(doc), directives.value, 0, std::move(ns)});
  return true;
}

void DirectivesReader::RunDirective(YamlSchemaReader& r, const yaml::Node& directive,
                                    const std::string& ns) {
  const Loc loc = r.LocOf(directive);
  // DMD-001: exactly one of the six directive kinds
  if (!r.CheckMap(directive, "a directive",
                  {"add_model", "add_model_instance", "add_frame", "add_weld",
                   "add_collision_filter_group", "add_directives"},
                  loc)) {
    return;
  }
  if (directive.size() != 1) {
    diags().Report(DiagKind::BadValue, loc,
                   directive.size() == 0
                       ? std::string("a directive must name its kind: one of add_model, "
                                     "add_model_instance, add_frame, add_weld, "
                                     "add_collision_filter_group or add_directives")
                       : fmt::format("a directive must have exactly one kind, not {}; start "
                                     "each with its own '- '",
                                     directive.size()));
    return;
  }
  const yaml::Entry only = *directive.Entries().begin();
  const yaml::Node key = only.first;
  const yaml::Node body = only.second;
  const std::string_view kind = key.Scalar();
  // what a directive lacks is reported at its kind ("add_model:")
  const Loc kind_loc = r.LocOf(key, loc);
  if (kind == "add_model") AddModel(r, body, kind_loc, ns);
  else if (kind == "add_model_instance") AddModelInstanceDirective(r, body, kind_loc, ns);
  else if (kind == "add_frame") AddFrame(r, body, kind_loc, ns);
  else if (kind == "add_weld") AddWeld(r, body, kind_loc, ns);
  else if (kind == "add_collision_filter_group") AddCollisionFilterGroup(r, body, kind_loc, ns);
  else if (kind == "add_directives") AddDirectives(r, body, kind_loc, ns);
  // anything else was reported by CheckMap
}

std::optional<LocatedString> DirectivesReader::RequiredName(YamlSchemaReader& r,
                                                            const yaml::Node& node,
                                                            std::string_view directive,
                                                            std::string_view key, Loc loc) {
  auto field = r.Get(node, key);
  if (!field.present()) {
    diags().Report(DiagKind::MissingAttribute, loc,
                   fmt::format("{} needs '{}'", directive, key));
    return std::nullopt;
  }
  auto value = r.String(field.value, fmt::format("{} '{}'", directive, key), field.key_loc);
  if (!value) return std::nullopt;
  if (value->text.empty()) {
    diags().Report(DiagKind::BadValue, value->loc,
                   fmt::format("{} '{}' must not be empty", directive, key));
    return std::nullopt;
  }
  return value;
}

std::optional<std::string> DirectivesReader::ResolveFile(const LocatedString& file) {
  // Drake resolves directive files with no base folder: a relative path means
  // nothing (DMD-002)
  if (file.text.find("://") == std::string::npos && !fs::path(file.text).is_absolute()) {
    diags()
        .Report(DiagKind::BadValue, file.loc,
                fmt::format("'{}' is a relative path; model directives name files by URI "
                            "(package://, model:// or file://) or by absolute path",
                            file.text))
        .Note(file.loc, "a package:// URI keeps the scene independent of where it is run");
    return std::nullopt;
  }
  return assets::ResolveUri(file.text, "", packages(), file.loc, diags());
}

std::optional<FileId> DirectivesReader::Load(const std::string& path, Loc referenced_at) {
  LoadError error;
  auto file = ctx_.sources.LoadFile(path, referenced_at, &error);
  if (!file) ReportLoadError(diags(), referenced_at, error, fmt::format("cannot read '{}'", path));
  return file;
}

void DirectivesReader::AddModel(YamlSchemaReader& r, const yaml::Node& node, Loc loc,
                                const std::string& ns) {
  if (!r.CheckMap(node, "add_model",
                  {"name", "file", "default_joint_positions", "default_free_body_pose"}, loc)) {
    return;
  }
  auto name = RequiredName(r, node, "add_model", "name", loc);
  auto file = RequiredName(r, node, "add_model", "file", loc);

  // read the defaults before loading, so their mistakes are reported even
  // when the model cannot be loaded
  struct JointDefault { LocatedString joint; std::vector<double> positions; Loc values_loc; };
  struct PoseDefault { LocatedString frame; DirectiveTransform pose; };
  std::vector<JointDefault> joint_defaults;
  std::vector<PoseDefault> pose_defaults;
  bool defaults_ok = true;
  if (auto f = r.Get(node, "default_joint_positions"); f.present() && !f.value.IsNull()) {
    if (!f.value.IsMap()) {
      r.CheckMap(f.value, "add_model 'default_joint_positions'", {}, f.key_loc);
      defaults_ok = false;
    } else {
      for (const yaml::Entry entry : f.value.Entries()) {
        auto joint = r.String(entry.first, "a joint name", f.key_loc);
        auto values =
            r.Numbers(entry.second, "default joint positions", r.LocOf(entry.first, f.key_loc));
        if (!joint || !values) {
          defaults_ok = false;
          continue;
        }
        joint_defaults.push_back({*joint, std::move(*values), r.LocOf(entry.second, joint->loc)});
      }
    }
  }
  if (auto f = r.Get(node, "default_free_body_pose"); f.present() && !f.value.IsNull()) {
    if (!f.value.IsMap()) {
      r.CheckMap(f.value, "add_model 'default_free_body_pose'", {}, f.key_loc);
      defaults_ok = false;
    } else {
      for (const yaml::Entry entry : f.value.Entries()) {
        auto frame = r.String(entry.first, "a body or frame name", f.key_loc);
        auto pose = ReadDirectiveTransform(r, entry.second, "default_free_body_pose",
                                           r.LocOf(entry.first, f.key_loc));
        if (!frame || !pose) {
          defaults_ok = false;
          continue;
        }
        pose_defaults.push_back({*frame, std::move(*pose)});
      }
    }
  }
  if (!name || !file) return;
  auto path = ResolveFile(*file);
  if (!path) return;
  auto format = FormatFromPath(*path);
  if (format == Format::Directives) {
    diags().Report(DiagKind::BadValue, file->loc,
                   fmt::format("add_model cannot load '{}': it is a model directives file; use "
                               "add_directives",
                               file->text));
    return;
  }
  std::optional<FileId> model_file;
  if (!format && xacro::IsXacroPath(*path)) {
    // a .xacro is expanded with its defaults, and read as its root names
    model_file = Load(*path, file->loc);
    if (!model_file) return;
    format = XacroFormat(*model_file, ctx_.sources);
  }
  if (!format) {
    diags().Report(DiagKind::UnknownFormat, file->loc,
                   fmt::format("'{}': unknown file extension; expected .urdf, .sdf, .xml (MJCF) "
                               "or a .xacro of one of them",
                               file->text));
    return;
  }
  if (!model_file) model_file = Load(*path, file->loc);
  if (!model_file) return;
  // the model is named `name` inside the current namespace (DMD-010)
  FrontendContext sub = ctx_;
  sub.options.model_name = name->text;
  sub.options.name_prefix = ns.empty() ? "" : ns + "::";
  sub.options.single_model = true;
  std::optional<ModelId> model = ReadModel(*model_file, *format, sub);
  if (!model || !defaults_ok) return;
  for (JointDefault& d : joint_defaults) {
    Record(ir::DefaultJointPositionsEdit{d.joint.loc, *model, module().Intern(d.joint.text),
                                         d.values_loc, std::move(d.positions)});
  }
  for (PoseDefault& d : pose_defaults) {
    std::optional<ir::DirectiveFrameName> base;
    if (d.pose.base_frame) base = FrameName(ns, *d.pose.base_frame);
    Record(ir::DefaultFreeBodyPoseEdit{d.frame.loc, *model, module().Intern(d.frame.text), base,
                                       d.pose.X});
  }
}

void DirectivesReader::AddModelInstanceDirective(YamlSchemaReader& r, const yaml::Node& node,
                                                 Loc loc, const std::string& ns) {
  if (!r.CheckMap(node, "add_model_instance", {"name"}, loc)) return;
  auto name = RequiredName(r, node, "add_model_instance", "name", loc);
  if (!name) return;
  FrontendContext sub = ctx_;
  sub.options.model_name.reset();
  sub.options.name_prefix = ns.empty() ? "" : ns + "::";
  AddModelInstance(name->text, name->loc, ir::SourceFormat::Directives, sub);
}

void DirectivesReader::AddFrame(YamlSchemaReader& r, const yaml::Node& node, Loc loc,
                                const std::string& ns) {
  if (!r.CheckMap(node, "add_frame", {"name", "X_PF"}, loc)) return;
  auto name = RequiredName(r, node, "add_frame", "name", loc);
  auto x_pf = r.Get(node, "X_PF");
  std::optional<DirectiveTransform> pose;
  if (!x_pf.present()) {
    diags().Report(DiagKind::MissingAttribute, loc,
                   "add_frame needs 'X_PF' with a 'base_frame' (DMD-030)");
  } else {
    pose = ReadDirectiveTransform(r, x_pf.value, "add_frame 'X_PF'", x_pf.key_loc);
    if (pose && (!pose->base_frame || pose->base_frame->text.empty())) {
      diags().Report(DiagKind::MissingAttribute, x_pf.key_loc,
                     "add_frame 'X_PF' needs a 'base_frame': the frame the pose is given in");
      pose.reset();
    }
  }
  if (!name || !pose) return;
  auto split = ir::SplitScopedName(name->text);
  if (!split) {
    diags().Report(DiagKind::InvalidName, name->loc,
                   fmt::format("'{}' is not a valid scoped name", name->text));
    return;
  }
  // A scoped name puts the frame in that instance (inside the namespace). An
  // unscoped one leaves it to the base frame's instance (DMD-062).
  ir::AddFrameEdit edit;
  edit.loc = loc;
  edit.name = module().Intern(split->element);
  edit.name_loc = name->loc;
  if (!split->scope.empty()) edit.instance = module().Intern(ir::JoinScopedName(ns, split->scope));
  edit.base_frame = FrameName(ns, *pose->base_frame);
  edit.X_PF = pose->X;
  Record(std::move(edit));
}

void DirectivesReader::AddWeld(YamlSchemaReader& r, const yaml::Node& node, Loc loc,
                               const std::string& ns) {
  if (!r.CheckMap(node, "add_weld", {"parent", "child", "X_PC"}, loc)) return;
  auto parent = RequiredName(r, node, "add_weld", "parent", loc);
  auto child = RequiredName(r, node, "add_weld", "child", loc);
  std::optional<DirectiveTransform> pose = DirectiveTransform{};
  if (auto x_pc = r.Get(node, "X_PC"); x_pc.present()) {
    pose = ReadDirectiveTransform(r, x_pc.value, "add_weld 'X_PC'", x_pc.key_loc);
    if (pose && pose->base_frame) {
      diags().Report(DiagKind::BadValue, pose->base_frame->loc,
                     "add_weld 'X_PC' must not give a 'base_frame': the pose is always in the "
                     "parent frame (DMD-040)");
      pose.reset();
    }
  }
  if (!parent || !child || !pose) return;
  Record(ir::AddWeldEdit{loc, FrameName(ns, *parent), FrameName(ns, *child), pose->X});
}

void DirectivesReader::AddCollisionFilterGroup(YamlSchemaReader& r, const yaml::Node& node,
                                               Loc loc, const std::string& ns) {
  constexpr std::string_view kWhat = "add_collision_filter_group";
  if (!r.CheckMap(node, kWhat,
                  {"name", "members", "member_groups", "model_namespace",
                   "ignored_collision_filter_groups"},
                  loc)) {
    return;
  }
  auto name = RequiredName(r, node, kWhat, "name", loc);
  auto list = [&](std::string_view key) -> std::optional<std::vector<LocatedString>> {
    auto f = r.Get(node, key);
    if (!f.present()) return std::vector<LocatedString>{};
    return r.Strings(f.value, fmt::format("{} '{}'", kWhat, key), f.key_loc);
  };
  auto members = list("members");
  auto member_groups = list("member_groups");
  auto ignored = list("ignored_collision_filter_groups");
  std::optional<LocatedString> group_ns;
  if (auto f = r.Get(node, "model_namespace"); f.present()) {
    group_ns = r.String(f.value, fmt::format("{} 'model_namespace'", kWhat), f.key_loc);
    if (!group_ns) return;
  }
  if (!name || !members || !member_groups || !ignored) return;
  if (members->empty() && member_groups->empty()) {
    diags().Report(DiagKind::MissingAttribute, loc,
                   fmt::format("{} '{}' needs 'members' or 'member_groups' (DMD-050)", kWhat,
                               name->text));
    return;
  }
  // the group lives in the namespace's instance, and names its members and
  // groups relative to it; with no namespace it is global (COMMON-053)
  const std::string scope = ir::JoinScopedName(ns, group_ns ? group_ns->text : "");
  ModelId model = ir::kDefaultModel;
  if (!scope.empty()) {
    auto found = FindModel(scope);
    if (!found) {
      diags().Report(DiagKind::UnknownReference, group_ns ? group_ns->loc : loc,
                     fmt::format("collision filter group '{}': no model instance named '{}'",
                                 name->text, scope));
      return;
    }
    model = *found;
  }
  ir::CollisionFilterGroup group;
  group.name = module().Intern(name->text);
  group.model = model;
  group.loc = name->loc;
  for (const LocatedString& m : *members) group.members.push_back({module().Intern(m.text), m.loc, {}});
  for (const LocatedString& g : *member_groups) {
    group.member_groups.push_back({module().Intern(g.text), g.loc, {}});
  }
  for (const LocatedString& g : *ignored) {
    group.ignored_groups.push_back({module().Intern(g.text), g.loc, {}});
  }
  module().Add(std::move(group));
}

void DirectivesReader::AddDirectives(YamlSchemaReader& r, const yaml::Node& node, Loc loc,
                                     const std::string& ns) {
  if (!r.CheckMap(node, "add_directives", {"file", "model_namespace"}, loc)) return;
  auto file = RequiredName(r, node, "add_directives", "file", loc);
  std::optional<LocatedString> sub_ns;
  if (auto f = r.Get(node, "model_namespace"); f.present()) {
    sub_ns = r.String(f.value, "add_directives 'model_namespace'", f.key_loc);
    if (!sub_ns) return;
  }
  if (!file) return;
  // DMD-060: the namespace must already be an instance
  std::string new_ns = ir::JoinScopedName(ns, sub_ns ? sub_ns->text : "");
  if (!new_ns.empty() && !FindModel(new_ns)) {
    diags()
        .Report(DiagKind::UnknownReference, sub_ns ? sub_ns->loc : loc,
                fmt::format("namespace '{}' does not exist as a model instance", new_ns))
        .Note(sub_ns ? sub_ns->loc : loc,
              fmt::format("add it first with: - add_model_instance: {{name: {}}}",
                          sub_ns ? sub_ns->text : new_ns));
    return;
  }
  auto path = ResolveFile(*file);
  if (!path) return;
  // Drake reads any file named here as directives (bimanual_iiwa.yaml); a
  // file whose extension names a model format is a model, so say so
  if (auto format = FormatFromPath(*path); format && *format != Format::Directives) {
    diags().Report(DiagKind::UnknownFormat, file->loc,
                   fmt::format("add_directives needs a directives file, not the {} model '{}'; "
                               "use add_model for a model",
                               FormatName(*format), file->text));
    return;
  }
  // DMD-061: a file already being processed would recurse forever
  std::error_code ec;
  const std::string canonical = fs::weakly_canonical(*path, ec).string();
  for (size_t i = 0; i < stack_.size(); ++i) {
    if (stack_[i].canonical_path != canonical) continue;
    auto diag = diags().Report(
        DiagKind::IncludeCycle, file->loc,
        fmt::format("add_directives cycle: '{}' is already being processed", file->text));
    for (size_t k = i; k < stack_.size(); ++k) {
      const Loc at = ctx_.sources.IncludedFrom(stack_[k].file);
      if (at.valid()) diag.Note(at, fmt::format("'{}' is added here", ctx_.sources.Path(stack_[k].file)));
    }
    return;
  }
  if (auto sub_file = Load(*path, file->loc)) Open(*sub_file, std::move(new_ns));
}

}  // namespace

std::optional<ModelId> ReadDirectives(FileId file, FrontendContext& ctx) {
  DirectivesReader reader(ctx);
  if (!reader.Run(file)) return std::nullopt;
  return ir::kDefaultModel;
}

}  // namespace mdlc::frontend
