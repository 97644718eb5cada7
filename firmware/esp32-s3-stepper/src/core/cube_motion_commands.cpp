// Cube: the motion commands (move_steps, move_cm, rotate_deg, drive, stop)
// and their safety checks: the e-stop latch, the speed limit and the
// per-command step limit, whose breach latches the e-stop.
#include <cmath>
#include <cstdint>

#include "cube.h"
#include "reply.h"
#include "request_fields.h"
#include "text.h"

namespace cube {

namespace {

constexpr int64_t kMaxDriveDurationMs = 600000;

int64_t Abs64(int64_t v) { return v < 0 ? -v : v; }

// Steps a wheel travel would give, saturated so the limit check is safe.
bool WithinLimit(const StepAccumulator& acc, double cm, const Geometry& g,
                 int64_t* steps) {
  const double exact = ExactStepsForCm(cm, g);
  if (!(std::fabs(exact) <= 1e12)) {
    *steps = exact > 0 ? INT64_MAX : INT64_MIN + 1;
    return false;
  }
  *steps = acc.Peek(cm, g);
  return Abs64(*steps) <= kMaxStepsPerCommand;
}

}  // namespace

bool Cube::CheckNotEstopped(Reply& r) {
  if (!estop_) return true;
  Text t;
  t.S("emergency stop is latched (")
      .S(estop_reason_)
      .S("); send reset_estop first");
  r.Fail(kEmergencyStopped, t.c_str());
  r.DetailStr("reason", estop_reason_);
  return false;
}

bool Cube::ReadSpeed(Reply& r, double* speed, bool* clamped) {
  const double max = static_cast<double>(config_.max_speed_sps);
  *clamped = false;
  double v = 0;
  const Got g = GetNumber(r, "speed", &v);
  if (g == Got::kError) return false;
  if (g == Got::kAbsent) {
    *speed = max;
    return true;
  }
  if (!(v > 0)) {
    RangeError(r, "speed", 1, max, v, "steps/s");
    return false;
  }
  if (v > max) {
    v = max;
    *clamped = true;
  } else if (v < 1) {
    v = 1;
    *clamped = true;
  }
  *speed = v;
  return true;
}

void Cube::TripStepLimit(Reply& r, const char* field, int64_t steps) {
  Text t;
  t.Q(field)
      .S(" gives ")
      .I(steps)
      .S(" steps; the limit is ")
      .I(kMaxStepsPerCommand)
      .S(" steps per command (emergency stop latched)");
  r.Fail(kRangeExceeded, t.c_str());
  r.DetailStr("field", field);
  r.DetailInt("min", -kMaxStepsPerCommand);
  r.DetailInt("max", kMaxStepsPerCommand);
  r.DetailInt("value", steps);
  r.DetailBool("estop", true);
  Text d;
  d.S("step limit: ").Q(field).S(" ").I(steps).S(" steps");
  LatchEstop("step_limit", d.c_str(), MoveOutcome::kEstop);
}

void Cube::StartMove(Reply& r, int64_t left, int64_t right, double speed,
                     bool clamped) {
  IntegratePending();
  MotionRequest req;
  req.left_steps = left;
  req.right_steps = right;
  req.speed = speed;
  req.accel = static_cast<double>(config_.accel_sps2);
  const uint32_t id = motion_.Start(req, clock_.NowUs());
  const int64_t dur_us = motion_.report().duration_us;
  JsonWriter& w = r.Ok();
  w.Key("move_id");
  w.Uint(id);
  w.Key("left_steps");
  w.Int(left);
  w.Key("right_steps");
  w.Int(right);
  w.Key("speed");
  w.Double(speed);
  w.Key("speed_clamped");
  w.Bool(clamped);
  w.Key("duration_ms");
  w.Int((dur_us + 999) / 1000);
  w.Key("duration_us");
  w.Int(dur_us);
}

void Cube::CmdMoveSteps(Reply& r) {
  if (!CheckNotEstopped(r)) return;
  int64_t left = 0;
  int64_t right = 0;
  if (!Required(r, GetInt(r, "left", INT64_MIN, INT64_MAX, "steps", &left),
                "left")) {
    return;
  }
  if (!Required(r, GetInt(r, "right", INT64_MIN, INT64_MAX, "steps", &right),
                "right")) {
    return;
  }
  double speed = 0;
  bool clamped = false;
  if (!ReadSpeed(r, &speed, &clamped)) return;
  if (Abs64(left) > kMaxStepsPerCommand || left == INT64_MIN) {
    TripStepLimit(r, "left", left);
    return;
  }
  if (Abs64(right) > kMaxStepsPerCommand || right == INT64_MIN) {
    TripStepLimit(r, "right", right);
    return;
  }
  StartMove(r, left, right, speed, clamped);
}

void Cube::CmdMoveCm(Reply& r) {
  if (!CheckNotEstopped(r)) return;
  double lcm = 0;
  double rcm = 0;
  if (!Required(r, GetNumber(r, "left_cm", &lcm), "left_cm")) return;
  if (!Required(r, GetNumber(r, "right_cm", &rcm), "right_cm")) return;
  double speed = 0;
  bool clamped = false;
  if (!ReadSpeed(r, &speed, &clamped)) return;
  int64_t ls = 0;
  int64_t rs = 0;
  if (!WithinLimit(acc_left_, lcm, config_.geometry, &ls)) {
    TripStepLimit(r, "left_cm", ls);
    return;
  }
  if (!WithinLimit(acc_right_, rcm, config_.geometry, &rs)) {
    TripStepLimit(r, "right_cm", rs);
    return;
  }
  ls = acc_left_.Add(lcm, config_.geometry);
  rs = acc_right_.Add(rcm, config_.geometry);
  StartMove(r, ls, rs, speed, clamped);
}

void Cube::CmdRotateDeg(Reply& r) {
  if (!CheckNotEstopped(r)) return;
  double deg = 0;
  if (!Required(r, GetNumber(r, "degrees", &deg), "degrees")) return;
  double speed = 0;
  bool clamped = false;
  if (!ReadSpeed(r, &speed, &clamped)) return;
  const double arc = RotationArcCm(deg, config_.geometry);
  int64_t ls = 0;
  int64_t rs = 0;
  if (!WithinLimit(acc_left_, -arc, config_.geometry, &ls)) {
    TripStepLimit(r, "degrees", ls);
    return;
  }
  if (!WithinLimit(acc_right_, arc, config_.geometry, &rs)) {
    TripStepLimit(r, "degrees", rs);
    return;
  }
  ls = acc_left_.Add(-arc, config_.geometry);
  rs = acc_right_.Add(arc, config_.geometry);
  StartMove(r, ls, rs, speed, clamped);
}

void Cube::CmdDrive(Reply& r) {
  if (!CheckNotEstopped(r)) return;
  int64_t l = 0;
  int64_t rr = 0;
  int64_t dur = 0;
  if (!Required(r,
                GetInt(r, "left_sps", -2147483647, 2147483647, "steps/s", &l),
                "left_sps")) {
    return;
  }
  if (!Required(r,
                GetInt(r, "right_sps", -2147483647, 2147483647, "steps/s", &rr),
                "right_sps")) {
    return;
  }
  const Got gd = GetInt(r, "duration_ms", 1, kMaxDriveDurationMs, "ms", &dur);
  if (gd == Got::kError) return;
  const int64_t max = config_.max_speed_sps;
  const int64_t m = Abs64(l) > Abs64(rr) ? Abs64(l) : Abs64(rr);
  bool clamped = false;
  if (m > max) {
    l = l * max / m;
    rr = rr * max / m;
    clamped = true;
  }
  IntegratePending();
  const uint64_t now = clock_.NowUs();
  bool running = false;
  if (l == 0 && rr == 0) {
    motion_.Stop(MoveOutcome::kStopped, now);
  } else {
    MotionRequest req;
    req.velocity = true;
    req.left_sps = l;
    req.right_sps = rr;
    req.has_duration = gd == Got::kOk;
    req.duration_us = static_cast<uint64_t>(dur) * 1000u;
    req.accel = static_cast<double>(config_.accel_sps2);
    motion_.Start(req, now);
    running = true;
  }
  JsonWriter& w = r.Ok();
  w.Key("move_id");
  w.Uint(motion_.report().move_id);
  w.Key("left_sps");
  w.Int(l);
  w.Key("right_sps");
  w.Int(rr);
  w.Key("speed_clamped");
  w.Bool(clamped);
  if (gd == Got::kOk) {
    w.Key("duration_ms");
    w.Int(dur);
  }
  w.Key("running");
  w.Bool(running);
}

void Cube::CmdStop(Reply& r) {
  const bool was = motion_.running();
  motion_.Stop(MoveOutcome::kStopped, clock_.NowUs());
  IntegratePending();
  JsonWriter& w = r.Ok();
  w.Key("stopped");
  w.Bool(was);
  WriteStopReport(w);
}

}  // namespace cube
