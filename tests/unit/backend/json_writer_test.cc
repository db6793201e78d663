// The JSON writer: escaping, number formatting, layout (backend/json_writer.h).
#include "backend/json_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

namespace mdlc::backend {
namespace {

TEST(BackendJsonWriter, EscapesStrings) {
  std::string out;
  AppendJsonString(out, "a\"b\\c\n\t\x01 é");
  EXPECT_EQ(out, "\"a\\\"b\\\\c\\n\\t\\u0001 é\"");
}

TEST(BackendJsonWriter, InvalidUtf8BecomesReplacementCharacter) {
  std::string out;
  AppendJsonString(out, std::string("ok\xff\xc3(") + "\xe2\x82\xac");  // bad, bad, then euro
  EXPECT_EQ(out, "\"ok\\ufffd\\ufffd(\xe2\x82\xac\"");
  EXPECT_TRUE(nlohmann::json::accept(out));
}

TEST(BackendJsonWriter, NumbersRoundTripAndNonFiniteIsNull) {
  JsonWriter w;
  const double tricky = 0.1 + 0.2;
  w.BeginArray()
      .Number(tricky)
      .Number(1.0)
      .Number(-0.0)
      .Number(1e-300)
      .Number(std::numeric_limits<double>::infinity())
      .Number(std::nan(""))
      .Int(-7)
      .Bool(true)
      .Null()
      .EndArray();
  EXPECT_EQ(w.str(), "[0.30000000000000004,1,0,1e-300,null,null,-7,true,null]\n");
  EXPECT_EQ(nlohmann::json::parse(w.str())[0].get<double>(), tricky);
}

TEST(BackendJsonWriter, PrettyUpToDepthThenCompact) {
  JsonWriter w(2);
  w.BeginObject();
  w.Key("list").BeginArray();
  w.BeginObject().Key("a").Int(1).Key("b").BeginArray().Int(2).Int(3).EndArray().EndObject();
  w.EndArray();
  w.Key("empty").BeginArray().EndArray();
  w.Key("compact").BeginArray(JsonWriter::Layout::Compact).Int(4).Int(5).EndArray();
  w.EndObject();
  EXPECT_EQ(w.str(),
            "{\n"
            "  \"list\": [\n"
            "    {\"a\":1,\"b\":[2,3]}\n"
            "  ],\n"
            "  \"empty\": [],\n"
            "  \"compact\": [4,5]\n"
            "}\n");
}

}  // namespace
}  // namespace mdlc::backend
