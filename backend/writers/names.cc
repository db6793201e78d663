// names.cc - see names.h.
#include "backend/writers/names.h"

#include <fmt/format.h>

#include <set>

#include "ir/syntax/original_name_comment.h"

namespace mdlc::writers {

std::string Unscoped(std::string name) {
  for (size_t at; (at = name.find("::")) != std::string::npos;) name.replace(at, 2, "/");
  return name;
}

std::string Prefixed(std::string_view instance, std::string_view name) {
  return Unscoped(fmt::format("{}/{}", instance, name));
}

FlatNames::FlatNames(const backend::Plant& plant) : plant_(plant) {
  std::set<size_t> instances;
  for (size_t b = 1; b < plant.bodies.size(); ++b) instances.insert(plant.bodies[b].model.index());
  instance_count_ = instances.size();
  prefix_instances_ = instances.size() > 1;
  if (instances.empty()) {
    model_name_ = "world";
  } else {
    first_instance_ = *instances.begin();
    model_name_ = prefix_instances_ ? "scene" : plant.model_instances[first_instance_];
  }
}

std::string FlatNames::Named(ModelId model, std::string_view name) const {
  if (!prefix_instances_ || model.index() < 2) return Unscoped(std::string(name));
  return Prefixed(plant_.model_instances[model.index()], name);
}

std::string FlatNames::NamedScoped(const std::string& scoped) const {
  const size_t sep = scoped.rfind("::");
  if (!prefix_instances_ || sep == std::string::npos) {
    return sep == std::string::npos ? scoped : scoped.substr(sep + 2);
  }
  return Prefixed(scoped.substr(0, sep), scoped.substr(sep + 2));
}

std::optional<std::string> FlatNames::OriginalNameComment(ModelId model, std::string_view name,
                                                          std::string_view read_back) const {
  const std::string& instance = plant_.model_instances[model.index()];
  if (instance == model_name_ && read_back == name) return std::nullopt;
  return syntax::FormatOriginalNameComment(instance, name);
}

void FlatNames::ReportFlattening(const ir::Module& module, std::string_view what,
                                 DiagnosticEngine& diags) const {
  if (!prefix_instances_) return;
  diags.Report(DiagKind::Lossy,
               first_instance_ < module.models.size() ? module.models[first_instance_].loc : Loc{},
               fmt::format("the {} model instances are written as one {}; each name is prefixed "
                           "with its instance ('instance/name')",
                           instance_count_, what));
}

}  // namespace mdlc::writers
