// The ESP32-CAM sketch's request handling (esp32-cam-mjpeg/src/cam_http.*):
// bounded head reads, the token check, the route choice and the CORS header.
#include "cam_http.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace {

using cam::RequestReader;
using cam::Route;
using State = RequestReader::State;

const cam::HttpConfig kOpen = {"", ""};
const cam::HttpConfig kLocked = {"s3cret-Token_1", ""};
const cam::HttpConfig kCors = {"", "http://192.168.1.20:5173"};

State FeedText(RequestReader& reader, const std::string& text, uint32_t now) {
  return reader.Feed(reinterpret_cast<const uint8_t*>(text.data()),
                     text.size(), now);
}

Route RouteOf(const std::string& head, const cam::HttpConfig& config) {
  RequestReader reader;
  reader.Start(0);
  EXPECT_EQ(FeedText(reader, head, 1), State::kComplete) << head;
  return cam::Decide(cam::ParseRequest(reader.head(), reader.size()), config);
}

std::string HeadOf(Route route, const cam::HttpConfig& config) {
  char out[512];
  const size_t n =
      cam::FormatHead(cam::FixedReplyFor(route).head, config, out, sizeof(out));
  return std::string(out, n);
}

TEST(CamRequestReader, CompletesAtTheBlankLineEvenWhenBytesComeOneByOne) {
  RequestReader reader;
  reader.Start(100);
  const std::string head = "GET /status HTTP/1.1\r\nHost: cam\r\n\r\n";
  for (size_t i = 0; i + 1 < head.size(); ++i) {
    ASSERT_EQ(FeedText(reader, head.substr(i, 1), 100), State::kReading) << i;
  }
  EXPECT_EQ(FeedText(reader, head.substr(head.size() - 1), 100),
            State::kComplete);
  EXPECT_EQ(reader.size(), head.size());
}

TEST(CamRequestReader, AcceptsBareLineFeeds) {
  RequestReader reader;
  reader.Start(0);
  EXPECT_EQ(FeedText(reader, "GET / HTTP/1.0\n\n", 0), State::kComplete);
}

TEST(CamRequestReader, GivesUpOnASlowClientAtTheDeadline) {
  RequestReader reader;
  reader.Start(1000);
  EXPECT_EQ(FeedText(reader, "GET /sta", 1500), State::kReading);
  EXPECT_EQ(reader.Poll(1000 + cam::kRequestTimeoutMs - 1), State::kReading);
  EXPECT_EQ(reader.Poll(1000 + cam::kRequestTimeoutMs), State::kTimedOut);
  // A byte that arrives late changes nothing.
  EXPECT_EQ(FeedText(reader, "tus HTTP/1.1\r\n\r\n", 4000), State::kTimedOut);
}

TEST(CamRequestReader, DribblingBytesDoesNotExtendTheDeadline) {
  RequestReader reader;
  reader.Start(0);
  uint32_t now = 0;
  State state = State::kReading;
  while (state == State::kReading && now < 60000) {
    now += 100;  // one header byte every 100 ms, never a blank line
    state = FeedText(reader, "X", now);
  }
  EXPECT_EQ(state, State::kTimedOut);
  EXPECT_EQ(now, cam::kRequestTimeoutMs);
}

TEST(CamRequestReader, TimesOutAcrossTheMillisWrapAround) {
  RequestReader reader;
  reader.Start(0xFFFFFF00u);
  EXPECT_EQ(reader.Poll(0xFFFFFF00u + 1000u), State::kReading);
  EXPECT_EQ(reader.Poll(0xFFFFFF00u + cam::kRequestTimeoutMs),
            State::kTimedOut);
}

TEST(CamRequestReader, RefusesAHeadLargerThanItsBufferAndKeepsNoMore) {
  RequestReader reader;
  reader.Start(0);
  const std::string huge =
      "GET /status HTTP/1.1\r\nCookie: " + std::string(64 * 1024, 'a');
  EXPECT_EQ(FeedText(reader, huge, 0), State::kTooLarge);
  EXPECT_EQ(reader.size(), cam::kMaxRequestHead);
  EXPECT_EQ(reader.Room(), 0u);
  EXPECT_EQ(FeedText(reader, "\r\n\r\n", 0), State::kTooLarge);
}

