// convert.cc - mdlc/convert.h: the compiled model through a writer, its
// diagnostics reported to an engine of the convert's own so that the Result
// stays as the compile left it.
#include "mdlc/convert.h"

#include <stdexcept>

#include "backend/writers/writer.h"
#include "tools/driver/obj_transcoder.h"
#include "tools/driver/result_access.h"

namespace mdlc {

ConvertOutput Convert(const Result& result, const ConvertOptions& options) {
  if (!result.has_model()) {
    throw std::logic_error("mdlc: nothing to convert; the compile did not make a model");
  }
  const Compilation& c = ResultAccess::compilation(result);
  writers::WriteOptions write;
  write.to = options.to;
  write.output = options.output;
  if (options.copy_assets_dir) write.copy_assets_dir = *options.copy_assets_dir;
  write.keep_package_uris = options.keep_package_uris;
  write.fuse_fixed = options.fuse_fixed;
  write.plain = options.plain;
  // the compile's mesh cache: a mesh it read is not read again for an OBJ copy
  ObjTranscoder meshes(*c.meshes);
  write.meshes = &meshes;
  // -Werror, -Wno-lossy and --max-errors apply as they did to the compile
  DiagnosticEngine diags(c.options.diagnostics);
  ConvertOutput out;
  out.text = writers::Write(*c.model, c.module, write, diags);
  out.error_count = diags.error_count();
  out.warning_count = diags.warning_count();
  out.diagnostics = diags.TakeDiagnostics();
  return out;
}

}  // namespace mdlc
