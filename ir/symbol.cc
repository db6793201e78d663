#include "ir/symbol.h"

namespace mdlc {

SymbolTable::SymbolTable() {
  strings_.emplace_back();
  index_.emplace(std::string_view(strings_.back()), 0);
}

SymbolTable::SymbolTable(const SymbolTable& other) : strings_(other.strings_) { Reindex(); }

SymbolTable& SymbolTable::operator=(const SymbolTable& other) {
  if (this != &other) {
    strings_ = other.strings_;
    Reindex();
  }
  return *this;
}

void SymbolTable::Reindex() {
  index_.clear();
  index_.reserve(strings_.size());
  for (size_t i = 0; i < strings_.size(); ++i) {
    index_.emplace(std::string_view(strings_[i]), static_cast<uint32_t>(i));
  }
}

Symbol SymbolTable::Intern(std::string_view text) {
  if (auto it = index_.find(text); it != index_.end()) return Symbol{it->second};
  strings_.emplace_back(text);
  const auto id = static_cast<uint32_t>(strings_.size() - 1);
  index_.emplace(std::string_view(strings_.back()), id);
  return Symbol{id};
}

Symbol SymbolTable::Find(std::string_view text) const {
  auto it = index_.find(text);
  return it == index_.end() ? Symbol{} : Symbol{it->second};
}

}  // namespace mdlc
