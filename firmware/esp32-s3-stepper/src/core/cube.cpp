#include "cube.h"

#include <cmath>
#include <cstring>

namespace cube {

namespace {

constexpr const char* kMalformed = "MALFORMED";
constexpr const char* kUnknownCommand = "UNKNOWN_COMMAND";
constexpr const char* kInvalidParameter = "INVALID_PARAMETER";
constexpr const char* kRangeExceeded = "RANGE_EXCEEDED";
constexpr const char* kEmergencyStopped = "EMERGENCY_STOPPED";
constexpr const char* kStaleSequence = "STALE_SEQUENCE";
constexpr const char* kSessionMismatch = "SESSION_MISMATCH";
constexpr const char* kAuthFailed = "AUTH_FAILED";
constexpr const char* kHardwareError = "HARDWARE_ERROR";

constexpr int64_t kMaxDriveDurationMs = 600000;

bool Equals(const char* a, const char* b) { return std::strcmp(a, b) == 0; }

void CopyText(char* dst, size_t cap, const char* src, size_t len) {
  if (cap == 0) return;
  size_t n = len < cap - 1 ? len : cap - 1;
  // Do not cut a UTF-8 sequence in half.
  while (n > 0 && n < len &&
         (static_cast<unsigned char>(src[n]) & 0xC0) == 0x80) {
    --n;
  }
  std::memcpy(dst, src, n);
  dst[n] = '\0';
}

// Small bounded text builder for error messages.
class Text {
 public:
  Text& S(const char* s) {
    while (*s != '\0' && n_ + 1 < sizeof(buf_)) buf_[n_++] = *s++;
    buf_[n_] = '\0';
    return *this;
  }
  Text& Q(const char* field) { return S("\"").S(field).S("\""); }
  Text& I(int64_t v) {
    char tmp[24];
    const size_t k = FormatInt(v, tmp, sizeof(tmp));
    tmp[k] = '\0';
    return S(tmp);
  }
  Text& N(double v) {
    char tmp[40];
    const size_t k = FormatNumber(v, tmp, sizeof(tmp) - 1);
    tmp[k] = '\0';
    return S(k == 0 ? "?" : tmp);
  }
  const char* c_str() const { return buf_; }

 private:
  char buf_[160] = {};
  size_t n_ = 0;
};

bool IsLowerHex(uint8_t c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
}

void ToHex(const uint8_t* bytes, size_t n, char* out) {
  static const char kHex[] = "0123456789abcdef";
  for (size_t i = 0; i < n; ++i) {
    out[2 * i] = kHex[bytes[i] >> 4];
    out[2 * i + 1] = kHex[bytes[i] & 0xF];
  }
}

int64_t Abs64(int64_t v) { return v < 0 ? -v : v; }

}  // namespace

// Builds one reply: the envelope, then either the data or the error.
class Reply {
 public:
  struct Detail {
    const char* key = nullptr;
    enum Kind : uint8_t { kInt, kNum, kStr, kBool } kind = kInt;
    int64_t i = 0;
    double d = 0.0;
    char s[64] = {};
  };

  Reply(char* buf, size_t cap) : w_(buf, cap) {}

  bool has_seq = false;
  uint32_t seq = 0;
  bool has_sid = false;
  uint32_t sid = 0;
  const char* cmd = nullptr;  // NUL-terminated (from the reader)
  size_t cmd_len = 0;
  const JsonReader* req = nullptr;

  bool failed() const { return failed_; }
  const char* code() const { return code_; }

  JsonWriter& Ok() {
    if (!started_) {
      Begin();
      w_.Key("ok");
      w_.Bool(true);
      WriteCmd();
      started_ = true;
    }
    return w_;
  }

  void Fail(const char* code, const char* message) {
    if (failed_ || started_) return;
    failed_ = true;
    code_ = code;
    CopyText(message_, sizeof(message_), message, std::strlen(message));
  }

  void DetailInt(const char* key, int64_t v) {
    Detail* d = Add(key);
    if (d != nullptr) {
      d->kind = Detail::kInt;
      d->i = v;
    }
  }
  void DetailNum(const char* key, double v) {
    Detail* d = Add(key);
    if (d != nullptr) {
      d->kind = Detail::kNum;
      d->d = v;
    }
  }
  void DetailStr(const char* key, const char* v) {
    Detail* d = Add(key);
    if (d != nullptr) {
      d->kind = Detail::kStr;
      CopyText(d->s, sizeof(d->s), v, std::strlen(v));
    }
  }
  void DetailBool(const char* key, bool v) {
    Detail* d = Add(key);
    if (d != nullptr) {
      d->kind = Detail::kBool;
      d->i = v ? 1 : 0;
    }
  }

