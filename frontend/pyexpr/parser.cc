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
    if (tok.type == T::kName && tok.text == "async")
      return Error{Error::Kind::kSyntax, "asynchronous comprehensions are not allowed here", tok.offset};
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
    if (IsWord("lambda")) return Lambda();
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
      size_t arg_at = Peek().offset;
      auto value = Test();
      if (!value.ok()) return value;
      if (IsWord("for")) {
        // a generator expression: the sole argument unless parenthesized
        if (!arg_name.empty()) return Unexpected(Peek());
        auto gen = Comprehension(Node::Type::kGenExp, arg_at, std::move(*value));
        if (!gen.ok()) return gen;
        if (n->kids.size() != 1 || IsOp(","))
          return Error{Error::Kind::kSyntax, "a generator expression must be parenthesized unless it is the sole argument",
                       arg_at};
        value = std::move(gen);
      }
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
        n->constant = tok.big_value.IsInt() ? tok.big_value : Value::Int(tok.int_value);
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
          return Error{Error::Kind::kSyntax, "a lambda must be parenthesized here", tok.offset};
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
    if (IsWord("for")) {
      if ((*inner)->type == Node::Type::kTuple || (*inner)->type == Node::Type::kStarred) return Unexpected(Peek());
      auto gen = Comprehension(Node::Type::kGenExp, open, std::move(*inner));
      if (!gen.ok()) return gen;
      auto closed = Expect(")", open, "(");
      if (!closed.ok()) return std::move(closed).error();
      return gen;
    }
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
      if (IsWord("for")) {
        if (!n->kids.empty()) return Unexpected(Peek());
        if ((*item)->type == Node::Type::kStarred)
          return Error{Error::Kind::kSyntax, "iterable unpacking cannot be used in a comprehension", (*item)->offset};
        auto comp = Comprehension(Node::Type::kListComp, open, std::move(*item));
        if (!comp.ok()) return comp;
        auto closed = Expect("]", open, "[");
        if (!closed.ok()) return std::move(closed).error();
        return comp;
      }
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
          if (IsWord("for")) return Error{Error::Kind::kUnsupported, "sets are not supported", open};
          if (IsOp(",") || IsOp("}")) return Error{Error::Kind::kUnsupported, "sets are not supported", open};
          return Unexpected(Peek());
        }
        Next();
        auto value = Test();
        if (!value.ok()) return value;
        if (IsWord("for")) {
          if (!n->kids.empty()) return Unexpected(Peek());
          auto comp = Comprehension(Node::Type::kDictComp, open, std::move(*key), std::move(*value));
          if (!comp.ok()) return comp;
          auto closed = Expect("}", open, "{");
          if (!closed.ok()) return std::move(closed).error();
          return comp;
        }
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

  // The clauses after a comprehension's element (the cursor is at 'for'):
  // ('for' targets 'in' or_test ('if' or_test)*)+
  Result<NodePtr> Comprehension(Node::Type type, size_t offset, NodePtr element, NodePtr value = nullptr) {
    auto n = Make(type, offset);
    n->kids.push_back(std::move(element));
    if (value) n->kids.push_back(std::move(value));
    while (IsWord("for") || IsWord("if") || IsWord("async")) {
      if (IsWord("async")) return Unexpected(Peek());
      Depth depth(*this);
      if (depth.exceeded()) return TooDeep(Peek().offset);
      const Token& word = Next();
      if (word.text == "if") {
        auto clause = Make(Node::Type::kCompIf, word.offset);
        auto cond = Or();
        if (!cond.ok()) return cond;
        clause->kids.push_back(std::move(*cond));
        n->kids.push_back(std::move(clause));
        continue;
      }
      auto clause = Make(Node::Type::kCompFor, word.offset);
      auto target = TargetList();
      if (!target.ok()) return target;
      if ((*target)->type == Node::Type::kStarred)
        return Error{Error::Kind::kSyntax, "a starred assignment target must be in a list or tuple", (*target)->offset};
      if (!IsWord("in")) return Unexpected(Peek());
      Next();
      auto iterable = Or();
      if (!iterable.ok()) return iterable;
      clause->kids.push_back(std::move(*target));
      clause->kids.push_back(std::move(*iterable));
      n->kids.push_back(std::move(clause));
    }
    return n;
  }

  bool StartsTarget() const {
    return IsOp("(") || IsOp("[") || IsOp("*") || (Peek().type == T::kName && !IsKeyword(Peek().text));
  }

  // target (',' target)* [','] -> a tuple when there is a comma; at most one
  // starred target
  Result<NodePtr> TargetList() {
    size_t start = Peek().offset;
    auto first = Target();
    if (!first.ok() || !IsOp(",")) return first;
    auto tuple = Make(Node::Type::kTuple, start);
    tuple->kids.push_back(std::move(*first));
    while (IsOp(",")) {
      Next();
      if (!StartsTarget()) break;
      auto item = Target();
      if (!item.ok()) return item;
      tuple->kids.push_back(std::move(*item));
    }
    auto starred = CheckStarredTargets(*tuple);
    if (!starred.ok()) return std::move(starred).error();
    return tuple;
  }

  static Result<bool> CheckStarredTargets(const Node& list) {
    int starred = 0;
    for (const auto& kid : list.kids) starred += kid->type == Node::Type::kStarred;
    if (starred > 1) return Error{Error::Kind::kSyntax, "multiple starred expressions in assignment", list.offset};
    return true;
  }

  // a name, '*' target, or a parenthesized / bracketed target list
  Result<NodePtr> Target() {
    Depth depth(*this);
    if (depth.exceeded()) return TooDeep(Peek().offset);
    const Token& tok = Peek();
    if (IsOp("*")) {
      Next();
      auto inner = Target();
      if (!inner.ok()) return inner;
      if ((*inner)->type == Node::Type::kStarred)
        return Error{Error::Kind::kSyntax, "a starred target cannot be starred again", (*inner)->offset};
      auto n = Make(Node::Type::kStarred, tok.offset);
      n->kids.push_back(std::move(*inner));
      return n;
    }
    if (IsOp("(") || IsOp("[")) {
      bool paren = IsOp("(");
      size_t open = Next().offset;
      const char* close = paren ? ")" : "]";
      auto list = Make(paren ? Node::Type::kTuple : Node::Type::kList, open);
      bool comma = false;
      while (!IsOp(close)) {
        auto item = Target();
        if (!item.ok()) return item;
        list->kids.push_back(std::move(*item));
        if (!IsOp(",")) break;
        comma = true;
        Next();
      }
      auto closed = Expect(close, open, paren ? "(" : "[");
      if (!closed.ok()) return std::move(closed).error();
      if (paren && !comma && list->kids.size() == 1) {
        if (list->kids[0]->type == Node::Type::kStarred)
          return Error{Error::Kind::kSyntax, "a starred assignment target must be in a list or tuple", open};
        return std::move(list->kids[0]);
      }
      auto starred = CheckStarredTargets(*list);
      if (!starred.ok()) return std::move(starred).error();
      return list;
    }
    if (tok.type != T::kName || IsKeyword(tok.text)) return Unexpected(tok);
    if (tok.text.starts_with("__"))
      return Error{Error::Kind::kUnsupported, fmt::format("names starting with '__' are not allowed ('{}')", tok.text),
                   tok.offset};
    Next();
    if (IsOp(".") || IsOp("[") || IsOp("("))
      return Error{Error::Kind::kUnsupported, "only names can be assigned in a comprehension", Peek().offset};
    auto n = Make(Node::Type::kName, tok.offset);
    n->name = tok.text;
    return n;
  }

  // 'lambda' [parameters] ':' test
  Result<NodePtr> Lambda() {
    auto n = Make(Node::Type::kLambda, Next().offset);
    bool seen_default = false, seen_star = false, bare_star = false, seen_slash = false;
    size_t star_at = 0;
    while (!IsOp(":")) {
      if (!n->arg_names.empty() && n->arg_names.back() == "**") return Unexpected(Peek());
      const Token& tok = Peek();
      std::string kind = seen_star ? "kw" : "";
      if (IsOp("/")) {
        if (seen_slash || seen_star || n->ops.empty()) return Unexpected(tok);
        Next();
        seen_slash = true;
        for (auto& k : n->arg_names) k = "/";
        if (!IsOp(",")) break;
        Next();
        continue;
      }
      if (IsOp("**")) {
        Next();
        kind = "**";
      } else if (IsOp("*")) {
        if (seen_star) return Unexpected(tok);
        star_at = Next().offset;
        seen_star = true;
        if (IsOp(",") || IsOp(":")) {
          bare_star = true;
          if (!IsOp(",")) break;
          Next();
          continue;
        }
        kind = "*";
      }
      const Token& name = Peek();
      if (name.type != T::kName || IsKeyword(name.text)) return Unexpected(name);
      if (name.text.starts_with("__"))
        return Error{Error::Kind::kUnsupported, fmt::format("names starting with '__' are not allowed ('{}')", name.text),
                     name.offset};
      for (const auto& earlier : n->ops)
        if (earlier == name.text)
          return Error{Error::Kind::kSyntax, fmt::format("duplicate argument '{}' in lambda", name.text), name.offset};
      Next();
      NodePtr default_value;
      if (IsOp("=") && (kind == "" || kind == "kw")) {
        Next();
        auto value = Test();
        if (!value.ok()) return value;
        default_value = std::move(*value);
        if (kind == "") seen_default = true;
      } else if (kind == "" && seen_default) {
        return Error{Error::Kind::kSyntax, "non-default argument follows default argument", name.offset};
      }
      n->ops.push_back(name.text);
      n->op_offsets.push_back(name.offset);
      n->arg_names.push_back(kind);
      n->kids.push_back(std::move(default_value));
      if (!IsOp(",")) break;
      Next();
    }
    bool keyword_only = false;
    for (const auto& k : n->arg_names) keyword_only = keyword_only || k == "kw";
    if (bare_star && !keyword_only)
      return Error{Error::Kind::kSyntax, "named arguments must follow bare *", star_at};
    if (!IsOp(":")) return Unexpected(Peek());
    Next();
    auto body = Test();
    if (!body.ok()) return body;
    n->body = std::shared_ptr<const Node>(std::move(*body));
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
