// scoped_symbol_map.h - a table of names by (scope, symbol) whose common
// entries are found by index, not by hash.
//
// The frame graph's names and the module's model instances are each one
// table of every scope's names. In a world of many models each model adds
// two: its name in the root scope (the world's model frames, the top-level
// instances) and its link's name in its own scope. In a hash table each of
// those inserts and lookups lands in a random slot, and at 100,000 models
// the tables no longer fit in the cache and every one of them missed.
// Here neither is hashed:
// - the root scope is indexed by the symbol: a model's name is interned as
//   the model is read, so the root scope's symbols come one after another
//   and their entries are written and read in order, next to each other;
// - every other scope's first name is indexed by the scope, whose ids also
//   come in order; most scopes (a one-link model, a nesting level) hold one
//   name or a few.
// A scope's further names go to a hash table.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include <absl/container/flat_hash_map.h>

#include "ir/symbol.h"

namespace mdlc::ir {

/// (scope, name) -> Value, where Value is an Id (default-constructed:
/// invalid, which stands for "absent" in the indexes).
template <typename Value>
class ScopedSymbolMap {
 public:
  explicit ScopedSymbolMap(uint32_t root_scope) : root_scope_(root_scope) {}

  /// The value of `name` in `scope`; null when it has none.
  const Value* Find(uint32_t scope, Symbol name) const { return SlotIn(*this, scope, name); }

  /// Adds (scope, name) -> value unless the key has a value. Returns the
  /// value the key holds (valid until the next insertion) and whether it
  /// was added.
  std::pair<Value*, bool> TryAdd(uint32_t scope, Symbol name, Value value) {
    if (scope == root_scope_) {
      if (name.value >= root_.size()) root_.resize(name.value + 1);
      Value& held = root_[name.value];
      const bool added = !held.valid();
      if (added) {
        held = value;
        ++size_;
      }
      return {&held, added};
    }
    if (scope >= first_.size()) first_.resize(scope + 1);
    First& first = first_[scope];
    if (first.value.valid() && first.name == name) return {&first.value, false};
    // an empty first index means the scope has no other name unless an
    // erase emptied it, so only then is the hash table asked
    if (!first.value.valid() && (!first_vacated_ || !others_.contains(Key(scope, name)))) {
      first = First{name, value};
      ++size_;
      return {&first.value, true};
    }
    auto [it, added] = others_.try_emplace(Key(scope, name), value);
    size_ += added;
    return {&it->second, added};
  }

  /// Removes the key's value, if it has one.
  void Erase(uint32_t scope, Symbol name) {
    Value* held = SlotIn(*this, scope, name);
    if (!held) return;
    const bool indexed = scope == root_scope_ || held == &first_[scope].value;
    if (indexed) {
      *held = Value();
      if (scope != root_scope_) first_vacated_ = true;
    } else {
      others_.erase(Key(scope, name));
    }
    --size_;
  }

  /// Calls f(scope, name, value) for every entry, in no particular order.
  template <typename F>
  void ForEach(F&& f) const {
    for (uint32_t i = 0; i < root_.size(); ++i) {
      if (root_[i].valid()) f(root_scope_, Symbol{i}, root_[i]);
    }
    for (uint32_t scope = 0; scope < first_.size(); ++scope) {
      if (first_[scope].value.valid()) f(scope, first_[scope].name, first_[scope].value);
    }
    for (const auto& [key, value] : others_) {
      f(static_cast<uint32_t>(key >> 32), Symbol{static_cast<uint32_t>(key)}, value);
    }
  }

  /// Room for `entries` more names beyond each scope's first.
  void Reserve(size_t entries) { others_.reserve(others_.size() + entries); }
  size_t size() const { return size_; }
  void clear() {
    root_.clear();
    first_.clear();
    others_.clear();
    size_ = 0;
    first_vacated_ = false;
  }

  /// The same entries, however they are stored.
  friend bool operator==(const ScopedSymbolMap& a, const ScopedSymbolMap& b) {
    return a.root_scope_ == b.root_scope_ && a.Entries() == b.Entries();
  }

 private:
  struct First {
    Symbol name;
    Value value;
  };
  static uint64_t Key(uint32_t scope, Symbol name) { return (uint64_t{scope} << 32) | name.value; }

  // The value held for (scope, name), or null; `Self` is the map, const
  // or not, and the pointer is as const as it.
  template <typename Self>
  static auto SlotIn(Self& self, uint32_t scope, Symbol name) -> decltype(&self.root_[0]) {
    if (scope == self.root_scope_) {
      if (name.value >= self.root_.size() || !self.root_[name.value].valid()) return nullptr;
      return &self.root_[name.value];
    }
    // a scope with a name past its first has its index too (TryAdd)
    if (scope >= self.first_.size()) return nullptr;
    auto& first = self.first_[scope];
    if (first.value.valid() && first.name == name) return &first.value;
    if (self.others_.empty()) return nullptr;
    auto it = self.others_.find(Key(scope, name));
    return it == self.others_.end() ? nullptr : &it->second;
  }

  std::vector<std::tuple<uint32_t, uint32_t, uint32_t>> Entries() const {
    std::vector<std::tuple<uint32_t, uint32_t, uint32_t>> out;
    out.reserve(size_);
    ForEach([&](uint32_t scope, Symbol name, Value value) {
      out.emplace_back(scope, name.value, value.value);
    });
    std::sort(out.begin(), out.end());
    return out;
  }

  uint32_t root_scope_;
  std::vector<Value> root_;    // the root scope's, by symbol
  std::vector<First> first_;   // each other scope's first name, by scope
  absl::flat_hash_map<uint64_t, Value> others_;
  size_t size_ = 0;
  bool first_vacated_ = false;  // whether an erase ever emptied a first index
};

}  // namespace mdlc::ir
