// diagnostic_stream_test.cc - the command line gathers a flood of
// diagnostics into few writes, and never loses or reorders one.
#include "diagnostic_stream.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mdlc::cli {
namespace {

using namespace std::chrono_literals;

/// A stream whose clock the test moves, and the writes it made.
struct Recorded {
  DiagnosticStream::Clock::time_point now{};
  std::vector<std::string> writes;
  DiagnosticStream stream{[this](std::string_view text) { writes.emplace_back(text); },
                          [this] { return now; }};
};

TEST(DiagnosticStreamTest, ADiagnosticThatComesAloneIsWrittenAtOnce) {
  Recorded r;
  r.stream.Write("first\n");
  EXPECT_EQ(r.writes, std::vector<std::string>{"first\n"});
  r.now += DiagnosticStream::kGatherWindow;
  r.stream.Write("second\n");
  EXPECT_EQ(r.writes, (std::vector<std::string>{"first\n", "second\n"}));
}

TEST(DiagnosticStreamTest, AFloodIsGatheredUntilFinish) {
  Recorded r;
  r.stream.Write("a\n");
  std::string gathered;
  for (int i = 0; i < 100; ++i) {
    r.now += 100us;  // all within the window of the first write
    const std::string text = "b" + std::to_string(i) + "\n";
    r.stream.Write(text);
    gathered += text;
  }
  ASSERT_EQ(r.writes.size(), 1u);
  r.stream.Finish();
  EXPECT_EQ(r.writes, (std::vector<std::string>{"a\n", gathered}));
}

TEST(DiagnosticStreamTest, AFullBufferIsWrittenWithinTheWindow) {
  Recorded r;
  r.stream.Write("start\n");
  const std::string big(10 * 1024, 'x');
  std::string sent;
  while (r.writes.size() == 1) {
    r.stream.Write(big);
    sent += big;
  }
  // written the moment it held kGatherBytes, all of it in one piece
  EXPECT_GE(r.writes[1].size(), DiagnosticStream::kGatherBytes);
  EXPECT_LT(r.writes[1].size(), DiagnosticStream::kGatherBytes + big.size());
  EXPECT_EQ(r.writes[1], sent);
}

TEST(DiagnosticStreamTest, AQuietSpellWritesWhatWaitedWithTheNewOne) {
  Recorded r;
  r.stream.Write("1\n");
  r.now += 1ms;
  r.stream.Write("2\n");  // gathered
  r.now += DiagnosticStream::kGatherWindow + 1ms;
  r.stream.Write("3\n");  // after a quiet spell: written, after what waited
  EXPECT_EQ(r.writes, (std::vector<std::string>{"1\n", "2\n3\n"}));
}

TEST(DiagnosticStreamTest, AfterFinishEveryDiagnosticIsWrittenAtOnce) {
  Recorded r;
  r.stream.Write("1\n");
  r.stream.Finish();
  r.stream.Write("2\n");
  r.stream.Write("3\n");
  EXPECT_EQ(r.writes, (std::vector<std::string>{"1\n", "2\n", "3\n"}));
}

TEST(DiagnosticStreamTest, WhatWaitsIsWrittenWhenTheStreamEnds) {
  std::vector<std::string> writes;
  {
    DiagnosticStream::Clock::time_point now{};
    DiagnosticStream stream([&](std::string_view text) { writes.emplace_back(text); },
                            [&] { return now; });
    stream.Write("1\n");
    stream.Write("2\n");
  }
  EXPECT_EQ(writes, (std::vector<std::string>{"1\n", "2\n"}));
}

}  // namespace
}  // namespace mdlc::cli
