// The shared golden vectors: kinematics (written with @hal/kinematics) and
// protocol exchanges (read by the TypeScript codec too).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "harness.h"
#include "kinematics.h"
#include "settings.h"

namespace cube::testing {
namespace {

json Kinematics() {
  const std::string text = ReadVectorFile("kinematics.json");
  return text.empty() ? json() : json::parse(text);
}

// A missing vectors file is a failure, never a skip: ctest would count a
// skip as a pass.
#define REQUIRE_KINEMATICS(v)                                  \
  const json v = Kinematics();                                 \
  if (v.is_null()) {                                           \
    GTEST_FAIL() << "cannot read " << VectorPath("kinematics.json"); \
  }

Geometry RobotOf(const json& v) {
  Geometry g;
  g.steps_per_revolution = v["robot"]["steps_per_revolution"].get<double>();
  g.wheel_diameter_cm = v["robot"]["wheel_diameter_cm"].get<double>();
  g.wheel_base_cm = v["robot"]["wheel_base_cm"].get<double>();
  return g;
}

TEST(KinematicsVectors, DistanceToSteps) {
  REQUIRE_KINEMATICS(v);
  const Geometry g = RobotOf(v);
  for (const json& c : v["distance_to_steps"]) {
    EXPECT_EQ(DistanceToSteps(c["distance_cm"].get<double>(), g),
              c["steps"].get<int64_t>())
        << c.dump();
  }
}

TEST(KinematicsVectors, RotationToSteps) {
  REQUIRE_KINEMATICS(v);
  const Geometry g = RobotOf(v);
  for (const json& c : v["rotation_to_steps"]) {
    const double arc = RotationArcCm(c["degrees"].get<double>(), g);
    EXPECT_EQ(DistanceToSteps(-arc, g), c["left_steps"].get<int64_t>())
        << c.dump();
    EXPECT_EQ(DistanceToSteps(arc, g), c["right_steps"].get<int64_t>())
        << c.dump();
  }
}

TEST(KinematicsVectors, Accumulator) {
  REQUIRE_KINEMATICS(v);
  const Geometry g = RobotOf(v);
  for (const json& c : v["accumulator"]) {
    StepAccumulator acc;
    const json& d = c["distances_cm"];
    ASSERT_EQ(d.size(), c["deltas"].size());
    for (size_t i = 0; i < d.size(); ++i) {
      ASSERT_EQ(acc.Add(d[i].get<double>(), g), c["deltas"][i].get<int64_t>())
          << i;
    }
  }
}

TEST(KinematicsVectors, TrapezoidalProfileStepTimes) {
  REQUIRE_KINEMATICS(v);
  for (const json& c : v["profile"]) {
    StepProfile p;
    p.steps = c["steps"].get<int64_t>();
    p.speed = c["max_speed_steps_per_s"].get<double>();
    p.accel = c["acceleration_steps_per_s2"].get<double>();
    EXPECT_EQ(ProfileDurationUs(p), c["duration_us"].get<int64_t>())
        << c["steps"];
    for (const json& s : c["samples"]) {
      EXPECT_EQ(StepTimeUs(p, s["k"].get<int64_t>()), s["t_us"].get<int64_t>())
          << "steps " << p.steps << " k " << s["k"];
    }
  }
}

TEST(KinematicsVectors, VelocityProfileStepTimes) {
  REQUIRE_KINEMATICS(v);
  for (const json& c : v["velocity_profile"]) {
    StepProfile p;
    p.unbounded = true;
    p.speed = c["speed_steps_per_s"].get<double>();
    p.accel = c["acceleration_steps_per_s2"].get<double>();
    for (const json& s : c["samples"]) {
      EXPECT_EQ(StepTimeUs(p, s["k"].get<int64_t>()), s["t_us"].get<int64_t>())
          << s.dump();
    }
  }
}

TEST(KinematicsVectors, SlaveSteps) {
  REQUIRE_KINEMATICS(v);
  for (const json& c : v["slave_steps"]) {
    const int64_t n = c["master_steps"].get<int64_t>();
    const int64_t m = c["slave_steps"].get<int64_t>();
    for (const json& s : c["samples"]) {
      EXPECT_EQ(SlaveSteps(s["k"].get<int64_t>(), m, n),
                s["slave"].get<int64_t>())
          << s.dump();
    }
  }
}

TEST(KinematicsVectors, Odometry) {
  REQUIRE_KINEMATICS(v);
  const Geometry g = RobotOf(v);
  for (const json& c : v["odometry"]) {
    Pose p;
    for (const json& d : c["deltas"]) {
      IntegrateOdometry(p, d[0].get<int64_t>(), d[1].get<int64_t>(), g);
    }
    EXPECT_NEAR(p.x_cm, c["x_cm"].get<double>(), 1e-9) << c.dump();
    EXPECT_NEAR(p.y_cm, c["y_cm"].get<double>(), 1e-9) << c.dump();
    EXPECT_NEAR(p.heading_rad, c["heading_rad"].get<double>(), 1e-9)
        << c.dump();
  }
}

TEST(KinematicsVectors, RobotMatchesTheFirmwareDefaults) {
  REQUIRE_KINEMATICS(v);
  const CubeConfig defaults;
  EXPECT_EQ(v["robot"]["steps_per_revolution"].get<double>(),
            defaults.geometry.steps_per_revolution);
  EXPECT_EQ(v["robot"]["wheel_diameter_cm"].get<double>(),
            defaults.geometry.wheel_diameter_cm);
  EXPECT_EQ(v["robot"]["wheel_base_cm"].get<double>(),
            defaults.geometry.wheel_base_cm);
  EXPECT_EQ(v["robot"]["max_speed_steps_per_s"].get<int64_t>(),
            defaults.max_speed_sps);
  EXPECT_EQ(v["robot"]["acceleration_steps_per_s2"].get<int64_t>(),
            defaults.accel_sps2);
}

// settings.json ------------------------------------------------------------

json Settings() {
  const std::string text = ReadVectorFile("settings.json");
  return text.empty() ? json() : json::parse(text);
}

#define REQUIRE_SETTINGS(v)                                          \
  const json v = Settings();                                         \
  if (v.is_null()) {                                                 \
    GTEST_FAIL() << "cannot read " << VectorPath("settings.json");   \
  }

// The robot's value at boot of the field named `wire`.
double BootValue(const std::string& wire) {
  const CubeConfig c;
  if (wire == "wheel_diameter_cm") return c.geometry.wheel_diameter_cm;
  if (wire == "wheel_base_cm") return c.geometry.wheel_base_cm;
  if (wire == "steps_per_revolution") return c.geometry.steps_per_revolution;
  if (wire == "max_speed_steps_per_s") return c.max_speed_sps;
  if (wire == "acceleration_steps_per_s2") return c.accel_sps2;
  if (wire == "host_timeout_ms") return c.host_timeout_ms;
  if (wire == "max_steps_per_command") return kMaxStepsPerCommand;
  ADD_FAILURE() << "no boot value for " << wire;
  return 0;
}

TEST(SettingsVectors, TheTableIsSettingsH) {
  REQUIRE_SETTINGS(v);
  std::vector<json> rows;
  for (const json& s : v["settings"])
    if (s["set_by"] == "set_config") rows.push_back(s);
  ASSERT_EQ(rows.size(), sizeof(kSettings) / sizeof(kSettings[0]));
  for (size_t i = 0; i < rows.size(); ++i) {
    const Setting& s = *kSettings[i];
    EXPECT_EQ(rows[i]["wire"].get<std::string>(), s.wire);
    EXPECT_EQ(rows[i]["min"].get<double>(), s.min) << s.wire;
    EXPECT_EQ(rows[i]["max"].get<double>(), s.max) << s.wire;
    EXPECT_EQ(rows[i]["integer"].get<bool>(), s.integer) << s.wire;
    EXPECT_EQ(rows[i]["unit"].get<std::string>(), s.unit) << s.wire;
  }
}

TEST(SettingsVectors, DefaultsAndWireTypesAreTheRobots) {
  REQUIRE_SETTINGS(v);
  Device d;
  const json config = d.Send({{"cmd", "set_config"}})["config"];
  for (const json& s : v["settings"]) {
    if (s["wire"].is_null()) continue;
    const std::string wire = s["wire"].get<std::string>();
    EXPECT_EQ(s["default"].get<double>(), BootValue(wire)) << wire;
    EXPECT_EQ(config[wire].get<double>(), s["default"].get<double>()) << wire;
  }
  // A double the robot keeps is written as one: a fraction survives.
  Device boot;
  CubeConfig fractional;
  fractional.geometry.steps_per_revolution = 4075.5;
  boot.cube->Configure(fractional);
  const json kept = boot.Send({{"cmd", "set_config"}})["config"];
  EXPECT_EQ(kept["steps_per_revolution"], 4075.5);
}

// Each set_config field takes its min and max and refuses just outside
// them with RANGE_EXCEEDED, naming the range as the table has it.
TEST(SettingsVectors, TheRobotTakesExactlyTheRanges) {
  REQUIRE_SETTINGS(v);
  for (const json& s : v["settings"]) {
    if (s["set_by"] != "set_config") continue;
    const std::string wire = s["wire"].get<std::string>();
    for (const char* edge : {"min", "max"}) {
      Device d;
      const json r = d.Send({{"cmd", "set_config"}, {wire, s[edge]}});
      EXPECT_EQ(r["ok"], true) << wire << " " << edge << ": " << r.dump();
      EXPECT_EQ(r["config"][wire], s[edge]) << wire;
    }
    for (const json& out : s["refused"]) {
      Device d;
      const json r = d.Send({{"cmd", "set_config"}, {wire, out}});
      EXPECT_EQ(r["error"]["code"], "RANGE_EXCEEDED") << wire << " " << out;
      EXPECT_EQ(r["error"]["message"], s["range_message"]) << wire;
    }
  }
}

// The speed ceiling: 2048 steps/s is the top speed set_config takes, and a
// faster request runs at it.
TEST(SettingsVectors, TheSpeedCeiling) {
  REQUIRE_SETTINGS(v);
  const int64_t ceiling = v["speed_ceiling_steps_per_s"].get<int64_t>();
  EXPECT_EQ(static_cast<int64_t>(kMaxSpeedStepsPerS.max), ceiling);
  Device d;
  const json set =
      d.Send({{"cmd", "set_config"}, {"max_speed_steps_per_s", ceiling}});
  ASSERT_EQ(set["ok"], true);
  const json m = d.Send({{"cmd", "move_steps"},
                         {"left", 4000},
                         {"right", 4000},
                         {"speed", ceiling * 2}});
  EXPECT_EQ(m["speed"], ceiling);
  EXPECT_EQ(m["speed_clamped"], true);
}

// protocol-messages.json ---------------------------------------------------

json Substitute(const json& j, uint32_t sid) {
  if (j.is_string() && j.get<std::string>() == "$sid") return sid;
  if (j.is_object() || j.is_array()) {
    json out = j;
    for (auto it = out.begin(); it != out.end(); ++it)
      *it = Substitute(*it, sid);
    return out;
  }
  return j;
}

void ExpectSubset(const json& want, const json& got, const std::string& where) {
  if (want.is_object()) {
    ASSERT_TRUE(got.is_object()) << where << ": " << got.dump();
    for (auto it = want.begin(); it != want.end(); ++it) {
      ASSERT_TRUE(got.contains(it.key()))
          << where << "." << it.key() << " missing in " << got.dump();
      ExpectSubset(it.value(), got[it.key()], where + "." + it.key());
    }
    return;
  }
  if (want.is_number() && got.is_number()) {
    EXPECT_EQ(want.get<double>(), got.get<double>()) << where;
    return;
  }
  EXPECT_EQ(want, got) << where;
}

TEST(ProtocolVectors, EveryGoldenExchangeBehavesAsRecorded) {
  const std::string text = ReadVectorFile("protocol-messages.json");
  if (text.empty()) {
    GTEST_FAIL() << "cannot read " << VectorPath("protocol-messages.json");
  }
  const json file = json::parse(text);
  int steps = 0;
  for (const json& c : file["cases"]) {
    Device d;
    uint32_t sid = 0;
    std::string previous;
    for (const json& s : c["steps"]) {
      const std::string where =
          c["name"].get<std::string>() + " step " + std::to_string(steps);
      if (s.contains("advance_ms")) d.Run(s["advance_ms"].get<uint64_t>());
      const std::string raw = s.contains("send_raw")
                                  ? d.Raw(s["send_raw"].get<std::string>())
                                  : d.Raw(Substitute(s["send"], sid).dump());
      const json reply = json::parse(raw);
      if (reply.contains("cmd") && reply["cmd"] == "hello" &&
          reply.value("ok", false)) {
        sid = reply["sid"].get<uint32_t>();
      }
      if (s.contains("expect"))
        ExpectSubset(Substitute(s["expect"], sid), reply, where);
      for (const json& k : s.value("expect_absent", json::array())) {
        EXPECT_FALSE(reply.contains(k.get<std::string>()))
            << where << " has " << k;
      }
      if (s.value("same_as_previous", false)) EXPECT_EQ(raw, previous) << where;
      previous = raw;
      ++steps;
    }
  }
  EXPECT_GT(steps, 30);
}

}  // namespace
}  // namespace cube::testing
