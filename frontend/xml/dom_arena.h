#pragma once
// DomArena: the memory of one parsed XML document.
//
// A libxml2 DOM is millions of small allocations (a node, an attribute, a
// string each). Made with malloc, they cost a header each, and freeing them
// costs as much again: glibc defers the work of millions of small frees to the
// next large allocation (malloc_consolidate), which walks every freed chunk
// while none of it is in cache. A profile of a 10,000-link model parsed and
// freed in a loop spends half its time there.
//
// So while a DomArena::Scope is active on a thread, libxml2's small
// allocations on that thread come from the arena's blocks, freeing them does
// nothing, and the whole document goes when the arena does. Large
// allocations (input buffers, the dictionary's big pools) are made with the
// allocator libxml2 had before, but the arena keeps track of them and frees
// those still held when it goes. Anything allocated outside a scope is
// libxml2's as before: a pointer is the arena's only if it lies in one of the
// active arena's blocks or is one of its large allocations, so memory
// libxml2 allocated elsewhere (by the host program, or before the arena was
// installed) is never mistaken for arena memory.
//
// The rule for users: nothing allocated in a scope may be freed by libxml2
// after the arena is gone. XmlDocument keeps this by never calling
// xmlFreeDoc on an arena document and by resetting libxml2's thread-global
// last error before its scope ends.

#include <cstddef>
#include <cstdint>
#include <unordered_set>
#include <vector>

namespace mdlc::xml {

class DomArena {
 public:
  DomArena() = default;
  ~DomArena();
  DomArena(const DomArena&) = delete;
  DomArena& operator=(const DomArena&) = delete;

  /// Routes libxml2's allocator through the arenas (once per process; safe to
  /// call from any thread). Must run before the first Scope.
  static void Install();

  /// Makes `arena` this thread's arena for libxml2 until the scope ends.
  class Scope {
   public:
    explicit Scope(DomArena& arena);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    DomArena* previous_;
  };

  /// Bytes taken from the system for blocks.
  size_t block_bytes() const { return blocks_.size() * kBlockSize; }

  /// Requests this small or smaller are served from blocks; larger ones go to
  /// the allocator (they are few, and often reallocated as they grow).
  static constexpr size_t kLargestSmall = 16 * 1024;
  static constexpr size_t kBlockSize = 1024 * 1024;

  // The allocator hooks, public for the tests.
  void* Allocate(size_t size);
  void* Reallocate(void* p, size_t size);  // `p` must be owned
  void Release(void* p);                   // `p` must be owned
  bool Owns(const void* p) const;
  /// The size a small allocation was made with.
  static size_t SizeOf(const void* p);

 private:
  // block starts, sorted by address (blocks are the allocator's memory, so
  // they are reused as any freed memory is, e.g. by the next document)
  std::vector<char*> blocks_;
  // large allocations made in a scope, freed with the arena unless released
  std::unordered_set<void*> large_;
  char* next_ = nullptr;
  char* end_ = nullptr;
};

}  // namespace mdlc::xml
