// lexer.cc - Python literals and operators as tokens.
#include "frontend/pyexpr/lexer.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "frontend/pyexpr/internal.h"
#include "frontend/pyexpr/number_text.h"

namespace mdlc::pyexpr {
namespace {

bool IsNameStart(unsigned char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c >= 0x80; }
bool IsNameChar(unsigned char c) { return IsNameStart(c) || (c >= '0' && c <= '9'); }
bool IsDigit(char c) { return c >= '0' && c <= '9'; }
int DigitValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'z') return c - 'a' + 10;
  if (c >= 'A' && c <= 'Z') return c - 'A' + 10;
  return 99;
}

Error SyntaxError(std::string message, size_t offset) {
  return Error{Error::Kind::kSyntax, std::move(message), offset};
}

void AppendUtf8(uint32_t cp, std::string& out) {
  if (cp < 0x80) {
    out.push_back(static_cast<char>(cp));
  } else if (cp < 0x800) {
    out.push_back(static_cast<char>(0xC0 | (cp >> 6)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  } else if (cp < 0x10000) {
    out.push_back(static_cast<char>(0xE0 | (cp >> 12)));
    out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  } else {
    out.push_back(static_cast<char>(0xF0 | (cp >> 18)));
    out.push_back(static_cast<char>(0x80 | ((cp >> 12) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  }
}

class Lexer {
 public:
  explicit Lexer(std::string_view text) : s_(text) {}

  Result<std::vector<Token>> Run() {
    std::vector<Token> tokens;
    while (true) {
      SkipSpace();
      if (pos_ >= s_.size()) break;
      size_t start = pos_;
      unsigned char c = static_cast<unsigned char>(s_[pos_]);
      Result<Token> token = Error{};
      if (IsDigit(static_cast<char>(c)) || (c == '.' && pos_ + 1 < s_.size() && IsDigit(s_[pos_ + 1]))) {
        token = Number();
      } else if (IsNameStart(c)) {
        size_t end = pos_;
        while (end < s_.size() && IsNameChar(static_cast<unsigned char>(s_[end]))) ++end;
        std::string_view word = s_.substr(pos_, end - pos_);
        if (end < s_.size() && (s_[end] == '\'' || s_[end] == '"') && word.size() <= 2 && IsPrefix(word)) {
          token = String(word);
        } else {
          pos_ = end;
          token = Token{Token::Type::kName, std::string(word), 0, 0, start, {}};
        }
      } else if (c == '\'' || c == '"') {
        token = String("");
      } else {
        token = Operator();
      }
      if (!token.ok()) return std::move(token).error();
      token->offset = start;
      tokens.push_back(std::move(*token));
    }
    tokens.push_back(Token{Token::Type::kEnd, "", 0, 0, s_.size(), {}});
    return tokens;
  }

 private:
  static bool IsPrefix(std::string_view w) {
    static constexpr std::array<std::string_view, 24> kPrefixes = {
        "r", "u", "R", "U", "f", "F", "b", "B", "br", "Br", "bR", "BR", "rb", "rB", "Rb", "RB",
        "fr", "Fr", "fR", "FR", "rf", "rF", "Rf", "RF"};
    for (auto p : kPrefixes)
      if (p == w) return true;
    return false;
  }

  void SkipSpace() {
    while (pos_ < s_.size()) {
      char c = s_[pos_];
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
        ++pos_;
      } else if (c == '\\' && pos_ + 1 < s_.size() && (s_[pos_ + 1] == '\n' || s_[pos_ + 1] == '\r')) {
        pos_ += 2;
      } else if (c == '#') {
        while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
      } else {
        break;
      }
    }
  }

  // Digits of a base with single underscores between (and, for prefixed
  // literals, one after the prefix); appends them to out.
  Result<bool> Digits(int base, std::string& out, bool allow_leading_underscore) {
    size_t start = pos_;
    bool last_digit = false;
    while (pos_ < s_.size()) {
      char c = s_[pos_];
      if (c == '_') {
        bool ok_before = last_digit || (allow_leading_underscore && pos_ == start);
        if (!ok_before || pos_ + 1 >= s_.size() || DigitValue(s_[pos_ + 1]) >= base)
          return SyntaxError("invalid number literal", pos_);
        ++pos_;
        last_digit = false;
        continue;
      }
      if (DigitValue(c) >= base) break;
      out.push_back(c);
      ++pos_;
      last_digit = true;
    }
    return true;
  }

  Result<Token> Number() {
    size_t start = pos_;
    Token t;
    if (s_[pos_] == '0' && pos_ + 1 < s_.size() &&
        (s_[pos_ + 1] == 'x' || s_[pos_ + 1] == 'X' || s_[pos_ + 1] == 'o' || s_[pos_ + 1] == 'O' ||
         s_[pos_ + 1] == 'b' || s_[pos_ + 1] == 'B')) {
      char p = static_cast<char>(s_[pos_ + 1] | 0x20);
      int base = p == 'x' ? 16 : (p == 'o' ? 8 : 2);
      pos_ += 2;
      std::string digits;
      auto ok = Digits(base, digits, true);
      if (!ok.ok()) return std::move(ok).error();
      if (digits.empty()) return SyntaxError("invalid number literal", start);
      if (pos_ < s_.size() && IsNameChar(static_cast<unsigned char>(s_[pos_])))
        return SyntaxError("invalid number literal", start);
      t.type = Token::Type::kInt;
      return BigLiteral(std::move(t), digits, base, start);
    }
    std::string text;
    auto ok = Digits(10, text, false);
    if (!ok.ok()) return std::move(ok).error();
    bool is_float = false;
    if (pos_ < s_.size() && s_[pos_] == '.') {
      is_float = true;
      text.push_back('.');
      ++pos_;
      if (pos_ < s_.size() && IsDigit(s_[pos_])) {
        ok = Digits(10, text, false);
        if (!ok.ok()) return std::move(ok).error();
      }
    }
    if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
      size_t save = pos_;
      std::string exp = "e";
      ++pos_;
      if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) exp.push_back(s_[pos_++]);
      if (pos_ < s_.size() && IsDigit(s_[pos_])) {
        ok = Digits(10, exp, false);
        if (!ok.ok()) return std::move(ok).error();
        text += exp;
        is_float = true;
      } else {
        pos_ = save;
        return SyntaxError("invalid number literal", start);
      }
    }
    if (pos_ < s_.size() && (s_[pos_] == 'j' || s_[pos_] == 'J'))
      return Error{Error::Kind::kUnsupported, "complex numbers are not supported", start};
    if (is_float) {
      auto d = ParsePythonFloat(text);
      if (!d) return SyntaxError("invalid number literal", start);
      t.type = Token::Type::kFloat;
      t.float_value = *d;
      return t;
    }
    if (text.size() > 1 && text[0] == '0' && text.find_first_not_of('0') != std::string::npos)
      return SyntaxError("leading zeros are not allowed in decimal integers (use 0o for octal)", start);
    t.type = Token::Type::kInt;
    return BigLiteral(std::move(t), text, 10, start);
  }

  // an int literal's digits (no underscores) as int_value or big_value
  Result<Token> BigLiteral(Token t, std::string_view digits, int base, size_t start) {
    size_t first = digits.find_first_not_of('0');
    if (first == std::string_view::npos) return t;
    digits.remove_prefix(first);
    if (base == 10 && digits.size() > 4300)
      return Error{Error::Kind::kValue,
                   "the literal exceeds the limit (4300 digits) for integer string conversion", start};
    BigInt v = BigInt::FromDigits(digits, base);
    if (auto small = v.ToInt64()) {
      t.int_value = *small;
      return t;
    }
    auto ok = internal::CheckIntBits(static_cast<double>(v.BitLength()));
    if (!ok.ok()) return Error{ok.error().kind, ok.error().message, start};
    t.big_value = Value::Big(std::move(v));
    return t;
  }

  Result<Token> String(std::string_view prefix) {
    size_t start = pos_;
    bool raw = false;
    for (char c : prefix) {
      if (c == 'r' || c == 'R') raw = true;
      if (c == 'b' || c == 'B') return Error{Error::Kind::kUnsupported, "bytes literals are not supported", start};
      if (c == 'f' || c == 'F') return Error{Error::Kind::kUnsupported, "f-strings are not supported", start};
    }
    pos_ += prefix.size();
    char quote = s_[pos_];
    bool triple = pos_ + 2 < s_.size() && s_[pos_ + 1] == quote && s_[pos_ + 2] == quote;
    pos_ += triple ? 3 : 1;
    std::string out;
    while (true) {
      if (pos_ >= s_.size()) return SyntaxError("unterminated string literal", start);
      char c = s_[pos_];
      if (c == quote) {
        if (!triple) {
          ++pos_;
          break;
        }
        if (pos_ + 2 < s_.size() && s_[pos_ + 1] == quote && s_[pos_ + 2] == quote) {
          pos_ += 3;
          break;
        }
      }
      if (!triple && (c == '\n' || c == '\r')) return SyntaxError("unterminated string literal", start);
      if (c != '\\') {
        out.push_back(c);
        ++pos_;
        continue;
      }
      if (pos_ + 1 >= s_.size()) return SyntaxError("unterminated string literal", start);
      char e = s_[pos_ + 1];
      if (raw) {  // the backslash stays, and it keeps the next character from ending the string
        out.push_back('\\');
        out.push_back(e);
        pos_ += 2;
        continue;
      }
      size_t escape_at = pos_;
      pos_ += 2;
      switch (e) {
        case '\n': break;
        case '\\': out.push_back('\\'); break;
        case '\'': out.push_back('\''); break;
        case '"': out.push_back('"'); break;
        case 'a': out.push_back('\a'); break;
        case 'b': out.push_back('\b'); break;
        case 'f': out.push_back('\f'); break;
        case 'n': out.push_back('\n'); break;
        case 'r': out.push_back('\r'); break;
        case 't': out.push_back('\t'); break;
        case 'v': out.push_back('\v'); break;
        case 'x':
        case 'u':
        case 'U': {
          int n = e == 'x' ? 2 : (e == 'u' ? 4 : 8);
          uint32_t cp = 0;
          for (int k = 0; k < n; ++k) {
            if (pos_ >= s_.size() || DigitValue(s_[pos_]) >= 16)
              return SyntaxError(std::string("truncated \\") + e + " escape", escape_at);
            cp = cp * 16 + static_cast<uint32_t>(DigitValue(s_[pos_++]));
          }
          if (cp > 0x10FFFF) return SyntaxError("invalid unicode escape", escape_at);
          AppendUtf8(cp, out);
          break;
        }
        case 'N': return Error{Error::Kind::kUnsupported, "\\N{...} escapes are not supported", escape_at};
        default:
          if (e >= '0' && e <= '7') {
            uint32_t cp = static_cast<uint32_t>(e - '0');
            for (int k = 0; k < 2 && pos_ < s_.size() && s_[pos_] >= '0' && s_[pos_] <= '7'; ++k)
              cp = cp * 8 + static_cast<uint32_t>(s_[pos_++] - '0');
            AppendUtf8(cp, out);
          } else {
            out.push_back('\\');
            out.push_back(e);
          }
      }
    }
    Token t;
    t.type = Token::Type::kStr;
    t.text = std::move(out);
    return t;
  }

  Result<Token> Operator() {
    static constexpr std::array<std::string_view, 12> kTwo = {"**", "//", "<<", ">>", "<=", ">=",
                                                              "==", "!=", "->", ":=", "<>", "..."};
    Token t;
    t.type = Token::Type::kOp;
    if (s_.substr(pos_, 3) == "...")
      return Error{Error::Kind::kUnsupported, "the ellipsis is not supported", pos_};
    for (auto op : kTwo) {
      if (s_.substr(pos_, op.size()) == op) {
        if (op == "<>") break;
        // augmented assignment operators are statements
        if (pos_ + 2 < s_.size() && s_[pos_ + 2] == '=' && (op == "**" || op == "//" || op == "<<" || op == ">>"))
          return SyntaxError("assignments are not expressions", pos_);
        t.text = std::string(op);
        pos_ += op.size();
        return t;
      }
    }
    char c = s_[pos_];
    static constexpr std::string_view kSingles = "+-*/%@&|^~<>()[]{},:.;=";
    if (kSingles.find(c) == std::string_view::npos) {
      return SyntaxError(std::string("invalid character '") + c + "'", pos_);
    }
    t.text = std::string(1, c);
    ++pos_;
    return t;
  }

  std::string_view s_;
  size_t pos_ = 0;
};

}  // namespace

bool IsKeyword(std::string_view name) {
  static constexpr std::array<std::string_view, 35> kKeywords = {
      "False", "None",   "True",    "and",      "as",       "assert", "async", "await", "break",
      "class", "continue", "def",   "del",      "elif",     "else",   "except", "finally", "for",
      "from",  "global", "if",      "import",   "in",       "is",     "lambda", "nonlocal", "not",
      "or",    "pass",   "raise",   "return",   "try",      "while",  "with",  "yield"};
  for (auto k : kKeywords)
    if (k == name) return true;
  return false;
}

Result<std::vector<Token>> Lex(std::string_view text) { return Lexer(text).Run(); }

}  // namespace mdlc::pyexpr
