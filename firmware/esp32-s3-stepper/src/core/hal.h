// The small hardware interfaces through which the core reaches the board.
// The board glue (src/platform/esp32) and the host build (firmware/host)
// implement them. Each method says in which context it may run.
#ifndef CUBE_CORE_HAL_H_
#define CUBE_CORE_HAL_H_

#include <cstddef>
#include <cstdint>

// Marks the functions that run in the step interrupt. On ESP-IDF builds
// (the Arduino core defines ESP_PLATFORM) they go to IRAM, so the interrupt
// never waits on the flash cache; elsewhere it expands to nothing.
#if defined(ESP_PLATFORM)
#define CUBE_ISR_FN __attribute__((section(".iram1.cube_isr")))
#else
#define CUBE_ISR_FN
#endif

namespace cube {

enum class Wheel : uint8_t { kLeft = 0, kRight = 1 };

// Monotonic microsecond clock. NowUs() may be called from an interrupt.
class Clock {
 public:
  virtual ~Clock() = default;
  virtual uint64_t NowUs() = 0;
};

// The ULN2003 inputs of one 28BYJ-48. WriteCoils() runs in interrupt
// context and must be short: bit 0..3 of `pattern` drive IN1..IN4
// (1 = energised); 0 switches the motor off.
class MotorDriver {
 public:
  virtual ~MotorDriver() = default;
  virtual void WriteCoils(Wheel wheel, uint8_t pattern) = 0;
};

// The status RGB LED. Task context only.
class StatusLed {
 public:
  virtual ~StatusLed() = default;
  virtual void SetRgb(uint8_t r, uint8_t g, uint8_t b) = 0;
};

// Hardware watchdog. Feed() is called from the core's Poll(), task context.
// Optional: without one, nothing is fed.
class Watchdog {
 public:
  virtual ~Watchdog() = default;
  virtual void Feed() = 0;
};

// Source of session ids. Task context. Should be unpredictable (the board
// uses its hardware RNG).
class RandomSource {
 public:
  virtual ~RandomSource() = default;
  virtual uint32_t NextU32() = 0;
};

// HMAC-SHA256, used only when a key is configured. Task context.
class MacProvider {
 public:
  virtual ~MacProvider() = default;
  // Writes the 32-byte HMAC-SHA256(key, data) to `out`; false on failure.
  virtual bool HmacSha256(const uint8_t* key, size_t key_len,
                          const uint8_t* data, size_t len, uint8_t* out) = 0;
};

}  // namespace cube

#endif  // CUBE_CORE_HAL_H_
