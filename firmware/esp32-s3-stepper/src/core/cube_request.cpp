// Cube: one request in, one reply out. The envelope (MAC, seq, sid), the
// session and reply-memory rules that make retries exactly-once, and the
// dispatch to the command handlers.
#include <cstring>

#include "cube.h"
#include "reply.h"
#include "request_fields.h"
#include "text.h"

namespace cube {

namespace {

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

}  // namespace

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

// Compares every digit whatever the first difference, so the time taken
// does not tell an attacker how much of a forged MAC was right.
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

size_t Cube::FinishRemembered(Reply& reply, uint8_t* out, size_t cap) {
  last_seq_ = reply.seq;
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

bool Cube::IsMotionCommand(const char* cmd) {
  return Equals(cmd, "move_steps") || Equals(cmd, "move_cm") ||
         Equals(cmd, "rotate_deg") || Equals(cmd, "drive");
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

  // With a key, an unauthenticated request is refused as such, whatever
  // else is wrong with it.
  const bool keyed = auth_ == AuthMode::kHmacSha256;
  const bool mac_ok =
      !keyed || (mac_hex != nullptr && VerifyMac(req, json_len, mac_hex));

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
        if (!bad_envelope && mac_ok) {
          TypeError(reply, key, "an integer 0..4294967295");
        }
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

  if (!mac_ok) {
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

  // Closed until configured: only a stop gets through.
  if (auth_ == AuthMode::kUnconfigured && !Equals(cmd, "stop") &&
      !Equals(cmd, "estop")) {
    reply.Fail(kAuthFailed,
               "authentication is not configured on this device: it runs "
               "only stop and estop until it has a key or the explicit "
               "opt-out");
    return Finish(reply, out, cap);
  }

  if (keyed) {
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
                          (Equals(cmd, "reset_estop") && !keyed);

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
    if (Equals(cmd, "stop") || Equals(cmd, "estop")) {
      // The safety lane (section 4.1): executed whatever the seq, never
      // remembered, the session's highest seq untouched, so a request still
      // being retried stays valid; older motion commands are fenced off.
      if (reply.seq >= stop_fence_) {
        stop_fence_ = reply.seq;
        fence_by_estop_ = Equals(cmd, "estop");
      }
      last_host_us_ = now;
      Dispatch(cmd, reply);
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
      // reset_estop without a key: accepted whatever the seq, not remembered.
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
    if (IsMotionCommand(cmd) && reply.seq < stop_fence_) {
      // Sent before a stop that overtook it: it must not start after it.
      Text t;
      t.S("\"").S(cmd).S("\" was sent before ")
          .S(fence_by_estop_ ? "an estop" : "a stop")
          .S(" that was already executed");
      reply.Fail(fence_by_estop_ ? kEmergencyStopped : kInterrupted, t.c_str());
      reply.DetailInt("stop_seq", stop_fence_);
      return FinishRemembered(reply, out, cap);
    }
    Dispatch(cmd, reply);
    return FinishRemembered(reply, out, cap);
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

}  // namespace cube
