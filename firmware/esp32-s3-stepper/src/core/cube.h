// The stepper cube: protocol 1.1 (docs/protocol.md) on top of the motion
// core. One instance per robot. Handle()/HandleOversize()/Poll()/UpdateMotion()
// run in one task; Tick() runs in the step interrupt.
#ifndef CUBE_CORE_CUBE_H_
#define CUBE_CORE_CUBE_H_

#include <cstddef>
#include <cstdint>

#include "hal.h"
#include "json_reader.h"
#include "json_writer.h"
#include "key_hex.h"
#include "kinematics.h"
#include "motion.h"
#include "stepper.h"

namespace cube {

constexpr const char* kFirmwareVersion = "1.1.0";
constexpr const char* kProtocolVersion = "1.1";
constexpr size_t kMaxMessage = 1024;
constexpr int64_t kMaxStepsPerCommand = 40960;
constexpr size_t kReplyMemory = 16;
constexpr size_t kMacHexLen = 32;

// How the device authenticates requests (docs/protocol.md section 8). A
// Cube starts closed: until SetKey() or AllowUnauthenticated() it runs only
// stop and estop and refuses everything else with AUTH_FAILED.
enum class AuthMode : uint8_t {
  kUnconfigured,  // neither a key nor the opt-out: closed
  kHmacSha256,    // a pre-shared key: every message MACed, sessions required
  kNone,          // the explicit opt-out: anyone who reaches it commands it
};
// "unconfigured", "hmac-sha256", "none" (the last two are hello's `auth`).
const char* AuthModeName(AuthMode m);

// The settings at boot; set_config's ranges are in settings.h.
struct CubeConfig {
  Geometry geometry;
  int64_t max_speed_sps = 1024;
  int64_t accel_sps2 = 512;
  int64_t host_timeout_ms = 2000;
};

// Writes the six set_config fields of `c` as keys and values of the object
// being written, each as the config reply carries it (settings.h's names).
void WriteConfigFields(JsonWriter& w, const CubeConfig& c);

enum class LedPattern : uint8_t { kOff, kSolid, kBlink, kPulse };
const char* LedPatternName(LedPattern p);

struct LedState {
  uint8_t r = 0;
  uint8_t g = 0;
  uint8_t b = 0;
  LedPattern pattern = LedPattern::kOff;
};

struct SafetyTrip {
  const char* reason = "";  // "estop_command", "step_limit", "host_timeout"
  char detail[64] = {};
  uint64_t uptime_ms = 0;
};

// Everything the core needs from outside. clock, motors and random are
// required; the others may be null.
struct CubeDeps {
  Clock* clock = nullptr;
  MotorDriver* motors = nullptr;
  RandomSource* random = nullptr;
  StatusLed* led = nullptr;
  Watchdog* watchdog = nullptr;
  MacProvider* mac = nullptr;
};

// Notified of motions and safety trips, in task context (the emulator prints
// them; the board may log them).
class CubeObserver : public MotionListener {
 public:
  virtual void OnTrip(const SafetyTrip& trip) = 0;
};

class Reply;  // defined in reply.h

class Cube : private MotionListener {
 public:
  Cube(const CubeDeps& deps, const char* device_id);
  Cube(const Cube&) = delete;
  Cube& operator=(const Cube&) = delete;

  void set_observer(CubeObserver* o) { observer_ = o; }
  // Boot-time configuration (the board's defaults, the emulator's flags).
  // Values are used as given; set_config over the wire validates.
  void Configure(const CubeConfig& config);
  // Configures the pre-shared key (1..64 bytes): authentication on. False
  // (and nothing changed) without a MacProvider or with a bad length.
  bool SetKey(const uint8_t* key, size_t len);
  // The explicit opt-out (CUBE_ALLOW_UNAUTHENTICATED, the emulator without
  // --key): no MAC, and requests without a session are accepted. Forgets a
  // key set before.
  void AllowUnauthenticated();
  AuthMode auth_mode() const { return auth_; }

  // Handles one request (a UDP datagram or a frame's payload) and writes
  // exactly one reply into `out` (cap >= kMaxMessage + 33 recommended).
  // Returns the reply's length.
  size_t Handle(const uint8_t* req, size_t len, uint8_t* out, size_t cap);
  // The reply to a message that was too long to receive whole.
  size_t HandleOversize(size_t announced_len, uint8_t* out, size_t cap);

  // Task context, about every millisecond: queue refill, end of motion,
  // odometry, host timeout, LED, watchdog.
  void Poll();
  // Task context: the motion part of Poll() alone (queue refill, end of
  // motion, odometry).
  // The host emulator calls it (with Tick()) before it reads a serial frame,
  // as its step interrupt runs only between passes of its loop; the host
  // timeout is left to Poll(), after the frames that were waiting are read.
  void UpdateMotion();
  // Interrupt context: executes due steps.
  void Tick();

