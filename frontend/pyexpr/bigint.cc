// bigint.cc - arbitrary-precision integer arithmetic (see bigint.h).
#include "frontend/pyexpr/bigint.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mdlc::pyexpr {
namespace {

using Limbs = std::vector<uint32_t>;

void TrimLimbs(Limbs& v) {
  while (!v.empty() && v.back() == 0) v.pop_back();
}

Limbs ShiftLeftLimbs(const Limbs& v, size_t bits) {
  if (v.empty()) return {};
  size_t limbs = bits / 32, rest = bits % 32;
  Limbs out(v.size() + limbs + 1, 0);
  for (size_t i = 0; i < v.size(); ++i) {
    uint64_t x = static_cast<uint64_t>(v[i]) << rest;
    out[i + limbs] |= static_cast<uint32_t>(x);
    out[i + limbs + 1] |= static_cast<uint32_t>(x >> 32);
  }
  TrimLimbs(out);
  return out;
}

Limbs ShiftRightLimbs(const Limbs& v, size_t bits) {
  size_t limbs = bits / 32, rest = bits % 32;
  if (limbs >= v.size()) return {};
  Limbs out(v.size() - limbs, 0);
  for (size_t i = 0; i < out.size(); ++i) {
    uint64_t lo = v[i + limbs];
    uint64_t hi = i + limbs + 1 < v.size() ? v[i + limbs + 1] : 0;
    out[i] = static_cast<uint32_t>(((hi << 32) | lo) >> rest);
  }
  TrimLimbs(out);
  return out;
}

// v = v * m + a
void MulAddSmall(Limbs& v, uint32_t m, uint32_t a) {
  uint64_t carry = a;
  for (auto& limb : v) {
    uint64_t x = static_cast<uint64_t>(limb) * m + carry;
    limb = static_cast<uint32_t>(x);
    carry = x >> 32;
  }
  if (carry) v.push_back(static_cast<uint32_t>(carry));
}

uint64_t MixHash(uint64_t h) {
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  return h;
}

}  // namespace

void BigInt::Trim() {
  TrimLimbs(mag_);
  if (mag_.empty()) negative_ = false;
}

BigInt BigInt::FromUint64(uint64_t v, bool negative) {
  BigInt r;
  if (v) r.mag_.push_back(static_cast<uint32_t>(v));
  if (v >> 32) r.mag_.push_back(static_cast<uint32_t>(v >> 32));
  r.negative_ = negative && v != 0;
  return r;
}

BigInt BigInt::FromInt64(int64_t v) {
  uint64_t m = v < 0 ? 0 - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
  return FromUint64(m, v < 0);
}

std::optional<BigInt> BigInt::FromDouble(double d) {
  if (!std::isfinite(d)) return std::nullopt;
  d = std::trunc(d);
  if (std::fabs(d) < 9223372036854775808.0) return FromInt64(static_cast<int64_t>(d));
  int e = 0;
  double m = std::frexp(std::fabs(d), &e);  // |d| = m * 2^e, m in [0.5, 1)
  uint64_t mantissa = static_cast<uint64_t>(std::ldexp(m, 53));
  BigInt r = FromUint64(mantissa).ShiftLeft(static_cast<size_t>(e - 53));
  r.negative_ = d < 0;
  return r;
}

BigInt BigInt::FromDigits(std::string_view digits, int base, bool negative) {
  BigInt r;
  auto value = [](char c) -> uint32_t {
    if (c >= '0' && c <= '9') return static_cast<uint32_t>(c - '0');
    if (c >= 'a' && c <= 'z') return static_cast<uint32_t>(c - 'a' + 10);
    return static_cast<uint32_t>(c - 'A' + 10);
  };
  // several digits per multiplication while the multiplier fits 32 bits
  size_t i = 0;
  while (i < digits.size()) {
    uint32_t mult = 1, chunk = 0;
    while (i < digits.size() && static_cast<uint64_t>(mult) * static_cast<uint32_t>(base) <= 0xffffffffULL) {
      mult *= static_cast<uint32_t>(base);
      chunk = chunk * static_cast<uint32_t>(base) + value(digits[i++]);
    }
    MulAddSmall(r.mag_, mult, chunk);
  }
  r.Trim();
  r.negative_ = negative && !r.mag_.empty();
  return r;
}

