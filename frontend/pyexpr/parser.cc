// parser.cc - recursive descent over Python's expression grammar.
#include "frontend/pyexpr/parser.h"

#include <fmt/format.h>

#include "frontend/pyexpr/lexer.h"

namespace mdlc::pyexpr {
namespace {

using T = Token::Type;

class Parser {
 public:
  Parser(std::vector<Token> tokens, int max_depth) : t_(std::move(tokens)), max_depth_(max_depth) {}

  Result<NodePtr> ParseAll() {
    auto node = TestList(/*allow_star=*/true);
    if (!node.ok()) return node;
    if (Peek().type != T::kEnd) return Unexpected(Peek());
    return node;
  }

 private:
  // Counts nesting; Exit on every path out of a counted rule.
  class Depth {
   public:
    explicit Depth(Parser& p) : p_(p) { ++p_.depth_; }
    ~Depth() { --p_.depth_; }
    Depth(const Depth&) = delete;
    Depth& operator=(const Depth&) = delete;
    bool exceeded() const { return p_.depth_ > p_.max_depth_; }

   private:
    Parser& p_;
  };

  const Token& Peek(size_t ahead = 0) const { return t_[std::min(i_ + ahead, t_.size() - 1)]; }
  bool IsOp(std::string_view op, size_t ahead = 0) const {
    return Peek(ahead).type == T::kOp && Peek(ahead).text == op;
  }
  bool IsWord(std::string_view word, size_t ahead = 0) const {
    return Peek(ahead).type == T::kName && Peek(ahead).text == word;
  }
  const Token& Next() { return t_[i_ < t_.size() - 1 ? i_++ : i_]; }

  Error Unexpected(const Token& tok) const {
    if (tok.type == T::kEnd) return Error{Error::Kind::kSyntax, "unexpected end of expression", tok.offset};
    if (tok.type == T::kName && (tok.text == "for" || tok.text == "async"))
      return Error{Error::Kind::kUnsupported, "comprehensions are not supported", tok.offset};
    if (tok.type == T::kOp && tok.text == "=")
      return Error{Error::Kind::kSyntax, "'=' is not an expression (use '==' to compare)", tok.offset};
    if (tok.type == T::kOp && tok.text == ":=")
      return Error{Error::Kind::kUnsupported, "assignment expressions are not supported", tok.offset};
    std::string what = tok.type == T::kStr ? "string" : (tok.type == T::kInt || tok.type == T::kFloat) ? "number" : tok.text;
    return Error{Error::Kind::kSyntax, fmt::format("invalid syntax at '{}'", what), tok.offset};
  }

  Result<bool> Expect(std::string_view op, size_t open_offset, std::string_view open) {
    if (IsOp(op)) {
      Next();
      return true;
    }
    if (Peek().type == T::kEnd)
      return Error{Error::Kind::kSyntax, fmt::format("'{}' was never closed", open), open_offset};
    return Unexpected(Peek());
  }

  Error TooDeep(size_t offset) const {
    return Error{Error::Kind::kLimit, fmt::format("expression nested deeper than the limit of {} levels", max_depth_),
                 offset};
  }

  static NodePtr Make(Node::Type type, size_t offset) {
    auto n = std::make_unique<Node>();
    n->type = type;
    n->offset = offset;
    return n;
  }

  bool StartsExpression() const {
    const Token& tok = Peek();
    switch (tok.type) {
      case T::kEnd: return false;
      case T::kOp:
        return tok.text == "(" || tok.text == "[" || tok.text == "{" || tok.text == "-" || tok.text == "+" ||
               tok.text == "~" || tok.text == "*";
      case T::kName:
        return !IsKeyword(tok.text) || tok.text == "not" || tok.text == "None" || tok.text == "True" ||
               tok.text == "False" || tok.text == "lambda";
      default: return true;
    }
  }