  // Closes the reply; returns false if it did not fit.
  bool Close() {
    if (failed_) {
      Begin();
      w_.Key("ok");
      w_.Bool(false);
      WriteCmd();
      w_.Key("error");
      w_.BeginObject();
      w_.Key("code");
      w_.String(code_);
      w_.Key("message");
      w_.String(message_);
      w_.Key("details");
      w_.BeginObject();
      for (size_t i = 0; i < ndetails_; ++i) {
        const Detail& d = details_[i];
        w_.Key(d.key);
        switch (d.kind) {
          case Detail::kInt:
            w_.Int(d.i);
            break;
          case Detail::kNum:
            w_.Double(d.d);
            break;
          case Detail::kStr:
            w_.String(d.s);
            break;
          case Detail::kBool:
            w_.Bool(d.i != 0);
            break;
        }
      }
      w_.EndObject();
      w_.EndObject();
    } else {
      Ok();
    }
    w_.EndObject();
    return w_.ok();
  }

  size_t size() const { return w_.size(); }

 private:
  Detail* Add(const char* key) {
    if (ndetails_ >= kMaxDetails) return nullptr;
    Detail* d = &details_[ndetails_++];
    d->key = key;
    return d;
  }
  void Begin() {
    w_.BeginObject();
    if (has_seq) {
      w_.Key("seq");
      w_.Uint(seq);
    }
    if (has_sid) {
      w_.Key("sid");
      w_.Uint(sid);
    }
  }
  void WriteCmd() {
    if (cmd != nullptr) {
      w_.Key("cmd");
      w_.String(cmd, cmd_len);
    }
  }

  static constexpr size_t kMaxDetails = 6;
  JsonWriter w_;
  bool started_ = false;
  bool failed_ = false;
  const char* code_ = "";
  char message_[160] = {};
  Detail details_[kMaxDetails];
  size_t ndetails_ = 0;
};

namespace {

enum class Got { kAbsent, kOk, kError };

void RangeError(Reply& r, const char* field, double min, double max,
                double value, const char* unit) {
  Text t;
  t.Q(field).S(" must be ").N(min).S("..").N(max);
  if (unit[0] != '\0') t.S(" ").S(unit);
  r.Fail(kRangeExceeded, t.c_str());
  r.DetailStr("field", field);
  r.DetailNum("min", min);
  r.DetailNum("max", max);
  r.DetailNum("value", value);
}

void TypeError(Reply& r, const char* field, const char* what) {
  Text t;
  t.Q(field).S(" must be ").S(what);
  r.Fail(kInvalidParameter, t.c_str());
  r.DetailStr("field", field);
}

void Missing(Reply& r, const char* field) {
  Text t;
  t.Q(field).S(" is required");
  r.Fail(kInvalidParameter, t.c_str());
  r.DetailStr("field", field);
}

Got GetInt(Reply& r, const char* key, int64_t min, int64_t max,
           const char* unit, int64_t* out) {
  const JsonField* f = r.req->Find(key);
  if (f == nullptr) return Got::kAbsent;
  if (f->type != JsonType::kNumber || !f->is_integer) {
    TypeError(r, key, "an integer");
    return Got::kError;
  }
  if (f->integer < min || f->integer > max) {
    RangeError(r, key, static_cast<double>(min), static_cast<double>(max),
               f->number, unit);
    return Got::kError;
  }
  *out = f->integer;
  return Got::kOk;
}

// Any finite number; range checks are the caller's.
Got GetNumber(Reply& r, const char* key, double* out) {
  const JsonField* f = r.req->Find(key);
  if (f == nullptr) return Got::kAbsent;
  if (f->type != JsonType::kNumber) {
    TypeError(r, key, "a number");
    return Got::kError;
  }
  *out = f->number;
  return Got::kOk;
}

Got GetRangedNumber(Reply& r, const char* key, double min, double max,
                    const char* unit, double* out) {
  double v = 0;
  const Got g = GetNumber(r, key, &v);
  if (g != Got::kOk) return g;
  if (!(v >= min && v <= max)) {
    RangeError(r, key, min, max, v, unit);
    return Got::kError;
  }
  *out = v;
  return Got::kOk;
}

Got GetString(Reply& r, const char* key, const JsonField** out) {
  const JsonField* f = r.req->Find(key);
  if (f == nullptr) return Got::kAbsent;
  if (f->type != JsonType::kString) {
    TypeError(r, key, "a string");
    return Got::kError;
  }
  *out = f;
  return Got::kOk;
}

bool Required(Reply& r, Got g, const char* key) {
  if (g == Got::kAbsent) {
    Missing(r, key);
    return false;
  }
  return g == Got::kOk;
}

}  // namespace

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
  IntegratePending();
  if (observer_ != nullptr) observer_->OnMotionFinished(r);
}