size_t BigInt::BitLength() const {
  if (mag_.empty()) return 0;
  return (mag_.size() - 1) * 32 + (32 - static_cast<size_t>(__builtin_clz(mag_.back())));
}

std::optional<int64_t> BigInt::ToInt64() const {
  if (mag_.size() > 2) return std::nullopt;
  uint64_t m = 0;
  if (!mag_.empty()) m = mag_[0];
  if (mag_.size() == 2) m |= static_cast<uint64_t>(mag_[1]) << 32;
  if (negative_) {
    if (m > (static_cast<uint64_t>(1) << 63)) return std::nullopt;
    return static_cast<int64_t>(0 - m);
  }
  if (m > static_cast<uint64_t>(std::numeric_limits<int64_t>::max())) return std::nullopt;
  return static_cast<int64_t>(m);
}

std::optional<double> BigInt::ToDouble() const {
  size_t n = BitLength();
  if (n == 0) return 0.0;
  double d;
  if (n <= 64) {
    uint64_t m = mag_[0];
    if (mag_.size() > 1) m |= static_cast<uint64_t>(mag_[1]) << 32;
    d = static_cast<double>(m);
  } else {
    if (n > 1100) return std::nullopt;
    size_t shift = n - 64;
    Limbs top = ShiftRightLimbs(mag_, shift);
    uint64_t m = top[0] | (top.size() > 1 ? static_cast<uint64_t>(top[1]) << 32 : 0);
    // the bits below the top 64 only matter as a sticky bit (the rounding
    // position of the 53-bit mantissa is well above bit 0)
    bool sticky = false;
    for (size_t i = 0; i < shift / 32 && !sticky; ++i) sticky = mag_[i] != 0;
    if (!sticky && shift % 32) sticky = (mag_[shift / 32] & ((1u << (shift % 32)) - 1)) != 0;
    if (sticky) m |= 1;
    d = std::ldexp(static_cast<double>(m), static_cast<int>(shift));
  }
  if (std::isinf(d)) return std::nullopt;
  return negative_ ? -d : d;
}

std::string BigInt::ToString(int base) const {
  if (mag_.empty()) return "0";
  if (base != 10) {
    Limbs v = mag_;
    std::string digits;
    while (!v.empty()) digits.push_back("0123456789abcdefghijklmnopqrstuvwxyz"[DivSmall(v, static_cast<uint32_t>(base))]);
    if (negative_) digits.push_back('-');
    return std::string(digits.rbegin(), digits.rend());
  }
  Limbs v = mag_;
  std::vector<uint32_t> chunks;  // base 10^9, least significant first
  while (!v.empty()) chunks.push_back(DivSmall(v, 1000000000u));
  std::string out = negative_ ? "-" : "";
  out += std::to_string(chunks.back());
  for (size_t i = chunks.size() - 1; i-- > 0;) {
    std::string part = std::to_string(chunks[i]);
    out.append(9 - part.size(), '0');
    out += part;
  }
  return out;
}

uint64_t BigInt::Hash() const {
  uint64_t h = negative_ ? 0x2545f4914f6cdd1dULL : 0x9e3779b97f4a7c15ULL;
  for (uint32_t limb : mag_) h = MixHash(h * 1000003 ^ limb);
  return h;
}

int BigInt::CompareMagnitude(const Limbs& a, const Limbs& b) {
  if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
  for (size_t i = a.size(); i-- > 0;)
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  return 0;
}

int BigInt::Compare(const BigInt& a, const BigInt& b) {
  if (a.negative_ != b.negative_) return a.negative_ ? -1 : 1;
  int c = CompareMagnitude(a.mag_, b.mag_);
  return a.negative_ ? -c : c;
}

int BigInt::CompareDouble(const BigInt& a, double d) {
  if (std::isinf(d)) return d > 0 ? -1 : 1;
  double t = std::trunc(d);
  int c = Compare(a, *FromDouble(t));
  if (c != 0) return c;
  double frac = d - t;
  return frac > 0 ? -1 : (frac < 0 ? 1 : 0);
}

