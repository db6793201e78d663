// mdlc/pass_list.h - the built-in passes and what each does, for a caller
// that shows them (`mdlc --list-passes`), and what a compile's passes took
// (`--time-passes`), without reaching into the passes' own headers: the
// command line is built on the public API alone. Developer instrumentation,
// apart from Result (mdlc.h).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace mdlc {

struct PassListing {
  std::string_view name;         // as --passes and --print-after take it
  std::string_view description;  // one line
};

/// Every built-in pass, in the default pipeline's order.
const std::vector<PassListing>& PassList();

class Result;
/// The time each pass took, and the mesh cache and reader used, of a compile
/// made with Options::instrumentation.time_passes; empty otherwise.
const std::string& TimingReport(const Result& result);

}  // namespace mdlc
