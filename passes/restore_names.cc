// restore_names.cc - the restore-names pass: entities get back the model
// instance and name they had before `mdlc convert` wrote them under another
// (round-trip metadata, ir/original_name.h).
//
// Reads: Module::original_names (recorded by the URDF and MJCF frontends)
// and each entity's current model instance, the instance its file was read
// into. Writes: the entities' `model` and `name`; new model instances.
//
// Per file instance S: the instances named by its entities' original names
// are found or made, in order of first mention. When every body, joint and
// frame of S has an original name (S's name is the writer's, "scene"), the
// first one that is neither the world nor the default instance takes over S
// itself (renamed), so what the metadata says nothing about (materials,
// constraints, filter groups) stays with it and no empty instance is left;
// the others are added. (Otherwise S is an original instance itself.) An instance of that name that already exists elsewhere (another
// file made it) is not taken over: the entities naming it keep the names
// they were written with, and a warning says so. Geometries and cameras
// without names of their own follow their body. Runs after
// apply-directives, so every by-name reference is already an id (a
// directive names what the file wrote), and before the checks, so their
// messages use the restored names.
#include <fmt/format.h>

#include <map>
#include <set>
#include <type_traits>
#include <variant>

#include "ir/overloaded.h"
#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {

class RestoreNamesPass : public Pass {
 public:
  std::string_view name() const override { return "restore-names"; }
  std::string_view description() const override {
    return "Give back the names `mdlc convert` wrote under others (round-trip metadata)";
  }
  ir::VerifyLevel level_after() const override { return ir::VerifyLevel::Resolved; }

  bool Run(PassContext& ctx) override {
    ir::Module& m = ctx.module;
    if (m.original_names.empty()) return true;
    // group by the instance each entity was read into, in order
    std::map<uint32_t, std::vector<const ir::OriginalName*>> by_source;
    std::vector<uint32_t> sources;
    for (const ir::OriginalName& o : m.original_names) {
      const ModelId s = ModelOf(m, o.entity);
      if (!by_source.count(s.value)) sources.push_back(s.value);
      by_source[s.value].push_back(&o);
    }
    for (uint32_t s : sources) Restore(ctx, ModelId(s), by_source[s]);
    m.original_names.clear();
    return true;
  }

 private:
  using Entity = decltype(ir::OriginalName::entity);

  template <typename IdT>
  static auto& At(ir::Module& m, IdT id) {
    if constexpr (std::is_same_v<IdT, CameraId>) {
      return m.cameras[id.index()];
    } else {
      return m[id];
    }
  }
  static ModelId& ModelOf(ir::Module& m, const Entity& entity) {
    return std::visit([&](auto id) -> ModelId& { return At(m, id).model; }, entity);
  }
  static Symbol& NameOf(ir::Module& m, const Entity& entity) {
    return std::visit([&](auto id) -> Symbol& { return At(m, id).name; }, entity);
  }

  void Restore(PassContext& ctx, ModelId source,
               const std::vector<const ir::OriginalName*>& names) {
    ir::Module& m = ctx.module;
    std::map<std::string, std::optional<ModelId>> targets;  // nullopt: taken elsewhere
    // a body, joint or frame the file names without an original name of its
    // own had the file's instance: then the instance keeps its name
    std::set<std::pair<int, size_t>> recorded;
    for (const ir::OriginalName* o : names) {
      recorded.insert({static_cast<int>(o->entity.index()),
                       std::visit([](auto id) { return id.index(); }, o->entity)});
    }
    auto unrecorded_in_source = [&](const auto& table, Entity kind) {
      for (size_t i = 0; i < table.size(); ++i) {
        if (table[i].model == source && !table[i].unnamed &&
            !recorded.count({static_cast<int>(kind.index()), i})) {
          return true;
        }
      }
      return false;
    };
    bool keep_source_name = unrecorded_in_source(m.bodies, BodyId()) ||
                            unrecorded_in_source(m.joints, JointId()) ||
                            unrecorded_in_source(m.frames, FrameId());
    for (const ir::OriginalName* o : names) {
      if (targets.count(o->model)) continue;
      const std::optional<ModelId> existing = m.FindModel(o->model);
      if (existing &&
          (*existing == source || existing->index() < 2 || made_.count(existing->value))) {
        targets[o->model] = existing;
        continue;
      }
      if (existing) {
        ctx.diags.Report(DiagKind::RenamedDuplicate, o->loc,
                         fmt::format("this file was written from model instance '{}', which "
                                     "another model already names; its entities keep the names "
                                     "they were written with",
                                     o->model));
        targets[o->model] = std::nullopt;
        continue;
      }
      if (!keep_source_name && source.index() >= 2) {
        // a top-level instance whose local name is the whole scoped name:
        // what the name was read as before it was written flat
        m.RenameModel(source, ModelId(), m.Intern(o->model));
        keep_source_name = true;
        targets[o->model] = source;
        continue;
      }
      const ModelId added =
          m.Add(ir::ModelInstance{m.Intern(o->model), m[source].loc, m[source].format,
                                  m[source].mass_adjustments, ModelId()});
      made_.insert(added.value);
      targets[o->model] = added;
    }

    std::set<uint32_t> moved_bodies;
    for (const ir::OriginalName* o : names) {
      const std::optional<ModelId> target = targets.at(o->model);
      if (!target) continue;
      ModelOf(m, o->entity) = *target;
      NameOf(m, o->entity) = m.Intern(o->name);
      if (const auto* body = std::get_if<BodyId>(&o->entity)) moved_bodies.insert(body->value);
    }
    // unnamed geometry and cameras follow their body
    const std::set<std::pair<int, size_t>>& restored = recorded;
    auto follow = [&](auto& table, int kind) {
      for (size_t i = 0; i < table.size(); ++i) {
        auto& e = table[i];
        if (e.model != source || restored.count({kind, i}) || !e.body.resolved() ||
            !moved_bodies.count(e.body.id.value)) {
          continue;
        }
        e.model = m[e.body.id].model;
      }
    };
    follow(m.geometries, static_cast<int>(Entity(GeometryId()).index()));
    follow(m.cameras, static_cast<int>(Entity(CameraId()).index()));
  }

  std::set<uint32_t> made_;  // instances this pass added
};

}  // namespace

std::unique_ptr<Pass> CreateRestoreNamesPass() { return std::make_unique<RestoreNamesPass>(); }

}  // namespace mdlc::passes
