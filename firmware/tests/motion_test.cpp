// The step planner and executor at the level of individual steps.
#include "motion.h"

#include <gtest/gtest.h>

#include <vector>

#include "harness.h"
#include "stepper.h"

namespace cube::testing {
namespace {

struct Rig {
  FakeClock clock;
  RecordingMotors motors{clock};
  StepExecutor exec{motors, true};
  Motion motion{exec};
  std::vector<std::pair<uint64_t, int>> left_steps;  // time, direction
  std::vector<std::pair<uint64_t, int>> right_steps;

  // Advances straight to each queued step's due time and executes it, so
  // every step is seen at its exact time.
  void RunExactly(uint64_t start_us) {
    (void)start_us;
    for (int guard = 0; guard < 200000 && motion.running(); ++guard) {
      StepEvent e;
      if (exec.queue().Front(&e) && e.generation == exec.generation()) {
        clock.now_us = e.due_us;
        const int32_t l0 = exec.left_position();
        const int32_t r0 = exec.right_position();
        exec.Tick(clock.now_us);
        if (exec.left_position() != l0)
          left_steps.emplace_back(clock.now_us, exec.left_position() - l0);
        if (exec.right_position() != r0)
          right_steps.emplace_back(clock.now_us, exec.right_position() - r0);
      } else {
        exec.Tick(clock.now_us);
      }
      motion.Update(clock.now_us);
    }
  }
};

MotionRequest Move(int64_t l, int64_t r, double v = 1024) {
  MotionRequest m;
  m.left_steps = l;
  m.right_steps = r;
  m.speed = v;
  m.accel = 512;
  return m;
}

TEST(StepPlanner, MasterStepsHappenAtTheProfileTimesToTheMicrosecond) {
  Rig rig;
  const uint64_t start = rig.clock.now_us;
  rig.motion.Start(Move(2172, 2172), start);
  rig.RunExactly(start);
  ASSERT_EQ(rig.left_steps.size(), 2172u);
  StepProfile p{2172, 1024, 512, false};
  for (int64_t k = 1; k <= 2172; ++k) {
    ASSERT_EQ(rig.left_steps[static_cast<size_t>(k - 1)].first,
              start + static_cast<uint64_t>(StepTimeUs(p, k)))
        << k;
  }
}

TEST(StepPlanner, BothWheelsFinishTogetherOnAnArc) {
  Rig rig;
  const uint64_t start = rig.clock.now_us;
  rig.motion.Start(Move(3000, 1234), start);
  rig.RunExactly(start);
  ASSERT_EQ(rig.left_steps.size(), 3000u);
  ASSERT_EQ(rig.right_steps.size(), 1234u);
  EXPECT_EQ(rig.left_steps.back().first, rig.right_steps.back().first);
  // After the master's k-th step the slave has made floor(k * M / N).
  size_t slave = 0;
  for (size_t k = 1; k <= 3000; ++k) {
    while (slave < rig.right_steps.size() &&
           rig.right_steps[slave].first <= rig.left_steps[k - 1].first) {
      ++slave;
    }
    ASSERT_EQ(static_cast<int64_t>(slave),
              SlaveSteps(static_cast<int64_t>(k), 1234, 3000))
        << k;
  }
}

TEST(StepPlanner, TheRightWheelCanBeTheMasterAndEachWheelKeepsItsSign) {
  Rig rig;
  rig.motion.Start(Move(-500, 1706), rig.clock.now_us);
  rig.RunExactly(rig.clock.now_us);
  EXPECT_EQ(rig.motion.left_position(), -500);
  EXPECT_EQ(rig.motion.right_position(), 1706);
  for (const auto& s : rig.left_steps) ASSERT_EQ(s.second, -1);
  EXPECT_EQ(rig.motion.report().duration_us,
            ProfileDurationUs({1706, 1024, 512, false}));
}

TEST(StepPlanner, DrivesTheCoilsThroughTheHalfStepSequence) {
  Rig rig;
  rig.motion.Start(Move(8, -8), rig.clock.now_us);
  rig.RunExactly(rig.clock.now_us);
  std::vector<uint8_t> left;
  std::vector<uint8_t> right;
  for (const auto& w : rig.motors.writes) {
    (w.wheel == Wheel::kLeft ? left : right).push_back(w.pattern);
  }
  // First writes energise the current phase, then one per step.
  const std::vector<uint8_t> fwd = {0x3, 0x2, 0x6, 0x4, 0xC, 0x8, 0x9, 0x1};
  ASSERT_GE(left.size(), 9u);
  EXPECT_EQ(std::vector<uint8_t>(left.begin() + 1, left.begin() + 9), fwd);
  // The right motor is mirrored: a backward wheel step turns its shaft
  // forward, so it runs the same sequence.
  ASSERT_GE(right.size(), 9u);
  EXPECT_EQ(std::vector<uint8_t>(right.begin() + 1, right.begin() + 9), fwd);
}

TEST(StepPlanner, ATwoThousandStepsPerSecondMoveKeepsUpWithAQueueOf128) {
  Rig rig;
  MotionRequest m = Move(40960, 40960, 2048);
  m.accel = 100000;
  rig.motion.Start(m, rig.clock.now_us);
  rig.RunExactly(rig.clock.now_us);
  EXPECT_EQ(rig.motion.left_position(), 40960);
  EXPECT_EQ(rig.motion.right_position(), 40960);
}

TEST(StepPlanner, CancelDiscardsEveryQueuedStep) {
  Rig rig;
  rig.motion.Start(Move(1000, 1000), rig.clock.now_us);
  EXPECT_GT(rig.exec.queue().Size(), 0u);
  rig.motion.Stop(MoveOutcome::kStopped, rig.clock.now_us);
  rig.clock.now_us += 10000000;
  rig.exec.Tick(rig.clock.now_us);
  EXPECT_EQ(rig.exec.queue().Size(), 0u);
  EXPECT_EQ(rig.exec.left_position(), 0);
  EXPECT_FALSE(rig.exec.coils_on());
}

TEST(StepPlanner, PositionsSurviveTheInterruptCounterWrapping) {
  Rig rig;
  // Drive far enough in one direction through many moves: the 32-bit ISR
  // counter is read as deltas, so int64 positions keep counting.
  for (int i = 0; i < 3; ++i) {
    rig.motion.Start(Move(-40960, -40960, 2048), rig.clock.now_us);
    rig.RunExactly(rig.clock.now_us);
  }
  EXPECT_EQ(rig.motion.left_position(), -3 * 40960);
}

TEST(StepPlanner, ReportsCurrentSpeedsFromTheProfile) {
  Rig rig;
  const uint64_t start = rig.clock.now_us;
  rig.motion.Start(Move(4000, 2000), start);
  double l = 0;
  double r = 0;
  rig.motion.CurrentSpeeds(start + 1000000, &l, &r);
  EXPECT_DOUBLE_EQ(l, 512.0);
  EXPECT_DOUBLE_EQ(r, 256.0);
}

}  // namespace
}  // namespace cube::testing
