// dof_values.h - one number per joint coordinate, held inside the joint.
//
// A joint has at most seven position coordinates (a quaternion floating
// joint: w x y z, then x y z) and six velocities, so its limits, damping and
// default positions always fit in seven slots. Keeping them inline, instead
// of in nine std::vectors, leaves a joint without heap allocations: in a
// world of one-link models the vectors of each model's floating joint were
// more than half of all the allocations a compile made, in the IR and again
// in the plant.
//
// The interface is the part of std::vector<double> that per-dof data uses.
// Asking for more than seven values is a programming error (every reader
// checks a list's length against the joint's coordinate count first) and
// throws std::length_error.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <ostream>
#include <stdexcept>
#include <vector>

namespace mdlc::ir {

class DofValues {
 public:
  /// The most coordinates any joint has.
  static constexpr size_t kCapacity = 7;

  DofValues() = default;
  DofValues(size_t count, double value) { assign(count, value); }
  DofValues(std::initializer_list<double> values) { assign(values.begin(), values.end()); }
  /// From a list already checked against the joint's coordinate count.
  DofValues(const std::vector<double>& values) { assign(values.begin(), values.end()); }

  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  double& operator[](size_t i) { return values_[i]; }
  double operator[](size_t i) const { return values_[i]; }
  double* data() { return values_.data(); }
  const double* data() const { return values_.data(); }
  double* begin() { return values_.data(); }
  double* end() { return values_.data() + size_; }
  const double* begin() const { return values_.data(); }
  const double* end() const { return values_.data() + size_; }

  void assign(size_t count, double value) {
    CheckFits(count);
    std::fill_n(values_.begin(), count, value);
    size_ = static_cast<uint8_t>(count);
  }
  template <typename It>
  void assign(It first, It last) {
    const auto count = static_cast<size_t>(std::distance(first, last));
    CheckFits(count);
    std::copy(first, last, values_.begin());
    size_ = static_cast<uint8_t>(count);
  }

  std::vector<double> ToVector() const { return {begin(), end()}; }

  friend bool operator==(const DofValues& a, const DofValues& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }
  friend bool operator==(const DofValues& a, const std::vector<double>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }
  /// For test failure messages: [a, b, c].
  friend std::ostream& operator<<(std::ostream& os, const DofValues& v) {
    os << '[';
    for (size_t i = 0; i < v.size(); ++i) os << (i ? ", " : "") << v[i];
    return os << ']';
  }

 private:
  static void CheckFits(size_t count) {
    if (count > kCapacity) throw std::length_error("a joint has at most seven coordinates");
  }

  std::array<double, kCapacity> values_{};
  uint8_t size_ = 0;
};

}  // namespace mdlc::ir
