// xml_declaration.h - the version an XML declaration names, checked before
// libxml2 reads it.
//
// libxml2 refuses a document whose declaration names a version that does not
// start with "1." (`<?xml version="0.0" ?>`, written by some exporters and
// found in pybullet's models) as a fatal error, while urdfdom, MuJoCo and
// Drake (all on tinyxml2) read such files as XML 1.0. mdlc reads them too,
// with a warning: the declaration is handed to libxml2 with "1.0" in its
// place. Versions 1.x are XML 1.0 to libxml2 already and pass untouched.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace mdlc::xml {

/// Where the value of the version pseudo-attribute sits in `text`.
struct DeclaredVersion {
  size_t offset = 0;       // of the value's first character
  std::string_view value;  // as written, without its quotes
};

/// The version `text`'s XML declaration names when it is one libxml2 would
/// refuse (anything not "1." followed by digits); nullopt when there is no
/// declaration, no version, or a version libxml2 reads.
std::optional<DeclaredVersion> UnsupportedXmlVersion(std::string_view text);

}  // namespace mdlc::xml
