// The shared golden vectors: kinematics (written with @hal/kinematics) and
// protocol exchanges (read by the TypeScript codec too).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "harness.h"
#include "kinematics.h"

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
