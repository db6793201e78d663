// mdlc/pass_list.h - the built-in passes and what each does, for a caller
// that shows them (`mdlc --list-passes`), without reaching into the passes'
// own headers: the command line is built on the public API alone.
#pragma once

#include <string_view>
#include <vector>

namespace mdlc {

struct PassListing {
  std::string_view name;         // as --passes and --print-after take it
  std::string_view description;  // one line
};

/// Every built-in pass, in the default pipeline's order.
const std::vector<PassListing>& PassList();

}  // namespace mdlc
