// model_instance_names.h - the plant's model instance names, kept as the IR
// keeps them: each instance's parent and its own local name. Spelling every
// name out in full would cost O(depth) per instance and O(N^2) for N nested
// instances (issue 16); here a full name is built only when it is asked for.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "ir/ids.h"

namespace mdlc::backend {

class ModelInstanceNames {
 public:
  /// Adds the next instance: `local` below `parent` (invalid: top level, where
  /// `local` is the whole name).
  void Add(std::string local, ModelId parent);

  size_t size() const { return entries_.size(); }
  /// Instance `m`'s own name, below its parent.
  const std::string& local(size_t m) const { return entries_[m].local; }
  /// Instance `m`'s parent, or an invalid id at top level.
  ModelId parent(size_t m) const {
    const ModelId p = entries_[m].parent;
    return p.valid() && p.index() < entries_.size() ? p : ModelId();
  }
  bool empty() const { return entries_.empty(); }
  /// The full name of instance `m`, "a::b::c" (O(depth)).
  std::string operator[](size_t m) const;
  std::string back() const { return (*this)[size() - 1]; }
  /// "instance::local" for an entity of instance `model`.
  std::string Scoped(ModelId model, std::string_view local) const;
  /// Every full name, by ModelId.
  std::vector<std::string> ToVector() const;

  /// Iterates the full names in ModelId order (each built as it is read).
  class Iterator {
   public:
    Iterator(const ModelInstanceNames* names, size_t index) : names_(names), index_(index) {}
    std::string operator*() const { return (*names_)[index_]; }
    Iterator& operator++() {
      ++index_;
      return *this;
    }
    bool operator==(const Iterator& other) const { return index_ == other.index_; }

   private:
    const ModelInstanceNames* names_;
    size_t index_;
  };
  Iterator begin() const { return {this, 0}; }
  Iterator end() const { return {this, size()}; }

 private:
  // appends instance m's full name to `out`
  void AppendName(size_t m, std::string& out) const;

  struct Entry {
    std::string local;
    ModelId parent;
  };
  std::vector<Entry> entries_;
};

}  // namespace mdlc::backend
