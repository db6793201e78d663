// written.h - what `mdlc convert` writes of a model compiled in a writer
// test, as the writers' unit tests ask for it.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <string_view>

#include "backend/writers/writer.h"
#include "tests/unit/compile_test_util.h"

namespace mdlc::testing {

/// `model` written in format `to`, its warnings in `diags`; a failed write
/// fails the test and gives "".
inline std::string Written(const CompiledText& model, Format to, DiagnosticEngine& diags) {
  writers::WriteOptions options;
  options.to = to;
  std::optional<std::string> text = writers::Write(model.model(), model.module(), options, diags);
  EXPECT_TRUE(text.has_value());
  return text.value_or("");
}

/// How many times `what` occurs in `text`.
inline size_t Count(const std::string& text, std::string_view what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace mdlc::testing
