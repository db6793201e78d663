// unknown_element.cc - see unknown_element.h.
#include "frontend/unknown_element.h"

#include <fmt/format.h>

#include <vector>

#include "ir/scoped_name.h"

namespace mdlc::frontend {

void ReportUnknownElement(DiagnosticEngine& diags, const xml::XmlElement& child,
                          std::string_view parent, std::initializer_list<std::string_view> known) {
  const std::string_view tag = child.Name();
  auto diag = diags.Report(DiagKind::UnknownElement, child.GetLoc(),
                           fmt::format("unknown element <{}> in <{}> is ignored", tag, parent));
  if (auto best = ir::ClosestName(tag, std::vector(known))) {
    diag.Note(child.GetLoc(), fmt::format("did you mean <{}>?", *best));
  }
}

}  // namespace mdlc::frontend
