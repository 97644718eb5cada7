// Protocol 1.0 (docs/protocol.md): sessions, exactly-once replies, seed compatibility, heartbeat and errors.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "harness.h"

namespace cube::testing {
namespace {

std::string Code(const json& r) {
  return r.contains("error") ? r["error"]["code"].get<std::string>() : "";
}

TEST(Hello, OpensASessionAndDescribesTheDevice) {
  Device d;
  const json r = d.Hello();
  EXPECT_TRUE(r["ok"]);
  EXPECT_EQ(r["seq"], 1);
  EXPECT_NE(r["sid"], 0);
  EXPECT_EQ(r["cmd"], "hello");
  EXPECT_EQ(r["device_id"], "cube-test");
  EXPECT_EQ(r["protocol_version"], "1.1");
  EXPECT_EQ(r["auth"], false);
  const json caps = r["capabilities"];
  EXPECT_NE(std::find(caps.begin(), caps.end(), "locomotion.differential:v1.0"),
            caps.end());
  EXPECT_NE(std::find(caps.begin(), caps.end(), "communication.led:v1.0"),
            caps.end());
  EXPECT_NE(std::find(caps.begin(), caps.end(), "safety.estop:v1.0"),
            caps.end());
  EXPECT_EQ(r["config"]["steps_per_revolution"], 4096);
  EXPECT_EQ(r["config"]["max_speed_steps_per_s"], 1024);
  EXPECT_EQ(r["config"]["acceleration_steps_per_s2"], 512);
  EXPECT_EQ(r["config"]["host_timeout_ms"], 2000);
  EXPECT_EQ(r["config"]["max_steps_per_command"], 40960);
}

TEST(Hello, RepeatedWithTheSameNonceAndSeqGetsTheSameReply) {
  Device d;
  const std::string req = R"({"cmd":"hello","seq":5,"nonce":"abc"})";
  const std::string first = d.Raw(req);
  const std::string again = d.Raw(req);
  EXPECT_EQ(first, again);
  EXPECT_EQ(d.cube->session_id(), json::parse(first)["sid"].get<uint32_t>());
}

TEST(Hello, AnotherHelloOpensANewSessionWithANewSid) {
  Device d;
  const uint32_t a = d.Hello()["sid"];
  const uint32_t b = d.Hello()["sid"];
  EXPECT_NE(a, b);
  const json old = d.Send({{"cmd", "get_status"}, {"seq", 9}, {"sid", a}});
  EXPECT_EQ(Code(old), "SESSION_MISMATCH");
}

TEST(Session, ARetriedMoveIsAnsweredFromMemoryAndNotExecutedTwice) {
  Device d;
  d.Hello();
  const std::string req = json({{"cmd", "move_cm"},
                                {"seq", 2},
                                {"sid", d.sid},
                                {"left_cm", 10},
                                {"right_cm", 10}})
                              .dump();
  const std::string first = d.Raw(req);
  d.Run(100);
  const std::string again = d.Raw(req);  // the reply was lost; the host retries
  EXPECT_EQ(first, again) << "byte for byte";
  d.RunUntilIdle();
  d.Run(100);
  EXPECT_EQ(d.cube->left_position(), 2172);
  EXPECT_EQ(d.cube->right_position(), 2172);
  EXPECT_EQ(d.observer.started.size(), 1u);
  EXPECT_EQ(d.Raw(req), first) << "still remembered after the move";
}

TEST(Session, RemembersTheLast16RepliesAndCallsOlderOnesStale) {
  Device d;
  d.Hello();
  std::string replies[20];
  for (uint32_t s = 2; s < 22; ++s) {
    replies[s - 2] =
        d.Raw(json({{"cmd", "heartbeat"}, {"seq", s}, {"sid", d.sid}}).dump());
  }
  // seq 6..21 are the last 16.
  EXPECT_EQ(
      d.Raw(json({{"cmd", "heartbeat"}, {"seq", 6}, {"sid", d.sid}}).dump()),
      replies[4]);
  const json stale = d.Send({{"cmd", "heartbeat"}, {"seq", 5}, {"sid", d.sid}});
  EXPECT_EQ(Code(stale), "STALE_SEQUENCE");
  EXPECT_EQ(stale["seq"], 5);
  EXPECT_EQ(stale["error"]["details"]["last_seq"], 21);
}

TEST(Session, ASeqBelowTheHighestThatWasNeverSentIsStaleAndNotExecuted) {
  Device d;
  d.Hello();
  d.Send({{"cmd", "heartbeat"}, {"seq", 10}, {"sid", d.sid}});
  const json r = d.Send({{"cmd", "move_steps"},
                         {"seq", 7},
                         {"sid", d.sid},
                         {"left", 100},
                         {"right", 100}});
  EXPECT_EQ(Code(r), "STALE_SEQUENCE");
  EXPECT_FALSE(d.cube->running());
}

TEST(Session, AWrongSidIsASessionMismatchAndNotExecuted) {
  Device d;
  d.Hello();
  const json r = d.Send({{"cmd", "move_steps"},
                         {"seq", 2},
                         {"sid", d.sid + 1},
                         {"left", 100},
                         {"right", 100}});
  EXPECT_FALSE(r["ok"]);
  EXPECT_EQ(Code(r), "SESSION_MISMATCH");
  EXPECT_EQ(r["seq"], 2);
  EXPECT_FALSE(d.cube->running());
}

TEST(Session, SeqWithoutSidIsRefused) {
  Device d;
  d.Hello();
  const json r = d.Send(
      {{"cmd", "move_steps"}, {"seq", 2}, {"left", 100}, {"right", 100}});
  EXPECT_EQ(Code(r), "SESSION_MISMATCH");
  EXPECT_FALSE(d.cube->running());
}

TEST(Session, ARestartedHostIsNotMistakenForARetry) {
  Device d;
  d.Hello();
  d.Call("move_steps", {{"left", 100}, {"right", 100}});  // seq 2
  d.RunUntilIdle();
  d.Hello();  // the host restarted: new session, seq starts again
  const json r =
      d.Call("move_steps", {{"left", 100}, {"right", 100}});  // seq 2 again
  EXPECT_TRUE(r["ok"]);
  EXPECT_EQ(r["move_id"], 2) << "executed, not replayed";
  d.RunUntilIdle();
  EXPECT_EQ(d.cube->left_position(), 200);
}

TEST(Session, EveryReplyEchoesSeqAndSid) {
  Device d;
  d.Hello();
  for (const char* cmd :
       {"heartbeat", "get_status", "stop", "no_such_command"}) {
    const json r = d.Call(cmd);
    EXPECT_EQ(r["seq"], d.seq) << cmd;
    EXPECT_EQ(r["sid"], d.sid) << cmd;
    EXPECT_EQ(r["cmd"], cmd);
  }
}

TEST(Seed, CommandsWithoutSeqWorkAsTheSeedFirmwareDid) {
  Device d;
  json r = d.Send(
      {{"cmd", "move_steps"}, {"left", 500}, {"right", 500}, {"speed", 800}});
  EXPECT_TRUE(r["ok"]);
  EXPECT_FALSE(r.contains("seq"));
  EXPECT_EQ(r["speed"], 800);
  d.RunUntilIdle();
  r = d.Send(
      {{"cmd", "move_cm"}, {"left_cm", 10}, {"right_cm", 10}, {"speed", 1024}});
  EXPECT_EQ(r["left_steps"], 2172);
  d.RunUntilIdle();
  r = d.Send({{"cmd", "rotate_deg"}, {"degrees", 90}, {"speed", 1024}});
  // The accumulators carry the fractions of the 10 cm move (2172.995):
  // left 466.39 -> 466 (-1706), right 3879.60 -> 3879 (+1707).
  EXPECT_EQ(r["left_steps"], -1706);
  EXPECT_EQ(r["right_steps"], 1707);
  d.RunUntilIdle();
  r = d.Send({{"cmd", "stop"}});
  EXPECT_TRUE(r["ok"]);
  r = d.Send({{"cmd", "set_config"},
              {"wheel_diameter_cm", 6.0},
              {"wheel_base_cm", 10.0}});
  EXPECT_TRUE(r["ok"]);
  r = d.Status();
  EXPECT_EQ(r["left_steps"], 500 + 2172 - 1706);
  EXPECT_EQ(r["right_steps"], 500 + 2172 + 1707);
}

TEST(Seed, ARepeatedSeedRequestIsExecutedAgain) {
  Device d;
  const std::string req = R"({"cmd":"move_steps","left":100,"right":100})";
  d.Raw(req);
  d.RunUntilIdle();
  d.Raw(req);
  d.RunUntilIdle();
  EXPECT_EQ(d.cube->left_position(), 200) << "why hosts should use sessions";
}

TEST(Heartbeat, ReportsUptimeAndState) {
  Device d;
  d.Hello();
  d.Run(1234, false);
  const json r = d.Call("heartbeat");
  EXPECT_TRUE(r["ok"]);
  EXPECT_EQ(r["uptime_ms"], 1234);
  EXPECT_EQ(r["running"], false);
  EXPECT_EQ(r["estop"], false);
}

TEST(Errors, GarbageTruncatedAndOversizedInputGetMalformedReplies) {
  Device d;
  for (const std::string bad :
       {std::string("garbage"),
        std::string("{\"cmd\":\"move_steps\",\"left\":1"), std::string(""),
        std::string("[1,2,3]"), std::string("{\"cmd\":\"stop\"} trailing"),
        std::string("{\"cmd\":\"stop\",\"cmd\":\"stop\"}"),
        std::string("\xff\xfe\x00\x01", 4)}) {
    const json r = json::parse(d.Raw(bad));
    EXPECT_EQ(Code(r), "MALFORMED") << bad;
    EXPECT_FALSE(r["ok"]);
    EXPECT_FALSE(r.contains("seq"));
  }
  const json big = json::parse(d.Raw(std::string(1500, '{')));
  EXPECT_EQ(Code(big), "MALFORMED");
  EXPECT_EQ(big["error"]["details"]["length"], 1500);
  EXPECT_TRUE(d.Send({{"cmd", "heartbeat"}})["ok"])
      << "and the device keeps answering";
}

TEST(Errors, UnknownCommandsAreNamed) {
  Device d;
  const json r = d.Send({{"cmd", "fly"}});
  EXPECT_EQ(Code(r), "UNKNOWN_COMMAND");
  EXPECT_EQ(r["cmd"], "fly");
  EXPECT_EQ(r["error"]["message"], "unknown command \"fly\"");
}

TEST(Errors, MissingOrMistypedCmdIsInvalid) {
  Device d;
  EXPECT_EQ(d.Send({{"left", 1}})["error"]["message"], "\"cmd\" is required");
  EXPECT_EQ(d.Send({{"cmd", 5}})["error"]["message"],
            "\"cmd\" must be a string");
  const json r = d.Send({{"cmd", "stop"}, {"seq", -1}});
  EXPECT_EQ(Code(r), "INVALID_PARAMETER");
  EXPECT_FALSE(r.contains("seq"));
}

TEST(Errors, UnknownFieldsAreIgnored) {
  Device d;
  const json r = d.Send({{"cmd", "move_steps"},
                         {"left", 10},
                         {"right", 10},
                         {"note", "hi"},
                         {"meta", {{"a", {1, 2, 3}}}},
                         {"flag", nullptr}});
  EXPECT_TRUE(r["ok"]);
}

TEST(Errors, ErrorRepliesHaveCodeMessageAndDetails) {
  Device d;
  const json r = d.Send({{"cmd", "move_steps"}});
  ASSERT_TRUE(r["error"].is_object());
  EXPECT_TRUE(r["error"]["code"].is_string());
  EXPECT_TRUE(r["error"]["message"].is_string());
  EXPECT_TRUE(r["error"]["details"].is_object());
}

TEST(Errors, RandomBytesAlwaysGetOneValidJsonReply) {
  Device d;
  std::mt19937 rng(42);
  const std::string pieces[] = {
      "{",          "}",     "\"cmd\"",     ":",    ",", "\"move_steps\"",
      "\"left\"",   "1e999", "-0",          "[",    "]", "\"seq\"",
      "4294967296", "null",  "\"\\u0000\"", "true", " ", "\"sid\"",
      "#",          "\xff"};
  for (int i = 0; i < 5000; ++i) {
    std::string msg;
    const int n = static_cast<int>(rng() % 24);
    for (int k = 0; k < n; ++k)
      msg += pieces[rng() % (sizeof(pieces) / sizeof(pieces[0]))];
    const std::string raw = d.Raw(msg);
    ASSERT_FALSE(raw.empty()) << msg;
    const json r = json::parse(raw, nullptr, false);
    ASSERT_FALSE(r.is_discarded()) << msg << " -> " << raw;
    ASSERT_TRUE(r.contains("ok")) << raw;
  }
  EXPECT_FALSE(d.cube->running() && d.cube->estopped());
}

}  // namespace
}  // namespace cube::testing