Limbs BigInt::AddMagnitude(const Limbs& a, const Limbs& b) {
  const Limbs& x = a.size() >= b.size() ? a : b;
  const Limbs& y = a.size() >= b.size() ? b : a;
  Limbs out(x.size() + 1, 0);
  uint64_t carry = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    uint64_t s = static_cast<uint64_t>(x[i]) + (i < y.size() ? y[i] : 0) + carry;
    out[i] = static_cast<uint32_t>(s);
    carry = s >> 32;
  }
  out[x.size()] = static_cast<uint32_t>(carry);
  TrimLimbs(out);
  return out;
}

Limbs BigInt::SubMagnitude(const Limbs& a, const Limbs& b) {
  Limbs out(a.size(), 0);
  int64_t borrow = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    int64_t s = static_cast<int64_t>(a[i]) - (i < b.size() ? b[i] : 0) - borrow;
    borrow = s < 0;
    out[i] = static_cast<uint32_t>(s + (borrow << 32));
  }
  TrimLimbs(out);
  return out;
}

uint32_t BigInt::DivSmall(Limbs& a, uint32_t d) {
  uint64_t rem = 0;
  for (size_t i = a.size(); i-- > 0;) {
    uint64_t cur = (rem << 32) | a[i];
    a[i] = static_cast<uint32_t>(cur / d);
    rem = cur % d;
  }
  TrimLimbs(a);
  return static_cast<uint32_t>(rem);
}

BigInt BigInt::operator-() const {
  BigInt r = *this;
  r.negative_ = !r.negative_ && !r.mag_.empty();
  return r;
}

BigInt BigInt::Abs() const {
  BigInt r = *this;
  r.negative_ = false;
  return r;
}

BigInt operator+(const BigInt& a, const BigInt& b) {
  BigInt r;
  if (a.negative_ == b.negative_) {
    r.mag_ = BigInt::AddMagnitude(a.mag_, b.mag_);
    r.negative_ = a.negative_;
  } else if (BigInt::CompareMagnitude(a.mag_, b.mag_) >= 0) {
    r.mag_ = BigInt::SubMagnitude(a.mag_, b.mag_);
    r.negative_ = a.negative_;
  } else {
    r.mag_ = BigInt::SubMagnitude(b.mag_, a.mag_);
    r.negative_ = b.negative_;
  }
  r.Trim();
  return r;
}

BigInt operator-(const BigInt& a, const BigInt& b) { return a + (-b); }

BigInt operator*(const BigInt& a, const BigInt& b) {
  BigInt r;
  if (a.mag_.empty() || b.mag_.empty()) return r;
  r.mag_.assign(a.mag_.size() + b.mag_.size(), 0);
  for (size_t i = 0; i < a.mag_.size(); ++i) {
    uint64_t carry = 0;
    uint64_t x = a.mag_[i];
    for (size_t j = 0; j < b.mag_.size(); ++j) {
      uint64_t t = x * b.mag_[j] + r.mag_[i + j] + carry;
      r.mag_[i + j] = static_cast<uint32_t>(t);
      carry = t >> 32;
    }
    size_t k = i + b.mag_.size();
    while (carry) {
      uint64_t t = static_cast<uint64_t>(r.mag_[k]) + carry;
      r.mag_[k++] = static_cast<uint32_t>(t);
      carry = t >> 32;
    }
  }
  r.negative_ = a.negative_ != b.negative_;
  r.Trim();
  return r;
}