  // test (',' test)* [','] -> a tuple when there is a comma
  Result<NodePtr> TestList(bool allow_star) {
    size_t start = Peek().offset;
    auto first = StarOrTest(allow_star);
    if (!first.ok()) return first;
    if (!IsOp(",")) {
      if ((*first)->type == Node::Type::kStarred)
        return Error{Error::Kind::kSyntax, "a starred expression cannot stand alone", (*first)->offset};
      return first;
    }
    auto tuple = Make(Node::Type::kTuple, start);
    tuple->kids.push_back(std::move(*first));
    while (IsOp(",")) {
      Next();
      if (!StartsExpression()) break;
      auto item = StarOrTest(allow_star);
      if (!item.ok()) return item;
      tuple->kids.push_back(std::move(*item));
    }
    return tuple;
  }

  Result<NodePtr> StarOrTest(bool allow_star) {
    if (allow_star && IsOp("*")) {
      size_t at = Next().offset;
      auto inner = Or();
      if (!inner.ok()) return inner;
      auto n = Make(Node::Type::kStarred, at);
      n->kids.push_back(std::move(*inner));
      return n;
    }
    return Test();
  }

  // or_test ['if' or_test 'else' test] | lambda
  Result<NodePtr> Test() {
    Depth depth(*this);
    if (depth.exceeded()) return TooDeep(Peek().offset);
    if (IsWord("lambda")) return Error{Error::Kind::kUnsupported, "lambda is not supported", Peek().offset};
    auto value = Or();
    if (!value.ok()) return value;
    if (IsOp(":=")) return Unexpected(Peek());
    if (!IsWord("if")) return value;
    size_t at = Next().offset;
    auto cond = Or();
    if (!cond.ok()) return cond;
    if (!IsWord("else")) {
      if (Peek().type == T::kEnd)
        return Error{Error::Kind::kSyntax, "a conditional expression needs 'else'", Peek().offset};
      return Unexpected(Peek());
    }
    Next();
    auto other = Test();
    if (!other.ok()) return other;
    auto n = Make(Node::Type::kIfElse, at);
    n->kids.push_back(std::move(*value));
    n->kids.push_back(std::move(*cond));
    n->kids.push_back(std::move(*other));
    return n;
  }

  Result<NodePtr> Or() {
    auto first = And();
    if (!first.ok() || !IsWord("or")) return first;
    auto n = Make(Node::Type::kOr, (*first)->offset);
    n->kids.push_back(std::move(*first));
    while (IsWord("or")) {
      n->op_offsets.push_back(Next().offset);
      auto next = And();
      if (!next.ok()) return next;
      n->kids.push_back(std::move(*next));
    }
    return n;
  }

  Result<NodePtr> And() {
    auto first = Not();
    if (!first.ok() || !IsWord("and")) return first;
    auto n = Make(Node::Type::kAnd, (*first)->offset);
    n->kids.push_back(std::move(*first));
    while (IsWord("and")) {
      n->op_offsets.push_back(Next().offset);
      auto next = Not();
      if (!next.ok()) return next;
      n->kids.push_back(std::move(*next));
    }
    return n;
  }

  Result<NodePtr> Not() {
    if (!IsWord("not")) return Comparison();
    Depth depth(*this);
    if (depth.exceeded()) return TooDeep(Peek().offset);
    size_t at = Next().offset;
    auto inner = Not();
    if (!inner.ok()) return inner;
    auto n = Make(Node::Type::kNot, at);
    n->kids.push_back(std::move(*inner));
    return n;
  }

  // the comparison operator at the cursor ("" if none), consuming it
  std::string ComparisonOp() {
    const Token& tok = Peek();
    if (tok.type == T::kOp) {
      for (std::string_view op : {"<", ">", "==", ">=", "<=", "!="})
        if (tok.text == op) {
          Next();
          return std::string(op);
        }
      return "";
    }
    if (IsWord("in")) {
      Next();
      return "in";
    }
    if (IsWord("not") && IsWord("in", 1)) {
      Next();
      Next();
      return "not in";
    }
    if (IsWord("is")) {
      Next();
      if (IsWord("not")) {
        Next();
        return "is not";
      }
      return "is";
    }
    return "";
  }

