// builtins.h - the names xacro puts in every expression's globals.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "frontend/pyexpr/value.h"

namespace mdlc::pyexpr {

// What xacro 2.0 exposes (create_global_symbols): list dict map len str
// float int True False min max round, sorted and range, the `python`
// namespace (those and abs all any complex divmod enumerate filter frozenset
// hash isinstance issubclass ord repr reversed slice set sum tuple type
// zip), the `math` namespace and every public math name directly. Not the
// `xacro` namespace: the host builds that with the helpers below.
//
// Where Python returns an iterator (map, filter, zip, enumerate, reversed)
// or a range, these return a list: expressions index and iterate them the
// same way, and only str() of the result differs (Python would print an
// iterator's address, which no model wants). complex, frozenset, set,
// slice, hash and issubclass report kUnsupported naming the builtin.
const NameTable& StandardGlobals();

// xacro.dotify: the dict with attribute access (d.key); other values as they are.
Value Dotify(const Value& dict);

// xacro.tokenize: s split at any of the separator characters; empty pieces
// dropped when skip_empty.
std::vector<std::string> Tokenize(std::string_view s, std::string_view separators = ",; ", bool skip_empty = true);

}  // namespace mdlc::pyexpr
