// ESP32-S3-DevKitC-1 wiring of the V1 stepper cube (docs/hardware.md).
#ifndef CUBE_PLATFORM_ESP32_BOARD_H_
#define CUBE_PLATFORM_ESP32_BOARD_H_

#include <cstdint>

// A maker's board options, optional and untracked: src/board_options.h (copy
// board_options.example.h), e.g. `#define CUBE_RGB_LED_PIN 38` for a v1.1 board.
#if __has_include("../../board_options.h")
#include "../../board_options.h"
#endif

namespace cube::board {

// ULN2003 IN1..IN4 of each 28BYJ-48.
constexpr uint8_t kLeftPins[4] = {4, 5, 6, 7};
constexpr uint8_t kRightPins[4] = {15, 16, 17, 18};

// Onboard WS2812 RGB LED: GPIO48 on DevKitC-1 v1.0, GPIO38 on v1.1. The
// Arduino core's ESP32-S3 variant names GPIO48 (RGB_BUILTIN) whatever the
// board revision, so a v1.1 board sets CUBE_RGB_LED_PIN 38 in board_options.h.
// Without it: RGB_BUILTIN when the variant defines it, else GPIO48.
#if defined(CUBE_RGB_LED_PIN)
constexpr bool kRgbLedPinSet = true;
constexpr uint8_t kRgbLedPin = CUBE_RGB_LED_PIN;
static_assert(CUBE_RGB_LED_PIN >= 0 && CUBE_RGB_LED_PIN <= 48,
              "CUBE_RGB_LED_PIN is an ESP32-S3 GPIO, 0..48 (38 or 48 on a DevKitC-1)");
static_assert(CUBE_RGB_LED_PIN != 4 && CUBE_RGB_LED_PIN != 5 && CUBE_RGB_LED_PIN != 6 &&
                  CUBE_RGB_LED_PIN != 7 && CUBE_RGB_LED_PIN != 15 && CUBE_RGB_LED_PIN != 16 &&
                  CUBE_RGB_LED_PIN != 17 && CUBE_RGB_LED_PIN != 18,
              "CUBE_RGB_LED_PIN is one of the motor pins (GPIO4-7, GPIO15-18)");
#else
constexpr bool kRgbLedPinSet = false;
constexpr uint8_t kRgbLedPin = 48;
#endif

constexpr uint16_t kUdpPort = 4210;
constexpr uint32_t kSerialBaud = 115200;
// Step interrupt: 20 kHz, so a step is at most 50 us late.
constexpr uint32_t kStepTimerHz = 1000000;
constexpr uint32_t kStepTickUs = 50;
// Hardware task watchdog for the cube task.
constexpr uint32_t kWatchdogMs = 1000;

}  // namespace cube::board

#endif  // CUBE_PLATFORM_ESP32_BOARD_H_
