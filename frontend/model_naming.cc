#include "frontend/model_naming.h"

#include <fmt/format.h>

#include <utility>

namespace mdlc::frontend {

std::optional<ModelId> FindModelInstance(const ir::Module& module, std::string_view name) {
  return module.FindModel(name);
}

std::optional<ModelId> AddModelInstance(std::string_view requested, Loc loc,
                                        ir::SourceFormat format, FrontendContext& ctx) {
  std::string name = ctx.options.name_prefix +
                     std::string(ctx.options.model_name ? std::string_view(*ctx.options.model_name)
                                                        : requested);
  if (auto existing = FindModelInstance(ctx.module, name)) {
    if (!ctx.options.auto_rename) {
      auto diag = ctx.diags.Report(
          DiagKind::DuplicateName, loc,
          fmt::format("a model instance named '{}' already exists; rename the model or "
                      "use --auto-rename",
                      name));
      const Loc first = ctx.module[*existing].loc;
      if (first.valid()) diag.Note(first, "the first model instance of that name is defined here");
      return std::nullopt;
    }
    int* last = ctx.renames ? &ctx.renames->last[name] : nullptr;
    for (int n = last ? *last + 1 : 1;; ++n) {
      std::string candidate = fmt::format("{}_{}", name, n);
      if (!FindModelInstance(ctx.module, candidate)) {
        if (last) *last = n;
        name = std::move(candidate);
        break;
      }
    }
  }
  ir::ModelInstance instance;
  instance.local_name = ctx.module.Intern(name);
  instance.loc = loc;
  instance.format = format;
  return ctx.module.Add(std::move(instance));  // top level: no parent
}

}  // namespace mdlc::frontend