void BigInt::DivModMagnitude(const BigInt& a, const BigInt& b, BigInt* quotient, BigInt* remainder) {
  BigInt q, r;
  if (CompareMagnitude(a.mag_, b.mag_) < 0) {
    r.mag_ = a.mag_;
  } else if (b.mag_.size() == 1) {
    q.mag_ = a.mag_;
    uint32_t rem = DivSmall(q.mag_, b.mag_[0]);
    if (rem) r.mag_.push_back(rem);
  } else {
    // Knuth's algorithm D (as in Hacker's Delight, divmnu), base 2^32
    const Limbs& u = a.mag_;
    const Limbs& v = b.mag_;
    size_t n = v.size(), m = u.size() - n;
    int s = __builtin_clz(v.back());
    Limbs vn = ShiftLeftLimbs(v, static_cast<size_t>(s));
    vn.resize(n, 0);
    Limbs un = ShiftLeftLimbs(u, static_cast<size_t>(s));
    un.resize(u.size() + 1, 0);
    q.mag_.assign(m + 1, 0);
    constexpr uint64_t kBase = 1ULL << 32;
    for (size_t j = m + 1; j-- > 0;) {
      uint64_t num = (static_cast<uint64_t>(un[j + n]) << 32) | un[j + n - 1];
      uint64_t qhat = num / vn[n - 1];
      uint64_t rhat = num % vn[n - 1];
      while (qhat >= kBase || qhat * vn[n - 2] > ((rhat << 32) | un[j + n - 2])) {
        --qhat;
        rhat += vn[n - 1];
        if (rhat >= kBase) break;
      }
      int64_t k = 0, t = 0;
      for (size_t i = 0; i < n; ++i) {
        uint64_t p = qhat * vn[i];
        t = static_cast<int64_t>(un[i + j]) - k - static_cast<int64_t>(p & 0xffffffffULL);
        un[i + j] = static_cast<uint32_t>(t);
        k = static_cast<int64_t>(p >> 32) - (t >> 32);
      }
      t = static_cast<int64_t>(un[j + n]) - k;
      un[j + n] = static_cast<uint32_t>(t);
      if (t < 0) {  // subtracted once too often: add back
        --qhat;
        uint64_t carry = 0;
        for (size_t i = 0; i < n; ++i) {
          uint64_t sum = static_cast<uint64_t>(un[i + j]) + vn[i] + carry;
          un[i + j] = static_cast<uint32_t>(sum);
          carry = sum >> 32;
        }
        un[j + n] = static_cast<uint32_t>(un[j + n] + carry);
      }
      q.mag_[j] = static_cast<uint32_t>(qhat);
    }
    un.resize(n);
    TrimLimbs(un);
    r.mag_ = ShiftRightLimbs(un, static_cast<size_t>(s));
    TrimLimbs(q.mag_);
  }
  q.Trim();
  r.Trim();
  if (quotient) *quotient = std::move(q);
  if (remainder) *remainder = std::move(r);
}

void BigInt::DivMod(const BigInt& a, const BigInt& b, BigInt* quotient, BigInt* remainder) {
  BigInt q, r;
  DivModMagnitude(a, b, &q, &r);
  // truncated toward zero on magnitudes; make it Python's floor division
  q.negative_ = a.negative_ != b.negative_;
  r.negative_ = a.negative_;
  q.Trim();
  r.Trim();
  if (!r.IsZero() && r.negative_ != b.negative_) {
    q = q - FromInt64(1);
    r = r + b;
  }
  if (quotient) *quotient = std::move(q);
  if (remainder) *remainder = std::move(r);
}

BigInt BigInt::Pow(const BigInt& base, uint64_t exponent) {
  BigInt result = FromInt64(1);
  BigInt b = base;
  while (exponent) {
    if (exponent & 1) result = result * b;
    exponent >>= 1;
    if (exponent) b = b * b;
  }
  return result;
}

BigInt BigInt::ShiftLeft(size_t bits) const {
  BigInt r;
  r.mag_ = ShiftLeftLimbs(mag_, bits);
  r.negative_ = negative_;
  r.Trim();
  return r;
}

BigInt BigInt::ShiftRight(size_t bits) const {
  if (!negative_) {
    BigInt r;
    r.mag_ = ShiftRightLimbs(mag_, bits);
    return r;
  }
  // floor for negatives: -((|a| - 1) >> bits) - 1
  BigInt m = Abs() - FromInt64(1);
  BigInt r;
  r.mag_ = ShiftRightLimbs(m.mag_, bits);
  return -r - FromInt64(1);
}

