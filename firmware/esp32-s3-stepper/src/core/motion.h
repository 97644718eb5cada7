// Task-side motion control: plans a move or a drive for both wheels (master
// on the trapezoidal profile, slave by Bresenham so both finish together),
// keeps the step queue filled, detects the end of a motion, and turns the
// interrupt side's positions into int64 positions and odometry deltas.
#ifndef CUBE_CORE_MOTION_H_
#define CUBE_CORE_MOTION_H_

#include <cstdint>

#include "kinematics.h"
#include "stepper.h"

namespace cube {

enum class MoveOutcome : uint8_t {
  kNone,
  kRunning,
  kDone,
  kStopped,
  kEstop,
  kHostTimeout,
  kReplaced,
};

// "none", "running", "done", "stopped", "estop", "host_timeout", "replaced".
const char* MoveOutcomeName(MoveOutcome o);

struct MotionRequest {
  bool velocity = false;
  // Position mode: signed steps per wheel, cruise speed of the master.
  int64_t left_steps = 0;
  int64_t right_steps = 0;
  double speed = 0.0;
  // Velocity mode: signed steps/s per wheel, optional duration.
  int64_t left_sps = 0;
  int64_t right_sps = 0;
  bool has_duration = false;
  uint64_t duration_us = 0;
  double accel = 512.0;
};

struct MotionReport {
  uint32_t move_id = 0;
  bool velocity = false;
  int64_t planned_left = 0;   // position mode only
  int64_t planned_right = 0;  // position mode only
  int64_t left_sps = 0;       // velocity mode only
  int64_t right_sps = 0;      // velocity mode only
  double speed = 0.0;
  int64_t duration_us = 0;  // planned; velocity mode: the limit or 0
  int64_t done_left = 0;    // steps executed by this motion
  int64_t done_right = 0;
  int64_t left_position = 0;
  int64_t right_position = 0;
  MoveOutcome outcome = MoveOutcome::kNone;
};

class MotionListener {
 public:
  virtual ~MotionListener() = default;
  virtual void OnMotionStarted(const MotionReport& r) = 0;
  virtual void OnMotionFinished(const MotionReport& r) = 0;
};

class Motion {
 public:
  explicit Motion(StepExecutor& executor);

  void set_listener(MotionListener* l) { listener_ = l; }

  // Starts a motion from rest at `now_us`, replacing a running one (which
  // ends with outcome kReplaced). Returns the new move id.
  uint32_t Start(const MotionRequest& req, uint64_t now_us);
  // Stops at once; no effect when idle.
  void Stop(MoveOutcome why, uint64_t now_us);
  // Refills the step queue, syncs positions, detects the end of a motion.
  void Update(uint64_t now_us);

  bool running() const { return running_; }
  const MotionReport& report() const { return report_; }
  int64_t left_position() const { return left_pos_; }
  int64_t right_position() const { return right_pos_; }
  // Current commanded wheel speeds, steps/s, signed.
  void CurrentSpeeds(uint64_t now_us, double* left, double* right) const;
  // Steps executed since the last call (for odometry).
  void TakeDeltas(int64_t* d_left, int64_t* d_right);

 private:
  void Sync();
  void Refill();
  void Finish(MoveOutcome outcome);

  StepExecutor& exec_;
  MotionListener* listener_ = nullptr;
  bool running_ = false;
  uint32_t next_id_ = 1;
  MotionReport report_;

  // Plan of the running motion.
  StepProfile profile_;
  bool master_left_ = true;
  int64_t n_ = 0;   // master steps (position mode)
  int64_t m_ = 0;   // slave steps (position mode)
  int64_t vm_ = 0;  // |master speed| (velocity mode)
  int64_t vs_ = 0;  // |slave speed| (velocity mode)
  int8_t master_dir_ = 0;
  int8_t slave_dir_ = 0;
  int64_t next_k_ = 1;
  int64_t slave_issued_ = 0;
  bool queued_all_ = false;
  uint64_t start_us_ = 0;
  uint32_t generation_ = 0;
  int64_t start_left_ = 0;
  int64_t start_right_ = 0;
  int64_t duration_limit_us_ = -1;  // velocity mode with a duration

  // Positions.
  int32_t last_raw_left_ = 0;
  int32_t last_raw_right_ = 0;
  int64_t left_pos_ = 0;
  int64_t right_pos_ = 0;
  int64_t odo_left_ = 0;
  int64_t odo_right_ = 0;
};

}  // namespace cube

#endif  // CUBE_CORE_MOTION_H_
