// fuzz_xacro.cc - a libFuzzer harness for the xacro stage (frontend/xacro,
// with frontend/pyexpr for its ${...} expressions): the input is the text of
// a `.urdf.xacro` file, held in memory, expanded as `mdlc compile` expands
// it, then written out as `mdlc xacro` writes it and turned into the XML
// document the format readers take. Any crash, leak, sanitizer report or
// hang is a bug: bad input must only ever give diagnostics. What the readers
// do with an expansion is fuzz_urdf's, fuzz_sdf's and fuzz_mjcf's.
//
// The expansion reads no file and no environment variable of the machine
// it runs on:
// - the text is named inside an empty folder made for this process, which
//   relative paths (an include, $(find fuzz_pkg)) resolve against;
// - the include-depth limit is 0, so an <xacro:include> or
//   xacro.load_yaml() is refused before its file is looked at, wherever it
//   is (an absolute path too);
// - an input that writes $(env ...) or $(optenv ...) is not run (libFuzzer
//   keeps it out of the corpus).
// An include whose file name is a glob pattern does list the folders the
// pattern names (the sandbox, for a relative one) before it is refused.
//
// Lower limits than a compile's keep each input fast: a macro that calls
// itself twice per level stops at expansion_nodes, not after minutes.
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>

#include "ir/assets/package_map.h"
#include "frontend/xacro/xacro.h"
#include "frontend/xml/xml_document.h"
#include "ir/diagnostics.h"
#include "ir/source_manager.h"

namespace {

std::string& Sandbox() {
  static std::string sandbox;
  return sandbox;
}

/// Whether the text has a `$(env NAME)` or `$(optenv NAME ...)`
/// substitution: its command is the first word after `$(` and spaces.
bool ReadsEnvironment(std::string_view text) {
  for (size_t at = text.find("$("); at != std::string_view::npos; at = text.find("$(", at + 2)) {
    std::string_view rest = text.substr(at + 2);
    rest.remove_prefix(std::min(rest.find_first_not_of(' '), rest.size()));
    if (rest.starts_with("opt")) rest.remove_prefix(3);
    if (rest.starts_with("env")) return true;
  }
  return false;
}

mdlc::Limits FuzzLimits() {
  mdlc::Limits limits;
  limits.include_depth = 0;       // no include or YAML file is read (above)
  limits.macro_depth = 32;        // a compile's is 200
  limits.expansion_nodes = 20000;  // a compile's is 2,000,000
  limits.elements = 20000;        // of the input document
  limits.depth = 256;
  return limits;
}

/// Reads the document as a format reader does, and prints a diagnostic at
/// the first elements as a reader's error about expanded text would be
/// printed: with the macro calls and includes that placed it there.
void ReadDocument(const mdlc::xml::XmlElement& element, const mdlc::SourceManager& sources,
                  int& reported, int depth = 0) {
  if (depth > 1000) return;  // the reader's own walk is bounded by the depth limit
  std::string storage;
  (void)element.TextView(storage);
  element.ForEachAttributeName([&](std::string_view name) {
    const mdlc::xml::XmlAttribute a = element.Attribute(name);
    (void)a.value;
  });
  if (reported < 16) {
    ++reported;
    const mdlc::Diagnostic d{mdlc::DiagKind::XacroMessage, mdlc::Severity::Note, element.GetLoc(),
                             std::string(element.Name()), {}};
    (void)mdlc::FormatDiagnosticText(d, sources);
  }
  for (mdlc::xml::XmlElement child = element.FirstChild(); child; child = child.NextSibling()) {
    ReadDocument(child, sources, reported, depth + 1);
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/mdlc-fuzz-xacro-XXXXXX";
  if (!mkdtemp(pattern.data())) {
    std::perror("fuzz_xacro: cannot make a sandbox folder");
    std::abort();
  }
  Sandbox() = pattern;
  // the folder stays empty; it is removed when the fuzzer ends
  std::atexit([] { rmdir(Sandbox().c_str()); });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (ReadsEnvironment(text)) return -1;

  mdlc::SourceManager sources;
  sources.set_limits(FuzzLimits());
  mdlc::DiagnosticPolicy policy;
  policy.max_errors = 50;  // a long tail of errors adds nothing
  mdlc::DiagnosticEngine diags(policy);
  // $(find fuzz_pkg) names the (empty) sandbox
  mdlc::assets::PackageMap packages;
  packages.Add("fuzz_pkg", Sandbox(), diags);

  mdlc::xacro::XacroOptions options;
  options.args = {{"prefix", "fuzz_"}, {"scale", "2.5"}};  // as NAME:=VALUE arguments
  options.packages = &packages;
  const mdlc::FileId file = sources.AddBuffer(Sandbox() + "/fuzz.urdf.xacro", text);
  std::unique_ptr<mdlc::xacro::Expansion> expansion =
      mdlc::xacro::ExpandBuffer(file, options, sources, diags);
  if (expansion && !diags.has_errors()) {
    // what `mdlc xacro` writes, and what `mdlc compile` hands a reader
    (void)mdlc::xacro::WriteXml(*expansion, "fuzz.urdf.xacro");
    std::unique_ptr<mdlc::xml::XmlDocument> doc =
        mdlc::xacro::ToXmlDocument(*expansion, sources);
    int reported = 0;
    if (doc && doc->Root()) ReadDocument(doc->Root(), sources, reported);
  }
  // exercise what a user reads: each diagnostic with the macro calls and
  // includes that led to it
  for (const mdlc::Diagnostic& d : diags.diagnostics()) {
    (void)mdlc::FormatDiagnosticText(d, sources);
    (void)mdlc::FormatDiagnosticJson(d, sources);
  }
  return 0;
}
