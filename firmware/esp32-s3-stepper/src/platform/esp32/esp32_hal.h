// The ESP32-S3 implementations of the core's hardware interfaces.
// Compiled by arduino-cli only (the host build compiles src/core alone).
#ifndef CUBE_PLATFORM_ESP32_ESP32_HAL_H_
#define CUBE_PLATFORM_ESP32_ESP32_HAL_H_

#if defined(ARDUINO_ARCH_ESP32)

#include "../../core/frame.h"
#include "../../core/hal.h"

namespace cube {

// esp_timer_get_time(): microseconds since boot, safe in an interrupt.
class Esp32Clock : public Clock {
 public:
  uint64_t NowUs() override;
};

// Writes coil patterns straight to the GPIO set/clear registers (all eight
// pins are below GPIO32), so it is short enough for the step interrupt.
class Esp32Motors : public MotorDriver {
 public:
  void Begin();
  void WriteCoils(Wheel wheel, uint8_t pattern) override;

 private:
  uint32_t masks_[2][4] = {};
  uint32_t all_[2] = {0, 0};
};

// The onboard WS2812.
class Esp32Led : public StatusLed {
 public:
  void SetRgb(uint8_t r, uint8_t g, uint8_t b) override;
};

// The ESP-IDF task watchdog, subscribed by the task that calls Begin().
class Esp32Watchdog : public Watchdog {
 public:
  void Begin(uint32_t timeout_ms);
  void Feed() override;
};

// The hardware random number generator (esp_random()).
class Esp32Random : public RandomSource {
 public:
  uint32_t NextU32() override;
};

// HMAC-SHA256 by the mbedtls that ships with the ESP32 Arduino core.
class Esp32Mac : public MacProvider {
 public:
  bool HmacSha256(const uint8_t* key, size_t key_len, const uint8_t* data,
                  size_t len, uint8_t* out) override;
};

// Writes frames to the serial port.
class SerialSink : public ByteSink {
 public:
  void Write(const uint8_t* data, size_t len) override;
};

}  // namespace cube

#endif  // ARDUINO_ARCH_ESP32
#endif  // CUBE_PLATFORM_ESP32_ESP32_HAL_H_
