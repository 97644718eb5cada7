// Differential-drive stepper kinematics shared, formula for formula, with
// @hal/kinematics. Pure functions and small value types; no I/O.
#ifndef CUBE_CORE_KINEMATICS_H_
#define CUBE_CORE_KINEMATICS_H_

#include <cstdint>

namespace cube {

constexpr double kPi = 3.141592653589793;

// Robot geometry in the units the protocol uses.
struct Geometry {
  double steps_per_revolution = 4096.0;
  double wheel_diameter_cm = 6.0;
  double wheel_base_cm = 10.0;
};

// Truncates toward zero with a 1e-9 guard so that 2171.9999999999 counts as
// 2172 on every platform.
int64_t TruncateSteps(double x);

// Exact (fractional) steps for a wheel travel of `cm`: (cm * S) / (pi * D).
double ExactStepsForCm(double cm, const Geometry& g);

// Whole steps for a wheel travel of `cm`, truncated toward zero.
int64_t DistanceToSteps(double cm, const Geometry& g);

// Wheel arc in cm for an in-place turn of `degrees` (CCW positive).
double RotationArcCm(double degrees, const Geometry& g);

// Per-wheel accumulator: issues whole steps so that repeated commands do not
// drift from the exact commanded distance.
class StepAccumulator {
 public:
  // Adds `cm` of travel and returns the whole steps to issue for it.
  int64_t Add(double cm, const Geometry& g);
  // What Add() would return, without changing the accumulator.
  int64_t Peek(double cm, const Geometry& g) const;
  void Reset();

 private:
  double exact_ = 0.0;
  int64_t issued_ = 0;
};

// Trapezoidal (or triangular) profile of the master wheel from rest to rest,
// or, with `unbounded`, accelerate-then-cruise velocity mode.
struct StepProfile {
  int64_t steps = 0;       // N, ignored when unbounded
  double speed = 0.0;      // v, steps/s (> 0)
  double accel = 0.0;      // a, steps/s^2 (> 0)
  bool unbounded = false;  // velocity mode: N = infinity
};

// Time of master step k (1..N) after the motion's start, in whole
// microseconds: floor(t * 1e6 + 0.5).
int64_t StepTimeUs(const StepProfile& p, int64_t k);

// Duration of a bounded profile: StepTimeUs(N) (0 when N is 0).
int64_t ProfileDurationUs(const StepProfile& p);

// Commanded speed of the master wheel at `t_s` seconds into the motion.
double ProfileSpeedAt(const StepProfile& p, double t_s);

// Steps the slave wheel has made once the master has made k of n steps,
// for a slave total of m: floor(k * m / n).
int64_t SlaveSteps(int64_t k, int64_t m, int64_t n);

// Planar pose, REP-103: x forward, y left, heading CCW positive in (-pi, pi].
struct Pose {
  double x_cm = 0.0;
  double y_cm = 0.0;
  double heading_rad = 0.0;
};

double NormalizeAngle(double rad);

// Integrates one pair of executed step deltas into `pose`.
void IntegrateOdometry(Pose& pose, int64_t d_left_steps, int64_t d_right_steps,
                       const Geometry& g);

}  // namespace cube

#endif  // CUBE_CORE_KINEMATICS_H_
