#include "motion.h"

#include <cmath>

namespace cube {

const char* MoveOutcomeName(MoveOutcome o) {
  switch (o) {
    case MoveOutcome::kNone:
      return "none";
    case MoveOutcome::kRunning:
      return "running";
    case MoveOutcome::kDone:
      return "done";
    case MoveOutcome::kStopped:
      return "stopped";
    case MoveOutcome::kEstop:
      return "estop";
    case MoveOutcome::kHostTimeout:
      return "host_timeout";
    case MoveOutcome::kReplaced:
      return "replaced";
  }
  return "none";
}

namespace {

int64_t Abs64(int64_t v) { return v < 0 ? -v : v; }
int8_t Sign(int64_t v) {
  return static_cast<int8_t>(v > 0 ? 1 : (v < 0 ? -1 : 0));
}

}  // namespace

Motion::Motion(StepExecutor& executor) : exec_(executor) {}

void Motion::Sync() {
  const int32_t l = exec_.left_position();
  const int32_t r = exec_.right_position();
  // Differences of wrapping 32-bit counters, read back as signed.
  const int32_t dl = static_cast<int32_t>(
      static_cast<uint32_t>(l) - static_cast<uint32_t>(last_raw_left_));
  const int32_t dr = static_cast<int32_t>(
      static_cast<uint32_t>(r) - static_cast<uint32_t>(last_raw_right_));
  last_raw_left_ = l;
  last_raw_right_ = r;
  left_pos_ += dl;
  right_pos_ += dr;
  report_.left_position = left_pos_;
  report_.right_position = right_pos_;
  if (running_) {
    report_.done_left = left_pos_ - start_left_;
    report_.done_right = right_pos_ - start_right_;
  }
}

void Motion::TakeDeltas(int64_t* d_left, int64_t* d_right) {
  Sync();
  *d_left = left_pos_ - odo_left_;
  *d_right = right_pos_ - odo_right_;
  odo_left_ = left_pos_;
  odo_right_ = right_pos_;
}

uint32_t Motion::Start(const MotionRequest& req, uint64_t now_us) {
  if (running_) Stop(MoveOutcome::kReplaced, now_us);
  Sync();
  running_ = true;
  queued_all_ = false;
  start_us_ = now_us;
  start_left_ = left_pos_;
  start_right_ = right_pos_;
  next_k_ = 1;
  slave_issued_ = 0;
  generation_ = exec_.generation();

  report_ = MotionReport();
  report_.move_id = next_id_++;
  report_.velocity = req.velocity;
  report_.outcome = MoveOutcome::kRunning;
  report_.left_position = left_pos_;
  report_.right_position = right_pos_;

  profile_ = StepProfile();
  profile_.accel = req.accel;
  if (req.velocity) {
    master_left_ = Abs64(req.left_sps) >= Abs64(req.right_sps);
    const int64_t vm = master_left_ ? req.left_sps : req.right_sps;
    const int64_t vs = master_left_ ? req.right_sps : req.left_sps;
    vm_ = Abs64(vm);
    vs_ = Abs64(vs);
    master_dir_ = Sign(vm);
    slave_dir_ = Sign(vs);
    profile_.unbounded = true;
    profile_.speed = static_cast<double>(vm_);
    report_.left_sps = req.left_sps;
    report_.right_sps = req.right_sps;
    report_.speed = profile_.speed;
    report_.duration_us =
        req.has_duration ? static_cast<int64_t>(req.duration_us) : 0;
    n_ = 0;
    m_ = 0;
    if (vm_ == 0) queued_all_ = true;
  } else {
    master_left_ = Abs64(req.left_steps) >= Abs64(req.right_steps);
    const int64_t sm = master_left_ ? req.left_steps : req.right_steps;
    const int64_t ss = master_left_ ? req.right_steps : req.left_steps;
    n_ = Abs64(sm);
    m_ = Abs64(ss);
    master_dir_ = Sign(sm);
    slave_dir_ = Sign(ss);
    profile_.steps = n_;
    profile_.speed = req.speed;
    report_.planned_left = req.left_steps;
    report_.planned_right = req.right_steps;
    report_.speed = req.speed;
    report_.duration_us = ProfileDurationUs(profile_);
    vm_ = 0;
    vs_ = 0;
  }
  duration_limit_us_ = req.has_duration && req.velocity
                           ? static_cast<int64_t>(req.duration_us)
                           : -1;
  exec_.SetCoilsEnabled(true);
  if (listener_ != nullptr) listener_->OnMotionStarted(report_);
  Refill();
  return report_.move_id;
}

void Motion::Refill() {
  StepQueue& q = exec_.queue();
  while (!queued_all_ && !q.Full()) {
    if (!profile_.unbounded && next_k_ > n_) {
      queued_all_ = true;
      break;
    }
    const int64_t t = StepTimeUs(profile_, next_k_);
    if (duration_limit_us_ >= 0 && t >= duration_limit_us_) {
      queued_all_ = true;
      break;
    }
    const int64_t slave_target = profile_.unbounded
                                     ? (next_k_ * vs_) / vm_
                                     : SlaveSteps(next_k_, m_, n_);
    StepEvent e;
    e.due_us = start_us_ + static_cast<uint64_t>(t);
    e.generation = generation_;
    const int8_t slave = slave_target > slave_issued_ ? slave_dir_ : 0;
    slave_issued_ = slave_target;
    if (master_left_) {
      e.left = master_dir_;
      e.right = slave;
    } else {
      e.right = master_dir_;
      e.left = slave;
    }
    q.Push(e);
    ++next_k_;
  }
}

void Motion::Finish(MoveOutcome outcome) {
  Sync();
  running_ = false;
  report_.outcome = outcome;
  exec_.SetCoilsEnabled(false);
  if (listener_ != nullptr) listener_->OnMotionFinished(report_);
}

void Motion::Stop(MoveOutcome why, uint64_t now_us) {
  (void)now_us;
  if (!running_) return;
  exec_.Cancel();
  Finish(why);
}

void Motion::Update(uint64_t now_us) {
  (void)now_us;
  Sync();
  if (!running_) return;
  Refill();
  if (queued_all_ && exec_.queue().Size() == 0) {
    if (duration_limit_us_ >= 0 || profile_.unbounded) {
      // A drive ends at its duration, not at its last queued step.
      if (duration_limit_us_ >= 0 &&
          now_us >= start_us_ + static_cast<uint64_t>(duration_limit_us_)) {
        Finish(MoveOutcome::kDone);
      } else if (duration_limit_us_ < 0 && vm_ == 0) {
        Finish(MoveOutcome::kDone);
      }
      return;
    }
    Finish(MoveOutcome::kDone);
  }
}

void Motion::CurrentSpeeds(uint64_t now_us, double* left, double* right) const {
  *left = 0.0;
  *right = 0.0;
  if (!running_ || now_us < start_us_) return;
  const double t = static_cast<double>(now_us - start_us_) / 1e6;
  const double vm = ProfileSpeedAt(profile_, t);
  double vs;
  if (profile_.unbounded) {
    vs = vm_ == 0 ? 0.0
                  : vm * static_cast<double>(vs_) / static_cast<double>(vm_);
  } else {
    vs = n_ == 0 ? 0.0 : vm * static_cast<double>(m_) / static_cast<double>(n_);
  }
  const double master = vm * master_dir_;
  const double slave = vs * slave_dir_;
  *left = master_left_ ? master : slave;
  *right = master_left_ ? slave : master;
}

}  // namespace cube
