#include "kinematics.h"

#include <cmath>

namespace cube {

int64_t TruncateSteps(double x) {
  return x >= 0 ? static_cast<int64_t>(std::floor(x + 1e-9))
                : -static_cast<int64_t>(std::floor(-x + 1e-9));
}

double ExactStepsForCm(double cm, const Geometry& g) {
  return (cm * g.steps_per_revolution) / (kPi * g.wheel_diameter_cm);
}

int64_t DistanceToSteps(double cm, const Geometry& g) {
  return TruncateSteps(ExactStepsForCm(cm, g));
}

double RotationArcCm(double degrees, const Geometry& g) {
  return ((kPi * g.wheel_base_cm) * degrees) / 360.0;
}

int64_t StepAccumulator::Add(double cm, const Geometry& g) {
  exact_ += ExactStepsForCm(cm, g);
  const int64_t target = TruncateSteps(exact_);
  const int64_t delta = target - issued_;
  issued_ = target;
  return delta;
}

int64_t StepAccumulator::Peek(double cm, const Geometry& g) const {
  StepAccumulator copy = *this;
  return copy.Add(cm, g);
}

void StepAccumulator::Reset() {
  exact_ = 0.0;
  issued_ = 0;
}

namespace {

int64_t ToMicros(double t_s) {
  return static_cast<int64_t>(std::floor(t_s * 1e6 + 0.5));
}

}  // namespace

int64_t StepTimeUs(const StepProfile& p, int64_t k) {
  const double v = p.speed;
  const double a = p.accel;
  const double n_acc = (v * v) / (2.0 * a);
  const double kd = static_cast<double>(k);
  double t;
  if (p.unbounded) {
    if (kd <= n_acc) {
      t = std::sqrt((2.0 * kd) / a);
    } else {
      t = v / a + (kd - n_acc) / v;
    }
    return ToMicros(t);
  }
  const double n = static_cast<double>(p.steps);
  const double rem = static_cast<double>(p.steps - k);
  if (n * a >= v * v) {
    const double total = n / v + v / a;
    if (kd <= n_acc) {
      t = std::sqrt((2.0 * kd) / a);
    } else if (kd <= n - n_acc) {
      t = v / a + (kd - n_acc) / v;
    } else {
      t = total - std::sqrt((2.0 * rem) / a);
    }
  } else {
    const double total = 2.0 * std::sqrt(n / a);
    if (2 * k <= p.steps) {
      t = std::sqrt((2.0 * kd) / a);
    } else {
      t = total - std::sqrt((2.0 * rem) / a);
    }
  }
  return ToMicros(t);
}

int64_t ProfileDurationUs(const StepProfile& p) {
  if (p.unbounded || p.steps <= 0) return 0;
  return StepTimeUs(p, p.steps);
}

double ProfileSpeedAt(const StepProfile& p, double t_s) {
  const double v = p.speed;
  const double a = p.accel;
  if (t_s <= 0) return 0.0;
  if (p.unbounded) return std::fmin(a * t_s, v);
  const double n = static_cast<double>(p.steps);
  if (p.steps <= 0) return 0.0;
  double total;
  double peak;
  if (n * a >= v * v) {
    total = n / v + v / a;
    peak = v;
  } else {
    total = 2.0 * std::sqrt(n / a);
    peak = a * total / 2.0;
  }
  if (t_s >= total) return 0.0;
  return std::fmin(peak, std::fmin(a * t_s, a * (total - t_s)));
}

int64_t SlaveSteps(int64_t k, int64_t m, int64_t n) {
  if (n <= 0) return 0;
  return (k * m) / n;
}

double NormalizeAngle(double rad) {
  while (rad > kPi) rad -= 2.0 * kPi;
  while (rad <= -kPi) rad += 2.0 * kPi;
  return rad;
}

void IntegrateOdometry(Pose& pose, int64_t d_left_steps, int64_t d_right_steps,
                       const Geometry& g) {
  const double steps_per_cm =
      g.steps_per_revolution / (kPi * g.wheel_diameter_cm);
  const double dl = static_cast<double>(d_left_steps) / steps_per_cm;
  const double dr = static_cast<double>(d_right_steps) / steps_per_cm;
  const double ds = (dl + dr) / 2.0;
  const double dth = (dr - dl) / g.wheel_base_cm;
  const double th = pose.heading_rad;
  if (std::fabs(dth) < 1e-12) {
    pose.x_cm += ds * std::cos(th);
    pose.y_cm += ds * std::sin(th);
  } else {
    const double r = ds / dth;
    pose.x_cm += r * (std::sin(th + dth) - std::sin(th));
    pose.y_cm -= r * (std::cos(th + dth) - std::cos(th));
  }
  pose.heading_rad = NormalizeAngle(th + dth);
}

}  // namespace cube
