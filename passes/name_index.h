// name_index.h - lookup of entities by (model instance, local name), and the
// scoped-name rules shared by every pass that resolves references
// (COMMON-030..033).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <absl/container/flat_hash_map.h>

#include "ir/module.h"
#include "ir/scoped_name.h"

namespace mdlc::passes {

using ir::ClosestName;
using ir::SplitName;
using ir::SplitScopedName;

template <typename IdT>
class NameIndex {
 public:
  void Add(ModelId model, Symbol name, IdT id) { map_.emplace(Key(model, name), id); }
  std::optional<IdT> Find(ModelId model, Symbol name) const {
    auto it = map_.find(Key(model, name));
    if (it == map_.end()) return std::nullopt;
    return it->second;
  }

 private:
  static uint64_t Key(ModelId model, Symbol name) {
    return (uint64_t{model.value} << 32) | name.value;
  }
  absl::flat_hash_map<uint64_t, IdT> map_;
};

/// A NameIndex of one IR table (its entities from `first` on), built on its
/// first lookup: a module whose references the frontends already resolved
/// (the SDFormat and MJCF frontends resolve theirs) never builds one. The
/// table must not change between lookups.
template <typename IdT, typename Table>
class LazyNameIndex {
 public:
  LazyNameIndex(const Table& table, size_t first) : table_(table), first_(first) {}
  std::optional<IdT> Find(ModelId model, Symbol name) const {
    if (!built_) {
      for (size_t i = first_; i < table_.size(); ++i) {
        index_.Add(table_[i].model, table_[i].name, IdT(i));
      }
      built_ = true;
    }
    return index_.Find(model, name);
  }

 private:
  const Table& table_;
  size_t first_;
  mutable bool built_ = false;
  mutable NameIndex<IdT> index_;
};

/// Model instances by full name, or by a name relative to another instance;
/// found by walking nested instances (Module::FindModel), never through a
/// table of full names, which would grow with the square of the nesting depth.
class ModelIndex {
 public:
  explicit ModelIndex(const ir::Module& module) : module_(&module) {}
  std::optional<ModelId> Find(std::string_view name) const { return module_->FindModel(name); }
  /// "<within>::name"
  std::optional<ModelId> Find(std::string_view name, ModelId within) const {
    return module_->FindModel(name, within);
  }

 private:
  const ir::Module* module_;
};

}  // namespace mdlc::passes