  Result<NodePtr> Comparison() {
    auto first = BitOr();
    if (!first.ok()) return first;
    NodePtr n;
    while (true) {
      size_t at = Peek().offset;
      std::string op = ComparisonOp();
      if (op.empty()) break;
      if (!n) {
        n = Make(Node::Type::kCompare, (*first)->offset);
        n->kids.push_back(std::move(*first));
      }
      auto next = BitOr();
      if (!next.ok()) return next;
      n->ops.push_back(op);
      n->op_offsets.push_back(at);
      n->kids.push_back(std::move(*next));
    }
    if (!n) return first;
    return n;
  }

  // A left-associative chain of the given operators over `sub`.
  template <typename Sub>
  Result<NodePtr> Chain(std::initializer_list<std::string_view> ops, Sub sub) {
    auto first = (this->*sub)();
    if (!first.ok()) return first;
    NodePtr n;
    while (Peek().type == T::kOp) {
      bool match = false;
      for (auto op : ops) match = match || Peek().text == op;
      if (!match) break;
      if (!n) {
        n = Make(Node::Type::kBinary, (*first)->offset);
        n->kids.push_back(std::move(*first));
      }
      const Token& op = Next();
      n->ops.push_back(op.text);
      n->op_offsets.push_back(op.offset);
      auto next = (this->*sub)();
      if (!next.ok()) return next;
      n->kids.push_back(std::move(*next));
    }
    if (!n) return first;
    return n;
  }

  Result<NodePtr> BitOr() { return Chain({"|"}, &Parser::BitXor); }
  Result<NodePtr> BitXor() { return Chain({"^"}, &Parser::BitAnd); }
  Result<NodePtr> BitAnd() { return Chain({"&"}, &Parser::Shift); }
  Result<NodePtr> Shift() { return Chain({"<<", ">>"}, &Parser::Arith); }
  Result<NodePtr> Arith() { return Chain({"+", "-"}, &Parser::Term); }
  Result<NodePtr> Term() { return Chain({"*", "/", "//", "%", "@"}, &Parser::Factor); }

  Result<NodePtr> Factor() {
    if (IsOp("-") || IsOp("+") || IsOp("~")) {
      Depth depth(*this);
      if (depth.exceeded()) return TooDeep(Peek().offset);
      const Token& op = Next();
      auto n = Make(Node::Type::kUnary, op.offset);
      n->ops.push_back(op.text);
      auto inner = Factor();
      if (!inner.ok()) return inner;
      n->kids.push_back(std::move(*inner));
      return n;
    }
    return Power();
  }

  Result<NodePtr> Power() {
    auto base = Primary();
    if (!base.ok() || !IsOp("**")) return base;
    Depth depth(*this);
    if (depth.exceeded()) return TooDeep(Peek().offset);
    size_t at = Next().offset;
    auto exponent = Factor();
    if (!exponent.ok()) return exponent;
    auto n = Make(Node::Type::kPower, at);
    n->kids.push_back(std::move(*base));
    n->kids.push_back(std::move(*exponent));
    return n;
  }

  Result<NodePtr> Primary() {
    auto node = Atom();
    if (!node.ok()) return node;
    NodePtr n = std::move(*node);
    int trailers = 0;
    while (true) {
      if (IsOp(".")) {
        size_t at = Next().offset;
        const Token& name = Peek();
        if (name.type != T::kName || IsKeyword(name.text)) return Unexpected(name);
        Next();
        if (name.text.starts_with("__"))
          return Error{Error::Kind::kUnsupported, fmt::format("names starting with '__' are not allowed ('{}')", name.text),
                       name.offset};
        auto a = Make(Node::Type::kAttribute, at);
        a->name = name.text;
        a->kids.push_back(std::move(n));
        n = std::move(a);
      } else if (IsOp("(")) {
        auto call = Call(std::move(n));
        if (!call.ok()) return call;
        n = std::move(*call);
      } else if (IsOp("[")) {
        size_t at = Next().offset;
        auto index = SubscriptList();
        if (!index.ok()) return index;
        auto closed = Expect("]", at, "[");
        if (!closed.ok()) return std::move(closed).error();
        auto s = Make(Node::Type::kSubscript, at);
        s->kids.push_back(std::move(n));
        s->kids.push_back(std::move(*index));
        n = std::move(s);
      } else {
        break;
      }
      // each trailer adds a level to the tree the evaluator walks
      if (++trailers > max_depth_) return TooDeep(Peek().offset);
    }
    return n;
  }

