// dof_values.h - one number per joint coordinate, held compactly in the joint.
//
// A joint has at most seven position coordinates (a quaternion floating
// joint: w x y z, then x y z) and six velocities, and it carries nine such
// lists (seven limits, damping, default positions) in the IR and nine in the
// plant. Most lists are one of two kinds: a single coordinate (revolute and
// prismatic joints) or a constant fill (a floating joint's six unbounded
// limits, its zero damping, its identity pose). So a list is 16 bytes:
//
//  - up to one value is held inline;
//  - a list equal to a prefix of a shared constant table (all -inf, all +inf,
//    all zero, or the identity pose 1 0 0 0 0 0 0) points at that table;
//  - anything else owns a heap array.
//
// A world of one-link models has a floating joint per model. With seven
// inline slots per list a joint was 952 bytes, in the IR and again in the
// plant; now it is 520, and its lists still allocate nothing.
//
// The interface is the part of std::vector<double> that per-dof data uses.
// Writing to a shared list (set) first copies it to the heap. Asking for more
// than seven values is a programming error (every reader checks a list's
// length against the joint's coordinate count first) and throws
// std::length_error.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <ostream>
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
  DofValues(const std::vector<double>& values) {
    assign(values.data(), values.data() + values.size());
  }

  DofValues(const DofValues& other) { CopyFrom(other); }
  DofValues(DofValues&& other) noexcept { StealFrom(other); }
  DofValues& operator=(const DofValues& other) {
    if (this != &other) {
      Release();
      CopyFrom(other);
    }
    return *this;
  }
  DofValues& operator=(DofValues&& other) noexcept {
    if (this != &other) {
      Release();
      StealFrom(other);
    }
    return *this;
  }
  ~DofValues() { Release(); }

  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  double operator[](size_t i) const { return data()[i]; }
  const double* data() const {
    return storage_ == Storage::kInline ? &slot_.inline_value : slot_.values;
  }
  const double* begin() const { return data(); }
  const double* end() const { return data() + size_; }

  /// Writes one value. There is no mutable operator[], so that only a write,
  /// never a read, copies a shared list to the heap.
  void set(size_t i, double value) {
    if (storage_ == Storage::kInline) {
      slot_.inline_value = value;  // an inline list has one value: i is 0
      return;
    }
    if (storage_ == Storage::kShared) Unshare();
    slot_.values[i] = value;
  }

  void assign(size_t count, double value) {
    CheckFits(count);
    const double* table = count > 1 ? FillTable(value) : nullptr;
    if (count > 1 && !table) return AssignFill(count, value);
    Release();
    if (table) {
      slot_.values = const_cast<double*>(table);
    } else {
      slot_.inline_value = value;
    }
    size_ = static_cast<uint8_t>(count);
    storage_ = table ? Storage::kShared : Storage::kInline;
  }
  void assign(const double* first, const double* last);
  std::vector<double> ToVector() const { return {begin(), end()}; }

  /// Whether the list points at a shared constant table (for tests).
  bool IsShared() const { return storage_ == Storage::kShared; }

  friend bool operator==(const DofValues& a, const DofValues& b);
  friend bool operator==(const DofValues& a, const std::vector<double>& b);
  /// For test failure messages: [a, b, c].
  friend std::ostream& operator<<(std::ostream& os, const DofValues& v);

 private:
  enum class Storage : uint8_t { kInline, kShared, kHeap };

  static void CheckFits(size_t count) {
    if (count > kCapacity) ThrowTooMany();
  }
  [[noreturn]] static void ThrowTooMany();
  /// The shared table filled with `value`, or null.
  static const double* FillTable(double value);
  void AssignFill(size_t count, double value);
  void CopyFrom(const DofValues& other) {
    slot_ = other.slot_;
    size_ = other.size_;
    storage_ = other.storage_;
    if (storage_ == Storage::kHeap) CopyHeap(other);
  }
  void CopyHeap(const DofValues& other);
  void StealFrom(DofValues& other) noexcept {
    slot_ = other.slot_;  // whichever member is live
    size_ = other.size_;
    storage_ = other.storage_;
    other.storage_ = Storage::kInline;
    other.size_ = 0;
  }
  void Release() noexcept {
    if (storage_ == Storage::kHeap) delete[] slot_.values;
    storage_ = Storage::kInline;
  }
  void Unshare();

  // kInline holds the one value, if any; kShared and kHeap point at the
  // values, so reading takes one branch. A shared table is constant: it is
  // never written through `values` (mutable access unshares it first).
  union Slot {
    double inline_value = 0;
    double* values;
  };
  Slot slot_;
  uint8_t size_ = 0;
  Storage storage_ = Storage::kInline;
};

}  // namespace mdlc::ir
