// writer_base.cc - see writer_base.h.
#include "backend/writers/writer_base.h"

namespace mdlc::writers {

WriterBase::WriterBase(const backend::CompiledModel& model, const ir::Module& module,
                       const WriteOptions& options, DiagnosticEngine& diags)
    : plant_(model.plant),
      scene_(model.scene),
      m_(module),
      diags_(diags),
      assets_(options, diags) {
  size_t ir_index = 0;
  geometry_locs_.reserve(scene_.geometries.size());
  for (size_t i = 0; i < scene_.geometries.size(); ++i) {
    while (ir_index < m_.geometries.size() && m_.geometries[ir_index].roles == 0) ++ir_index;
    geometry_locs_.push_back(ir_index < m_.geometries.size() ? m_.geometries[ir_index].loc
                                                             : Loc{});
    ++ir_index;
  }
}

const ir::Property* WriterBase::FindProperty(const backend::SceneGeometry& g,
                                             std::string_view key) {
  for (const ir::Property& p : g.properties) {
    if (p.key == key) return &p;
  }
  return nullptr;
}

bool WriterBase::IsAppearanceProperty(const ir::Property& p) {
  return p.key.starts_with("phong/") || p.key.starts_with("renderer/") ||
         p.key.starts_with("label/");
}

}  // namespace mdlc::writers
