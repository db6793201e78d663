// bigint.h - arbitrary-precision integers for pyexpr's ints.
//
// A Value holds an int in 64 bits while it fits and a BigInt only beyond
// (value.h); the arithmetic here is Python's: floor division and modulo,
// arithmetic right shifts and two's complement bit operations on negative
// numbers, correctly rounded conversion to float. Magnitudes are base 2^32
// limbs, least significant first, without leading zero limbs; schoolbook
// multiplication and Knuth's long division (sizes are bounded by Limits,
// about 10,000 digits, so quadratic algorithms are enough).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mdlc::pyexpr {

class BigInt {
 public:
  BigInt() = default;  // 0
  static BigInt FromInt64(int64_t v);
  static BigInt FromUint64(uint64_t v, bool negative = false);
  // trunc(d); nullopt for inf and nan
  static std::optional<BigInt> FromDouble(double d);
  // digits in base 2..36 (no sign, no underscores, no prefix; all valid)
  static BigInt FromDigits(std::string_view digits, int base, bool negative = false);

  bool IsZero() const { return mag_.empty(); }
  bool IsNegative() const { return negative_; }
  bool IsOdd() const { return !mag_.empty() && (mag_[0] & 1); }
  size_t BitLength() const;  // of the magnitude; 0 for 0
  std::optional<int64_t> ToInt64() const;
  // Correctly rounded (ties to even); nullopt when the magnitude rounds to
  // 2^1024 or more (Python's OverflowError).
  std::optional<double> ToDouble() const;
  std::string ToString(int base = 10) const;  // digits 0-9a-z, with '-' if negative
  // Consistent with equal int64 values and integral doubles (value.cc).
  uint64_t Hash() const;

  // -1, 0, 1
  static int Compare(const BigInt& a, const BigInt& b);
  // a <=> d for finite d
  static int CompareDouble(const BigInt& a, double d);

  BigInt operator-() const;
  BigInt Abs() const;
  friend BigInt operator+(const BigInt& a, const BigInt& b);
  friend BigInt operator-(const BigInt& a, const BigInt& b);
  friend BigInt operator*(const BigInt& a, const BigInt& b);
  // Python's floor division and modulo; b must not be 0.
  static void DivMod(const BigInt& a, const BigInt& b, BigInt* quotient, BigInt* remainder);
  // Truncating division of magnitudes (signs ignored); b must not be 0.
  static void DivModMagnitude(const BigInt& a, const BigInt& b, BigInt* quotient, BigInt* remainder);
  static BigInt Pow(const BigInt& base, uint64_t exponent);
  BigInt ShiftLeft(size_t bits) const;
  BigInt ShiftRight(size_t bits) const;  // floor(a / 2^bits)
  enum class BitOp { kAnd, kOr, kXor };
  static BigInt Bitwise(BitOp op, const BigInt& a, const BigInt& b);
  BigInt Invert() const { return -*this - FromInt64(1); }  // ~a
  // floor(sqrt(a)) for a >= 0
  BigInt Isqrt() const;
  static BigInt Gcd(BigInt a, BigInt b);  // >= 0

  // a / b correctly rounded; nullopt when too large for a float. b != 0.
  static std::optional<double> TrueDivide(const BigInt& a, const BigInt& b);

 private:
  void Trim();
  static int CompareMagnitude(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b);
  static std::vector<uint32_t> AddMagnitude(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b);
  // a - b for a >= b
  static std::vector<uint32_t> SubMagnitude(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b);
  // a / d, returning a % d
  static uint32_t DivSmall(std::vector<uint32_t>& a, uint32_t d);

  bool negative_ = false;
  std::vector<uint32_t> mag_;
};

}  // namespace mdlc::pyexpr
