#include "frontend/xml/document_cache.h"

namespace mdlc::xml {

std::shared_ptr<const XmlDocument> DocumentCache::Parse(FileId file, const SourceManager& sources,
                                                        DiagnosticEngine& diags) {
  const std::string& path = sources.Path(file);
  auto [it, first_load] = by_path_.try_emplace(path);
  // the file may have changed between loads: share only the same text
  if (it->second && sources.Contents(it->second->file()) == sources.Contents(file)) {
    ++reused_;
    return XmlDocument::SameTextAs(it->second, file);
  }
  const size_t reported = diags.error_count() + diags.warning_count();
  std::shared_ptr<const XmlDocument> doc = XmlDocument::Parse(file, sources, diags);
  const bool clean = doc && diags.error_count() + diags.warning_count() == reported;
  if (!first_load && clean) it->second = doc;
  return doc;
}

}  // namespace mdlc::xml
