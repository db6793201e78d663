// symbol.h - interned strings. A Symbol is a 32-bit handle; equal strings get
// equal handles, so comparing and hashing names is an integer operation.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <unordered_map>

namespace mdlc {

struct Symbol {
  uint32_t value = 0;  // 0 is the empty string
  bool empty() const { return value == 0; }
  friend bool operator==(Symbol, Symbol) = default;
};

struct SymbolHash {
  size_t operator()(Symbol s) const { return s.value; }
};

/// Copying a table copies its strings and builds the copy its own index, so
/// a copy stays valid after the original is gone. Moving keeps the strings
/// where they are (a deque's elements do not move with it); a moved-from
/// table may only be assigned to or destroyed.
class SymbolTable {
 public:
  SymbolTable();
  SymbolTable(const SymbolTable& other);
  SymbolTable& operator=(const SymbolTable& other);
  SymbolTable(SymbolTable&&) = default;
  SymbolTable& operator=(SymbolTable&&) = default;
  Symbol Intern(std::string_view text);
  /// Returns the symbol if `text` was interned before; the empty symbol otherwise.
  Symbol Find(std::string_view text) const;
  std::string_view Text(Symbol s) const { return strings_[s.value]; }
  size_t size() const { return strings_.size(); }

 private:
  /// Rebuilds index_ from strings_ (after a copy: the views must point into
  /// this table's own strings, never the original's).
  void Reindex();

  // deque: growing never moves existing strings, so the map's views stay valid
  std::deque<std::string> strings_;
  // views into strings_ (of this table only)
  std::unordered_map<std::string_view, uint32_t> index_;
};

}  // namespace mdlc