bool Cube::SetKey(const uint8_t* key, size_t len) {
  if (len == 0) {
    key_len_ = 0;
    return true;
  }
  if (mac_ == nullptr || len > kMaxKeyLen) return false;
  std::memcpy(key_, key, len);
  key_len_ = len;
  return true;
}

uint64_t Cube::uptime_ms() const { return (clock_.NowUs() - boot_us_) / 1000; }

CUBE_ISR_FN void Cube::Tick() { executor_.Tick(clock_.NowUs()); }

void Cube::IntegratePending() {
  int64_t dl = 0;
  int64_t dr = 0;
  motion_.TakeDeltas(&dl, &dr);
  if (dl != 0 || dr != 0) IntegrateOdometry(pose_, dl, dr, config_.geometry);
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
  motion_.Stop(why, clock_.NowUs());
  IntegratePending();
  estop_ = true;
  CopyText(estop_reason_, sizeof(estop_reason_), detail, std::strlen(detail));
  RecordTrip(reason, detail);
}

size_t Cube::AppendMac(uint8_t* buf, size_t len, size_t cap) {
  if (key_len_ == 0) return len;
  uint8_t digest[32];
  if (len + 1 + kMacHexLen > cap ||
      !mac_->HmacSha256(key_, key_len_, buf, len, digest)) {
    return len;
  }
  buf[len] = '#';
  ToHex(digest, kMacHexLen / 2, reinterpret_cast<char*>(buf + len + 1));
  return len + 1 + kMacHexLen;
}

bool Cube::VerifyMac(const uint8_t* json, size_t len, const uint8_t* hex) {
  uint8_t digest[32];
  if (!mac_->HmacSha256(key_, key_len_, json, len, digest)) return false;
  char want[kMacHexLen];
  ToHex(digest, kMacHexLen / 2, want);
  uint8_t diff = 0;
  for (size_t i = 0; i < kMacHexLen; ++i) {
    diff =
        static_cast<uint8_t>(diff | (static_cast<uint8_t>(want[i]) ^ hex[i]));
  }
  return diff == 0;
}

size_t Cube::Finish(Reply& reply, uint8_t* out, size_t cap) {
  (void)out;
  if (!reply.Close()) {
    // Cannot happen with the replies of this version; answer something
    // short and valid rather than a cut-off text.
    const char* fallback =
        "{\"ok\":false,\"error\":{\"code\":\"HARDWARE_ERROR\",\"message\":"
        "\"reply too long\",\"details\":{}}}";
    const size_t n = std::strlen(fallback);
    if (n > cap) return 0;
    std::memcpy(out, fallback, n);
    return AppendMac(out, n, cap);
  }
  return AppendMac(out, reply.size(), cap);
}

bool Cube::IsCommand(const char* cmd) const {
  static const char* const kCommands[] = {
      "hello",      "heartbeat", "move_steps", "move_cm",
      "rotate_deg", "drive",     "stop",       "get_status",
      "set_config", "set_led",   "estop",      "reset_estop"};
  for (const char* c : kCommands) {
    if (Equals(c, cmd)) return true;
  }
  return false;
}

