// repeated_warnings.cc - see repeated_warnings.h.
#include "repeated_warnings.h"

#include <fmt/format.h>

#include "ir/count_text.h"

namespace mdlc::cli {

bool RepeatedWarnings::FirstOfItsKind(std::string_view group, std::string_view message,
                                      std::string_view where) {
  std::string key;
  key.reserve(group.size() + 1 + message.size());
  key.append(group).push_back('\0');
  key.append(message);
  auto [it, first] = index_.try_emplace(std::move(key), kinds_.size());
  if (first) {
    kinds_.push_back({std::string(where), std::string(group), std::string(message), 0});
    return true;
  }
  ++kinds_[it->second].repeats;
  ++hidden_;
  return false;
}

std::string RepeatedWarnings::Notes() const {
  std::string out;
  for (const Kind& kind : kinds_) {
    if (kind.repeats == 0) continue;
    const bool one = kind.repeats == 1;
    out += fmt::format("{}: note: {} '{}' {} not shown [-fno-collapse shows {}]\n", kind.where,
                       ir::CountOf(kind.repeats, "more warning"), kind.message,
                       one ? "was" : "were", one ? "it" : "them");
  }
  return out;
}

}  // namespace mdlc::cli
