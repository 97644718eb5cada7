// Authentication (docs/protocol.md section 8): a key, the explicit
// unauthenticated opt-out, and the closed state before either is set.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "harness.h"
#include "key_hex.h"

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
  EXPECT_EQ(h["auth"], "hmac-sha256");
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

TEST(Auth, AMacWrongInAnySingleDigitIsRefused) {
  Device d(kKey);
  d.Hello();
  const std::string body = json({{"cmd", "move_steps"},
                                 {"seq", 2},
                                 {"sid", d.sid},
                                 {"left", 100},
                                 {"right", 100}})
                               .dump();
  const std::string good = MacHex(kKey, body);
  for (size_t i = 0; i < good.size(); ++i) {
    std::string forged = good;
    forged[i] = forged[i] == '0' ? '1' : '0';
    const json r = Unsigned(d.Raw(body + "#" + forged));
    EXPECT_EQ(Code(r), "AUTH_FAILED") << "digit " << i;
  }
  EXPECT_FALSE(d.cube->running());
  EXPECT_TRUE(Unsigned(d.Raw(body + "#" + good))["ok"]);
}

TEST(Auth, ResetEstopWithoutTheSessionIsRefusedWhenAKeyIsSet) {
  Device d(kKey);
  d.Hello();
  d.Call("estop");
  // seed-style, correctly MACed: refused, the latch stays
  const std::string seed = R"({"cmd":"reset_estop"})";
  EXPECT_EQ(Code(Unsigned(d.Raw(seed + "#" + MacHex(kKey, seed)))),
            "AUTH_FAILED");
  // a session id that was never issued
  const std::string other =
      json({{"cmd", "reset_estop"}, {"seq", 9}, {"sid", d.sid + 1}}).dump();
  EXPECT_EQ(Code(Unsigned(d.Raw(other + "#" + MacHex(kKey, other)))),
            "SESSION_MISMATCH");
  EXPECT_TRUE(d.cube->estopped());
}

TEST(Auth, TheOptOutAcceptsSeedStyleRequestsAndSaysAuthNone) {
  Device d;
  EXPECT_EQ(d.cube->auth_mode(), AuthMode::kNone);
  const json m = d.Send({{"cmd", "move_steps"}, {"left", 50}, {"right", 50}});
  EXPECT_TRUE(m["ok"]);
  EXPECT_FALSE(m.contains("seq"));
  d.RunUntilIdle();
  EXPECT_EQ(d.cube->left_position(), 50);
  d.Send({{"cmd", "estop"}});
  EXPECT_TRUE(d.Send({{"cmd", "reset_estop"}})["ok"]);
  EXPECT_FALSE(d.cube->estopped());
  EXPECT_EQ(d.Hello()["auth"], "none");
}

// A Cube nobody configured (neither SetKey nor AllowUnauthenticated) is
// closed: only a stop gets through.
class Unconfigured : public ::testing::Test {
 protected:
  Unconfigured() {
    CubeDeps deps;
    deps.clock = &clock_;
    deps.motors = &motors_;
    deps.random = &random_;
    deps.mac = &mac_;
    cube_ = std::make_unique<Cube>(deps, "cube-closed");
  }
  json Send(const std::string& text) {
    uint8_t out[kMaxMessage + 64];
    const size_t n =
        cube_->Handle(reinterpret_cast<const uint8_t*>(text.data()),
                      text.size(), out, sizeof(out));
    return json::parse(std::string(reinterpret_cast<char*>(out), n));
  }
  FakeClock clock_;
  RecordingMotors motors_{clock_};
  SequenceRandom random_;
  MbedtlsMac mac_;
  std::unique_ptr<Cube> cube_;
};

TEST_F(Unconfigured, RefusesEverythingButStopAndEstop) {
  EXPECT_EQ(cube_->auth_mode(), AuthMode::kUnconfigured);
  for (const char* req :
       {R"({"cmd":"hello","seq":1,"nonce":"n"})",
        R"({"cmd":"move_steps","left":100,"right":100})",
        R"({"cmd":"drive","left_sps":100,"right_sps":100})",
        R"({"cmd":"set_config","host_timeout_ms":9000})",
        R"({"cmd":"get_status"})", R"({"cmd":"reset_estop"})"}) {
    const json r = Send(req);
    EXPECT_EQ(Code(r), "AUTH_FAILED") << req;
    EXPECT_NE(r["error"]["message"].get<std::string>().find(
                  "authentication is not configured"),
              std::string::npos);
  }
  EXPECT_FALSE(cube_->running());
  EXPECT_EQ(cube_->config().host_timeout_ms, 2000);
  EXPECT_TRUE(Send(R"({"cmd":"stop"})")["ok"]);
  EXPECT_TRUE(Send(R"({"cmd":"estop","reason":"closed"})")["ok"]);
  EXPECT_TRUE(cube_->estopped());
  EXPECT_EQ(Code(Send(R"({"cmd":"reset_estop"})")), "AUTH_FAILED");
  EXPECT_TRUE(cube_->estopped());
}

TEST_F(Unconfigured, ABadKeyLeavesItClosedAndAGoodOneOpensASignedSession) {
  EXPECT_FALSE(cube_->SetKey(kKey.data(), 0));
  std::vector<uint8_t> long_key(kMaxKeyLen + 1, 7);
  EXPECT_FALSE(cube_->SetKey(long_key.data(), long_key.size()));
  EXPECT_EQ(cube_->auth_mode(), AuthMode::kUnconfigured);
  ASSERT_TRUE(cube_->SetKey(kKey.data(), kKey.size()));
  EXPECT_EQ(cube_->auth_mode(), AuthMode::kHmacSha256);
  cube_->AllowUnauthenticated();
  EXPECT_EQ(cube_->auth_mode(), AuthMode::kNone);
  EXPECT_EQ(Send(R"({"cmd":"hello","seq":1})")["auth"], "none");
}

TEST(KeyHex, ChecksAKeyTheWayTheSketchBuildDoes) {
  static_assert(CheckKeyHex("00ff") == KeyHexError::kOk, "two bytes");
  static_assert(ParseKeyHex("a0Fb").bytes[1] == 0xfb, "either case");
  EXPECT_EQ(CheckKeyHex(""), KeyHexError::kEmpty);
  EXPECT_EQ(CheckKeyHex("abc"), KeyHexError::kOddLength);
  EXPECT_EQ(CheckKeyHex("zz"), KeyHexError::kNotHex);
  EXPECT_EQ(CheckKeyHex("00 11"), KeyHexError::kNotHex);
  EXPECT_EQ(CheckKeyHex(std::string(128, 'a').c_str()), KeyHexError::kOk);
  EXPECT_EQ(CheckKeyHex(std::string(130, 'a').c_str()), KeyHexError::kTooLong);
  const KeyBytes k = ParseKeyHex("00112233445566778899aabbccddeeff");
  ASSERT_EQ(k.len, kKey.size());
  EXPECT_TRUE(std::equal(kKey.begin(), kKey.end(), k.bytes));
  EXPECT_EQ(ParseKeyHex("0g").len, 0u);
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
