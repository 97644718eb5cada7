// Cube: the session, status and settings commands (hello, heartbeat,
// get_status, set_config, set_led, estop, reset_estop).
#include "capabilities.h"
#include "cube.h"
#include "reply.h"
#include "request_fields.h"
#include "settings.h"
#include "text.h"

namespace cube {
namespace {

// A whole-number setting, read with its row's range and unit.
Got GetSettingInt(Reply& r, const Setting& s, int64_t* out) {
  return GetInt(r, s.wire, static_cast<int64_t>(s.min),
                static_cast<int64_t>(s.max), s.unit, out);
}

}  // namespace

void WriteConfigFields(JsonWriter& w, const CubeConfig& c) {
  w.Key(kWheelDiameterCm.wire);
  w.Double(c.geometry.wheel_diameter_cm);
  w.Key(kWheelBaseCm.wire);
  w.Double(c.geometry.wheel_base_cm);
  w.Key(kStepsPerRevolution.wire);
  w.Double(c.geometry.steps_per_revolution);
  w.Key(kMaxSpeedStepsPerS.wire);
  w.Int(c.max_speed_sps);
  w.Key(kAccelerationStepsPerS2.wire);
  w.Int(c.accel_sps2);
  w.Key(kHostTimeoutMs.wire);
  w.Int(c.host_timeout_ms);
}

void Cube::WriteConfig(JsonWriter& w) const {
  w.BeginObject();
  WriteConfigFields(w, config_);
  w.Key("max_steps_per_command");
  w.Int(kMaxStepsPerCommand);
  w.EndObject();
}

void Cube::WriteLed(JsonWriter& w) const {
  w.Key("led");
  w.BeginObject();
  w.Key("r");
  w.Uint(led_.r);
  w.Key("g");
  w.Uint(led_.g);
  w.Key("b");
  w.Uint(led_.b);
  w.Key("pattern");
  w.String(LedPatternName(led_.pattern));
  w.EndObject();
}

void Cube::CmdHello(Reply& r) {
  const JsonField* nonce = nullptr;
  const Got gn = GetString(r, "nonce", &nonce);
  if (gn == Got::kError) return;
  if (gn == Got::kAbsent && auth_ == AuthMode::kHmacSha256) {
    Missing(r, "nonce");
    return;
  }
  if (gn == Got::kOk && (nonce->str_len < 1 || nonce->str_len > 64)) {
    TypeError(r, "nonce", "1..64 characters");
    return;
  }
  const JsonField* client = nullptr;
  if (GetString(r, "client", &client) == Got::kError) return;

  uint32_t sid = 0;
  for (int i = 0; i < 8 && (sid == 0 || sid == sid_); ++i) {
    sid = random_.NextU32();
  }
  if (sid == 0 || sid == sid_) sid = sid_ + 1 == 0 ? 1 : sid_ + 1;
  sid_ = sid;
  session_open_ = true;
  last_seq_ = r.has_seq ? r.seq : 0;
  stop_fence_ = 0;
  memory_count_ = 0;
  memory_next_ = 0;
  hello_has_seq_ = r.has_seq;
  hello_seq_ = r.seq;
  hello_reply_len_ = 0;
  if (nonce != nullptr) {
    CopyText(hello_nonce_, sizeof(hello_nonce_), nonce->str, nonce->str_len);
  } else {
    hello_nonce_[0] = '\0';
  }
  acc_left_.Reset();
  acc_right_.Reset();

  r.has_sid = true;
  r.sid = sid_;
  JsonWriter& w = r.Ok();
  if (nonce != nullptr) {
    w.Key("nonce");
    w.String(nonce->str, nonce->str_len);
  }
  w.Key("device_id");
  w.String(device_id_);
  w.Key("firmware_version");
  w.String(kFirmwareVersion);
  w.Key("protocol_version");
  w.String(kProtocolVersion);
  w.Key("auth");
  w.String(AuthModeName(auth_));
  w.Key("capabilities");
  w.BeginArray();
  CapabilityList caps;
  ListCapabilities(config_.geometry, &caps);
  for (size_t i = 0; i < caps.count; ++i) w.String(caps.items[i]);
  w.EndArray();
  w.Key("config");
  WriteConfig(w);
}

void Cube::CmdHeartbeat(Reply& r) {
  JsonWriter& w = r.Ok();
  w.Key("uptime_ms");
  w.Uint(uptime_ms());
  w.Key("running");
  w.Bool(motion_.running());
  w.Key("estop");
  w.Bool(estop_);
}

void Cube::CmdGetStatus(Reply& r) {
  const uint64_t now = clock_.NowUs();
  motion_.Update(now);
  IntegratePending();
  double lsps = 0;
  double rsps = 0;
  motion_.CurrentSpeeds(now, &lsps, &rsps);
  JsonWriter& w = r.Ok();
  w.Key("x_cm");
  w.Double(pose_.x_cm);
  w.Key("y_cm");
  w.Double(pose_.y_cm);
  w.Key("heading_rad");
  w.Double(pose_.heading_rad);
  w.Key("left_steps");
  w.Int(motion_.left_position());
  w.Key("right_steps");
  w.Int(motion_.right_position());
  w.Key("running");
  w.Bool(motion_.running());
  WriteLastMove(w);
  w.Key("left_sps");
  w.Double(lsps);
  w.Key("right_sps");
  w.Double(rsps);
  w.Key("uptime_ms");
  w.Uint(uptime_ms());
  w.Key("safety");
  w.BeginObject();
  w.Key("estop");
  w.Bool(estop_);
  w.Key("estop_reason");
  w.String(estop_reason_);
  w.Key("trips");
  w.Uint(trips_);
  w.Key("last_trip");
  if (trips_ == 0) {
    w.Null();
  } else {
    w.BeginObject();
    w.Key("reason");
    w.String(last_trip_.reason);
    w.Key("detail");
    w.String(last_trip_.detail);
    w.Key("uptime_ms");
    w.Uint(last_trip_.uptime_ms);
    w.EndObject();
  }
  w.Key("host_timeout_ms");
  w.Int(config_.host_timeout_ms);
  w.Key("ms_since_host");
  w.Uint((now - last_host_us_) / 1000);
  w.Key("coils_on");
  w.Bool(executor_.coils_wanted());
  w.EndObject();
  WriteLed(w);
}

void Cube::CmdSetConfig(Reply& r) {
  CubeConfig next = config_;
  double d = 0;
  int64_t i = 0;
  Got g = GetRangedNumber(r, kWheelDiameterCm.wire, kWheelDiameterCm.min,
                          kWheelDiameterCm.max, kWheelDiameterCm.unit, &d);
  if (g == Got::kError) return;
  if (g == Got::kOk) next.geometry.wheel_diameter_cm = d;
  g = GetRangedNumber(r, kWheelBaseCm.wire, kWheelBaseCm.min, kWheelBaseCm.max,
                      kWheelBaseCm.unit, &d);
  if (g == Got::kError) return;
  if (g == Got::kOk) next.geometry.wheel_base_cm = d;
  g = GetSettingInt(r, kStepsPerRevolution, &i);
  if (g == Got::kError) return;
  if (g == Got::kOk)
    next.geometry.steps_per_revolution = static_cast<double>(i);
  g = GetSettingInt(r, kMaxSpeedStepsPerS, &i);
  if (g == Got::kError) return;
  if (g == Got::kOk) next.max_speed_sps = i;
  g = GetSettingInt(r, kAccelerationStepsPerS2, &i);
  if (g == Got::kError) return;
  if (g == Got::kOk) next.accel_sps2 = i;
  g = GetSettingInt(r, kHostTimeoutMs, &i);
  if (g == Got::kError) return;
  if (g == Got::kOk) next.host_timeout_ms = i;

  IntegratePending();  // steps so far count with the old geometry
  config_ = next;
  acc_left_.Reset();
  acc_right_.Reset();
  JsonWriter& w = r.Ok();
  w.Key("config");
  WriteConfig(w);
}

void Cube::CmdSetLed(Reply& r) {
  LedState next;
  next.pattern = LedPattern::kSolid;
  const JsonField* p = nullptr;
  const Got gp = GetString(r, "pattern", &p);
  if (gp == Got::kError) return;
  if (gp == Got::kOk) {
    if (Equals(p->str, "solid")) {
      next.pattern = LedPattern::kSolid;
    } else if (Equals(p->str, "blink")) {
      next.pattern = LedPattern::kBlink;
    } else if (Equals(p->str, "pulse")) {
      next.pattern = LedPattern::kPulse;
    } else if (Equals(p->str, "off")) {
      next.pattern = LedPattern::kOff;
    } else {
      TypeError(r, "pattern", "one of solid, blink, pulse, off");
      return;
    }
  }
  const char* keys[3] = {"r", "g", "b"};
  uint8_t* dst[3] = {&next.r, &next.g, &next.b};
  for (int c = 0; c < 3; ++c) {
    int64_t v = 0;
    const Got g = GetInt(r, keys[c], 0, 255, "", &v);
    if (g == Got::kError) return;
    if (g == Got::kAbsent && next.pattern != LedPattern::kOff) {
      Missing(r, keys[c]);
      return;
    }
    *dst[c] = static_cast<uint8_t>(v);
  }
  led_ = next;
  JsonWriter& w = r.Ok();
  WriteLed(w);
}

void Cube::CmdEstop(Reply& r) {
  // An e-stop never fails: a reason of the wrong type is ignored.
  const JsonField* reason = r.req->Find("reason");
  char text[64] = "estop command";
  if (reason != nullptr && reason->type == JsonType::kString &&
      reason->str_len > 0) {
    const size_t n = CopyText(text, sizeof(text), reason->str, reason->str_len);
    if (SanitizeReason(text, n) == 0) {
      CopyText(text, sizeof(text), "estop command", 13);
    }
  }
  LatchEstop("estop_command", text, MoveOutcome::kEstop);
  JsonWriter& w = r.Ok();
  w.Key("estop");
  w.Bool(true);
  w.Key("estop_reason");
  w.String(estop_reason_);
  w.Key("estop_us");
  w.Int(static_cast<int64_t>(estop_us_));
  WriteStopReport(w);
}

void Cube::WriteLastMove(JsonWriter& w) const {
  const MotionReport& m = motion_.report();
  w.Key("move_id");
  w.Uint(m.move_id);
  w.Key("move_outcome");
  w.String(MoveOutcomeName(m.outcome));
  w.Key("move_left_steps");
  w.Int(m.done_left);
  w.Key("move_right_steps");
  w.Int(m.done_right);
}

void Cube::WriteStopReport(JsonWriter& w) const {
  WriteLastMove(w);
  w.Key("left_steps");
  w.Int(motion_.left_position());
  w.Key("right_steps");
  w.Int(motion_.right_position());
  w.Key("uptime_us");
  w.Int(static_cast<int64_t>(clock_.NowUs() - boot_us_));
  w.Key("stopped_us");
  w.Int(static_cast<int64_t>(rest_us_));
}

void Cube::CmdResetEstop(Reply& r) {
  const bool was = estop_;
  estop_ = false;
  estop_reason_[0] = '\0';
  JsonWriter& w = r.Ok();
  w.Key("estop");
  w.Bool(false);
  w.Key("was_estopped");
  w.Bool(was);
}

}  // namespace cube
