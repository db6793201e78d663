// lexer.h - tokens of a Python expression.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "frontend/pyexpr/value.h"

namespace mdlc::pyexpr {

struct Token {
  enum class Type { kName, kInt, kFloat, kStr, kOp, kEnd };
  Type type = Type::kEnd;
  std::string text;  // kName: the name; kOp: the operator; kStr: the decoded string
  int64_t int_value = 0;
  double float_value = 0;
  size_t offset = 0;  // byte offset of the token's first character
  Value big_value;    // kInt beyond 64 bits: the int (else None)
};

// Splits the expression into tokens, ending with a kEnd token. Newlines and
// comments count as white space (xacro expressions sit in attributes).
Result<std::vector<Token>> Lex(std::string_view text);

bool IsKeyword(std::string_view name);

}  // namespace mdlc::pyexpr
