#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "json_number.h"
#include "json_reader.h"
#include "json_writer.h"
#include "text.h"

namespace cube {
namespace {

JsonError ParseText(JsonReader& r, const std::string& s) {
  return r.Parse(s.data(), s.size());
}

TEST(JsonReader, ReadsAFlatMessage) {
  JsonReader r;
  ASSERT_EQ(
      ParseText(
          r,
          R"({"cmd":"move_steps","seq":42,"left":-100,"speed":512.5,"x":true,"n":null})"),
      JsonError::kOk);
  EXPECT_STREQ(r.Find("cmd")->str, "move_steps");
  EXPECT_EQ(r.Find("seq")->integer, 42);
  EXPECT_EQ(r.Find("left")->integer, -100);
  EXPECT_TRUE(r.Find("left")->is_integer);
  EXPECT_DOUBLE_EQ(r.Find("speed")->number, 512.5);
  EXPECT_FALSE(r.Find("speed")->is_integer);
  EXPECT_TRUE(r.Find("x")->boolean);
  EXPECT_EQ(r.Find("n"), nullptr) << "null counts as absent";
  EXPECT_EQ(r.Find("missing"), nullptr);
}

TEST(JsonReader, SkipsNestedUnknownFields) {
  JsonReader r;
  ASSERT_EQ(
      ParseText(r, R"( { "meta" : {"a":[1,2,{"b":"}"}]}, "cmd" : "stop" } )"),
      JsonError::kOk);
  EXPECT_EQ(r.Find("meta")->type, JsonType::kNested);
  EXPECT_STREQ(r.Find("cmd")->str, "stop");
}

TEST(JsonReader, TreatsTenPointZeroAndOneE1AsIntegers) {
  JsonReader r;
  ASSERT_EQ(
      ParseText(
          r, R"({"a":10.0,"b":1e1,"c":10.5,"d":-0,"e":4294967295,"f":1.5e3})"),
      JsonError::kOk);
  EXPECT_TRUE(r.Find("a")->is_integer);
  EXPECT_EQ(r.Find("a")->integer, 10);
  EXPECT_TRUE(r.Find("b")->is_integer);
  EXPECT_EQ(r.Find("b")->integer, 10);
  EXPECT_FALSE(r.Find("c")->is_integer);
  EXPECT_TRUE(r.Find("d")->is_integer);
  EXPECT_EQ(r.Find("e")->integer, 4294967295LL);
  EXPECT_EQ(r.Find("f")->integer, 1500);
}

TEST(JsonReader, NumbersAreCorrectlyRoundedLikeStrtod) {
  const char* samples[] = {"10.5",
                           "0.1",
                           "12.345678901",
                           "-7.85398163397448",
                           "3.141592653589793",
                           "1e-5",
                           "123456789012345678",
                           "6.02214076e23",
                           "2.5e-300",
                           "0.30000000000000004"};
  for (const char* s : samples) {
    double d = 0;
    ASSERT_TRUE(ParseJsonNumber(s, std::strlen(s), &d)) << s;
    const double want = std::strtod(s, nullptr);
    // Correctly rounded whenever the digits fit 2^53 and |exponent| <= 22
    // (every value the protocol uses); close otherwise.
    if (std::strlen(s) < 18 && std::strchr(s, 'e') == nullptr) {
      EXPECT_EQ(d, want) << s;
    } else {
      EXPECT_NEAR(d, want, std::fabs(want) * 1e-15) << s;
    }
  }
}

TEST(JsonReader, TrailingZerosAfterThePointChangeNothing) {
  // Found by fuzzing: the zeros made the mantissa too long for the exact path.
  const char* samples[] = {"999999.00000000000", "0.50000000000000000000",
                           "1024.0000000000000000000", "-3.2500000000000000"};
  for (const char* s : samples) {
    double d = 0;
    ASSERT_TRUE(ParseJsonNumber(s, std::strlen(s), &d)) << s;
    EXPECT_EQ(d, std::strtod(s, nullptr)) << s;
  }
  JsonReader reader;
  const char* msg = "{\"speed\":999999.00000000000}";
  ASSERT_EQ(reader.Parse(msg, std::strlen(msg)), JsonError::kOk);
  const JsonField* f = reader.Find("speed");
  ASSERT_NE(f, nullptr);
  EXPECT_TRUE(f->is_integer);
  EXPECT_EQ(f->integer, 999999);
  EXPECT_EQ(f->number, 999999.0);
}

TEST(JsonReader, ALargeIntegerReadsAsTheSameDoubleBothWays) {
  // Found by fuzzing: above 2^53, 50200000000000004 * 10 rounded twice.
  JsonReader reader;
  const char* msg = "{\"n\":502000000000000040}";
  ASSERT_EQ(reader.Parse(msg, std::strlen(msg)), JsonError::kOk);
  const JsonField* f = reader.Find("n");
  ASSERT_NE(f, nullptr);
  ASSERT_TRUE(f->is_integer);
  EXPECT_EQ(f->integer, 502000000000000040LL);
  EXPECT_EQ(f->number, static_cast<double>(f->integer));
  EXPECT_EQ(f->number, std::strtod("502000000000000040", nullptr));
}

TEST(JsonReader, DecodesEscapesAndUnicode) {
  JsonReader r;
  ASSERT_EQ(ParseText(r, R"({"s":"a\"b\\c\/\n\u00e9\ud83d\ude00"})"),
            JsonError::kOk);
  EXPECT_STREQ(r.Find("s")->str, "a\"b\\c/\n\xc3\xa9\xf0\x9f\x98\x80");
}