  Result<NodePtr> Call(NodePtr callee) {
    size_t open = Next().offset;
    auto n = Make(Node::Type::kCall, open);
    n->kids.push_back(std::move(callee));
    bool seen_keyword = false;
    while (!IsOp(")")) {
      std::string arg_name;
      if (IsOp("*") || IsOp("**")) {
        arg_name = Next().text;
      } else if (Peek().type == T::kName && IsOp("=", 1)) {
        if (IsKeyword(Peek().text)) return Unexpected(Peek());
        arg_name = Next().text;
        Next();
        for (const auto& earlier : n->arg_names)
          if (earlier == arg_name)
            return Error{Error::Kind::kSyntax, fmt::format("keyword argument '{}' repeated", arg_name), Peek().offset};
        seen_keyword = true;
      } else if (seen_keyword && Peek().type != T::kEnd) {
        return Error{Error::Kind::kSyntax, "a positional argument cannot follow keyword arguments", Peek().offset};
      }
      auto value = Test();
      if (!value.ok()) return value;
      if (IsWord("for"))
        return Error{Error::Kind::kUnsupported, "comprehensions are not supported", Peek().offset};
      n->arg_names.push_back(arg_name);
      n->kids.push_back(std::move(*value));
      if (!IsOp(",")) break;
      Next();
    }
    auto closed = Expect(")", open, "(");
    if (!closed.ok()) return std::move(closed).error();
    return n;
  }

  // subscript (',' subscript)* -> a tuple when there is a comma
  Result<NodePtr> SubscriptList() {
    size_t start = Peek().offset;
    auto first = Subscript();
    if (!first.ok() || !IsOp(",")) return first;
    auto tuple = Make(Node::Type::kTuple, start);
    tuple->kids.push_back(std::move(*first));
    while (IsOp(",")) {
      Next();
      if (IsOp("]")) break;
      auto item = Subscript();
      if (!item.ok()) return item;
      tuple->kids.push_back(std::move(*item));
    }
    return tuple;
  }

  Result<NodePtr> Subscript() {
    size_t start = Peek().offset;
    NodePtr lower;
    if (!IsOp(":")) {
      auto value = Test();
      if (!value.ok() || !IsOp(":")) return value;
      lower = std::move(*value);
    }
    auto slice = Make(Node::Type::kSlice, start);
    slice->kids.push_back(std::move(lower));
    Next();  // ':'
    NodePtr upper, step;
    if (!IsOp(":") && !IsOp("]") && !IsOp(",")) {
      auto value = Test();
      if (!value.ok()) return value;
      upper = std::move(*value);
    }
    if (IsOp(":")) {
      Next();
      if (!IsOp("]") && !IsOp(",")) {
        auto value = Test();
        if (!value.ok()) return value;
        step = std::move(*value);
      }
    }
    slice->kids.push_back(std::move(upper));
    slice->kids.push_back(std::move(step));
    return slice;
  }

