// Fuzz target: the whole request handler, Cube::Handle (bytes in, one reply
// out), with sessions, reply memory and, in the keyed build
// (CUBE_FUZZ_KEYED=1), the MAC.
//
// Input: byte 0 picks a starting state the harness sets up with valid
// requests (bits 0-1: fresh; a session open; a session with a move running;
// a session with the e-stop latched). The rest is a list of requests
// separated by 0x1E; each starts with a control byte:
//   bit 0    sign the request with the key (keyed build), or append a MAC
//            of some key to it (keyless build, which must ignore it)
//   bit 1    send the same bytes again right after (a retry)
//   bits 2-4 let time pass first: 0, 1, 20, 100, 300, 800, 1500, 2500 ms
//   bit 5    while time passes, the host keeps the link alive
// In a request, "$sid" (with its quotes) becomes the current session id and
// "$seq" the next sequence number, so the fuzzer reaches in-session states.
//
// Properties, for every request:
// - exactly one reply: a single valid JSON object (strict parser), at most
//   1024 bytes, readable by the firmware's own JsonReader, and with a valid
//   MAC of the key after it in the keyed build (none in the keyless one);
// - "ok" is a boolean; an error reply carries "error" {code, message,
//   details} with a known code, a success reply no "error";
// - an echoed "seq" (and "sid", except hello's) is the request's;
// - an error reply changes nothing observable, except that a step-limit
//   refusal latches the emergency stop (and nothing else);
// - keyed: a request without the right MAC is refused with AUTH_FAILED;
// - a retry of an in-session request gets the same bytes and changes
//   nothing.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "check.h"
#include "cube_world.h"
#include "json_reader.h"
#include "strict_json.h"

#ifndef CUBE_FUZZ_KEYED
#define CUBE_FUZZ_KEYED 0
#endif