size_t Cube::HandleOversize(size_t announced_len, uint8_t* out, size_t cap) {
  const size_t mac_room = key_len_ > 0 ? 1 + kMacHexLen : 0;
  const size_t json_cap = (cap < kMaxMessage ? cap : kMaxMessage) - mac_room;
  Reply reply(reinterpret_cast<char*>(out), json_cap);
  Text t;
  t.S("message is ")
      .I(static_cast<int64_t>(announced_len))
      .S(" bytes; the limit is ")
      .I(static_cast<int64_t>(kMaxMessage));
  reply.Fail(kMalformed, t.c_str());
  reply.DetailInt("length", static_cast<int64_t>(announced_len));
  reply.DetailInt("max", static_cast<int64_t>(kMaxMessage));
  return Finish(reply, out, cap);
}

size_t Cube::Handle(const uint8_t* req, size_t len, uint8_t* out, size_t cap) {
  const uint64_t now = clock_.NowUs();
  if (len > kMaxMessage) return HandleOversize(len, out, cap);
  const size_t mac_room = key_len_ > 0 ? 1 + kMacHexLen : 0;
  if (cap < 64 + mac_room) return 0;
  const size_t json_cap = (cap < kMaxMessage ? cap : kMaxMessage) - mac_room;
  Reply reply(reinterpret_cast<char*>(out), json_cap);
  reply.req = &request_;

  // A trailing "#<32 lowercase hex>" is a MAC (JSON never ends that way).
  size_t json_len = len;
  const uint8_t* mac_hex = nullptr;
  if (len >= 1 + kMacHexLen && req[len - 1 - kMacHexLen] == '#') {
    bool hex = true;
    for (size_t i = len - kMacHexLen; i < len; ++i)
      hex = hex && IsLowerHex(req[i]);
    if (hex) {
      mac_hex = req + len - kMacHexLen;
      json_len = len - 1 - kMacHexLen;
    }
  }

  const JsonError perr =
      request_.Parse(reinterpret_cast<const char*>(req), json_len);
  const bool parsed = perr == JsonError::kOk;

  // Envelope fields, when they can be read.
  bool bad_envelope = false;
  if (parsed) {
    const JsonField* f = request_.Find("cmd");
    if (f != nullptr && f->type == JsonType::kString) {
      reply.cmd = f->str;
      reply.cmd_len = f->str_len;
    }
    static const char* const kEnvelope[] = {"seq", "sid"};
    for (const char* key : kEnvelope) {
      const JsonField* g = request_.Find(key);
      if (g == nullptr) continue;
      if (g->type != JsonType::kNumber || !g->is_integer || g->integer < 0 ||
          g->integer > 0xFFFFFFFFLL) {
        if (!bad_envelope) TypeError(reply, key, "an integer 0..4294967295");
        bad_envelope = true;
        continue;
      }
      if (Equals(key, "seq")) {
        reply.has_seq = true;
        reply.seq = static_cast<uint32_t>(g->integer);
      } else {
        reply.has_sid = true;
        reply.sid = static_cast<uint32_t>(g->integer);
      }
    }
  }

  if (key_len_ > 0 &&
      (mac_hex == nullptr || !VerifyMac(req, json_len, mac_hex))) {
    reply.Fail(kAuthFailed, mac_hex == nullptr
                                ? "message has no MAC; a key is configured"
                                : "MAC does not match the message");
    return Finish(reply, out, cap);
  }
  if (!parsed) {
    Text t;
    t.S("request is not a valid message: ").S(JsonErrorText(perr));
    reply.Fail(kMalformed, t.c_str());
    return Finish(reply, out, cap);
  }
  if (bad_envelope) return Finish(reply, out, cap);

  const JsonField* cmd_field = request_.Find("cmd");
  if (cmd_field == nullptr) {
    Missing(reply, "cmd");
    return Finish(reply, out, cap);
  }
  if (cmd_field->type != JsonType::kString) {
    TypeError(reply, "cmd", "a string");
    return Finish(reply, out, cap);
  }
  const char* cmd = cmd_field->str;
  const bool is_hello = Equals(cmd, "hello");

  if (key_len_ > 0) {
    if (!reply.has_seq) {
      reply.Fail(kAuthFailed, "\"seq\" is required when a key is configured");
      return Finish(reply, out, cap);
    }
    if (!is_hello && !reply.has_sid) {
      reply.Fail(kAuthFailed, "\"sid\" is required when a key is configured");
      return Finish(reply, out, cap);
    }
  }

  if (!IsCommand(cmd)) {
    Text t;
    t.S("unknown command \"").S(cmd).S("\"");
    reply.Fail(kUnknownCommand, t.c_str());
    reply.DetailStr("cmd", cmd);
    return Finish(reply, out, cap);
  }

  if (is_hello) {
    last_host_us_ = now;
    const JsonField* nonce = request_.Find("nonce");
    if (session_open_ && hello_reply_len_ > 0 && nonce != nullptr &&
        nonce->type == JsonType::kString && hello_nonce_[0] != '\0' &&
        Equals(nonce->str, hello_nonce_) && reply.has_seq == hello_has_seq_ &&
        reply.seq == hello_seq_ && hello_reply_len_ <= cap) {
      std::memcpy(out, hello_reply_, hello_reply_len_);
      return hello_reply_len_;
    }
    Dispatch(cmd, reply);
    const size_t n = Finish(reply, out, cap);
    if (!reply.failed() && n <= sizeof(hello_reply_)) {
      std::memcpy(hello_reply_, out, n);
      hello_reply_len_ = n;
    }
    return n;
  }

  const bool safety_cmd = Equals(cmd, "stop") || Equals(cmd, "estop") ||
                          (Equals(cmd, "reset_estop") && key_len_ == 0);

  if (reply.has_seq || reply.has_sid) {
    const bool in_session =
        reply.has_seq && reply.has_sid && session_open_ && reply.sid == sid_;
    if (!in_session) {
      if (safety_cmd) {
        last_host_us_ = now;
        Dispatch(cmd, reply);
        return Finish(reply, out, cap);
      }
      if (reply.has_seq != reply.has_sid) {
        reply.Fail(kSessionMismatch,
                   "\"sid\" and \"seq\" must be given together; send hello "
                   "to open a session");
      } else {
        reply.Fail(kSessionMismatch,
                   "\"sid\" is not the current session; send hello");
        reply.DetailInt("sid", reply.sid);
      }
      return Finish(reply, out, cap);
    }
    for (size_t i = 0; i < memory_count_; ++i) {
      const Remembered& m = memory_[i];
      if (m.seq == reply.seq && m.len <= cap) {
        last_host_us_ = now;
        std::memcpy(out, m.bytes, m.len);
        return m.len;
      }
    }
    if (reply.seq <= last_seq_ && safety_cmd) {
      // A stop is never refused; it is idempotent, so not remembered.
      last_host_us_ = now;
      Dispatch(cmd, reply);
      return Finish(reply, out, cap);
    }
    if (reply.seq <= last_seq_) {
      Text t;
      t.S("\"seq\" ")
          .I(reply.seq)
          .S(" is not above ")
          .I(last_seq_)
          .S(" and its reply is no longer remembered");
      reply.Fail(kStaleSequence, t.c_str());
      reply.DetailInt("seq", reply.seq);
      reply.DetailInt("last_seq", last_seq_);
      return Finish(reply, out, cap);
    }
    last_host_us_ = now;
    last_seq_ = reply.seq;
    Dispatch(cmd, reply);
    const size_t n = Finish(reply, out, cap);
    if (n <= kMaxMessage) {
      Remembered& m = memory_[memory_next_];
      m.seq = reply.seq;
      m.len = n;
      std::memcpy(m.bytes, out, n);
      memory_next_ = (memory_next_ + 1) % kReplyMemory;
      if (memory_count_ < kReplyMemory) ++memory_count_;
    }
    return n;
  }

  // Seed-style request: no session, no memory.
  last_host_us_ = now;
  Dispatch(cmd, reply);
  return Finish(reply, out, cap);
}

