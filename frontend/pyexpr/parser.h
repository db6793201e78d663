// parser.h - the syntax tree of a Python expression.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "frontend/pyexpr/value.h"

namespace mdlc::pyexpr {

struct Node;
using NodePtr = std::unique_ptr<Node>;

struct Node {
  enum class Type {
    kConst,     // constant
    kName,      // name
    kTuple,     // kids
    kList,      // kids
    kDict,      // kids: key, value, key, value... (a null key: `**mapping`)
    kBinary,    // kids[0] ops[0] kids[1] ops[1] kids[2]... (left-associative chain)
    kPower,     // kids[0] ** kids[1]
    kUnary,     // ops[0] kids[0]: '-', '+', '~'
    kNot,       // not kids[0]
    kAnd,       // kids[0] and kids[1] and ...
    kOr,        // kids[0] or kids[1] or ...
    kCompare,   // kids[0] ops[0] kids[1] ops[1] kids[2]... ('<', 'in', 'not in', 'is not', ...)
    kIfElse,    // kids[0] if kids[1] else kids[2]
    kAttribute, // kids[0].name
    kSubscript, // kids[0][kids[1]]
    kSlice,     // kids[0]:kids[1]:kids[2], any may be null
    kCall,      // kids[0](kids[1..]) with arg_names
    kStarred,   // *kids[0] inside a list/tuple display (or a target list)
    // Comprehensions: the element (kDictComp: key and value) first, then the
    // clauses in order, each a kCompFor or a kCompIf.
    kListComp,  // [kids[0] for ...]
    kDictComp,  // {kids[0]: kids[1] for ...}
    kGenExp,    // (kids[0] for ...), evaluated eagerly to a list
    kCompFor,   // for kids[0] in kids[1]: kids[0] is a target (kName, kTuple, kList, kStarred)
    kCompIf,    // if kids[0]
    kLambda,    // lambda: parameter names in ops, their kinds in arg_names
                // ("" positional or keyword, "/" positional-only, "*" the
                // *args, "kw" keyword-only, "**" the **kwargs); kids: each
                // parameter's default (null if none); the body in `body`
  };
  Type type = Type::kConst;
  size_t offset = 0;  // where the node's text starts (for operators: the operator)
  Value constant;
  std::string name;
  std::vector<std::string> ops;
  std::vector<size_t> op_offsets;
  std::vector<NodePtr> kids;
  // kCall: per argument after the callee: "" positional, "*" unpacked
  // sequence, "**" unpacked mapping, else the keyword's name
  std::vector<std::string> arg_names;
  // kLambda: the body, shared with the function values the lambda creates
  // (they outlive the tree)
  std::shared_ptr<const Node> body;
};

// Parses a whole expression (a tuple when it has top-level commas). Nesting
// deeper than max_depth is a kLimit error.
Result<NodePtr> Parse(std::string_view text, int max_depth);

}  // namespace mdlc::pyexpr
