#include "ir/dof_values.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace mdlc::ir {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The constant lists joints share. Zero is compared by its bits, so a -0.0
// the input wrote is kept as written.
constexpr double kNegativeInfinities[DofValues::kCapacity] = {-kInf, -kInf, -kInf, -kInf,
                                                              -kInf, -kInf, -kInf};
constexpr double kPositiveInfinities[DofValues::kCapacity] = {kInf, kInf, kInf, kInf,
                                                              kInf, kInf, kInf};
constexpr double kZeros[DofValues::kCapacity] = {0, 0, 0, 0, 0, 0, 0};
// a quaternion floating (or ball) joint's identity pose: w x y z, x y z
constexpr double kIdentityPose[DofValues::kCapacity] = {1, 0, 0, 0, 0, 0, 0};
constexpr const double* kTables[] = {kNegativeInfinities, kPositiveInfinities, kZeros,
                                     kIdentityPose};

bool SameBits(double a, double b) {
  return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b);
}

// The shared table whose first `count` entries are `values`, or null.
const double* FindTable(const double* values, size_t count) {
  for (const double* table : kTables) {
    if (!SameBits(table[0], values[0])) continue;
    if (std::equal(values + 1, values + count, table + 1, SameBits)) return table;
  }
  return nullptr;
}

// An owned copy of `count` values.
double* HeapCopy(const double* values, size_t count) {
  double* copy = new double[count];
  std::copy(values, values + count, copy);
  return copy;
}

}  // namespace

void DofValues::ThrowTooMany() {
  throw std::length_error("a joint has at most seven coordinates");
}

const double* DofValues::FillTable(double value) {
  if (value == kInf) return kPositiveInfinities;
  if (value == -kInf) return kNegativeInfinities;
  if (SameBits(value, 0.0)) return kZeros;
  return nullptr;
}

void DofValues::AssignFill(size_t count, double value) {
  // not a shared table's fill (FillTable said so): the list owns its values
  double* values = new double[count];
  std::fill_n(values, count, value);
  Release();
  slot_.values = values;
  size_ = static_cast<uint8_t>(count);
  storage_ = Storage::kHeap;
}

void DofValues::assign(const double* first, const double* last) {
  const auto count = static_cast<size_t>(last - first);
  CheckFits(count);
  // `first` may point into this list; decide and copy before releasing it
  const double* table = count > 1 ? FindTable(first, count) : nullptr;
  Slot slot;
  Storage storage = Storage::kInline;
  if (count <= 1) {
    slot.inline_value = count ? *first : 0;
  } else if (table) {
    slot.values = const_cast<double*>(table);
    storage = Storage::kShared;
  } else {
    slot.values = HeapCopy(first, count);
    storage = Storage::kHeap;
  }
  Release();
  slot_ = slot;
  size_ = static_cast<uint8_t>(count);
  storage_ = storage;
}

void DofValues::CopyHeap(const DofValues& other) {
  slot_.values = HeapCopy(other.slot_.values, size_);
}

void DofValues::Unshare() {
  slot_.values = HeapCopy(slot_.values, size_);
  storage_ = Storage::kHeap;
}

bool operator==(const DofValues& a, const DofValues& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end());
}

bool operator==(const DofValues& a, const std::vector<double>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end());
}

std::ostream& operator<<(std::ostream& os, const DofValues& v) {
  os << '[';
  for (size_t i = 0; i < v.size(); ++i) os << (i ? ", " : "") << v[i];
  return os << ']';
}

}  // namespace mdlc::ir
