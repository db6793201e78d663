#include "ir/module.h"

#include <algorithm>
#include <vector>

namespace mdlc::ir {
namespace {

size_t CountSeparators(std::string_view name) {
  size_t count = 0;
  for (size_t pos = name.find("::"); pos != std::string_view::npos;
       pos = name.find("::", pos + 2)) {
    ++count;
  }
  return count;
}

}  // namespace

Module::Module() {
  Add(ModelInstance{Intern("WorldModelInstance"), {}, SourceFormat::Internal, {}, {}});
  Add(ModelInstance{Intern("DefaultModelInstance"), {}, SourceFormat::Internal, {}, {}});
  Body world;
  world.name = Intern("world");
  world.model = kWorldModel;
  world.is_world = true;
  bodies.push_back(world);
}

ModelId Module::Add(ModelInstance m) {
  const ModelId id(models.size());
  model_by_parent_.TryAdd(m.parent.value, m.local_name, id);
  if (!m.parent.valid()) {
    max_top_level_separators_ =
        std::max(max_top_level_separators_, CountSeparators(Text(m.local_name)));
  }
  models.push_back(std::move(m));
  return id;
}

void Module::RenameModel(ModelId model, ModelId parent, Symbol local) {
  ModelInstance& m = models[model.index()];
  if (const ModelId* held = model_by_parent_.Find(m.parent.value, m.local_name);
      held && *held == model) {
    model_by_parent_.Erase(m.parent.value, m.local_name);
  }
  m.parent = parent;
  m.local_name = local;
  model_by_parent_.TryAdd(parent.value, local, model);
  if (!parent.valid()) {
    max_top_level_separators_ = std::max(max_top_level_separators_, CountSeparators(Text(local)));
  }
}

void Module::ReserveModels(size_t more) {
  const size_t wanted = models.size() + more;
  if (wanted <= models.capacity()) return;
  // at least doubling, as the frontends' entity tables do
  const size_t capacity = std::max(wanted, 2 * models.capacity());
  models.reserve(capacity);
}

void Module::RemoveLastModel() {
  const ModelId last(models.size() - 1);
  const ModelInstance& m = models.back();
  if (const ModelId* held = model_by_parent_.Find(m.parent.value, m.local_name);
      held && *held == last) {
    model_by_parent_.Erase(m.parent.value, m.local_name);
  }
  models.pop_back();
}

std::string Module::ModelName(ModelId model) const {
  // the chain from the top-level ancestor down to `model`
  std::vector<ModelId> chain;
  size_t size = 0;
  for (ModelId m = model; m.valid(); m = models[m.index()].parent) {
    chain.push_back(m);
    size += Text(models[m.index()].local_name).size() + 2;
  }
  std::string out;
  out.reserve(size);
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    if (!out.empty()) out += "::";
    out += Text(models[it->index()].local_name);
  }
  return out;
}

std::optional<ModelId> Module::FindChildModel(ModelId parent, Symbol local) const {
  if (local.empty()) return std::nullopt;
  const ModelId* found = model_by_parent_.Find(parent.value, local);
  if (!found) return std::nullopt;
  return *found;
}

std::optional<ModelId> Module::FindModel(std::string_view scoped, ModelId within) const {
  if (scoped.empty()) return std::nullopt;
  // walks `rest` ("b::c") down from `from`, one local name at a time
  auto walk = [this](ModelId from, std::string_view rest) -> std::optional<ModelId> {
    ModelId at = from;
    while (!rest.empty()) {
      const size_t sep = rest.find("::");
      const std::string_view part = rest.substr(0, sep);
      auto child = FindChildModel(at, symbols.Find(part));
      if (!child) return std::nullopt;
      at = *child;
      rest = sep == std::string_view::npos ? std::string_view() : rest.substr(sep + 2);
    }
    return at;
  };
  if (within.valid()) {
    if (auto found = walk(within, scoped)) return found;
    // a top-level instance named "<within>::..." (a Model Directives
    // namespace, or a test's hand-made module) is nested by its name
    if (max_top_level_separators_ == 0) return std::nullopt;
    return FindModel(ModelName(within) + "::" + std::string(scoped));
  }
  // a top-level name may itself hold "::": try each first component that long
  size_t end = 0;
  for (size_t separators = 0; separators <= max_top_level_separators_; ++separators) {
    end = scoped.find("::", separators == 0 ? 0 : end + 2);
    const std::string_view first = scoped.substr(0, end);
    if (auto top = FindChildModel(ModelId(), symbols.Find(first))) {
      if (end == std::string_view::npos) return top;
      if (auto found = walk(*top, scoped.substr(end + 2))) return found;
    }
    if (end == std::string_view::npos) break;
  }
  return std::nullopt;
}

std::string Module::ScopedName(ModelId model, Symbol local) const {
  std::string out = ModelName(model);
  out += "::";
  out += Text(local);
  return out;
}

std::string Module::ScopedName(BodyId body) const {
  const Body& b = bodies[body.index()];
  if (b.is_world) return "world";
  return ScopedName(b.model, b.name);
}

std::string Module::ScopedName(JointId joint) const {
  const Joint& j = joints[joint.index()];
  return ScopedName(j.model, j.name);
}

}  // namespace mdlc::ir
