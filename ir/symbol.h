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

class SymbolTable {
 public:
  SymbolTable();
  Symbol Intern(std::string_view text);
  /// Returns the symbol if `text` was interned before; the empty symbol otherwise.
  Symbol Find(std::string_view text) const;
  std::string_view Text(Symbol s) const { return strings_[s.value]; }
  size_t size() const { return strings_.size(); }

 private:
  // deque: growing never moves existing strings, so the map's views stay valid
  std::deque<std::string> strings_;
  std::unordered_map<std::string_view, uint32_t> index_;
};

}  // namespace mdlc
