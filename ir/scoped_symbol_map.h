// scoped_symbol_map.h - a table of names by (scope, symbol), whose root
// scope is indexed by the symbol itself.
//
// The frame graph's names and the module's model instances are each one
// table of every scope's names. In a world of many models the root scope
// (the world's model frames, the top-level instances) holds one name per
// model, and in a hash table each of those inserts and lookups lands in a
// random slot: at 100,000 models the tables no longer fit in the cache and
// every one of them missed. A model's name is interned as its model is
// read, so the root scope's symbols come one after another; indexed by the
// symbol, their entries are written and read in order, next to each other.
// Every other scope keeps its names in the hash table.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <absl/container/flat_hash_map.h>

#include "ir/symbol.h"

namespace mdlc::ir {

/// (scope, name) -> Value, where Value is an Id (default-constructed:
/// invalid, which stands for "absent" in the root scope's index).
template <typename Value>
class ScopedSymbolMap {
 public:
  explicit ScopedSymbolMap(uint32_t root_scope) : root_scope_(root_scope) {}

  /// The value of `name` in `scope`; null when it has none.
  const Value* Find(uint32_t scope, Symbol name) const {
    if (scope == root_scope_) {
      if (name.value >= root_.size() || !root_[name.value].valid()) return nullptr;
      return &root_[name.value];
    }
    auto it = others_.find(Key(scope, name));
    return it == others_.end() ? nullptr : &it->second;
  }

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
        ++root_count_;
      }
      return {&held, added};
    }
    auto [it, added] = others_.try_emplace(Key(scope, name), value);
    return {&it->second, added};
  }

  /// Removes the key's value, if it has one.
  void Erase(uint32_t scope, Symbol name) {
    if (scope == root_scope_) {
      if (name.value < root_.size() && root_[name.value].valid()) {
        root_[name.value] = Value();
        --root_count_;
      }
      return;
    }
    others_.erase(Key(scope, name));
  }

  /// Calls f(scope, name, value) for every entry: the root scope's in
  /// symbol order, then the others' in no particular order.
  template <typename F>
  void ForEach(F&& f) const {
    for (uint32_t i = 0; i < root_.size(); ++i) {
      if (root_[i].valid()) f(root_scope_, Symbol{i}, root_[i]);
    }
    for (const auto& [key, value] : others_) {
      f(static_cast<uint32_t>(key >> 32), Symbol{static_cast<uint32_t>(key)}, value);
    }
  }

  /// Room for `entries` more names outside the root scope.
  void Reserve(size_t entries) { others_.reserve(others_.size() + entries); }
  size_t size() const { return root_count_ + others_.size(); }
  void clear() {
    root_.clear();
    root_count_ = 0;
    others_.clear();
  }

  friend bool operator==(const ScopedSymbolMap& a, const ScopedSymbolMap& b) {
    if (a.root_scope_ != b.root_scope_ || a.root_count_ != b.root_count_ ||
        a.others_ != b.others_) {
      return false;
    }
    // equal up to the shorter index; past it, only absent entries
    const auto& [shorter, longer] =
        a.root_.size() <= b.root_.size() ? std::tie(a.root_, b.root_) : std::tie(b.root_, a.root_);
    for (size_t i = 0; i < longer.size(); ++i) {
      if ((i < shorter.size() ? shorter[i] : Value()) != longer[i]) return false;
    }
    return true;
  }

 private:
  static uint64_t Key(uint32_t scope, Symbol name) { return (uint64_t{scope} << 32) | name.value; }

  uint32_t root_scope_;
  std::vector<Value> root_;  // by symbol
  size_t root_count_ = 0;
  absl::flat_hash_map<uint64_t, Value> others_;
};

}  // namespace mdlc::ir
