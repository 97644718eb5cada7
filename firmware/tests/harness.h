// Test doubles and a driver for the cube core on a fake clock.
#ifndef CUBE_TESTS_HARNESS_H_
#define CUBE_TESTS_HARNESS_H_

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "cube.h"
#include "host_hal.h"

namespace cube::testing {

using nlohmann::json;

class FakeClock : public Clock {
 public:
  uint64_t NowUs() override { return now_us; }
  uint64_t now_us = 1000000;  // boot at t = 1 s
};

// Records every coil write with the time it happened.
class RecordingMotors : public MotorDriver {
 public:
  explicit RecordingMotors(FakeClock& clock) : clock_(clock) {}
  struct Write {
    Wheel wheel;
    uint8_t pattern;
    uint64_t at_us;
  };
  void WriteCoils(Wheel wheel, uint8_t pattern) override {
    writes.push_back({wheel, pattern, clock_.now_us});
    last[static_cast<int>(wheel)] = pattern;
  }
  std::vector<Write> writes;
  uint8_t last[2] = {0, 0};

 private:
  FakeClock& clock_;
};

class FakeLed : public StatusLed {
 public:
  void SetRgb(uint8_t r, uint8_t g, uint8_t b) override {
    rgb = {r, g, b};
    ++writes;
  }
  std::vector<uint8_t> rgb = {0, 0, 0};
  int writes = 0;
};

class CountingWatchdog : public Watchdog {
 public:
  void Feed() override { ++feeds; }
  int feeds = 0;
};

class SequenceRandom : public RandomSource {
 public:
  uint32_t NextU32() override { return next += 0x9E3779B9u; }
  uint32_t next = 0x12345678u;
};

class RecordingObserver : public CubeObserver {
 public:
  void OnMotionStarted(const MotionReport& r) override { started.push_back(r); }
  void OnMotionFinished(const MotionReport& r) override {
    finished.push_back(r);
  }
  void OnTrip(const SafetyTrip& t) override { trips.push_back(t.reason); }
  std::vector<MotionReport> started;
  std::vector<MotionReport> finished;
  std::vector<std::string> trips;
};

// One robot on a fake clock, with helpers to talk to it.
class Device {
 public:
  // Without a key: the unauthenticated opt-out (AllowUnauthenticated).
  Device();
  explicit Device(const std::vector<uint8_t>& key);

  // Sends raw bytes; returns the raw reply bytes.
  std::string Raw(const std::string& bytes);
  // Sends a JSON request (MACed when a key is set); returns the parsed
  // reply (MAC checked and stripped).
  json Send(const json& request);
  // Opens a session; later Call()s carry sid and an increasing seq.
  json Hello();
  json Call(const std::string& cmd, json params = json::object());

  // Advances the clock by `ms`, ticking the step interrupt every 250 us
  // and polling every ms. With `heartbeat`, a heartbeat every 500 ms.
  void Run(uint64_t ms, bool heartbeat = true);
  // Runs until no motion is running (at most `max_ms`); returns the ms run.
  uint64_t RunUntilIdle(uint64_t max_ms = 60000, bool heartbeat = true);

  json Status() { return Send({{"cmd", "get_status"}}); }

  FakeClock clock;
  RecordingMotors motors{clock};
  FakeLed led;
  CountingWatchdog watchdog;
  SequenceRandom random;
  MbedtlsMac mac;
  RecordingObserver observer;
  std::unique_ptr<Cube> cube;
  std::vector<uint8_t> key;
  uint32_t sid = 0;
  uint32_t seq = 0;
  std::string last_raw_reply;

 private:
  void Init();
  uint64_t since_heartbeat_ms_ = 0;
  int hellos_ = 0;
};

// The path of a file under tests/vectors (the CUBE_VECTORS_DIR environment
// variable, when set, names another folder).
std::string VectorPath(const std::string& name);
// Reads a file under tests/vectors; empty if it cannot be read.
std::string ReadVectorFile(const std::string& name);

std::vector<uint8_t> FromHex(const std::string& hex);
std::string ToHexString(const uint8_t* data, size_t len);

}  // namespace cube::testing

#endif  // CUBE_TESTS_HARNESS_H_
