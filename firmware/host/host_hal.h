// Host implementations of the core's interfaces, shared by cube-emulator
// and the tests.
#ifndef CUBE_HOST_HOST_HAL_H_
#define CUBE_HOST_HOST_HAL_H_

#include <chrono>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "hal.h"

namespace cube {

// HMAC-SHA256 by mbedtls (the ESP32 Arduino core ships the same library).
class MbedtlsMac : public MacProvider {
 public:
  bool HmacSha256(const uint8_t* key, size_t key_len, const uint8_t* data,
                  size_t len, uint8_t* out) override;
};

// Session ids from the operating system's entropy.
class SystemRandom : public RandomSource {
 public:
  SystemRandom();
  uint32_t NextU32() override;

 private:
  std::mt19937 engine_;
};

// The steady clock, optionally running `scale` times faster than real time.
class ScaledClock : public Clock {
 public:
  explicit ScaledClock(double scale = 1.0);
  // Never goes backwards, held or not.
  uint64_t NowUs() override;
  // steady_clock (CLOCK_MONOTONIC on Linux) at the start, microseconds.
  uint64_t StartSteadyUs() const;
  // Until Release(), reads as at `t` (a request's arrival, so that the core
  // handles it at the time it came, not at the time the process got to it).
  void HoldAt(std::chrono::steady_clock::time_point t);
  void Release();

 private:
  std::chrono::steady_clock::time_point start_;
  double scale_;
  bool held_ = false;
  std::chrono::steady_clock::time_point held_at_;
  uint64_t last_us_ = 0;
};

// Parses "00ff..." into bytes; false on odd length or a non-hex digit.
bool ParseHex(const std::string& hex, std::vector<uint8_t>* out);

// First 16 bytes of HMAC-SHA256 as 32 lowercase hex digits (host side of
// docs/protocol.md section 8).
std::string MacHex(const std::vector<uint8_t>& key, const std::string& json);

}  // namespace cube

#endif  // CUBE_HOST_HOST_HAL_H_
