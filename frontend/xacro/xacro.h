// xacro.h - the xacro stage: ROS's XML macro language expanded natively.
//
// A file ending in `.xacro` is expanded here, before any format reader sees
// it, exactly as ros/xacro 2.x expands it (properties, macros, includes,
// conditionals, args and `${...}` Python expressions, which frontend/pyexpr
// evaluates without any Python). The result is a tree whose every node is
// placed where its text is written; diagnostics about expanded text carry
// the chain of macro calls and includes that put it there.
//
//   Expansion e = ExpandFile("robot.urdf.xacro", options, sources, diags);
//   std::unique_ptr<xml::XmlDocument> doc = ToXmlDocument(*e, sources);  // for a reader
//   std::string text = WriteXml(*e);                                    // `mdlc xacro`
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "frontend/xacro/xacro_tree.h"
#include "ir/diagnostics.h"
#include "ir/source_manager.h"

namespace mdlc::assets {
class PackageMap;
}
namespace mdlc::xml {
class XmlDocument;
}

namespace mdlc::xacro {

struct XacroOptions {
  /// xacro's NAME:=VALUE arguments, which `$(arg NAME)` reads and which win
  /// over an <xacro:arg> default.
  std::vector<std::pair<std::string, std::string>> args;
  /// Where `$(find PKG)` looks (the compile's package map); null: nowhere.
  const assets::PackageMap* packages = nullptr;
};

/// An expanded document.
struct Expansion {
  Tree tree;
  Node* root = nullptr;  // the document element
  FileId file;           // the top-level file
  /// The top-level file's comments before and after its root element.
  std::vector<std::string> comments_before_root;
  std::vector<std::string> comments_after_root;
  /// Every file the expansion read after the top-level one (includes and
  /// YAML files), in the order first read, as `xacro --deps` lists them.
  std::vector<std::string> dependencies;
};

/// Whether `path` names a xacro file (`*.xacro`, so also `*.urdf.xacro`).
bool IsXacroPath(std::string_view path);

/// Expands the file at `path`; null after reporting an error.
std::unique_ptr<Expansion> ExpandFile(const std::string& path, const XacroOptions& options,
                                      SourceManager& sources, DiagnosticEngine& diags);
/// Expands a buffer already loaded.
std::unique_ptr<Expansion> ExpandBuffer(FileId file, const XacroOptions& options,
                                        SourceManager& sources, DiagnosticEngine& diags);

/// The expansion as an XML document for the format readers. Whitespace-only
/// text between elements is dropped, as the readers' own parse drops it.
std::unique_ptr<xml::XmlDocument> ToXmlDocument(const Expansion& expansion,
                                                const SourceManager& sources);

/// The expansion as XML text, with xacro's banner naming `shown_name`
/// (the input as the user wrote it), indented as xacro indents it.
std::string WriteXml(const Expansion& expansion, std::string_view shown_name);

}  // namespace mdlc::xacro
