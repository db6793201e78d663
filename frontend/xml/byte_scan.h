// byte_scan.h - forward scans of XML text that count the lines they pass.
//
// Placing start tags walks the whole text once, and each position it
// records needs its line. Searching for the next '<' and then, separately,
// for the newlines before it reads the text twice, one short library call
// at a time. These scans look for both in the same pass, 16 bytes at a
// time where the processor has SSE2 (every x86-64 does), a byte at a time
// elsewhere.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mdlc::xml {

/// The line a forward scan stands on: its number (from 1) and where it
/// starts. Columns count bytes from 1.
struct LineCursor {
  uint32_t line = 1;
  const char* line_start = nullptr;

  uint32_t ColumnOf(const char* p) const { return static_cast<uint32_t>(p - line_start + 1); }
  void PassNewlineAt(const char* p) {
    ++line;
    line_start = p + 1;
  }
};

namespace detail {

#if defined(__SSE2__)
// The bytes of the 16 at `p` equal to `c`, as a bit mask (bit i: p[i]).
inline uint32_t MatchMask(__m128i block, char c) {
  return static_cast<uint32_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(block, _mm_set1_epi8(c))));
}
#endif

// Counts into `lines` the newlines that `mask` marks among the bytes at `p`
// (16 or 32 of them).
// A block holds one newline or none nearly always, so they are counted one
// by one (std::popcount is a library call where the processor's own
// instruction is not assumed).
inline void PassNewlines(uint32_t mask, const char* p, LineCursor& lines) {
  if (mask == 0) return;
  lines.line_start = p + (31 - std::countl_zero(mask)) + 1;
  for (; mask != 0; mask &= mask - 1) ++lines.line;
}

}  // namespace detail

#if defined(__SSE2__)
/// The 32 bytes at `p` (all readable) equal to `c`, and those that are
/// newlines, as bit masks (bit i: p[i]).
struct WindowMasks {
  uint32_t hits;
  uint32_t newlines;
};
inline WindowMasks MatchWindow(const char* p, char c) {
  const __m128i low = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
  const __m128i high = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 16));
  return {detail::MatchMask(low, c) | detail::MatchMask(high, c) << 16,
          detail::MatchMask(low, '\n') | detail::MatchMask(high, '\n') << 16};
}
#endif

/// The first `target` in [p, end), or `end` when there is none; the
/// newlines before it are counted into `lines`.
inline const char* ScanTo(const char* p, const char* end, char target, LineCursor& lines) {
#if defined(__SSE2__)
  for (; end - p >= 16; p += 16) {
    const __m128i block = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    const uint32_t hits = detail::MatchMask(block, target);
    uint32_t newlines = detail::MatchMask(block, '\n');
    if (hits != 0) {
      const int at = std::countr_zero(hits);
      detail::PassNewlines(newlines & ((1u << at) - 1), p, lines);
      return p + at;
    }
    detail::PassNewlines(newlines, p, lines);
  }
#endif
  for (; p < end; ++p) {
    if (*p == target) return p;
    if (*p == '\n') lines.PassNewlineAt(p);
  }
  return end;
}

/// Counts into `lines` the newlines in [p, end).
inline void CountLines(const char* p, const char* end, LineCursor& lines) {
#if defined(__SSE2__)
  for (; end - p >= 16; p += 16) {
    const __m128i block = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    detail::PassNewlines(detail::MatchMask(block, '\n'), p, lines);
  }
#endif
  for (; p < end; ++p) {
    if (*p == '\n') lines.PassNewlineAt(p);
  }
}

}  // namespace mdlc::xml