TEST(CamRequestReader, AcceptsAHeadThatFillsTheBufferExactly) {
  RequestReader reader;
  reader.Start(0);
  std::string head = "GET /status HTTP/1.1\r\nX: ";
  head += std::string(cam::kMaxRequestHead - head.size() - 4, 'b');
  head += "\r\n\r\n";
  ASSERT_EQ(head.size(), cam::kMaxRequestHead);
  EXPECT_EQ(FeedText(reader, head, 0), State::kComplete);
}

TEST(CamRoutes, ServesEveryPathWithoutATokenWhenNoneIsConfigured) {
  EXPECT_EQ(RouteOf("GET / HTTP/1.1\r\n\r\n", kOpen), Route::kIndex);
  EXPECT_EQ(RouteOf("GET /status HTTP/1.1\r\n\r\n", kOpen), Route::kStatus);
  EXPECT_EQ(RouteOf("GET /stream?x=1 HTTP/1.1\r\n\r\n", kOpen),
            Route::kStream);
  EXPECT_EQ(RouteOf("GET /nope HTTP/1.1\r\n\r\n", kOpen), Route::kNotFound);
}

TEST(CamRoutes, RefusesMalformedRequestLinesAndOtherMethods) {
  EXPECT_EQ(RouteOf("GARBAGE\r\n\r\n", kOpen), Route::kBadRequest);
  EXPECT_EQ(RouteOf("GET status HTTP/1.1\r\n\r\n", kOpen), Route::kBadRequest);
  EXPECT_EQ(RouteOf("GET /status SPDY/3\r\n\r\n", kOpen), Route::kBadRequest);
  EXPECT_EQ(RouteOf("POST /status HTTP/1.1\r\n\r\n", kOpen),
            Route::kMethodNotAllowed);
}

TEST(CamRoutes, AMissingTokenIsRefusedForStatusAndStream) {
  EXPECT_EQ(RouteOf("GET /status HTTP/1.1\r\n\r\n", kLocked),
            Route::kUnauthorized);
  EXPECT_EQ(RouteOf("GET /stream HTTP/1.1\r\n\r\n", kLocked),
            Route::kUnauthorized);
  // The page itself holds no data; it passes its own query to the stream.
  EXPECT_EQ(RouteOf("GET / HTTP/1.1\r\n\r\n", kLocked), Route::kIndex);
}

TEST(CamRoutes, AWrongTokenIsRefusedWhateverItsLength) {
  for (const char* token : {"s3cret-Token_2", "s3cret-Token_",
                            "s3cret-Token_12", "S3CRET-TOKEN_1", ""}) {
    EXPECT_EQ(RouteOf(std::string("GET /stream?token=") + token +
                          " HTTP/1.1\r\n\r\n",
                      kLocked),
              Route::kUnauthorized)
        << token;
    EXPECT_EQ(RouteOf(std::string("GET /status HTTP/1.1\r\nAuthorization: "
                                  "Bearer ") +
                          token + "\r\n\r\n",
                      kLocked),
              Route::kUnauthorized)
        << token;
  }
  EXPECT_EQ(RouteOf("GET /status?mytoken=s3cret-Token_1 HTTP/1.1\r\n\r\n",
                    kLocked),
            Route::kUnauthorized);
  EXPECT_EQ(RouteOf("GET /status HTTP/1.1\r\nAuthorization: Basic "
                    "s3cret-Token_1\r\n\r\n",
                    kLocked),
            Route::kUnauthorized);
}

TEST(CamRoutes, TheRightTokenInTheQueryOrABearerHeaderIsAccepted) {
  EXPECT_EQ(RouteOf("GET /stream?token=s3cret-Token_1 HTTP/1.1\r\n\r\n",
                    kLocked),
            Route::kStream);
  EXPECT_EQ(RouteOf("GET /status?a=1&token=s3cret-Token_1&b=2 "
                    "HTTP/1.1\r\n\r\n",
                    kLocked),
            Route::kStatus);
  EXPECT_EQ(RouteOf("GET /status HTTP/1.1\r\nHost: cam\r\nauthorization:  "
                    "bearer s3cret-Token_1 \r\n\r\n",
                    kLocked),
            Route::kStatus);
}

