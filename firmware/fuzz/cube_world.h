// One cube on a fake clock for the request-handler fuzz targets, with a
// digest of everything a host can observe of its state.
#ifndef CUBE_FUZZ_CUBE_WORLD_H_
#define CUBE_FUZZ_CUBE_WORLD_H_

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "cube.h"
#include "host_hal.h"

namespace cube::fuzz {

class FuzzClock : public Clock {
 public:
  uint64_t NowUs() override { return now_us; }
  uint64_t now_us = 1000000;
};

class CountingMotors : public MotorDriver {
 public:
  void WriteCoils(Wheel wheel, uint8_t pattern) override {
    last[static_cast<int>(wheel)] = pattern;
    ++writes;
  }
  uint8_t last[2] = {0, 0};
  uint64_t writes = 0;
};

class FixedRandom : public RandomSource {
 public:
  uint32_t NextU32() override { return next += 0x9E3779B9u; }
  uint32_t next = 0x12345678u;
};

class QuietLed : public StatusLed {
 public:
  void SetRgb(uint8_t, uint8_t, uint8_t) override {}
};

// The key of the keyed target (and the one a keyless target's requests may
// carry a MAC of, to exercise MAC stripping).
inline const std::vector<uint8_t>& FuzzKey() {
  static const std::vector<uint8_t> k = {0x00, 0x11, 0x22, 0x33, 0x44, 0x55,
                                         0x66, 0x77, 0x88, 0x99, 0xaa, 0xbb,
                                         0xcc, 0xdd, 0xee, 0xff};
  return k;
}

struct World {
  explicit World(bool keyed) {
    CubeDeps deps;
    deps.clock = &clock;
    deps.motors = &motors;
    deps.random = &random;
    deps.led = &led;
    deps.mac = &mac;
    cube = new Cube(deps, "cube-fuzz");
    // keyless is the board's explicit opt-out (CUBE_ALLOW_UNAUTHENTICATED); a
    // Cube given neither would refuse all but stop and estop
    if (keyed) {
      cube->SetKey(FuzzKey().data(), FuzzKey().size());
    } else {
      cube->AllowUnauthenticated();
    }
  }
  ~World() { delete cube; }
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Lets `ms` of time pass: the step interrupt every 250 us, Poll every ms.
  void Run(uint64_t ms) {
    for (uint64_t i = 0; i < ms; ++i) {
      for (int t = 0; t < 4; ++t) {
        clock.now_us += 250;
        cube->Tick();
      }
      cube->Poll();
    }
  }

  FuzzClock clock;
  CountingMotors motors;
  FixedRandom random;
  QuietLed led;
  MbedtlsMac mac;
  Cube* cube = nullptr;
};

// Everything observable through the core's read-only views. `motion` holds
// the parts an emergency stop may change; `rest` everything else.
struct Digest {
  std::string motion;
  std::string rest;
};

inline Digest Observe(const Cube& c) {
  char buf[512];
  Digest d;
  const MotionReport& m = c.motion_report();
  std::snprintf(buf, sizeof(buf),
                "estop=%d trips=%u trip=%s/%s running=%d coils=%d move=%u "
                "vel=%d planned=%lld,%lld sps=%lld,%lld speed=%.17g "
                "dur=%lld done=%lld,%lld outcome=%d",
                c.estopped(), c.trips(), c.last_trip().reason,
                c.last_trip().detail, c.running(), c.coils_on(), m.move_id,
                m.velocity, static_cast<long long>(m.planned_left),
                static_cast<long long>(m.planned_right),
                static_cast<long long>(m.left_sps),
                static_cast<long long>(m.right_sps), m.speed,
                static_cast<long long>(m.duration_us),
                static_cast<long long>(m.done_left),
                static_cast<long long>(m.done_right),
                static_cast<int>(m.outcome));
  d.motion = buf;
  const CubeConfig& k = c.config();
  std::snprintf(
      buf, sizeof(buf),
      "pos=%lld,%lld pose=%.17g,%.17g,%.17g sid=%u led=%u,%u,%u,%d "
      "geo=%.17g,%.17g,%.17g max=%lld acc=%lld timeout=%lld",
      static_cast<long long>(c.left_position()),
      static_cast<long long>(c.right_position()), c.pose().x_cm,
      c.pose().y_cm, c.pose().heading_rad, c.session_id(), c.led().r,
      c.led().g, c.led().b, static_cast<int>(c.led().pattern),
      k.geometry.steps_per_revolution, k.geometry.wheel_diameter_cm,
      k.geometry.wheel_base_cm, static_cast<long long>(k.max_speed_sps),
      static_cast<long long>(k.accel_sps2),
      static_cast<long long>(k.host_timeout_ms));
  d.rest = buf;
  return d;
}

}  // namespace cube::fuzz

#endif  // CUBE_FUZZ_CUBE_WORLD_H_
