// Optional authentication (docs/protocol.md section 8).
#include <gtest/gtest.h>

#include "harness.h"

namespace cube::testing {
namespace {

const std::vector<uint8_t> kKey = {0x00, 0x11, 0x22, 0x33, 0x44, 0x55,
                                   0x66, 0x77, 0x88, 0x99, 0xaa, 0xbb,
                                   0xcc, 0xdd, 0xee, 0xff};

std::string Code(const json& r) {
  return r.contains("error") ? r["error"]["code"].get<std::string>() : "";
}

json Unsigned(const std::string& raw) {
  return json::parse(raw.substr(0, raw.size() - 33));
}

TEST(Hmac, MatchesTheRfc4231TestVector) {
  MbedtlsMac mac;
  const std::string key = "Jefe";
  const std::string data = "what do ya want for nothing?";
  uint8_t out[32];
  ASSERT_TRUE(mac.HmacSha256(
      reinterpret_cast<const uint8_t*>(key.data()), key.size(),
      reinterpret_cast<const uint8_t*>(data.data()), data.size(), out));
  EXPECT_EQ(ToHexString(out, 32),
            "5bdcc146bf60754e6a042426089575c75a003f089d2739839dec58b964ec3843");
}

TEST(Auth, ASignedSessionWorksAndEveryReplyIsSigned) {
  Device d(kKey);
  const json h = d.Hello();  // Send() checks the reply MAC
  EXPECT_TRUE(h["ok"]);
  EXPECT_EQ(h["auth"], true);
  EXPECT_TRUE(h.contains("nonce"));
  const json m = d.Call("move_steps", {{"left", 100}, {"right", 100}});
  EXPECT_TRUE(m["ok"]);
  d.RunUntilIdle();
  EXPECT_EQ(d.cube->left_position(), 100);
}

TEST(Auth, ARequestWithoutAMacIsRefusedAndNotExecuted) {
  Device d(kKey);
  d.Hello();
  const std::string raw = d.Raw(json({{"cmd", "move_steps"},
                                      {"seq", 2},
                                      {"sid", d.sid},
                                      {"left", 100},
                                      {"right", 100}})
                                    .dump());
  const json r = Unsigned(raw);
  EXPECT_EQ(Code(r), "AUTH_FAILED");
  EXPECT_EQ(r["seq"], 2);
  EXPECT_FALSE(d.cube->running());
}

TEST(Auth, AnUnsignedRequestWithABadEnvelopeIsStillAuthFailed) {
  // Found by the cube_keyed fuzz target: an invalid "sid" was reported as
  // INVALID_PARAMETER before the missing MAC.
  Device d(kKey);
  d.Hello();
  for (const std::string& raw :
       {std::string(R"({"cmd":"heartbeat","seq":5,"sid":"x"})"),
        std::string(R"({"cmd":"move_steps","seq":-1,"left":9,"right":9})")}) {
    const json r = Unsigned(d.Raw(raw));
    EXPECT_EQ(Code(r), "AUTH_FAILED") << raw;
  }
  // Signed, the same envelope error is named as such.
  const std::string body = R"({"cmd":"heartbeat","seq":5,"sid":"x"})";
  EXPECT_EQ(Code(Unsigned(d.Raw(body + "#" + MacHex(kKey, body)))),
            "INVALID_PARAMETER");
  EXPECT_FALSE(d.cube->running());
}

TEST(Auth, AWrongMacIsRefused) {
  Device d(kKey);
  d.Hello();
  const std::string body = json({{"cmd", "move_steps"},
                                 {"seq", 2},
                                 {"sid", d.sid},
                                 {"left", 100},
                                 {"right", 100}})
                               .dump();
  std::vector<uint8_t> other = kKey;
  other[0] ^= 1;
  const json r = Unsigned(d.Raw(body + "#" + MacHex(other, body)));
  EXPECT_EQ(Code(r), "AUTH_FAILED");
  // A body changed after signing fails too.
  std::string tampered = body;
  tampered.replace(tampered.find("100"), 3, "900");
  const json t = Unsigned(d.Raw(tampered + "#" + MacHex(kKey, body)));
  EXPECT_EQ(Code(t), "AUTH_FAILED");
  EXPECT_FALSE(d.cube->running());
}

TEST(Auth, SeedStyleRequestsAreRefusedWhenAKeyIsSet) {
  Device d(kKey);
  const std::string body = R"({"cmd":"move_steps","left":100,"right":100})";
  const json r = Unsigned(d.Raw(body + "#" + MacHex(kKey, body)));
  EXPECT_EQ(Code(r), "AUTH_FAILED");
  EXPECT_EQ(r["error"]["message"],
            "\"seq\" is required when a key is configured");
}

TEST(Auth, HelloNeedsANonce) {
  Device d(kKey);
  const json r = d.Send({{"cmd", "hello"}, {"seq", 1}});
  EXPECT_EQ(Code(r), "INVALID_PARAMETER");
  EXPECT_EQ(r["error"]["message"], "\"nonce\" is required");
}

TEST(Auth, ACapturedRequestReplayedLaterIsNeverExecutedAgain) {
  Device d(kKey);
  d.Hello();
  const std::string body = json({{"cmd", "move_steps"},
                                 {"seq", 2},
                                 {"sid", d.sid},
                                 {"left", 100},
                                 {"right", 100}})
                               .dump();
  const std::string packet = body + "#" + MacHex(kKey, body);
  const std::string first = d.Raw(packet);
  d.RunUntilIdle();
  EXPECT_EQ(d.Raw(packet), first) << "same session: the stored reply";
  d.seq = 2;
  for (int i = 0; i < 20; ++i) d.Call("heartbeat");
  EXPECT_EQ(Code(Unsigned(d.Raw(packet))), "STALE_SEQUENCE");
  d.Hello();
  EXPECT_EQ(Code(Unsigned(d.Raw(packet))), "SESSION_MISMATCH");
  d.RunUntilIdle();
  EXPECT_EQ(d.cube->left_position(), 100);
}

TEST(Auth, ResetEstopNeedsTheCurrentSessionWhenAKeyIsSet) {
  Device d(kKey);
  d.Hello();
  d.Call("estop");
  const uint32_t old = d.sid;
  d.Hello();
  const std::string body =
      json({{"cmd", "reset_estop"}, {"seq", 50}, {"sid", old}}).dump();
  EXPECT_EQ(Code(Unsigned(d.Raw(body + "#" + MacHex(kKey, body)))),
            "SESSION_MISMATCH");
  EXPECT_TRUE(d.cube->estopped());
  EXPECT_TRUE(d.Call("reset_estop")["ok"]);
  EXPECT_FALSE(d.cube->estopped());
}

TEST(Auth, WithoutAKeyAMacSuffixIsIgnored) {
  Device d;
  const std::string body = R"({"cmd":"heartbeat"})";
  const std::string raw = d.Raw(body + "#" + MacHex(kKey, body));
  const json r = json::parse(raw);
  EXPECT_TRUE(r["ok"]);
}

TEST(Auth, GarbageWithAKeyIsRefusedWithoutACrash) {
  Device d(kKey);
  const std::string raw = d.Raw("not json#0123456789abcdef0123456789abcdef");
  EXPECT_EQ(Code(Unsigned(raw)), "AUTH_FAILED");
}

}  // namespace
}  // namespace cube::testing
