// Cube: construction and configuration, the task's Poll() (motion, odometry,
// host timeout, LED, watchdog), the interrupt's Tick(), and safety trips.
#include "cube.h"

#include <cstring>

#include "text.h"

namespace cube {

const char* LedPatternName(LedPattern p) {
  switch (p) {
    case LedPattern::kOff:
      return "off";
    case LedPattern::kSolid:
      return "solid";
    case LedPattern::kBlink:
      return "blink";
    case LedPattern::kPulse:
      return "pulse";
  }
  return "off";
}

Cube::Cube(const CubeDeps& deps, const char* device_id)
    : clock_(*deps.clock),
      random_(*deps.random),
      led_out_(deps.led),
      watchdog_(deps.watchdog),
      mac_(deps.mac),
      executor_(*deps.motors, true),
      motion_(executor_),
      boot_us_(deps.clock->NowUs()),
      last_host_us_(boot_us_) {
  CopyText(device_id_, sizeof(device_id_), device_id, std::strlen(device_id));
  motion_.set_listener(this);
}

void Cube::Configure(const CubeConfig& config) {
  IntegratePending();
  config_ = config;
  acc_left_.Reset();
  acc_right_.Reset();
}

void Cube::OnMotionStarted(const MotionReport& r) {
  if (observer_ != nullptr) observer_->OnMotionStarted(r);
}

void Cube::OnMotionFinished(const MotionReport& r) {
  rest_us_ = clock_.NowUs() - boot_us_;
  IntegratePending();
  if (observer_ != nullptr) observer_->OnMotionFinished(r);
}

const char* AuthModeName(AuthMode m) {
  switch (m) {
    case AuthMode::kUnconfigured:
      return "unconfigured";
    case AuthMode::kHmacSha256:
      return "hmac-sha256";
    case AuthMode::kNone:
      return "none";
  }
  return "unconfigured";
}

bool Cube::SetKey(const uint8_t* key, size_t len) {
  if (mac_ == nullptr || key == nullptr || len == 0 || len > kMaxKeyLen) {
    return false;
  }
  std::memcpy(key_, key, len);
  key_len_ = len;
  auth_ = AuthMode::kHmacSha256;
  return true;
}

void Cube::AllowUnauthenticated() {
  std::memset(key_, 0, sizeof(key_));
  key_len_ = 0;
  auth_ = AuthMode::kNone;
}

uint64_t Cube::uptime_ms() const { return (clock_.NowUs() - boot_us_) / 1000; }

CUBE_ISR_FN void Cube::Tick() { executor_.Tick(clock_.NowUs()); }

void Cube::IntegratePending() {
  int64_t dl = 0;
  int64_t dr = 0;
  motion_.TakeDeltas(&dl, &dr);
  if (dl != 0 || dr != 0) IntegrateOdometry(pose_, dl, dr, config_.geometry);
}

void Cube::UpdateMotion() {
  motion_.Update(clock_.NowUs());
  IntegratePending();
}

void Cube::Poll() {
  const uint64_t now = clock_.NowUs();
  motion_.Update(now);
  IntegratePending();
  if (motion_.running() &&
      now - last_host_us_ >=
          static_cast<uint64_t>(config_.host_timeout_ms) * 1000u) {
    motion_.Stop(MoveOutcome::kHostTimeout, now);
    IntegratePending();
    Text t;
    t.S("no request from the host for ").I(config_.host_timeout_ms).S(" ms");
    RecordTrip("host_timeout", t.c_str());
  }
  UpdateLed(now);
  if (watchdog_ != nullptr) watchdog_->Feed();
}

void Cube::UpdateLed(uint64_t now_us) {
  if (led_out_ == nullptr) return;
  const uint64_t ms = (now_us - boot_us_) / 1000;
  uint8_t rgb[3] = {0, 0, 0};
  if (estop_) {
    // A latched e-stop shows as a fast red blink, whatever was commanded.
    if (ms % 500 < 250) rgb[0] = 255;
  } else {
    uint32_t level = 0;  // 0..1000
    switch (led_.pattern) {
      case LedPattern::kOff:
        level = 0;
        break;
      case LedPattern::kSolid:
        level = 1000;
        break;
      case LedPattern::kBlink:
        level = ms % 1000 < 500 ? 1000 : 0;
        break;
      case LedPattern::kPulse: {
        const uint32_t p = static_cast<uint32_t>(ms % 2000);
        level = p < 1000 ? p : 2000 - p;
        break;
      }
    }
    rgb[0] = static_cast<uint8_t>(led_.r * level / 1000);
    rgb[1] = static_cast<uint8_t>(led_.g * level / 1000);
    rgb[2] = static_cast<uint8_t>(led_.b * level / 1000);
  }
  if (led_written_ && std::memcmp(rgb, led_last_, 3) == 0) return;
  led_out_->SetRgb(rgb[0], rgb[1], rgb[2]);
  std::memcpy(led_last_, rgb, 3);
  led_written_ = true;
}

void Cube::RecordTrip(const char* reason, const char* detail) {
  ++trips_;
  last_trip_.reason = reason;
  CopyText(last_trip_.detail, sizeof(last_trip_.detail), detail,
           std::strlen(detail));
  last_trip_.uptime_ms = uptime_ms();
  if (observer_ != nullptr) observer_->OnTrip(last_trip_);
}

void Cube::LatchEstop(const char* reason, const char* detail, MoveOutcome why) {
  const uint64_t now = clock_.NowUs();
  motion_.Stop(why, now);
  IntegratePending();
  // Already latched (a resent estop): the first reason and time stay, and no
  // further trip is counted.
  if (estop_) return;
  estop_ = true;
  estop_us_ = now - boot_us_;
  CopyText(estop_reason_, sizeof(estop_reason_), detail, std::strlen(detail));
  RecordTrip(reason, detail);
}

}  // namespace cube
