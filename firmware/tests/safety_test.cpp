// The firmware's own safety layer: limits, e-stop latch, host timeout,
// watchdog, trip records. Each refuses on its own, whatever the host sends.
#include <gtest/gtest.h>

#include "harness.h"

namespace cube::testing {
namespace {

std::string Code(const json& r) {
  return r.contains("error") ? r["error"]["code"].get<std::string>() : "";
}

TEST(StepLimit, MoreThan40960StepsIsRefusedAndTripsTheEstop) {
  Device d;
  const json r = d.Send({{"cmd", "move_steps"}, {"left", 40961}, {"right", 0}});
  EXPECT_EQ(Code(r), "RANGE_EXCEEDED");
  EXPECT_EQ(r["error"]["details"]["field"], "left");
  EXPECT_EQ(r["error"]["details"]["max"], 40960);
  EXPECT_EQ(r["error"]["details"]["estop"], true);
  EXPECT_FALSE(d.cube->running());
  EXPECT_TRUE(d.cube->estopped());
  const json s = d.Status();
  EXPECT_EQ(s["safety"]["estop"], true);
  EXPECT_EQ(s["safety"]["trips"], 1);
  EXPECT_EQ(s["safety"]["last_trip"]["reason"], "step_limit");
}

TEST(StepLimit, ExactlyTheLimitIsAllowed) {
  Device d;
  const json r =
      d.Send({{"cmd", "move_steps"}, {"left", -40960}, {"right", 40960}});
  EXPECT_TRUE(r["ok"]);
  EXPECT_FALSE(d.cube->estopped());
}

TEST(StepLimit, AppliesToDistancesAndTurnsToo) {
  Device a;
  EXPECT_EQ(
      Code(a.Send({{"cmd", "move_cm"}, {"left_cm", 0}, {"right_cm", 200}})),
      "RANGE_EXCEEDED");
  EXPECT_TRUE(a.cube->estopped());
  Device b;
  EXPECT_EQ(Code(b.Send({{"cmd", "rotate_deg"}, {"degrees", 3600}})),
            "RANGE_EXCEEDED");
  EXPECT_TRUE(b.cube->estopped());
  Device c;
  EXPECT_EQ(
      Code(c.Send({{"cmd", "move_cm"}, {"left_cm", 1e300}, {"right_cm", 0}})),
      "RANGE_EXCEEDED");
  EXPECT_TRUE(c.cube->estopped());
}

TEST(StepLimit, ARefusedDistanceDoesNotShiftTheAccumulator) {
  Device d;
  d.Send({{"cmd", "move_cm"}, {"left_cm", 500}, {"right_cm", 500}});
  d.Send({{"cmd", "reset_estop"}});
  const json r =
      d.Send({{"cmd", "move_cm"}, {"left_cm", 10}, {"right_cm", 10}});
  EXPECT_EQ(r["left_steps"], 2172);
}

TEST(Estop, StopsMotionAtOnceAndLatches) {
  Device d;
  d.Hello();
  d.Call("move_steps", {{"left", 3000}, {"right", 3000}});
  d.Run(1500);
  const json r = d.Call("estop", {{"reason", "bumper"}});
  EXPECT_TRUE(r["ok"]);
  EXPECT_EQ(r["estop"], true);
  EXPECT_EQ(r["estop_reason"], "bumper");
  const int64_t at = d.cube->left_position();
  d.Run(1000);
  EXPECT_EQ(d.cube->left_position(), at);
  EXPECT_EQ(d.motors.last[0], 0);
  const json m = d.Call("move_steps", {{"left", 10}, {"right", 10}});
  EXPECT_EQ(Code(m), "EMERGENCY_STOPPED");
  EXPECT_EQ(m["error"]["details"]["reason"], "bumper");
  EXPECT_EQ(d.Call("get_status")["move_outcome"], "estop");
}

TEST(Estop, IsNotClearedByAnyOtherPacket) {
  Device d;
  d.Send({{"cmd", "estop"}});
  for (const json& req :
       {json{{"cmd", "hello"}, {"seq", 1}}, json{{"cmd", "stop"}},
        json{{"cmd", "heartbeat"}}, json{{"cmd", "get_status"}},
        json{{"cmd", "set_config"}, {"max_speed_steps_per_s", 100}},
        json{{"cmd", "set_led"}, {"r", 1}, {"g", 2}, {"b", 3}},
        json{{"cmd", "estop"}}, json{{"cmd", "nonsense"}}}) {
    d.Send(req);
    d.Raw("garbage");
    d.Run(10);
    EXPECT_TRUE(d.cube->estopped()) << req.dump();
  }
  for (const char* cmd : {"move_steps", "move_cm", "rotate_deg", "drive"}) {
    const json r = d.Send({{"cmd", cmd},
                           {"left", 1},
                           {"right", 1},
                           {"left_cm", 1},
                           {"right_cm", 1},
                           {"degrees", 1},
                           {"left_sps", 1},
                           {"right_sps", 1}});
    EXPECT_EQ(Code(r), "EMERGENCY_STOPPED") << cmd;
  }
}

TEST(Estop, ResetIsAcceptedAndMotionWorksAgain) {
  Device d;
  d.Hello();
  d.Call("estop");
  const json r = d.Call("reset_estop");
  EXPECT_TRUE(r["ok"]);
  EXPECT_EQ(r["was_estopped"], true);
  EXPECT_EQ(r["estop"], false);
  EXPECT_TRUE(d.Call("move_steps", {{"left", 10}, {"right", 10}})["ok"]);
}

TEST(Estop, ResetIsAcceptedFromAHostWithAnOldSession) {
  Device d;
  d.Hello();
  const uint32_t old_sid = d.sid;
  d.Call("estop");
  d.Hello();  // another host took over
  const json r =
      d.Send({{"cmd", "reset_estop"}, {"seq", 99}, {"sid", old_sid}});
  EXPECT_TRUE(r["ok"]);
  EXPECT_FALSE(d.cube->estopped());
}

TEST(Estop, StopAndEstopWorkWhateverTheSession) {
  Device d;
  d.Hello();
  d.Call("move_steps", {{"left", 3000}, {"right", 3000}});
  d.Run(100);
  const json r = d.Send({{"cmd", "estop"}, {"seq", 1}, {"sid", 12345}});
  EXPECT_TRUE(r["ok"]);
  EXPECT_TRUE(d.cube->estopped());
  EXPECT_FALSE(d.cube->running());
}

TEST(Estop, AStaleSeqDoesNotBlockAStop) {
  Device d;
  d.Hello();
  d.Call("heartbeat");
  d.Call("heartbeat");
  d.Call("move_steps", {{"left", 3000}, {"right", 3000}});
  d.Run(100);
  const json r = d.Send({{"cmd", "stop"}, {"seq", 1}, {"sid", d.sid}});
  EXPECT_TRUE(r["ok"]);
  EXPECT_FALSE(d.cube->running());
}

TEST(HostTimeout, StopsMotionWhenTheHostGoesQuietAndRecordsATrip) {
  Device d;
  d.Send({{"cmd", "move_steps"}, {"left", 10000}, {"right", 10000}});
  d.Run(1999, false);
  EXPECT_TRUE(d.cube->running());
  d.Run(2, false);
  EXPECT_FALSE(d.cube->running());
  const json s = d.Status();
  EXPECT_EQ(s["move_outcome"], "host_timeout");
  EXPECT_EQ(s["safety"]["trips"], 1);
  EXPECT_EQ(s["safety"]["last_trip"]["reason"], "host_timeout");
  EXPECT_EQ(s["safety"]["estop"], false) << "not latched";
  EXPECT_EQ(d.observer.trips, (std::vector<std::string>{"host_timeout"}));
  EXPECT_TRUE(
      d.Send({{"cmd", "move_steps"}, {"left", 10}, {"right", 10}})["ok"]);
}

// The emulator's catch-up before it reads waiting requests: the move goes on
// and ends, and the host timeout waits for Poll(), after the requests.
TEST(HostTimeout, UpdateMotionMovesAndEndsAMoveButLeavesTheTimeoutToPoll) {
  Device d;
  const json r =
      d.Send({{"cmd", "move_steps"}, {"left", 100}, {"right", 100}});
  ASSERT_TRUE(r["ok"]);
  // One long stall (longer than the move and the host timeout), then the
  // step interrupt and the motion update until no step is left to make.
  d.clock.now_us += 2500 * 1000;
  for (int pass = 0; pass < 256; ++pass) {
    const int64_t before = d.cube->left_position();
    d.cube->Tick();
    d.cube->UpdateMotion();
    if (d.cube->left_position() == before) break;
  }
  EXPECT_EQ(d.cube->left_position(), 100);
  EXPECT_FALSE(d.cube->running());
  EXPECT_EQ(d.cube->trips(), 0u);
  // With a move still running, UpdateMotion() makes steps but never trips.
  d.Send({{"cmd", "move_steps"}, {"left", 10000}, {"right", 10000}});
  d.clock.now_us += 2500 * 1000;
  d.cube->Tick();
  d.cube->UpdateMotion();
  EXPECT_TRUE(d.cube->running());
  EXPECT_EQ(d.cube->trips(), 0u);
  d.cube->Poll();
  EXPECT_FALSE(d.cube->running());
  EXPECT_EQ(d.cube->last_trip().reason, std::string("host_timeout"));
}

TEST(HostTimeout, HeartbeatsKeepAMoveLongerThanTheTimeoutRunning) {
  Device d;
  const json r =
      d.Send({{"cmd", "move_steps"}, {"left", 8000}, {"right", 8000}});
  EXPECT_GT(r["duration_ms"].get<int>(), 5000);
  d.RunUntilIdle(20000, true);
  EXPECT_EQ(d.cube->left_position(), 8000);
  EXPECT_EQ(d.Status()["move_outcome"], "done");
  EXPECT_EQ(d.cube->trips(), 0u);
}

TEST(HostTimeout, IsSettableAndDoesNotFireWhenIdle) {
  Device d;
  d.Send({{"cmd", "set_config"}, {"host_timeout_ms", 500}});
  d.Run(5000, false);
  EXPECT_EQ(d.cube->trips(), 0u);
  d.Send({{"cmd", "drive"}, {"left_sps", 100}, {"right_sps", 100}});
  d.Run(501, false);
  EXPECT_FALSE(d.cube->running());
  EXPECT_EQ(d.cube->last_trip().reason, std::string("host_timeout"));
}

TEST(HostTimeout, RequestsFromAStaleSessionDoNotKeepTheRobotAlive) {
  Device d;
  d.Hello();
  d.Call("move_steps", {{"left", 10000}, {"right", 10000}});
  for (int i = 0; i < 6; ++i) {
    d.Run(500, false);
    d.Send({{"cmd", "heartbeat"}, {"seq", 100 + i}, {"sid", d.sid + 1}});
  }
  EXPECT_FALSE(d.cube->running());
  EXPECT_EQ(d.cube->last_trip().reason, std::string("host_timeout"));
}

TEST(Watchdog, IsFedOnEveryPoll) {
  Device d;
  d.Run(10);
  EXPECT_EQ(d.watchdog.feeds, 10);
}

TEST(Trips, EveryTripIsCountedWithItsReason) {
  Device d;
  d.Send({{"cmd", "estop"}, {"reason", "test"}});
  d.Send({{"cmd", "reset_estop"}});
  d.Send({{"cmd", "move_steps"}, {"left", 50000}, {"right", 0}});
  d.Send({{"cmd", "reset_estop"}});
  d.Send({{"cmd", "drive"}, {"left_sps", 10}, {"right_sps", 10}});
  d.Run(2100, false);
  EXPECT_EQ(d.observer.trips,
            (std::vector<std::string>{"estop_command", "step_limit",
                                      "host_timeout"}));
  EXPECT_EQ(d.Status()["safety"]["trips"], 3);
}

TEST(Estop, ShowsAsAFastRedBlinkOnTheLed) {
  Device d;
  d.Send({{"cmd", "set_led"}, {"r", 0}, {"g", 255}, {"b", 0}});
  d.Send({{"cmd", "estop"}});
  d.Run(100);
  EXPECT_EQ(d.led.rgb, (std::vector<uint8_t>{255, 0, 0}));
  EXPECT_EQ(d.Status()["led"]["g"], 255)
      << "the commanded colour is still reported";
}

}  // namespace
}  // namespace cube::testing
