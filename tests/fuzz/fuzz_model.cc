// fuzz_model.cc - a libFuzzer harness per model format (issue 16): the
// input is a model file's text, compiled as mdlc compiles a file, through
// every frontend, pass and the backend, then written out in each format as
// `mdlc convert` writes it. Any crash, leak, sanitizer report or
// hang is a bug: bad input must only ever give diagnostics.
//
// MDLC_FUZZ_FORMAT (a compile definition) picks the format; CMake builds one
// fuzzer per format from this file.
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>

#include "mdlc/convert.h"
#include "mdlc/kinematics.h"
#include "mdlc/mdlc.h"

namespace {
constexpr mdlc::Format kFormat = mdlc::Format::MDLC_FUZZ_FORMAT;

const char* FileName() {
  switch (kFormat) {
    case mdlc::Format::Urdf: return "fuzz.urdf";
    case mdlc::Format::Sdf: return "fuzz.sdf";
    case mdlc::Format::Mjcf: return "fuzz.xml";
    case mdlc::Format::Directives: return "fuzz.dmd.yaml";
  }
  return "fuzz";
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  mdlc::Options options;
  options.diagnostics.policy.max_errors = 50;  // a long tail of errors adds nothing
  mdlc::Result result = mdlc::Compile(
      mdlc::Input::Text(std::string(reinterpret_cast<const char*>(data), size), FileName(),
                        kFormat),
      options);
  // exercise what a user reads after a compile
  for (const mdlc::Diagnostic& d : result.diagnostics()) (void)result.FormatText(d);
  if (!result.has_model()) return 0;
  (void)mdlc::PlantJson(result, mdlc::DefaultPositions(result));
  // and what `mdlc convert` writes of it, in each format and with MJCF's
  // fused bodies (a lossy warning is a diagnostic; only a crash, leak or
  // hang is a finding). An error ends the model, so each write asks again.
  const mdlc::Format targets[] = {mdlc::Format::Urdf, mdlc::Format::Sdf, mdlc::Format::Mjcf,
                                  mdlc::Format::Mjcf};
  for (size_t i = 0; i < std::size(targets) && result.has_model(); ++i) {
    mdlc::ConvertOptions convert;
    convert.to = targets[i];
    convert.fuse_fixed = i == 3;
    (void)mdlc::Convert(result, convert);
  }
  return 0;
}
