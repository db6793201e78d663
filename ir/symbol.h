// symbol.h - interned strings. A Symbol is a 32-bit handle; equal strings get
// equal handles, so comparing and hashing names is an integer operation.
#pragma once

#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

namespace mdlc {

struct Symbol {
  uint32_t value = 0;  // 0 is the empty string
  bool empty() const { return value == 0; }
  friend bool operator==(Symbol, Symbol) = default;
};

struct SymbolHash {
  size_t operator()(Symbol s) const { return s.value; }
};

/// The table keeps its texts in large blocks (each text followed by a NUL)
/// and indexes them with a flat open-addressing table of (hash, id) pairs: a
/// model interns a name or more per element, and a node-based map's
/// allocation per name, its rehashing walks and its freeing, node by node,
/// were a fifth of lowering a large model.
///
/// Copying a table copies its texts and builds the copy its own index, so a
/// copy stays valid after the original is gone. Moving keeps the texts where
/// they are; a moved-from table may only be assigned to or destroyed.
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
  /// The text, NUL-terminated in the table's storage.
  std::string_view Text(Symbol s) const { return texts_[s.value]; }
  size_t size() const { return texts_.size(); }

 private:
  static constexpr uint32_t kNoId = UINT32_MAX;
  struct Slot {
    uint32_t hash = 0;   // low bits of the text's hash
    uint32_t id = kNoId;
  };

  /// The slot holding `text`, or the empty slot where it would go.
  size_t Probe(std::string_view text, uint32_t hash) const;
  /// Copies `text` into the blocks, NUL-terminated.
  std::string_view Store(std::string_view text);
  /// Doubles the slots and re-places every id (hashes are kept in the slots).
  void Grow();

  std::vector<std::string_view> texts_;  // by id; views into blocks_
  std::vector<std::unique_ptr<char[]>> blocks_;
  char* block_next_ = nullptr;
  size_t block_left_ = 0;
  std::vector<Slot> slots_;  // a power of two long, at most half full
};

}  // namespace mdlc