  Result<NodePtr> Atom() {
    const Token& tok = Peek();
    switch (tok.type) {
      case T::kInt: {
        Next();
        auto n = Make(Node::Type::kConst, tok.offset);
        n->constant = Value::Int(tok.int_value);
        return n;
      }
      case T::kFloat: {
        Next();
        auto n = Make(Node::Type::kConst, tok.offset);
        n->constant = Value::Float(tok.float_value);
        return n;
      }
      case T::kStr: {
        auto n = Make(Node::Type::kConst, tok.offset);
        std::string s;
        while (Peek().type == T::kStr) s += Next().text;
        n->constant = Value::Str(std::move(s));
        return n;
      }
      case T::kName: {
        if (tok.text == "None" || tok.text == "True" || tok.text == "False") {
          Next();
          auto n = Make(Node::Type::kConst, tok.offset);
          if (tok.text != "None") n->constant = Value::Bool(tok.text == "True");
          return n;
        }
        if (tok.text == "lambda")
          return Error{Error::Kind::kUnsupported, "lambda is not supported", tok.offset};
        if (tok.text == "yield" || tok.text == "await")
          return Error{Error::Kind::kUnsupported, fmt::format("'{}' is not supported", tok.text), tok.offset};
        if (IsKeyword(tok.text)) return Unexpected(tok);
        if (tok.text.starts_with("__"))
          return Error{Error::Kind::kUnsupported, fmt::format("names starting with '__' are not allowed ('{}')", tok.text),
                       tok.offset};
        Next();
        auto n = Make(Node::Type::kName, tok.offset);
        n->name = tok.text;
        return n;
      }
      case T::kOp:
        if (tok.text == "(") return Parenthesized();
        if (tok.text == "[") return ListDisplay();
        if (tok.text == "{") return DictDisplay();
        if (tok.text == ")" || tok.text == "]" || tok.text == "}")
          return Error{Error::Kind::kSyntax, fmt::format("unmatched '{}'", tok.text), tok.offset};
        return Unexpected(tok);
      case T::kEnd: return Unexpected(tok);
    }
    return Unexpected(tok);
  }

  Result<NodePtr> Parenthesized() {
    size_t open = Next().offset;
    if (IsOp(")")) {
      Next();
      return Make(Node::Type::kTuple, open);
    }
    auto inner = TestList(/*allow_star=*/true);
    if (!inner.ok()) return inner;
    if (IsWord("for")) return Error{Error::Kind::kUnsupported, "generator expressions are not supported", Peek().offset};
    auto closed = Expect(")", open, "(");
    if (!closed.ok()) return std::move(closed).error();
    if ((*inner)->type == Node::Type::kTuple) (*inner)->offset = open;
    return inner;
  }

  Result<NodePtr> ListDisplay() {
    size_t open = Next().offset;
    auto n = Make(Node::Type::kList, open);
    while (!IsOp("]")) {
      auto item = StarOrTest(true);
      if (!item.ok()) return item;
      if (IsWord("for")) return Error{Error::Kind::kUnsupported, "comprehensions are not supported", Peek().offset};
      n->kids.push_back(std::move(*item));
      if (!IsOp(",")) break;
      Next();
    }
    auto closed = Expect("]", open, "[");
    if (!closed.ok()) return std::move(closed).error();
    return n;
  }

  Result<NodePtr> DictDisplay() {
    size_t open = Next().offset;
    auto n = Make(Node::Type::kDict, open);
    while (!IsOp("}")) {
      if (IsOp("**")) {
        Next();
        auto mapping = BitOr();
        if (!mapping.ok()) return mapping;
        n->kids.push_back(nullptr);
        n->kids.push_back(std::move(*mapping));
      } else {
        auto key = Test();
        if (!key.ok()) return key;
        if (!IsOp(":")) {
          if (IsWord("for")) return Error{Error::Kind::kUnsupported, "comprehensions are not supported", Peek().offset};
          if (IsOp(",") || IsOp("}")) return Error{Error::Kind::kUnsupported, "sets are not supported", open};
          return Unexpected(Peek());
        }
        Next();
        auto value = Test();
        if (!value.ok()) return value;
        if (IsWord("for")) return Error{Error::Kind::kUnsupported, "comprehensions are not supported", Peek().offset};
        n->kids.push_back(std::move(*key));
        n->kids.push_back(std::move(*value));
      }
      if (!IsOp(",")) break;
      Next();
    }
    auto closed = Expect("}", open, "{");
    if (!closed.ok()) return std::move(closed).error();
    return n;
  }

  std::vector<Token> t_;
  size_t i_ = 0;
  int depth_ = 0;
  int max_depth_;
};

}  // namespace

Result<NodePtr> Parse(std::string_view text, int max_depth) {
  auto tokens = Lex(text);
  if (!tokens.ok()) return std::move(tokens).error();
  return Parser(std::move(*tokens), max_depth).ParseAll();
}

}  // namespace mdlc::pyexpr
