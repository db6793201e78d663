#include "frontend/xml/dom_arena.h"

#include <libxml/xmlmemory.h>

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <cstring>
#include <functional>
#include <mutex>
#include <new>

#if defined(__SANITIZE_ADDRESS__)
#define MDLC_DOM_ARENA_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MDLC_DOM_ARENA_ASAN 1
#endif
#endif

#ifdef MDLC_DOM_ARENA_ASAN
#include <sanitizer/asan_interface.h>
#define MDLC_POISON(p, n) ASAN_POISON_MEMORY_REGION(p, n)
#define MDLC_UNPOISON(p, n) ASAN_UNPOISON_MEMORY_REGION(p, n)
#else
#define MDLC_POISON(p, n) ((void)(p), (void)(n))
#define MDLC_UNPOISON(p, n) ((void)(p), (void)(n))
#endif

namespace mdlc::xml {
namespace {

// Each small allocation is preceded by its size (for realloc) and rounded to
// 8 bytes, the strictest alignment of anything libxml2 allocates.
constexpr size_t kHeader = sizeof(uint64_t);
constexpr size_t kAlign = 8;
#ifdef MDLC_DOM_ARENA_ASAN
// under AddressSanitizer a poisoned gap after each allocation catches
// overruns into the next one
constexpr size_t kRedzone = 16;
#else
constexpr size_t kRedzone = 0;
#endif

size_t RoundUp(size_t n) { return (n + kAlign - 1) & ~(kAlign - 1); }

thread_local DomArena* t_current = nullptr;

// libxml2's allocator before Install: everything outside a scope goes there
// (the C library's until Install reads libxml2's own)
xmlFreeFunc g_free = std::free;
xmlMallocFunc g_malloc = std::malloc;
xmlReallocFunc g_realloc = std::realloc;

void* HookMalloc(size_t size) {
  if (DomArena* arena = t_current) return arena->Allocate(size);
  return g_malloc(size);
}

void HookFree(void* p) {
  if (!p) return;
  if (DomArena* arena = t_current; arena && arena->Owns(p)) {
    arena->Release(p);
    return;
  }
  g_free(p);
}

void* HookRealloc(void* p, size_t size) {
  DomArena* arena = t_current;
  if (!arena || !p || !arena->Owns(p)) return p ? g_realloc(p, size) : HookMalloc(size);
  return arena->Reallocate(p, size);
}

char* HookStrdup(const char* s) {
  const size_t n = std::strlen(s) + 1;
  auto* out = static_cast<char*>(HookMalloc(n));
  if (out) std::memcpy(out, s, n);
  return out;
}

}  // namespace

void DomArena::Install() {
  static std::once_flag once;
  std::call_once(once, [] {
    // libxml2's strdup is not kept: HookStrdup copies through HookMalloc
    xmlMemGet(&g_free, &g_malloc, &g_realloc, nullptr);
    xmlMemSetup(HookFree, HookMalloc, HookRealloc, HookStrdup);
  });
}

DomArena::Scope::Scope(DomArena& arena) : previous_(t_current) { t_current = &arena; }
DomArena::Scope::~Scope() { t_current = previous_; }

DomArena::~DomArena() {
  for (void* p : large_) g_free(p);
  for (char* block : blocks_) {
    MDLC_UNPOISON(block, kBlockSize);
    g_free(block);
  }
}

void* DomArena::Allocate(size_t size) {
  if (size > kLargestSmall) {
    void* p = g_malloc(size);
    if (p) large_.insert(p);
    return p;
  }
  const size_t need = kHeader + RoundUp(size) + kRedzone;
  if (static_cast<size_t>(end_ - next_) < need) {
    auto* block = static_cast<char*>(g_malloc(kBlockSize));
    if (!block) return nullptr;
    MDLC_POISON(block, kBlockSize);
    blocks_.insert(std::upper_bound(blocks_.begin(), blocks_.end(), block, std::less<>()), block);
    next_ = block;
    end_ = block + kBlockSize;
  }
  char* header = next_;
  next_ += need;
  MDLC_UNPOISON(header, kHeader + size);
  const uint64_t recorded = size;
  std::memcpy(header, &recorded, kHeader);
  return header + kHeader;
}

bool DomArena::Owns(const void* p) const {
  // the last block starting at or before p, if p lies inside it
  const auto* c = static_cast<const char*>(p);
  auto after = std::upper_bound(blocks_.begin(), blocks_.end(), c,
                                std::less<>());
  if (after != blocks_.begin() && std::less<>()(c, *std::prev(after) + kBlockSize)) return true;
  return large_.contains(const_cast<void*>(p));
}

size_t DomArena::SizeOf(const void* p) {
  uint64_t size = 0;
  std::memcpy(&size, static_cast<const char*>(p) - kHeader, kHeader);
  return static_cast<size_t>(size);
}

void DomArena::Release(void* p) {
  if (auto it = large_.find(p); it != large_.end()) {
    large_.erase(it);
    g_free(p);
  }
  // a small allocation's bytes stay until the arena goes
}

void* DomArena::Reallocate(void* p, size_t size) {
  if (auto it = large_.find(p); it != large_.end()) {
    void* q = g_realloc(p, size);
    if (!q) return nullptr;
    large_.erase(it);
    large_.insert(q);
    return q;
  }
  const size_t old = SizeOf(p);
  if (size <= old) return p;
  void* q = Allocate(size);
  if (q) std::memcpy(q, p, old);
  return q;
}

}  // namespace mdlc::xml