BigInt BigInt::Bitwise(BitOp op, const BigInt& a, const BigInt& b) {
  size_t n = std::max(a.mag_.size(), b.mag_.size()) + 1;
  auto twos = [n](const BigInt& x) {
    Limbs v(n, 0);
    std::copy(x.mag_.begin(), x.mag_.end(), v.begin());
    if (x.negative_) {
      uint64_t carry = 1;
      for (auto& limb : v) {
        uint64_t t = static_cast<uint64_t>(static_cast<uint32_t>(~limb)) + carry;
        limb = static_cast<uint32_t>(t);
        carry = t >> 32;
      }
    }
    return v;
  };
  Limbs x = twos(a), y = twos(b), out(n);
  for (size_t i = 0; i < n; ++i)
    out[i] = op == BitOp::kAnd ? (x[i] & y[i]) : op == BitOp::kOr ? (x[i] | y[i]) : (x[i] ^ y[i]);
  BigInt r;
  if (out.back() >> 31) {
    uint64_t carry = 1;
    for (auto& limb : out) {
      uint64_t t = static_cast<uint64_t>(static_cast<uint32_t>(~limb)) + carry;
      limb = static_cast<uint32_t>(t);
      carry = t >> 32;
    }
    r.negative_ = true;
  }
  r.mag_ = std::move(out);
  r.Trim();
  return r;
}

BigInt BigInt::Isqrt() const {
  if (mag_.empty()) return {};
  // Newton's iteration from above, starting from the square root of the
  // top (about 100) bits, rounded up
  size_t n = BitLength();
  size_t shift = n > 100 ? (n - 100) & ~static_cast<size_t>(1) : 0;
  double top = *ShiftRight(shift).ToDouble();
  BigInt x = (*FromDouble(std::floor(std::sqrt(top + 1)) + 2)).ShiftLeft(shift / 2);
  while (true) {
    BigInt q;
    DivModMagnitude(*this, x, &q, nullptr);
    BigInt y = (x + q).ShiftRight(1);
    if (Compare(y, x) >= 0) return x;
    x = std::move(y);
  }
}

BigInt BigInt::Gcd(BigInt a, BigInt b) {
  // binary gcd on magnitudes
  a.negative_ = b.negative_ = false;
  if (a.IsZero()) return b;
  if (b.IsZero()) return a;
  auto trailing = [](const BigInt& x) {
    size_t i = 0;
    while (x.mag_[i / 32] == 0) i += 32;
    return i + static_cast<size_t>(__builtin_ctz(x.mag_[i / 32]));
  };
  size_t za = trailing(a), zb = trailing(b);
  size_t shift = std::min(za, zb);
  a = a.ShiftRight(za);
  b = b.ShiftRight(zb);
  while (true) {
    int c = Compare(a, b);
    if (c == 0) break;
    if (c < 0) std::swap(a, b);
    a = a - b;
    a = a.ShiftRight(trailing(a));
  }
  return a.ShiftLeft(shift);
}

std::optional<double> BigInt::TrueDivide(const BigInt& a, const BigInt& b) {
  bool negative = a.negative_ != b.negative_;
  if (a.IsZero()) return negative ? -0.0 : 0.0;
  // scale so that the quotient has 63 or 64 bits, then round once
  long k = 63 + static_cast<long>(b.BitLength()) - static_cast<long>(a.BitLength());
  BigInt num = a.Abs(), den = b.Abs();
  if (k >= 0) {
    num = num.ShiftLeft(static_cast<size_t>(k));
  } else {
    den = den.ShiftLeft(static_cast<size_t>(-k));
  }
  BigInt q, r;
  DivModMagnitude(num, den, &q, &r);
  uint64_t m = q.mag_.empty() ? 0 : q.mag_[0];
  if (q.mag_.size() > 1) m |= static_cast<uint64_t>(q.mag_[1]) << 32;
  if (!r.IsZero()) m |= 1;
  if (k > 2000) return negative ? -0.0 : 0.0;
  if (k < -2000) return std::nullopt;
  double d = std::ldexp(static_cast<double>(m), static_cast<int>(-k));
  if (std::isinf(d)) return std::nullopt;
  return negative ? -d : d;
}

}  // namespace mdlc::pyexpr
