#include "mdlc/pass_list.h"

#include "passes/pass_registry.h"
#include "tools/driver/result_access.h"

namespace mdlc {

const std::vector<PassListing>& PassList() {
  // the registry keeps its views of each pass's name and description for
  // the program's life, so these may view the same text
  static const std::vector<PassListing> list = [] {
    std::vector<PassListing> out;
    for (const passes::PassInfo& info : passes::RegisteredPasses()) {
      out.push_back({info.name, info.description});
    }
    return out;
  }();
  return list;
}

const std::string& TimingReport(const Result& result) {
  return ResultAccess::compilation(result).timing_report();
}

}  // namespace mdlc