void Cube::Dispatch(const char* cmd, Reply& r) {
  if (Equals(cmd, "hello")) return CmdHello(r);
  if (Equals(cmd, "heartbeat")) return CmdHeartbeat(r);
  if (Equals(cmd, "move_steps")) return CmdMoveSteps(r);
  if (Equals(cmd, "move_cm")) return CmdMoveCm(r);
  if (Equals(cmd, "rotate_deg")) return CmdRotateDeg(r);
  if (Equals(cmd, "drive")) return CmdDrive(r);
  if (Equals(cmd, "stop")) return CmdStop(r);
  if (Equals(cmd, "get_status")) return CmdGetStatus(r);
  if (Equals(cmd, "set_config")) return CmdSetConfig(r);
  if (Equals(cmd, "set_led")) return CmdSetLed(r);
  if (Equals(cmd, "estop")) return CmdEstop(r);
  if (Equals(cmd, "reset_estop")) return CmdResetEstop(r);
  r.Fail(kHardwareError, "command table out of date");
}

void Cube::WriteConfig(JsonWriter& w) const {
  w.BeginObject();
  w.Key("wheel_diameter_cm");
  w.Double(config_.geometry.wheel_diameter_cm);
  w.Key("wheel_base_cm");
  w.Double(config_.geometry.wheel_base_cm);
  w.Key("steps_per_revolution");
  w.Double(config_.geometry.steps_per_revolution);
  w.Key("max_speed_steps_per_s");
  w.Int(config_.max_speed_sps);
  w.Key("acceleration_steps_per_s2");
  w.Int(config_.accel_sps2);
  w.Key("host_timeout_ms");
  w.Int(config_.host_timeout_ms);
  w.Key("max_steps_per_command");
  w.Int(kMaxStepsPerCommand);
  w.EndObject();
}

