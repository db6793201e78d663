// original_names.cc - see original_names.h.
#include "frontend/original_names.h"

namespace mdlc::frontend {

std::optional<syntax::ParsedOriginalName> ReadOriginalName(const xml::XmlElement& e,
                                                           OriginalEntity entity,
                                                           FrontendContext& ctx) {
  if (ctx.options.model_name || !ctx.options.name_prefix.empty() || ctx.options.single_model) {
    return std::nullopt;
  }
  for (const std::string& comment : e.Comments()) {
    if (auto parsed = syntax::ParseOriginalNameComment(comment)) {
      ctx.module.original_names.push_back({entity, parsed->model, parsed->name, e.GetLoc()});
      return parsed;
    }
  }
  return std::nullopt;
}

}  // namespace mdlc::frontend
