#include "frontend/xml/document_cache.h"

namespace mdlc::xml {

std::shared_ptr<const XmlDocument> DocumentCache::Parse(FileId file, const SourceManager& sources,
                                                        DiagnosticEngine& diags) {
  const std::string& path = sources.Path(file);
  if (auto it = by_path_.find(path); it != by_path_.end()) {
    // the file may have changed between loads: share only the same text
    if (sources.Contents(it->second->file()) == sources.Contents(file)) {
      ++reused_;
      return XmlDocument::SameTextAs(it->second, file);
    }
  }
  const size_t reported = diags.error_count() + diags.warning_count();
  std::shared_ptr<const XmlDocument> doc = XmlDocument::Parse(file, sources, diags);
  if (doc && diags.error_count() + diags.warning_count() == reported) by_path_[path] = doc;
  return doc;
}

}  // namespace mdlc::xml
