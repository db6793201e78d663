// element_counts.h - how many elements of each name a document holds,
// counted while its tree is built, so a frontend can size the IR's tables
// for exactly what the document will add (frontend/entity_capacity.h).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace mdlc::xml {

class ElementCounts {
 public:
  /// Counts one element. `name` must be the tree's interned copy (libxml2's
  /// dictionary entry, or the builder's one copy of a prefixed name): the
  /// count is keyed by its address, so counting is a pointer hash and a probe.
  void Add(std::string_view name) {
    Slot& slot = Find(name.data());
    if (slot.count++ == 0) {
      slot.size = name.size();
      if (++used_ * 2 > slots_.size()) Grow();
    }
  }

  /// How many elements are named `name` ("link", "drake:joint").
  uint64_t Of(std::string_view name) const {
    uint64_t total = 0;
    for (const Slot& slot : slots_) {
      if (slot.count && std::string_view(slot.key, slot.size) == name) total += slot.count;
    }
    return total;
  }

 private:
  struct Slot {
    const char* key = nullptr;
    size_t size = 0;
    uint64_t count = 0;
  };
  Slot& Find(const char* key) {
    const size_t mask = slots_.size() - 1;
    // Fibonacci hashing of the address; the low bits of an allocation's
    // address carry little
    size_t i = (reinterpret_cast<uintptr_t>(key) * 0x9E3779B97F4A7C15ull) >> 40 & mask;
    while (slots_[i].key != key && slots_[i].key != nullptr) i = (i + 1) & mask;
    slots_[i].key = key;
    return slots_[i];
  }
  void Grow() {
    std::vector<Slot> old(slots_.size() * 2);
    old.swap(slots_);
    for (const Slot& slot : old) {
      if (slot.count) Find(slot.key) = slot;
    }
  }

  std::vector<Slot> slots_ = std::vector<Slot>(64);  // a power of two, at most half full
  size_t used_ = 0;
};

}  // namespace mdlc::xml
