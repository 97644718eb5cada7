// Protocol 1.0 (docs/protocol.md): every command, its reply and its parameters.
#include <gtest/gtest.h>

#include <string>

#include "harness.h"

namespace cube::testing {
namespace {

std::string Code(const json& r) {
  return r.contains("error") ? r["error"]["code"].get<std::string>() : "";
}

TEST(MoveSteps, ReplyCarriesThePlan) {
  Device d;
  d.Hello();
  const json r =
      d.Call("move_steps", {{"left", 2172}, {"right", -1000}, {"speed", 1024}});
  EXPECT_TRUE(r["ok"]);
  EXPECT_EQ(r["move_id"], 1);
  EXPECT_EQ(r["left_steps"], 2172);
  EXPECT_EQ(r["right_steps"], -1000);
  EXPECT_EQ(r["speed"], 1024);
  EXPECT_EQ(r["speed_clamped"], false);
  EXPECT_EQ(r["duration_us"], ProfileDurationUs({2172, 1024, 512, false}));
  EXPECT_EQ(r["duration_ms"], 4122);
}

TEST(MoveSteps, MakesExactlyTheRequestedStepsAndFinishesOnTime) {
  Device d;
  d.Hello();
  const json r = d.Call("move_steps", {{"left", 1706}, {"right", 1706}});
  const uint64_t ran = d.RunUntilIdle();
  EXPECT_NEAR(static_cast<double>(ran), r["duration_ms"].get<double>(), 2.0);
  EXPECT_EQ(d.cube->left_position(), 1706);
  EXPECT_EQ(d.cube->right_position(), 1706);
  const json s = d.Status();
  EXPECT_EQ(s["move_outcome"], "done");
  EXPECT_EQ(s["move_left_steps"], 1706);
}

TEST(MoveSteps, ZeroStepsFinishAtOnce) {
  Device d;
  const json r = d.Send({{"cmd", "move_steps"}, {"left", 0}, {"right", 0}});
  EXPECT_EQ(r["duration_ms"], 0);
  d.Run(2);
  EXPECT_FALSE(d.cube->running());
  EXPECT_EQ(d.Status()["move_outcome"], "done");
}

TEST(MoveSteps, MissingOrMistypedParametersAreInvalid) {
  Device d;
  json r = d.Send({{"cmd", "move_steps"}, {"left", 10}});
  EXPECT_EQ(Code(r), "INVALID_PARAMETER");
  EXPECT_EQ(r["error"]["message"], "\"right\" is required");
  r = d.Send({{"cmd", "move_steps"}, {"left", "10"}, {"right", 10}});
  EXPECT_EQ(r["error"]["message"], "\"left\" must be an integer");
  r = d.Send({{"cmd", "move_steps"}, {"left", 10.5}, {"right", 10}});
  EXPECT_EQ(Code(r), "INVALID_PARAMETER");
  r = d.Send(
      {{"cmd", "move_steps"}, {"left", 10}, {"right", 10}, {"speed", "fast"}});
  EXPECT_EQ(r["error"]["message"], "\"speed\" must be a number");
  EXPECT_FALSE(d.cube->running());
}

// JSON allows 1e400, a double does not: it reads as infinity, which the
// protocol's finite numbers exclude.
TEST(Commands, ANumberBeyondTheDoubleRangeIsAnInvalidParameter) {
  Device d;
  json r = json::parse(d.Raw(R"({"cmd":"move_steps","left":10,"right":10,)"
                             R"("speed":1e400})"));
  EXPECT_EQ(Code(r), "INVALID_PARAMETER");
  EXPECT_EQ(r["error"]["message"], "\"speed\" must be a finite number");
  EXPECT_EQ(r["error"]["details"]["field"], "speed");
  r = json::parse(d.Raw(R"({"cmd":"move_cm","left_cm":-1e400,"right_cm":1})"));
  EXPECT_EQ(Code(r), "INVALID_PARAMETER");
  EXPECT_EQ(r["error"]["message"], "\"left_cm\" must be a finite number");
  r = json::parse(d.Raw(R"({"cmd":"rotate_deg","degrees":1e400})"));
  EXPECT_EQ(Code(r), "INVALID_PARAMETER");
  r = json::parse(d.Raw(R"({"cmd":"move_steps","left":1e400,"right":1})"));
  EXPECT_EQ(r["error"]["message"], "\"left\" must be an integer");
  r = json::parse(d.Raw(R"({"cmd":"set_config","wheel_base_cm":12,)"
                        R"("wheel_diameter_cm":1e400})"));
  EXPECT_EQ(Code(r), "INVALID_PARAMETER");
  EXPECT_EQ(r["error"]["message"],
            "\"wheel_diameter_cm\" must be a finite number");
  EXPECT_FALSE(d.cube->running());
  EXPECT_EQ(d.cube->left_position(), 0);
  EXPECT_EQ(d.cube->config().geometry.wheel_base_cm, 10.0) << "nothing applied";
  EXPECT_EQ(d.cube->trips(), 0u);
  // An unknown field may still carry such a number: it is ignored.
  r = json::parse(d.Raw(R"({"cmd":"heartbeat","later":1e400})"));
  EXPECT_TRUE(r["ok"]);
}

TEST(MoveSteps, SpeedAboveTheMaximumIsClampedAndReported) {
  Device d;
  const json r = d.Send(
      {{"cmd", "move_steps"}, {"left", 100}, {"right", 100}, {"speed", 5000}});
  EXPECT_TRUE(r["ok"]);
  EXPECT_EQ(r["speed"], 1024);
  EXPECT_EQ(r["speed_clamped"], true);
  const json slow = d.Send(
      {{"cmd", "move_steps"}, {"left", 1}, {"right", 1}, {"speed", 0.25}});
  EXPECT_EQ(slow["speed"], 1);
  EXPECT_EQ(slow["speed_clamped"], true);
}

TEST(MoveSteps, SpeedOfZeroOrLessIsOutOfRange) {
  Device d;
  const json r = d.Send(
      {{"cmd", "move_steps"}, {"left", 100}, {"right", 100}, {"speed", 0}});
  EXPECT_EQ(Code(r), "RANGE_EXCEEDED");
  EXPECT_EQ(r["error"]["message"], "\"speed\" must be 1..1024 steps/s");
  EXPECT_EQ(r["error"]["details"]["field"], "speed");
  EXPECT_EQ(r["error"]["details"]["max"], 1024);
  EXPECT_FALSE(d.cube->estopped()) << "a bad speed is not a safety trip";
}

TEST(MoveCm, TenCentimetresIs2172Steps) {
  Device d;
  const json r =
      d.Send({{"cmd", "move_cm"}, {"left_cm", 10}, {"right_cm", 10}});
  EXPECT_EQ(r["left_steps"], 2172);
  EXPECT_EQ(r["right_steps"], 2172);
  EXPECT_NEAR(r["duration_ms"].get<double>(), 4121, 1);
}

TEST(MoveCm, RepeatedMovesDoNotDrift) {
  Device d;
  d.Send({{"cmd", "set_config"},
          {"max_speed_steps_per_s", 2048},
          {"acceleration_steps_per_s2", 100000}});
  int64_t total = 0;
  for (int i = 0; i < 100; ++i) {
    const json r =
        d.Send({{"cmd", "move_cm"}, {"left_cm", 10}, {"right_cm", 10}});
    total += r["left_steps"].get<int64_t>();
    d.RunUntilIdle();
  }
  EXPECT_EQ(total, 217299);
  EXPECT_EQ(d.cube->left_position(), 217299);
}

TEST(MoveCm, AnArcMovesTheWheelsInProportion) {
  Device d;
  const json r = d.Send({{"cmd", "move_cm"}, {"left_cm", 5}, {"right_cm", 10}});
  EXPECT_EQ(r["left_steps"], DistanceToSteps(5, Geometry()));
  d.RunUntilIdle();
  const json s = d.Status();
  EXPECT_GT(s["y_cm"].get<double>(), 0.0) << "a left arc ends to the left";
  EXPECT_GT(s["heading_rad"].get<double>(), 0.0);
}

TEST(MoveMotion, AMotionWhileMovingReplacesIt) {
  Device d;
  d.Send({{"cmd", "move_steps"}, {"left", 2000}, {"right", 2000}});
  d.Run(1000);
  const int64_t at = d.cube->left_position();
  const json r =
      d.Send({{"cmd", "move_steps"}, {"left", -100}, {"right", -100}});
  EXPECT_EQ(r["move_id"], 2);
  ASSERT_EQ(d.observer.finished.size(), 1u);
  EXPECT_EQ(d.observer.finished[0].outcome, MoveOutcome::kReplaced);
  d.RunUntilIdle();
  EXPECT_EQ(d.cube->left_position(), at - 100);
}

TEST(RotateDeg, PositiveDegreesTurnCounterClockwise) {
  Device d;
  const json r = d.Send({{"cmd", "rotate_deg"}, {"degrees", 90}});
  EXPECT_EQ(r["left_steps"], -1706);
  EXPECT_EQ(r["right_steps"], 1706);
  EXPECT_NEAR(r["duration_ms"].get<double>(), 3651, 1);
  d.RunUntilIdle();
  const json s = d.Status();
  EXPECT_NEAR(s["heading_rad"].get<double>(), kPi / 2, 0.002);
  EXPECT_NEAR(s["x_cm"].get<double>(), 0.0, 1e-6);
}

TEST(RotateDeg, NegativeDegreesTurnClockwise) {
  Device d;
  const json r = d.Send({{"cmd", "rotate_deg"}, {"degrees", -90}});
  EXPECT_EQ(r["left_steps"], 1706);
  EXPECT_EQ(r["right_steps"], -1706);
  d.RunUntilIdle();
  EXPECT_NEAR(d.Status()["heading_rad"].get<double>(), -kPi / 2, 0.002);
}

TEST(Drive, RunsForItsDurationThenStops) {
  Device d;
  const json r = d.Send({{"cmd", "drive"},
                         {"left_sps", 400},
                         {"right_sps", 400},
                         {"duration_ms", 1500}});
  EXPECT_TRUE(r["ok"]);
  EXPECT_EQ(r["running"], true);
  EXPECT_EQ(r["duration_ms"], 1500);
  const uint64_t ran = d.RunUntilIdle();
  EXPECT_NEAR(static_cast<double>(ran), 1500, 2);
  StepProfile p;
  p.unbounded = true;
  p.speed = 400;
  p.accel = 512;
  int64_t expected = 0;
  while (StepTimeUs(p, expected + 1) < 1500000) ++expected;
  EXPECT_EQ(d.cube->left_position(), expected);
  EXPECT_EQ(d.Status()["move_outcome"], "done");
}

TEST(Drive, ScalesBothSpeedsToKeepTheCurvature) {
  Device d;
  const json r = d.Send({{"cmd", "drive"},
                         {"left_sps", 4096},
                         {"right_sps", -2048},
                         {"duration_ms", 100}});
  EXPECT_EQ(r["left_sps"], 1024);
  EXPECT_EQ(r["right_sps"], -512);
  EXPECT_EQ(r["speed_clamped"], true);
}

TEST(Drive, WithoutDurationRunsUntilStopped) {
  Device d;
  d.Send({{"cmd", "drive"}, {"left_sps", -300}, {"right_sps", 300}});
  d.Run(5000);
  EXPECT_TRUE(d.cube->running());
  const json s = d.Send({{"cmd", "stop"}});
  EXPECT_EQ(s["stopped"], true);
  EXPECT_FALSE(d.cube->running());
  EXPECT_LT(d.cube->left_position(), 0);
  EXPECT_EQ(d.cube->left_position(), -d.cube->right_position());
}

TEST(Drive, ZeroSpeedsStopTheRobot) {
  Device d;
  d.Send({{"cmd", "drive"}, {"left_sps", 300}, {"right_sps", 300}});
  d.Run(200);
  const json r = d.Send({{"cmd", "drive"}, {"left_sps", 0}, {"right_sps", 0}});
  EXPECT_EQ(r["running"], false);
  EXPECT_FALSE(d.cube->running());
}

TEST(Drive, DurationOutOfRangeIsRefused) {
  Device d;
  const json r = d.Send({{"cmd", "drive"},
                         {"left_sps", 1},
                         {"right_sps", 1},
                         {"duration_ms", 0}});
  EXPECT_EQ(Code(r), "RANGE_EXCEEDED");
  EXPECT_EQ(r["error"]["message"], "\"duration_ms\" must be 1..600000 ms");
}

TEST(Stop, IsImmediateAndSwitchesTheCoilsOff) {
  Device d;
  d.Send({{"cmd", "move_steps"}, {"left", 4000}, {"right", 4000}});
  d.Run(2500);
  const json r = d.Send({{"cmd", "stop"}});
  EXPECT_EQ(r["stopped"], true);
  const int64_t at = d.cube->left_position();
  EXPECT_EQ(r["left_steps"], at);
  d.Run(1000);
  EXPECT_EQ(d.cube->left_position(), at) << "no ramp-down steps after a stop";
  EXPECT_FALSE(d.cube->coils_on());
  EXPECT_EQ(d.motors.last[0], 0);
  EXPECT_EQ(d.motors.last[1], 0);
  EXPECT_EQ(d.Status()["move_outcome"], "stopped");
}

TEST(Stop, WhenIdleSaysNothingWasStopped) {
  Device d;
  EXPECT_EQ(d.Send({{"cmd", "stop"}})["stopped"], false);
}

TEST(GetStatus, ReportsPoseStepsMotionAndSafety) {
  Device d;
  d.Hello();
  d.Call("move_steps", {{"left", 1000}, {"right", 1000}});
  d.Run(1000);
  json s = d.Call("get_status");
  EXPECT_TRUE(s["running"]);
  EXPECT_EQ(s["move_outcome"], "running");
  EXPECT_GT(s["left_sps"].get<double>(), 0.0);
  EXPECT_TRUE(s["safety"]["coils_on"]);
  d.RunUntilIdle();
  s = d.Call("get_status");
  for (const char* k :
       {"x_cm", "y_cm", "heading_rad", "left_steps", "right_steps", "running",
        "move_id", "move_outcome", "move_left_steps", "move_right_steps",
        "left_sps", "right_sps", "uptime_ms", "safety", "led"}) {
    EXPECT_TRUE(s.contains(k)) << k;
  }
  for (const char* k : {"estop", "estop_reason", "trips", "last_trip",
                        "host_timeout_ms", "ms_since_host", "coils_on"}) {
    EXPECT_TRUE(s["safety"].contains(k)) << k;
  }
  EXPECT_NEAR(s["x_cm"].get<double>(), 1000 / ExactStepsForCm(1, Geometry()),
              1e-6);
  EXPECT_EQ(s["left_steps"], 1000);
  EXPECT_EQ(s["running"], false);
  EXPECT_EQ(s["left_sps"], 0);
  EXPECT_FALSE(s["safety"]["coils_on"]);
  EXPECT_TRUE(s["safety"]["last_trip"].is_null());
}

TEST(SetConfig, AppliesAndReportsTheNewConfiguration) {
  Device d;
  const json r = d.Send({{"cmd", "set_config"},
                         {"steps_per_revolution", 4076},
                         {"max_speed_steps_per_s", 2048},
                         {"host_timeout_ms", 5000},
                         {"unknown_future_field", 1}});
  EXPECT_TRUE(r["ok"]);
  EXPECT_EQ(r["config"]["steps_per_revolution"], 4076);
  EXPECT_EQ(r["config"]["max_speed_steps_per_s"], 2048);
  EXPECT_EQ(r["config"]["host_timeout_ms"], 5000);
  const json m =
      d.Send({{"cmd", "move_cm"}, {"left_cm", 10}, {"right_cm", 10}});
  EXPECT_EQ(m["left_steps"], 2162) << "trunc(10 * 4076 / (pi * 6))";
  EXPECT_EQ(m["speed"], 2048);
}

TEST(SetConfig, AnInvalidFieldAppliesNothing) {
  Device d;
  const json r = d.Send({{"cmd", "set_config"},
                         {"wheel_diameter_cm", 7.0},
                         {"max_speed_steps_per_s", 4096}});
  EXPECT_EQ(Code(r), "RANGE_EXCEEDED");
  EXPECT_EQ(r["error"]["message"],
            "\"max_speed_steps_per_s\" must be 1..2048 steps/s");
  EXPECT_EQ(d.cube->config().geometry.wheel_diameter_cm, 6.0);
  EXPECT_EQ(Code(d.Send({{"cmd", "set_config"}, {"host_timeout_ms", 100}})),
            "RANGE_EXCEEDED");
  EXPECT_EQ(
      Code(d.Send({{"cmd", "set_config"}, {"steps_per_revolution", 4096.5}})),
      "INVALID_PARAMETER");
  EXPECT_EQ(Code(d.Send({{"cmd", "set_config"}, {"wheel_base_cm", "10"}})),
            "INVALID_PARAMETER");
}

TEST(SetConfig, ResetsTheDistanceAccumulators) {
  Device d;
  d.Send({{"cmd", "move_cm"},
          {"left_cm", 10},
          {"right_cm", 10}});  // 2172.995 -> 2172
  d.RunUntilIdle();
  d.Send({{"cmd", "set_config"}});
  const json r =
      d.Send({{"cmd", "move_cm"}, {"left_cm", 10}, {"right_cm", 10}});
  EXPECT_EQ(r["left_steps"], 2172) << "not 2173: the fraction was forgotten";
}

TEST(SetLed, SetsColourAndPattern) {
  Device d;
  json r = d.Send({{"cmd", "set_led"},
                   {"r", 0},
                   {"g", 128},
                   {"b", 255},
                   {"pattern", "blink"}});
  EXPECT_TRUE(r["ok"]);
  EXPECT_EQ(r["led"]["pattern"], "blink");
  EXPECT_EQ(r["led"]["b"], 255);
  d.Run(100);
  EXPECT_EQ(d.led.rgb, (std::vector<uint8_t>{0, 128, 255}));
  d.Run(500);
  EXPECT_EQ(d.led.rgb, (std::vector<uint8_t>{0, 0, 0}))
      << "blink: off half the second";
  r = d.Send({{"cmd", "set_led"}, {"pattern", "off"}});
  EXPECT_TRUE(r["ok"]);
  EXPECT_EQ(d.Status()["led"]["pattern"], "off");
}

TEST(SetLed, RejectsUnknownPatternsAndOutOfRangeColours) {
  Device d;
  json r = d.Send(
      {{"cmd", "set_led"}, {"r", 1}, {"g", 1}, {"b", 1}, {"pattern", "disco"}});
  EXPECT_EQ(Code(r), "INVALID_PARAMETER");
  EXPECT_EQ(r["error"]["message"],
            "\"pattern\" must be one of solid, blink, pulse, off");
  r = d.Send({{"cmd", "set_led"}, {"r", 256}, {"g", 1}, {"b", 1}});
  EXPECT_EQ(Code(r), "RANGE_EXCEEDED");
  EXPECT_EQ(r["error"]["message"], "\"r\" must be 0..255");
  r = d.Send({{"cmd", "set_led"}, {"r", 1}, {"g", 1}});
  EXPECT_EQ(Code(r), "INVALID_PARAMETER");
}


}  // namespace
}  // namespace cube::testing
