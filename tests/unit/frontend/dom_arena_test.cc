// DomArena: libxml2's memory for one parsed document (dom_arena.h). What
// matters is that arena memory and the allocator's never mix: each is freed by
// its own owner, whatever libxml2 does after the arena is gone. Under the
// sanitizer suite a mix-up is a bad-free or use-after-free report.
#include "frontend/xml/dom_arena.h"

#include <libxml/parser.h>
#include <libxml/xmlerror.h>
#include <libxml/xmlmemory.h>

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "frontend/xml/xml_document.h"

namespace mdlc::xml {
namespace {

class DomArenaTest : public ::testing::Test {
 protected:
  void SetUp() override { DomArena::Install(); }
};

TEST_F(DomArenaTest, SmallAllocationsComeFromBlocksAndKeepTheirSize) {
  DomArena arena;
  void* a = arena.Allocate(24);
  void* b = arena.Allocate(1);
  ASSERT_TRUE(a && b);
  EXPECT_TRUE(arena.Owns(a));
  EXPECT_TRUE(arena.Owns(b));
  EXPECT_EQ(DomArena::SizeOf(a), 24u);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(b) % 8, 0u);
  EXPECT_EQ(arena.block_bytes(), DomArena::kBlockSize);
  int on_stack = 0;
  EXPECT_FALSE(arena.Owns(&on_stack));
}

TEST_F(DomArenaTest, ReallocationKeepsTheBytesAndLargeOnesAreTracked) {
  DomArena arena;
  auto* p = static_cast<char*>(arena.Allocate(16));
  std::memcpy(p, "0123456789abcde", 16);
  // shrinking keeps the allocation; growing copies it
  EXPECT_EQ(arena.Reallocate(p, 8), p);
  auto* grown = static_cast<char*>(arena.Reallocate(p, 100));
  EXPECT_STREQ(grown, "0123456789abcde");
  // past the small limit: the allocator's memory, still the arena's to free
  auto* large = static_cast<char*>(arena.Reallocate(grown, DomArena::kLargestSmall + 1));
  EXPECT_STREQ(large, "0123456789abcde");
  EXPECT_TRUE(arena.Owns(large));
  void* larger = arena.Reallocate(large, 4 * DomArena::kLargestSmall);
  EXPECT_TRUE(arena.Owns(larger));
  void* released = arena.Allocate(DomArena::kLargestSmall * 2);
  arena.Release(released);
  EXPECT_FALSE(arena.Owns(released));
  // `larger` is freed with the arena (the leak checker would say otherwise)
}

TEST_F(DomArenaTest, LibxmlAllocationsInAScopeAreTheArenasAndOutsideAreNot) {
  void* before = xmlMalloc(32);  // the allocator's
  DomArena arena;
  void* inside = nullptr;
  {
    DomArena::Scope scope(arena);
    inside = xmlMalloc(32);
    char* copy = xmlMemStrdup("joint");
    EXPECT_TRUE(arena.Owns(inside));
    EXPECT_TRUE(arena.Owns(copy));
    EXPECT_STREQ(copy, "joint");
    EXPECT_FALSE(arena.Owns(before));
    xmlFree(before);  // not the arena's: goes back to the allocator
    xmlFree(copy);    // the arena's: nothing to do
  }
  void* after = xmlMalloc(32);
  EXPECT_FALSE(arena.Owns(after));
  xmlFree(after);
}

TEST_F(DomArenaTest, ScopesNest) {
  DomArena outer, inner;
  DomArena::Scope a(outer);
  void* p = xmlMalloc(8);
  {
    DomArena::Scope b(inner);
    void* q = xmlMalloc(8);
    EXPECT_TRUE(inner.Owns(q));
    EXPECT_FALSE(inner.Owns(p));
  }
  void* r = xmlMalloc(8);
  EXPECT_TRUE(outer.Owns(p));
  EXPECT_TRUE(outer.Owns(r));
}

// A broken document leaves an error in libxml2's thread-global state while
// the arena is active; the next error, raised after the arena is gone, frees
// that state. It must not be arena memory by then.
TEST_F(DomArenaTest, AParseErrorLeavesNothingOfTheArenaBehind) {
  SourceManager sources;
  DiagnosticEngine diags;
  FileId broken = sources.AddBuffer("broken.urdf", "<robot name='r'><link name='a'></robot>\n");
  EXPECT_EQ(XmlDocument::Parse(broken, sources, diags), nullptr);
  EXPECT_GT(diags.error_count(), 0u);
  // a later error outside any arena
  xmlDocPtr again = xmlReadMemory("<a><b></a>", 10, "again.xml", nullptr,
                                  XML_PARSE_NOERROR | XML_PARSE_NOWARNING | XML_PARSE_NONET);
  EXPECT_EQ(again, nullptr);
  xmlErrorPtr last = xmlGetLastError();
  ASSERT_NE(last, nullptr);
  EXPECT_NE(last->message, nullptr);
  xmlResetLastError();
}

TEST_F(DomArenaTest, DocumentsOutliveOtherDocumentsAndThreadsParseInTheirOwnArenas) {
  // a source manager each, as each compile has its own
  std::vector<std::unique_ptr<SourceManager>> sources;
  std::vector<FileId> files;
  for (int i = 0; i < 8; ++i) {
    sources.push_back(std::make_unique<SourceManager>());
    std::string text = "<robot name='r" + std::to_string(i) + "'>";
    for (int j = 0; j < 200; ++j) text += "<link name='l" + std::to_string(j) + "'/>";
    text += "</robot>\n";
    files.push_back(sources.back()->AddBuffer("m" + std::to_string(i) + ".urdf", std::move(text)));
  }
  std::vector<std::unique_ptr<XmlDocument>> docs(files.size());
  std::vector<DiagnosticEngine> diags(files.size());
  std::vector<std::thread> threads;
  for (size_t t = 0; t < 2; ++t) {
    threads.emplace_back([&, t] {
      for (size_t i = t; i < files.size(); i += 2) docs[i] = XmlDocument::Parse(files[i], *sources[i], diags[i]);
    });
  }
  for (auto& th : threads) th.join();
  docs[3].reset();  // one document goes; the others stay readable
  for (size_t i = 0; i < docs.size(); ++i) {
    if (i == 3) continue;
    ASSERT_TRUE(docs[i]) << i;
    EXPECT_EQ(docs[i]->Root().Attribute("name").value, "r" + std::to_string(i));
    int links = 0;
    for (XmlElement e = docs[i]->Root().FirstChild(); e; e = e.NextSibling()) ++links;
    EXPECT_EQ(links, 200);
  }
}

}  // namespace
}  // namespace mdlc::xml