TEST(CamTokens, CompareEqualOnlyWhenLengthAndEveryByteMatch) {
  EXPECT_TRUE(cam::ConstantTimeEquals("abc", 3, "abc", 3));
  EXPECT_FALSE(cam::ConstantTimeEquals("abc", 3, "abd", 3));
  EXPECT_FALSE(cam::ConstantTimeEquals("abc", 3, "ab", 2));
  EXPECT_FALSE(cam::ConstantTimeEquals("abc", 3, "abcd", 4));
  EXPECT_FALSE(cam::ConstantTimeEquals("abc", 3, "", 0));
}

TEST(CamTokens, OnlyUrlSafeTokensAndHeaderSafeOriginsAreValid) {
  static_assert(cam::IsValidToken(""), "empty means no token");
  static_assert(cam::IsValidToken("aZ09-._~"), "unreserved characters");
  static_assert(!cam::IsValidToken("a b"), "no space");
  static_assert(!cam::IsValidToken("a&b"), "no query syntax");
  static_assert(cam::IsValidOrigin("http://192.168.1.20:5173"), "an origin");
  static_assert(!cam::IsValidOrigin("http://x\r\nSet-Cookie: a"), "no CRLF");
  EXPECT_FALSE(
      cam::IsValidToken(std::string(cam::kMaxTokenLen + 1, 'a').c_str()));
  EXPECT_TRUE(cam::IsValidToken(std::string(cam::kMaxTokenLen, 'a').c_str()));
}

TEST(CamCors, NoAllowOriginHeaderByDefault) {
  for (Route route : {Route::kIndex, Route::kUnauthorized, Route::kNotFound}) {
    EXPECT_EQ(HeadOf(route, kOpen).find("Access-Control"), std::string::npos);
  }
  char out[512];
  const size_t n = cam::FormatHead(cam::StreamHead(), kOpen, out, sizeof(out));
  ASSERT_GT(n, 0u);
  EXPECT_EQ(std::string(out, n).find("Access-Control"), std::string::npos);
  EXPECT_EQ(RouteOf("OPTIONS /stream HTTP/1.1\r\n\r\n", kOpen),
            Route::kMethodNotAllowed);
}

TEST(CamCors, TheConfiguredOriginIsSentWhenSet) {
  const std::string head = HeadOf(Route::kIndex, kCors);
  EXPECT_NE(head.find("\r\nAccess-Control-Allow-Origin: "
                      "http://192.168.1.20:5173\r\nVary: Origin\r\n"),
            std::string::npos)
      << head;
  EXPECT_EQ(RouteOf("OPTIONS /stream HTTP/1.1\r\n\r\n", kCors),
            Route::kPreflight);
  const std::string preflight = HeadOf(Route::kPreflight, kCors);
  EXPECT_EQ(preflight.rfind("HTTP/1.1 204 No Content\r\n", 0), 0u);
  EXPECT_NE(preflight.find("Access-Control-Allow-Headers: Authorization\r\n"),
            std::string::npos);
}

TEST(CamResponses, HeadsAreCompleteAndSayHowToAuthenticate) {
  const std::string unauthorized = HeadOf(Route::kUnauthorized, kOpen);
  EXPECT_EQ(unauthorized.rfind("HTTP/1.1 401 Unauthorized\r\n", 0), 0u);
  EXPECT_NE(unauthorized.find("WWW-Authenticate: Bearer"), std::string::npos);
  const cam::FixedReply too_large = cam::FixedReplyFor(Route::kTooLarge);
  EXPECT_EQ(too_large.head.status, 431);
  EXPECT_EQ(too_large.head.content_length,
            static_cast<long>(std::strlen(too_large.body)));
  const std::string timeout = HeadOf(Route::kTimeout, kOpen);
  EXPECT_EQ(timeout.rfind("HTTP/1.1 408 ", 0), 0u);
  const std::string close = "Connection: close\r\n\r\n";
  EXPECT_EQ(timeout.substr(timeout.size() - close.size()), close);
  const std::string stream_type = cam::kStreamContentType;
  EXPECT_EQ(
      stream_type.substr(stream_type.size() - std::strlen(cam::kBoundary)),
      cam::kBoundary);
}

TEST(CamResponses, AHeadThatDoesNotFitIsNotWrittenAtAll) {
  char out[40];
  std::memset(out, 'x', sizeof(out));
  EXPECT_EQ(cam::FormatHead(cam::FixedReplyFor(Route::kNotFound).head, kCors,
                            out, sizeof(out)),
            0u);
  EXPECT_EQ(out[0], '\0');
}

}  // namespace
