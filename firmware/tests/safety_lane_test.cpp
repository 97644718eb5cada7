// Protocol 1.1, section 4.1: stop and estop take the safety lane. They are
// executed whatever their seq, never remembered and never advance the
// session's highest seq, so a request still being retried stays valid; and a
// motion command numbered below an executed stop never starts after it.
#include <gtest/gtest.h>

#include <string>

#include "harness.h"

namespace cube::testing {
namespace {

std::string Code(const json& r) {
  return r.contains("error") ? r["error"]["code"].get<std::string>() : "";
}

json At(Device& d, const std::string& cmd, uint32_t seq, json params = {}) {
  if (params.is_null()) params = json::object();
  params["cmd"] = cmd;
  params["seq"] = seq;
  params["sid"] = d.sid;
  return d.Send(params);
}

TEST(SafetyLane, AnEstopAheadOfAPendingRequestLeavesItsRetryValid) {
  Device d;
  d.Hello();
  // get_status 5 was answered but its reply lost; the estop goes out as 6
  const json first = At(d, "get_status", 5);
  const std::string first_raw = d.last_raw_reply;
  EXPECT_TRUE(first["ok"]);
  EXPECT_TRUE(At(d, "estop", 6, {{"reason", "lane"}})["ok"]);
  // the retry of 5 is answered from memory, byte for byte, not refused
  At(d, "get_status", 5);
  EXPECT_EQ(d.last_raw_reply, first_raw);
  // a request 5 never reached the robot: 5 is still above the highest seq
  Device e;
  e.Hello();
  EXPECT_TRUE(At(e, "estop", 6)["ok"]);
  const json late = At(e, "set_led", 5, {{"r", 1}, {"g", 2}, {"b", 3}});
  EXPECT_TRUE(late["ok"]) << late.dump();
  EXPECT_EQ(Code(At(e, "set_led", 5, {{"r", 1}, {"g", 2}, {"b", 3}})), "")
      << "a retry gets the remembered reply";
}

TEST(SafetyLane, AMoveSentBeforeAStopButArrivingAfterItNeverStarts) {
  Device d;
  d.Hello();
  EXPECT_TRUE(At(d, "stop", 8)["ok"]);
  const json r = At(d, "move_steps", 7, {{"left", 500}, {"right", 500}});
  EXPECT_EQ(Code(r), "INTERRUPTED") << r.dump();
  EXPECT_EQ(r["error"]["details"]["stop_seq"], 8);
  EXPECT_FALSE(d.cube->running());
  // its retry gets the same refusal, and it still never runs
  const std::string refused = d.last_raw_reply;
  At(d, "move_steps", 7, {{"left", 500}, {"right", 500}});
  EXPECT_EQ(d.last_raw_reply, refused);
  d.Run(50);
  EXPECT_EQ(d.cube->left_position(), 0);
  // a move numbered after the stop runs
  EXPECT_TRUE(At(d, "move_steps", 9, {{"left", 10}, {"right", 10}})["ok"]);
  EXPECT_TRUE(d.cube->running());
}

TEST(SafetyLane, AMoveOvertakenByAnEstopIsRefusedEvenAfterTheReset) {
  Device d;
  d.Hello();
  EXPECT_TRUE(At(d, "estop", 10)["ok"]);
  EXPECT_TRUE(At(d, "reset_estop", 11)["ok"]);
  // seq 9 is below the highest seq (11) now: stale, and not executed
  EXPECT_EQ(Code(At(d, "move_steps", 9, {{"left", 5}, {"right", 5}})),
            "STALE_SEQUENCE");
  Device e;
  e.Hello();
  EXPECT_TRUE(At(e, "estop", 10)["ok"]);
  const json r = At(e, "move_cm", 9, {{"left_cm", 1}, {"right_cm", 1}});
  EXPECT_EQ(Code(r), "EMERGENCY_STOPPED");
  EXPECT_EQ(e.cube->left_position(), 0);
}

TEST(SafetyLane, AResentEstopIsExecutedAgainButKeepsTheFirstReasonAndTime) {
  Device d;
  d.Hello();
  d.Call("move_steps", {{"left", 3000}, {"right", 3000}});
  d.Run(500);
  const json a = At(d, "estop", 20, {{"reason", "first"}});
  d.Run(30);
  const json b = At(d, "estop", 20, {{"reason", "first"}});
  const json c = At(d, "estop", 21, {{"reason", "second"}});
  EXPECT_EQ(a["estop_reason"], "first");
  EXPECT_EQ(c["estop_reason"], "first");
  EXPECT_EQ(a["estop_us"], b["estop_us"]);
  EXPECT_EQ(b["estop_us"], c["estop_us"]);
  EXPECT_GT(b["uptime_us"].get<int64_t>(), a["uptime_us"].get<int64_t>());
  EXPECT_EQ(d.cube->trips(), 1u) << "one trip, however often it is resent";
  EXPECT_EQ(d.Status()["safety"]["trips"], 1);
}

TEST(SafetyLane, StopAndEstopRepliesTellWhatStoppedAndWhenOnTheRobotsClock) {
  Device d;
  d.Hello();
  const json move = d.Call("move_steps", {{"left", 3000}, {"right", 3000}});
  d.Run(1500);
  const int64_t at_us = static_cast<int64_t>(d.clock.now_us - 1000000);
  const json r = d.Call("estop", {{"reason", "bumper"}});
  EXPECT_EQ(r["move_id"], move["move_id"]);
  EXPECT_EQ(r["move_outcome"], "estop");
  EXPECT_EQ(r["estop_us"], at_us) << "the latch time is the uptime it stopped";
  EXPECT_EQ(r["stopped_us"], at_us);
  EXPECT_EQ(r["uptime_us"], at_us);
  EXPECT_EQ(r["left_steps"], d.cube->left_position());
  EXPECT_EQ(r["move_left_steps"], d.cube->motion_report().done_left);
  EXPECT_GT(r["move_left_steps"].get<int64_t>(), 0);
  d.Run(100);
  const json s = d.Call("stop");
  EXPECT_EQ(s["stopped"], false);
  EXPECT_EQ(s["stopped_us"], at_us) << "still the time the wheels stopped";
  EXPECT_EQ(s["uptime_us"], at_us + 100000);
}

TEST(SafetyLane, ARunningMoveIsStoppedWhateverTheSeqOfTheStop) {
  Device d;
  d.Hello();
  At(d, "move_steps", 30, {{"left", 3000}, {"right", 3000}});
  d.Run(200);
  ASSERT_TRUE(d.cube->running());
  // a stop numbered below the highest seq (a reordered datagram) still stops
  EXPECT_TRUE(At(d, "stop", 3)["ok"]);
  EXPECT_FALSE(d.cube->running());
  EXPECT_TRUE(At(d, "heartbeat", 31)["ok"]) << "the highest seq is still 30";
}

TEST(EstopReason, ControlCharactersBecomeOneSpaceAndTheEndsAreTrimmed) {
  Device d;
  d.Hello();
  const json r = d.Call("estop", {{"reason", "\t bumper\r\n\x01hit\x7f "}});
  EXPECT_EQ(r["estop_reason"], "bumper hit");
  d.Call("reset_estop");
  const json c1 = d.Call("estop", {{"reason", "a\u0085b"}});
  EXPECT_EQ(c1["estop_reason"], "a b");
  d.Call("reset_estop");
  const json blank = d.Call("estop", {{"reason", "\n\n"}});
  EXPECT_EQ(blank["estop_reason"], "estop command");
  d.Call("reset_estop");
  const json wrong_type = d.Call("estop", {{"reason", 42}});
  EXPECT_TRUE(wrong_type["ok"]) << "an e-stop is never refused";
  EXPECT_TRUE(d.cube->estopped());
  d.Call("reset_estop");
  const json longer = d.Call("estop", {{"reason", std::string(300, 'x')}});
  EXPECT_EQ(longer["estop_reason"], std::string(63, 'x'));
}

}  // namespace
}  // namespace cube::testing
