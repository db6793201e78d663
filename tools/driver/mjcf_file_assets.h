// mjcf_file_assets.h - the files an MJCF model names that mdlc does not
// read into its IR (textures, height fields, skins), for `mdlc assets`: a
// user packaging a model needs them all the same. It lives with the driver,
// which may read XML (frontend/xml), so the command line needs no frontend
// header of its own.
#pragma once

#include <string>
#include <vector>

#include "ir/location.h"
#include "ir/source_manager.h"

namespace mdlc::tools {

struct MjcfFileAsset {
  std::string kind;      // texture, hfield or skin
  std::string uri;       // as written
  std::string resolved;  // where MuJoCo would look (texturedir, meshdir, assetdir)
  Loc loc;               // the attribute that names it
};

/// The <texture>, <hfield> and <skin> files of the MJCF files among `sources`
/// (an included file's assets too), each file attribute once, in file order.
std::vector<MjcfFileAsset> MjcfFileAssets(const SourceManager& sources);

}  // namespace mdlc::tools