namespace {

using cube::fuzz::Digest;
using cube::fuzz::Document;
using cube::fuzz::Kind;
using cube::fuzz::Member;
using cube::fuzz::World;

constexpr bool kKeyed = CUBE_FUZZ_KEYED != 0;
constexpr uint8_t kSeparator = 0x1E;
constexpr size_t kMaxRequests = 48;
constexpr uint64_t kAdvanceMs[] = {0, 1, 20, 100, 300, 800, 1500, 2500};

struct Session {
  uint32_t next_seq = 2;  // the harness's hello uses seq 1
};

std::string Sign(const std::string& body, const std::vector<uint8_t>& key) {
  return body + "#" + cube::MacHex(key, body);
}

// The JSON part of a request, as the cube splits off a trailing MAC.
std::string JsonPart(const std::string& req) {
  const size_t mac = cube::kMacHexLen;
  if (req.size() < 1 + mac || req[req.size() - 1 - mac] != '#') return req;
  for (size_t i = req.size() - mac; i < req.size(); ++i) {
    const char c = req[i];
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return req;
  }
  return req.substr(0, req.size() - 1 - mac);
}

void ReplaceAll(std::string* s, const std::string& from, const std::string& to) {
  for (size_t at = s->find(from); at != std::string::npos;
       at = s->find(from, at + to.size())) {
    s->replace(at, from.size(), to);
  }
}

double NumberOf(const Member* m) {
  return m != nullptr && m->kind == Kind::kNumber
             ? std::strtod(m->text.c_str(), nullptr)
             : -1.0;
}

bool KnownCode(const std::string& code) {
  static const char* const kCodes[] = {
      "MALFORMED",         "UNKNOWN_COMMAND",  "INVALID_PARAMETER",
      "RANGE_EXCEEDED",    "EMERGENCY_STOPPED", "STALE_SEQUENCE",
      "SESSION_MISMATCH",  "AUTH_FAILED",      "HARDWARE_ERROR",
      "NOT_IMPLEMENTED",   "TIMEOUT",          "INTERRUPTED"};
  for (const char* c : kCodes) {
    if (code == c) return true;
  }
  return false;
}

struct Checked {
  bool ok = false;
  std::string code;
  std::string cmd;
  bool has_seq = false;
  bool has_sid = false;
  double sid = -1;
};

// The reply format properties; returns what the reply says.
Checked CheckReply(const std::string& request, const std::string& raw) {
  FUZZ_CHECK(!raw.empty(), "no reply to a request of %zu bytes",
             request.size());
  std::string body = raw;
  if (kKeyed) {
    const size_t mac = cube::kMacHexLen;
    FUZZ_CHECK(raw.size() > 1 + mac && raw[raw.size() - 1 - mac] == '#',
               "keyed reply without a MAC: %s", raw.c_str());
    body = raw.substr(0, raw.size() - 1 - mac);
    FUZZ_CHECK(cube::MacHex(cube::fuzz::FuzzKey(), body) ==
                   raw.substr(raw.size() - mac),
               "reply MAC does not verify: %s", raw.c_str());
  }
  FUZZ_CHECK(body.size() <= cube::kMaxMessage, "reply of %zu bytes",
             body.size());
  const Document d = cube::fuzz::ParseStrict(body.data(), body.size());
  FUZZ_CHECK(d.valid && d.is_object, "reply is not one JSON object: %s",
             body.c_str());
  static cube::JsonReader reader;
  FUZZ_CHECK(reader.Parse(body.data(), body.size()) == cube::JsonError::kOk,
             "the firmware cannot read its own reply: %s", body.c_str());

  const std::string req_json = JsonPart(request);
  if (cube::fuzz::IsValidUtf8(req_json.data(), req_json.size())) {
    FUZZ_CHECK(cube::fuzz::IsValidUtf8(body.data(), body.size()),
               "reply to UTF-8 text is not UTF-8: %s", body.c_str());
  }

  Checked c;
  const Member* ok = d.Find("ok");
  FUZZ_CHECK(ok != nullptr && ok->kind == Kind::kBool, "no boolean ok: %s",
             body.c_str());
  c.ok = ok->boolean;
  const Member* error = d.Find("error");
  if (c.ok) {
    FUZZ_CHECK(error == nullptr, "ok reply with an error: %s", body.c_str());
  } else {
    FUZZ_CHECK(error != nullptr && error->kind == Kind::kObject,
               "failed reply without an error object: %s", body.c_str());
    const Document e =
        cube::fuzz::ParseStrict(error->text.data(), error->text.size());
    const Member* code = e.Find("code");
    const Member* message = e.Find("message");
    const Member* details = e.Find("details");
    FUZZ_CHECK(code != nullptr && code->kind == Kind::kString &&
                   KnownCode(code->str),
               "error without a known code: %s", body.c_str());
    FUZZ_CHECK(message != nullptr && message->kind == Kind::kString &&
                   !message->str.empty(),
               "error without a message: %s", body.c_str());
    FUZZ_CHECK(details != nullptr && details->kind == Kind::kObject,
               "error without details: %s", body.c_str());
    c.code = code->str;
  }
  if (const Member* cmd = d.Find("cmd")) c.cmd = cmd->str;

  const Document q = cube::fuzz::ParseStrict(req_json.data(), req_json.size());
  if (const Member* seq = d.Find("seq")) {
    c.has_seq = true;
    FUZZ_CHECK(NumberOf(seq) == NumberOf(q.Find("seq")),
               "reply seq %s is not the request's", seq->text.c_str());
  }
  if (const Member* sid = d.Find("sid")) {
    c.has_sid = true;
    c.sid = NumberOf(sid);
    if (c.cmd != "hello") {
      FUZZ_CHECK(c.sid == NumberOf(q.Find("sid")),
                 "reply sid %s is not the request's", sid->text.c_str());
    }
  }
  return c;
}

std::string Send(World& w, const std::string& req) {
  uint8_t out[cube::kMaxMessage + 64];
  const size_t n =
      w.cube->Handle(reinterpret_cast<const uint8_t*>(req.data()), req.size(),
                     out, sizeof(out));
  FUZZ_CHECK(n <= sizeof(out), "reply length %zu beyond the buffer", n);
  return std::string(reinterpret_cast<const char*>(out), n);
}

std::string Envelope(const std::string& body, bool sign) {
  return kKeyed && sign ? Sign(body, cube::fuzz::FuzzKey()) : body;
}

// The harness's own requests (valid ones) must succeed.
void SendValid(World& w, const std::string& body) {
  const std::string req = Envelope(body, true);
  const Checked c = CheckReply(req, Send(w, req));
  FUZZ_CHECK(c.ok, "a valid request failed: %s", body.c_str());
}

void SetUp(World& w, uint8_t mode, Session& s) {
  if ((mode & 3) == 0) return;
  SendValid(w, "{\"cmd\":\"hello\",\"seq\":1,\"nonce\":\"fz\"}");
  const std::string sid = std::to_string(w.cube->session_id());
  if ((mode & 3) == 2) {
    SendValid(w, "{\"cmd\":\"move_steps\",\"seq\":2,\"sid\":" + sid +
                     ",\"left\":3000,\"right\":-3000}");
    s.next_seq = 3;
  } else if ((mode & 3) == 3) {
    SendValid(w, "{\"cmd\":\"estop\",\"seq\":2,\"sid\":" + sid + "}");
    s.next_seq = 3;
  }
}

void KeepAlive(World& w, Session& s) {
  std::string body = "{\"cmd\":\"heartbeat\"}";
  if (kKeyed) {
    body = "{\"cmd\":\"heartbeat\",\"seq\":" + std::to_string(s.next_seq++) +
           ",\"sid\":" + std::to_string(w.cube->session_id()) + "}";
  }
  const std::string req = Envelope(body, true);
  CheckReply(req, Send(w, req));
}

void Advance(World& w, Session& s, uint64_t ms, bool alive) {
  while (ms > 0) {
    const uint64_t step = ms < 400 ? ms : 400;
    w.Run(step);
    ms -= step;
    if (alive) KeepAlive(w, s);
  }
}

void CheckStateAfter(const Digest& before, const Digest& after,
                     const Checked& c, const std::string& req) {
  if (c.ok) return;
  FUZZ_CHECK(before.rest == after.rest,
             "error %s changed the state\n  %s\n  %s\n  request: %s",
             c.code.c_str(), before.rest.c_str(), after.rest.c_str(),
             req.c_str());
  if (before.motion != after.motion) {
    // Only a step-limit refusal may act, and only by latching the e-stop.
    FUZZ_CHECK(c.code == "RANGE_EXCEEDED" &&
                   after.motion.rfind("estop=1 ", 0) == 0 &&
                   after.motion.find("trip=step_limit/") != std::string::npos,
               "error %s changed the motion state\n  %s\n  %s\n  request: %s",
               c.code.c_str(), before.motion.c_str(), after.motion.c_str(),
               req.c_str());
  }
}

void OneRequest(World& w, Session& s, uint8_t ctl, std::string body) {
  Advance(w, s, kAdvanceMs[(ctl >> 2) & 7], (ctl & 0x20) != 0);
  const uint32_t sid = w.cube->session_id();
  ReplaceAll(&body, "\"$sid\"", std::to_string(sid));
  ReplaceAll(&body, "\"$seq\"", std::to_string(s.next_seq));
  const bool sign = (ctl & 1) != 0;
  std::string req = body;
  if (kKeyed && sign) {
    req = Sign(body, cube::fuzz::FuzzKey());
  } else if (!kKeyed && sign) {
    req = Sign(body, {0x42});
  }

  const Digest before = cube::fuzz::Observe(*w.cube);
  const std::string raw = Send(w, req);
  const Digest after = cube::fuzz::Observe(*w.cube);
  const Checked c = CheckReply(req, raw);
  CheckStateAfter(before, after, c, req);
  if (kKeyed && !sign && JsonPart(req) == req) {
    FUZZ_CHECK(!c.ok && c.code == "AUTH_FAILED",
               "unsigned request not refused with AUTH_FAILED: %s\n  reply: %s",
               req.c_str(), raw.c_str());
  }
  if (c.has_seq && c.has_sid && c.sid == w.cube->session_id() &&
      c.cmd != "hello") {
    const Document q = cube::fuzz::ParseStrict(JsonPart(req).data(),
                                               JsonPart(req).size());
    const double seq = NumberOf(q.Find("seq"));
    if (c.ok && seq >= s.next_seq) s.next_seq = static_cast<uint32_t>(seq) + 1;
  }

  const bool idempotent = c.cmd != "stop" && c.cmd != "estop" &&
                          c.cmd != "reset_estop" && c.cmd != "hello";
  if ((ctl & 2) != 0 && idempotent && c.has_seq && c.has_sid &&
      c.sid == sid && sid == w.cube->session_id() &&
      c.code != "AUTH_FAILED") {
    const std::string again = Send(w, req);
    FUZZ_CHECK(again == raw, "a retry got another reply\n  %s\n  %s",
               raw.c_str(), again.c_str());
    const Digest later = cube::fuzz::Observe(*w.cube);
    FUZZ_CHECK(later.rest == after.rest && later.motion == after.motion,
               "a retry changed the state: %s", req.c_str());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  World w(kKeyed);
  Session s;
  SetUp(w, data[0], s);
  size_t i = 1;
  for (size_t n = 0; i < size && n < kMaxRequests; ++n) {
    size_t end = i;
    while (end < size && data[end] != kSeparator) ++end;
    if (end > i) {
      OneRequest(w, s, data[i],
                 std::string(reinterpret_cast<const char*>(data + i + 1),
                             end - i - 1));
    }
    i = end + 1;
  }
  return 0;
}
