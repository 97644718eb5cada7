#include "kinematics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cube {
namespace {

const Geometry kV1;  // 4096 steps/rev, 6 cm wheels, 10 cm base

TEST(Kinematics, TenCentimetresIs2172Steps) {
  EXPECT_EQ(DistanceToSteps(10.0, kV1), 2172);
  EXPECT_EQ(DistanceToSteps(-10.0, kV1), -2172);
}

TEST(Kinematics, StepsPerCentimetreMatchTheSeedFigure) {
  EXPECT_NEAR(ExactStepsForCm(1.0, kV1), 217.3, 0.05);
  EXPECT_NEAR(kPi * kV1.wheel_diameter_cm, 18.85, 0.005);
}

TEST(Kinematics, NinetyDegreeTurnIs1706StepsPerWheel) {
  const double arc = RotationArcCm(90.0, kV1);
  EXPECT_NEAR(arc, 7.85, 0.005);
  EXPECT_EQ(DistanceToSteps(arc, kV1), 1706);
  EXPECT_EQ(DistanceToSteps(-arc, kV1), -1706);
}

TEST(Kinematics, TruncatesTowardZeroWithAGuardForRounding) {
  EXPECT_EQ(TruncateSteps(2171.9999999999), 2172);
  EXPECT_EQ(TruncateSteps(2171.99), 2171);
  EXPECT_EQ(TruncateSteps(-2171.99), -2171);
  EXPECT_EQ(TruncateSteps(-2171.9999999999), -2172);
  EXPECT_EQ(TruncateSteps(0.0), 0);
}

TEST(StepAccumulator, HundredMovesOfTenCentimetresDoNotDrift) {
  // Each 10 cm is 2172.995... steps: truncating every move alone would lose
  // almost a step per move (217200 in all); the accumulator issues
  // trunc(100 * 2172.995...) = 217299.
  StepAccumulator acc;
  int64_t total = 0;
  for (int i = 0; i < 100; ++i) total += acc.Add(10.0, kV1);
  EXPECT_EQ(total, 217299);
}

TEST(StepAccumulator, PeekDoesNotChangeTheAccumulator) {
  StepAccumulator acc;
  EXPECT_EQ(acc.Peek(10.0, kV1), 2172);
  EXPECT_EQ(acc.Peek(10.0, kV1), 2172);
  EXPECT_EQ(acc.Add(10.0, kV1), 2172);
  EXPECT_EQ(acc.Add(10.0, kV1), 2173);
}

TEST(StepAccumulator, ForwardThenBackReturnsToZero) {
  StepAccumulator acc;
  const int64_t a = acc.Add(3.3, kV1);
  const int64_t b = acc.Add(-3.3, kV1);
  EXPECT_EQ(a + b, 0);
}

StepProfile Move(int64_t n, double v = 1024, double a = 512) {
  StepProfile p;
  p.steps = n;
  p.speed = v;
  p.accel = a;
  return p;
}

TEST(StepProfile, TriangularMoveOf1706StepsTakesAbout3651Ms) {
  const int64_t d = ProfileDurationUs(Move(1706));
  EXPECT_NEAR(static_cast<double>(d) / 1e6, 3.651, 0.0005);
  EXPECT_EQ(d, static_cast<int64_t>(
                   std::floor(2.0 * std::sqrt(1706.0 / 512.0) * 1e6 + 0.5)));
}

TEST(StepProfile, TrapezoidOf2172StepsTakesAbout4121Ms) {
  const int64_t d = ProfileDurationUs(Move(2172));
  EXPECT_NEAR(static_cast<double>(d) / 1e6, 4.121, 0.0005);
  // 2 s up, 0.121 s cruise, 2 s down.
  EXPECT_NEAR(static_cast<double>(StepTimeUs(Move(2172), 1024)) / 1e6, 2.0,
              1e-6);
}

TEST(StepProfile, StepTimesIncreaseStrictly) {
  for (int64_t n : {1, 2, 3, 100, 1706, 2172, 40960}) {
    const StepProfile p = Move(n);
    int64_t prev = -1;
    for (int64_t k = 1; k <= n; ++k) {
      const int64_t t = StepTimeUs(p, k);
      ASSERT_GT(t, prev) << "n=" << n << " k=" << k;
      prev = t;
    }
  }
}

TEST(StepProfile, FirstStepComesAfterSqrtTwoOverA) {
  EXPECT_EQ(
      StepTimeUs(Move(2172), 1),
      static_cast<int64_t>(std::floor(std::sqrt(2.0 / 512.0) * 1e6 + 0.5)));
}

TEST(StepProfile, CruiseStepsAreOneOverVApart) {
  const StepProfile p = Move(40960);
  const int64_t dt = StepTimeUs(p, 20001) - StepTimeUs(p, 20000);
  EXPECT_NEAR(static_cast<double>(dt), 1e6 / 1024.0, 1.0);
}

TEST(StepProfile, VelocityModeAcceleratesThenCruises) {
  StepProfile p;
  p.unbounded = true;
  p.speed = 800;
  p.accel = 512;
  EXPECT_EQ(StepTimeUs(p, 1), StepTimeUs(Move(40960, 800), 1));
  const int64_t dt = StepTimeUs(p, 5001) - StepTimeUs(p, 5000);
  EXPECT_NEAR(static_cast<double>(dt), 1e6 / 800.0, 1.0);
  EXPECT_DOUBLE_EQ(ProfileSpeedAt(p, 100.0), 800.0);
  EXPECT_DOUBLE_EQ(ProfileSpeedAt(p, 0.5), 256.0);
}

TEST(StepProfile, SpeedIsZeroAtBothEndsAndPeaksInTheMiddle) {
  const StepProfile p = Move(1706);
  const double total = static_cast<double>(ProfileDurationUs(p)) / 1e6;
  EXPECT_DOUBLE_EQ(ProfileSpeedAt(p, 0.0), 0.0);
  EXPECT_NEAR(ProfileSpeedAt(p, total / 2), 512.0 * total / 2, 1e-6);
  EXPECT_DOUBLE_EQ(ProfileSpeedAt(p, total + 1), 0.0);
}

TEST(SlaveSteps, BresenhamCountReachesTheSlaveTotalWithTheMaster) {
  EXPECT_EQ(SlaveSteps(2172, 1000, 2172), 1000);
  EXPECT_EQ(SlaveSteps(1, 1000, 2172), 0);
  EXPECT_EQ(SlaveSteps(1086, 1000, 2172), 500);
  int64_t prev = 0;
  for (int64_t k = 1; k <= 2172; ++k) {
    const int64_t s = SlaveSteps(k, 1000, 2172);
    ASSERT_LE(s - prev, 1);
    prev = s;
  }
}

TEST(Odometry, StraightMoveAdvancesAlongX) {
  Pose p;
  IntegrateOdometry(p, 2172, 2172, kV1);
  EXPECT_NEAR(p.x_cm, 2172 / ExactStepsForCm(1.0, kV1), 1e-12);
  EXPECT_DOUBLE_EQ(p.y_cm, 0.0);
  EXPECT_DOUBLE_EQ(p.heading_rad, 0.0);
}

TEST(Odometry, PositiveTurnIsCounterClockwise) {
  Pose p;
  IntegrateOdometry(p, -1706, 1706, kV1);
  EXPECT_NEAR(p.heading_rad, kPi / 2, 0.002);
  EXPECT_NEAR(p.x_cm, 0.0, 1e-9);
  EXPECT_NEAR(p.y_cm, 0.0, 1e-9);
}

TEST(Odometry, ArcToTheLeftEndsWithPositiveY) {
  Pose p;
  IntegrateOdometry(p, 1000, 2000, kV1);
  EXPECT_GT(p.y_cm, 0.0);
  EXPECT_GT(p.heading_rad, 0.0);
}

TEST(Odometry, HeadingStaysInTheHalfOpenRangeMinusPiToPi) {
  Pose p;
  for (int i = 0; i < 8; ++i) IntegrateOdometry(p, -1706, 1706, kV1);
  EXPECT_GT(p.heading_rad, -kPi);
  EXPECT_LE(p.heading_rad, kPi);
  EXPECT_DOUBLE_EQ(NormalizeAngle(-kPi), kPi);
  EXPECT_DOUBLE_EQ(NormalizeAngle(3 * kPi), kPi);
}

}  // namespace
}  // namespace cube