TEST(JsonReader, RejectsEveryTruncationOfAValidMessage) {
  const std::string full =
      R"({"cmd":"move_cm","seq":3,"sid":99,"left_cm":10.5,"right_cm":-1e1,"tag":"x\"y","o":{"a":[true,false,null]}})";
  JsonReader r;
  ASSERT_EQ(ParseText(r, full), JsonError::kOk);
  for (size_t n = 0; n < full.size(); ++n) {
    const JsonError e = ParseText(r, full.substr(0, n));
    EXPECT_NE(e, JsonError::kOk) << n;
  }
}

TEST(JsonReader, NamesEachKindOfMalformedInput) {
  JsonReader r;
  EXPECT_EQ(ParseText(r, ""), JsonError::kEmpty);
  EXPECT_EQ(ParseText(r, "  "), JsonError::kEmpty);
  EXPECT_EQ(ParseText(r, "[1,2]"), JsonError::kNotAnObject);
  EXPECT_EQ(ParseText(r, "hello"), JsonError::kNotAnObject);
  EXPECT_EQ(ParseText(r, R"({"a":1)"), JsonError::kTruncated);
  EXPECT_EQ(ParseText(r, R"({"a":1,"a":2})"), JsonError::kDuplicateKey);
  EXPECT_EQ(ParseText(r, R"({"a":1} x)"), JsonError::kTrailingData);
  EXPECT_EQ(ParseText(r, R"({"a":01})"), JsonError::kSyntax);
  EXPECT_EQ(ParseText(r, R"({"a":tru})"), JsonError::kSyntax);
  EXPECT_EQ(ParseText(r, R"({"a":"\x"})"), JsonError::kSyntax);
  EXPECT_EQ(ParseText(r, "{\"a\":\"\x01\"}"), JsonError::kSyntax);
  EXPECT_EQ(ParseText(r, R"({"a":[[[[[[[[[1]]]]]]]]]})"), JsonError::kTooDeep);
  EXPECT_EQ(ParseText(r, R"({"a":[[[[[[[1]]]]]]]})"), JsonError::kOk);
  const std::string big = "{\"a\":\"" + std::string(1100, 'x') + "\"}";
  EXPECT_EQ(ParseText(r, big), JsonError::kTooLong);
  std::string many = "{";
  for (int i = 0; i < 33; ++i)
    many += (i ? ",\"k" : "\"k") + std::to_string(i) + "\":1";
  many += "}";
  EXPECT_EQ(ParseText(r, many), JsonError::kTooManyFields);
}

