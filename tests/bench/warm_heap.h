#pragma once
// KeepHeapWarm: the allocator policy every benchmark binary runs under.
//
// By default glibc serves large requests (a big vector, an XML tree's arena block)
// with fresh mmap'd pages and gives freed memory back to the kernel, so each
// repetition of a benchmark pays the kernel again for first touching the same
// memory, and the benchmarks with the largest allocations pay most: in a
// loop over the 100,000-model world a quarter of the compile's samples were
// page faults and unmapping, while the parse floor, made of small
// allocations, kept reusing its heap. With the heap kept (no mmap, no trim),
// every stage and the floor alike measure their work on memory already
// touched. What the first touch costs a one-shot compile is measured
// separately, on whole processes (tools/bench_table.py).
#include <malloc.h>

#include <climits>

namespace mdlc::bench {

inline void KeepHeapWarm() {
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, INT_MAX);
}

}  // namespace mdlc::bench
