#include "ir/symbol.h"

#include <algorithm>
#include <cstring>

#include <absl/hash/hash.h>
#include <absl/strings/string_view.h>

namespace mdlc {

namespace {
constexpr size_t kBlockSize = 64 * 1024;
constexpr size_t kInitialSlots = 256;

// absl's string hash, not std::hash: names are short, and for short texts
// it takes fewer instructions than std::hash's. It is asked for through
// absl::string_view because the installed absl has its own string_view type,
// and for std::string_view it would fall back to std::hash. Its per-process
// seed moves names between slots, never their ids, which follow the order
// of interning.
uint32_t HashText(std::string_view text) {
  return static_cast<uint32_t>(
      absl::Hash<absl::string_view>()(absl::string_view(text.data(), text.size())));
}
}  // namespace

SymbolTable::SymbolTable() : slots_(kInitialSlots) {
  texts_.emplace_back("");  // symbol 0; never placed in the slots
}

SymbolTable::SymbolTable(const SymbolTable& other) : SymbolTable() {
  // re-interning in id order gives every text its id again
  texts_.reserve(other.texts_.size());
  for (size_t i = 1; i < other.texts_.size(); ++i) Intern(other.texts_[i]);
}

SymbolTable& SymbolTable::operator=(const SymbolTable& other) {
  if (this != &other) *this = SymbolTable(other);
  return *this;
}

size_t SymbolTable::Probe(std::string_view text, uint32_t hash) const {
  const size_t mask = slots_.size() - 1;
  for (size_t i = hash & mask;; i = (i + 1) & mask) {
    const Slot& slot = slots_[i];
    if (slot.id == kNoId) return i;
    if (slot.hash == hash && texts_[slot.id] == text) return i;
  }
}

std::string_view SymbolTable::Store(std::string_view text) {
  const size_t need = text.size() + 1;
  if (need > block_left_) {
    const size_t size = std::max(kBlockSize, need);
    blocks_.push_back(std::make_unique<char[]>(size));
    block_next_ = blocks_.back().get();
    block_left_ = size;
  }
  char* out = block_next_;
  if (!text.empty()) std::memcpy(out, text.data(), text.size());
  out[text.size()] = '\0';
  block_next_ += need;
  block_left_ -= need;
  return std::string_view(out, text.size());
}

void SymbolTable::Grow() {
  std::vector<Slot> old(slots_.size() * 2);
  old.swap(slots_);
  const size_t mask = slots_.size() - 1;
  for (const Slot& slot : old) {
    if (slot.id == kNoId) continue;
    size_t i = slot.hash & mask;
    while (slots_[i].id != kNoId) i = (i + 1) & mask;
    slots_[i] = slot;
  }
}

Symbol SymbolTable::Intern(std::string_view text) {
  if (text.empty()) return Symbol{};
  const uint32_t hash = HashText(text);
  size_t at = Probe(text, hash);
  if (slots_[at].id != kNoId) return Symbol{slots_[at].id};
  const auto id = static_cast<uint32_t>(texts_.size());
  texts_.push_back(Store(text));
  slots_[at] = Slot{hash, id};
  if (texts_.size() * 2 > slots_.size()) Grow();
  return Symbol{id};
}

Symbol SymbolTable::Find(std::string_view text) const {
  if (text.empty()) return Symbol{};
  const Slot& slot = slots_[Probe(text, HashText(text))];
  return slot.id == kNoId ? Symbol{} : Symbol{slot.id};
}

}  // namespace mdlc
