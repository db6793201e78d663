// assets.h - `mdlc assets` (issue 15): every file a model uses, and for each
// one that could not be found, why (the diagnostic says where mdlc looked).
#pragma once

#include <string>

#include "mdlc/mdlc.h"

namespace mdlc::tools {

struct AssetReport {
  std::string text;  // or JSON
  bool all_found = true;
};

/// The model files read (inputs and what they include), then each distinct
/// mesh and texture: the URI as written, the file it resolved to, its format
/// (extension) and size, and how many geometries use it; or the error or
/// warning that reported it missing. `result` may hold errors: what was read
/// before them is listed.
AssetReport ListAssets(const Result& result, bool json);

}  // namespace mdlc::tools
