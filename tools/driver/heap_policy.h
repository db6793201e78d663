#pragma once
// KeepFreedMemoryForReuse: the allocator policy of the mdlc command and of
// every benchmark binary (not of the library, which leaves its embedder's
// allocator alone).
//
// A compile grows its tables by doubling and frees what it outgrows. By
// default glibc serves every block over 128 KiB with a fresh mapping and
// returns it on free, so each growth step, and every later large block,
// faults its pages in anew: a world of 100,000 models took 216,000 page
// faults in one compile, and in a benchmark loop a quarter of the compile's
// samples were page faults and unmapping while the parse floor, made of
// small allocations, kept reusing its heap. With the heap kept (no mmap, no
// trim) a compile takes 152,000 faults and a sixth less CPU time, for a
// peak 13% higher; benchmark repetitions of the compile and the floor alike
// measure their work on memory already touched. What the first touch costs
// a one-shot compile is measured on whole processes (tools/bench_table.py).
#include <malloc.h>

#include <climits>

namespace mdlc {

inline void KeepFreedMemoryForReuse() {
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, INT_MAX);
}

}  // namespace mdlc
