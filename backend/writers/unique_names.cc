#include "backend/writers/unique_names.h"

#include <fmt/format.h>

namespace mdlc::writers {

std::string UniqueNames::TakeSuffixed(const std::string& base) {
  int& next = next_suffix_.try_emplace(base, 1).first->second;
  std::string name;
  while (!Take(name = fmt::format("{}_{}", base, next))) ++next;
  ++next;
  return name;
}

}  // namespace mdlc::writers