void Cube::CmdHello(Reply& r) {
  const JsonField* nonce = nullptr;
  const Got gn = GetString(r, "nonce", &nonce);
  if (gn == Got::kError) return;
  if (gn == Got::kAbsent && key_len_ > 0) {
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
  w.Bool(key_len_ > 0);
  w.Key("capabilities");
  w.BeginArray();
  w.String("locomotion.differential:v1.0");
  char cap[64] = "locomotion.stepper:v1.0:steps_per_rev=";
  const size_t base = std::strlen(cap);
  const size_t k = FormatNumber(config_.geometry.steps_per_revolution,
                                cap + base, sizeof(cap) - base - 1);
  cap[base + k] = '\0';
  w.String(cap);
  w.String("communication.led:v1.0");
  w.String("safety.estop:v1.0");
  w.String("safety.host_timeout:v1.0");
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

namespace {

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
  w.Key("left_steps");
  w.Int(motion_.left_position());
  w.Key("right_steps");
  w.Int(motion_.right_position());
}

void Cube::CmdGetStatus(Reply& r) {
  const uint64_t now = clock_.NowUs();
  motion_.Update(now);
  IntegratePending();
  const MotionReport& m = motion_.report();
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
  w.Key("move_id");
  w.Uint(m.move_id);
  w.Key("move_outcome");
  w.String(MoveOutcomeName(m.outcome));
  w.Key("move_left_steps");
  w.Int(m.done_left);
  w.Key("move_right_steps");
  w.Int(m.done_right);
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

void Cube::CmdSetConfig(Reply& r) {
  CubeConfig next = config_;
  double d = 0;
  int64_t i = 0;
  Got g = GetRangedNumber(r, "wheel_diameter_cm", 0.5, 50, "cm", &d);
  if (g == Got::kError) return;
  if (g == Got::kOk) next.geometry.wheel_diameter_cm = d;
  g = GetRangedNumber(r, "wheel_base_cm", 1, 100, "cm", &d);
  if (g == Got::kError) return;
  if (g == Got::kOk) next.geometry.wheel_base_cm = d;
  g = GetInt(r, "steps_per_revolution", 100, 100000, "steps", &i);
  if (g == Got::kError) return;
  if (g == Got::kOk)
    next.geometry.steps_per_revolution = static_cast<double>(i);
  g = GetInt(r, "max_speed_steps_per_s", 1, 2048, "steps/s", &i);
  if (g == Got::kError) return;
  if (g == Got::kOk) next.max_speed_sps = i;
  g = GetInt(r, "acceleration_steps_per_s2", 1, 100000, "steps/s^2", &i);
  if (g == Got::kError) return;
  if (g == Got::kOk) next.accel_sps2 = i;
  g = GetInt(r, "host_timeout_ms", 500, 10000, "ms", &i);
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

void Cube::CmdEstop(Reply& r) {
  // An e-stop never fails: a reason of the wrong type is ignored.
  const JsonField* reason = r.req->Find("reason");
  char text[64] = "estop command";
  if (reason != nullptr && reason->type == JsonType::kString &&
      reason->str_len > 0) {
    CopyText(text, sizeof(text), reason->str, reason->str_len);
  }
  LatchEstop("estop_command", text, MoveOutcome::kEstop);
  JsonWriter& w = r.Ok();
  w.Key("estop");
  w.Bool(true);
  w.Key("estop_reason");
  w.String(estop_reason_);
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