TEST(JsonReader, SurvivesRandomBytes) {
  std::mt19937 rng(7);
  JsonReader r;
  const std::string alphabet = "{}[]\":,-+.eE0123456789abcdeftrunl\\ \x01\xff";
  for (int i = 0; i < 20000; ++i) {
    std::string s;
    const size_t n = rng() % 64;
    for (size_t k = 0; k < n; ++k) s += alphabet[rng() % alphabet.size()];
    (void)ParseText(r, s);
  }
  SUCCEED();
}

std::string Write(void (*fn)(JsonWriter&)) {
  char buf[256];
  JsonWriter w(buf, sizeof(buf));
  fn(w);
  EXPECT_TRUE(w.ok());
  return std::string(buf, w.size());
}

TEST(Text, NeverCutsAUtf8SequenceInHalf) {
  // The builder holds 159 bytes: after 156 the second two-byte character
  // (or a three-byte one after 157) would straddle the end; it is dropped
  // whole.
  const std::string pad(156, 'x');
  Text t;
  t.S(pad.c_str()).S("\xc3\xa9\xc3\xa9");
  EXPECT_EQ(std::string(t.c_str()), pad + "\xc3\xa9");
  Text u;
  u.S(pad.c_str()).S("a\xe2\x9c\x93");  // a check mark, 3 bytes
  EXPECT_EQ(std::string(u.c_str()), pad + "a");
}

TEST(JsonWriter, WritesNestedObjectsWithCommas) {
  EXPECT_EQ(Write([](JsonWriter& w) {
              w.BeginObject();
              w.Key("a");
              w.Int(-5);
              w.Key("b");
              w.BeginArray();
              w.String("x");
              w.Bool(false);
              w.Null();
              w.EndArray();
              w.Key("c");
              w.BeginObject();
              w.EndObject();
              w.Key("d");
              w.Uint(4294967295u);
              w.EndObject();
            }),
            R"({"a":-5,"b":["x",false,null],"c":{},"d":4294967295})");
}

TEST(JsonWriter, EscapesStrings) {
  EXPECT_EQ(Write([](JsonWriter& w) { w.String("q\"b\\n\n\x01"); }),
            R"("q\"b\\n\n\u0001")");
}

TEST(JsonWriter, WritesNumbersWithAtMostNineDecimals) {
  char buf[40];
  auto fmt = [&](double v) {
    const size_t n = FormatNumber(v, buf, sizeof(buf));
    return std::string(buf, n);
  };
  EXPECT_EQ(fmt(800.0), "800");
  EXPECT_EQ(fmt(-0.5), "-0.5");
  EXPECT_EQ(fmt(3.141592653589793), "3.141592654");
  EXPECT_EQ(fmt(-0.0), "0");
  EXPECT_EQ(fmt(1e-12), "0");
  EXPECT_EQ(fmt(0.9999999999), "1");
  EXPECT_EQ(fmt(46.0253), "46.0253");
  EXPECT_EQ(FormatNumber(NAN, buf, sizeof(buf)), 0u);
}

TEST(JsonWriter, ReportsOverflowInsteadOfWritingPastTheBuffer) {
  char buf[8];
  JsonWriter w(buf, sizeof(buf));
  w.BeginObject();
  w.Key("long_key");
  w.Int(1);
  w.EndObject();
  EXPECT_FALSE(w.ok());
  EXPECT_LE(w.size(), sizeof(buf));
}

}  // namespace
}  // namespace cube

TEST(Text, SanitizeReasonKeepsWellFormedUtf8AndReplacesAnyOtherByte) {
  // "é" and "→" kept; a lone continuation byte, a truncated sequence, an
  // overlong form and a surrogate each become '?'; controls become a space.
  char s[64] = "caf\xC3\xA9 \xA7 \xE2\x86\x92 \xE2\x86 \xC0\xAF \xED\xA0\x80\r\nend";
  const size_t n = cube::SanitizeReason(s, std::strlen(s));
  EXPECT_STREQ(s, "caf\xC3\xA9 ? \xE2\x86\x92 ?? ?? ??? end");
  EXPECT_EQ(n, std::strlen(s));
}
