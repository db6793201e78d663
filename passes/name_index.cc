#include "passes/name_index.h"

namespace mdlc::passes {

ModelIndex::ModelIndex(const ir::Module& module) {
  for (size_t i = 0; i < module.models.size(); ++i) {
    map_.emplace(std::string(module.Text(module.models[i].name)), ModelId(i));
  }
}

std::optional<ModelId> ModelIndex::Find(std::string_view name) const {
  auto it = map_.find(std::string(name));
  if (it == map_.end()) return std::nullopt;
  return it->second;
}

}  // namespace mdlc::passes