  // Read-only views, for the board glue and tests.
  const Pose& pose() const { return pose_; }
  const CubeConfig& config() const { return config_; }
  const char* device_id() const { return device_id_; }
  bool estopped() const { return estop_; }
  uint32_t trips() const { return trips_; }
  const SafetyTrip& last_trip() const { return last_trip_; }
  bool running() const { return motion_.running(); }
  const MotionReport& motion_report() const { return motion_.report(); }
  int64_t left_position() const { return motion_.left_position(); }
  int64_t right_position() const { return motion_.right_position(); }
  bool coils_on() const { return executor_.coils_on(); }
  const LedState& led() const { return led_; }
  uint32_t session_id() const { return sid_; }
  uint64_t uptime_ms() const;
  uint64_t uptime_us() const { return clock_.NowUs() - boot_us_; }
  // The clock reading at boot (uptime 0), in the clock's own microseconds.
  uint64_t boot_us() const { return boot_us_; }

 private:
  struct Remembered {
    uint32_t seq = 0;
    size_t len = 0;
    uint8_t bytes[kMaxMessage];
  };

  void OnMotionStarted(const MotionReport& r) override;
  void OnMotionFinished(const MotionReport& r) override;
  size_t Finish(Reply& reply, uint8_t* out, size_t cap);
  // Finish(), and remember the reply under its seq, which becomes the
  // session's highest.
  size_t FinishRemembered(Reply& reply, uint8_t* out, size_t cap);
  void Dispatch(const char* cmd, Reply& reply);
  bool IsCommand(const char* cmd) const;
  static bool IsMotionCommand(const char* cmd);
  void CmdHello(Reply& r);
  void CmdHeartbeat(Reply& r);
  void CmdMoveSteps(Reply& r);
  void CmdMoveCm(Reply& r);
  void CmdRotateDeg(Reply& r);
  void CmdDrive(Reply& r);
  void CmdStop(Reply& r);
  void CmdGetStatus(Reply& r);
  void CmdSetConfig(Reply& r);
  void CmdSetLed(Reply& r);
  void CmdEstop(Reply& r);
  void CmdResetEstop(Reply& r);

  bool CheckNotEstopped(Reply& r);
  bool ReadSpeed(Reply& r, double* speed, bool* clamped);
  void StartMove(Reply& r, int64_t left, int64_t right, double speed,
                 bool clamped);
  void TripStepLimit(Reply& r, const char* field, int64_t steps);
  void LatchEstop(const char* reason, const char* detail, MoveOutcome why);
  void RecordTrip(const char* reason, const char* detail);
  void WriteConfig(JsonWriter& w) const;
  // Writes the stop report of `stop` and `estop` replies (protocol 1.1): the
  // last motion, the wheel positions, and when the wheels came to rest.
  void WriteStopReport(JsonWriter& w) const;
  // Writes the last motion's move_id, move_outcome and steps made
  // (get_status, and the stop report).
  void WriteLastMove(JsonWriter& w) const;
  // Writes `"led":{r,g,b,pattern}` (get_status and set_led replies).
  void WriteLed(JsonWriter& w) const;
  void IntegratePending();
  void UpdateLed(uint64_t now_us);
  size_t AppendMac(uint8_t* buf, size_t len, size_t cap);
  bool VerifyMac(const uint8_t* json, size_t len, const uint8_t* hex);

  Clock& clock_;
  RandomSource& random_;
  StatusLed* led_out_;
  Watchdog* watchdog_;
  MacProvider* mac_;
  CubeObserver* observer_ = nullptr;
  char device_id_[32] = {};

  StepExecutor executor_;
  Motion motion_;
  CubeConfig config_;
  StepAccumulator acc_left_;
  StepAccumulator acc_right_;
  Pose pose_;
  uint64_t boot_us_;

  // Safety.
  bool estop_ = false;
  char estop_reason_[64] = {};
  uint64_t estop_us_ = 0;  // uptime when the latch was set
  uint64_t rest_us_ = 0;   // uptime when the wheels last came to rest
  uint32_t trips_ = 0;
  SafetyTrip last_trip_;
  uint64_t last_host_us_;

  // Session and reply memory.
  bool session_open_ = false;
  uint32_t sid_ = 0;
  uint32_t last_seq_ = 0;
  // The highest seq of a stop or estop executed in this session (protocol
  // 1.1, section 4.1): a motion command numbered below it that was never
  // executed is refused, so it cannot start after the stop.
  uint32_t stop_fence_ = 0;
  bool fence_by_estop_ = false;
  Remembered memory_[kReplyMemory];
  size_t memory_count_ = 0;
  size_t memory_next_ = 0;
  bool hello_has_seq_ = false;
  uint32_t hello_seq_ = 0;
  char hello_nonce_[65] = {};
  uint8_t hello_reply_[kMaxMessage + 1 + kMacHexLen];
  size_t hello_reply_len_ = 0;

  // Authentication.
  AuthMode auth_ = AuthMode::kUnconfigured;
  uint8_t key_[kMaxKeyLen] = {};
  size_t key_len_ = 0;

  // LED.
  LedState led_;
  bool led_written_ = false;
  uint8_t led_last_[3] = {0, 0, 0};

  JsonReader request_;
};

}  // namespace cube

#endif  // CUBE_CORE_CUBE_H_
