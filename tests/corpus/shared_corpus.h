// shared_corpus.h - where the corpus tests find the shared corpus
// (MDLC_SHARED_DIR/corpus, set by CMake). It may be absent: each test that
// reads it reports itself skipped then.
#pragma once

#include <filesystem>

namespace mdlc::corpus_test {

inline std::filesystem::path Corpus() { return std::filesystem::path(MDLC_SHARED_DIR) / "corpus"; }
/// Whether the corpus is there (its manifest, which every reader needs).
inline bool HaveCorpus() { return std::filesystem::exists(Corpus() / "manifest.tsv"); }

}  // namespace mdlc::corpus_test
