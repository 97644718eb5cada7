// ESP32-S3-DevKitC-1 wiring of the V1 stepper cube (docs/hardware.md).
#ifndef CUBE_PLATFORM_ESP32_BOARD_H_
#define CUBE_PLATFORM_ESP32_BOARD_H_

#include <cstdint>

namespace cube::board {

// ULN2003 IN1..IN4 of each 28BYJ-48.
constexpr uint8_t kLeftPins[4] = {4, 5, 6, 7};
constexpr uint8_t kRightPins[4] = {15, 16, 17, 18};

// Onboard WS2812 RGB LED: GPIO48 on DevKitC-1 v1.0, GPIO38 on v1.1. The
// Arduino core's RGB_BUILTIN wins when the board variant defines it.
constexpr uint8_t kRgbLedPinDefault = 48;

constexpr uint16_t kUdpPort = 4210;
constexpr uint32_t kSerialBaud = 115200;
// Step interrupt: 20 kHz, so a step is at most 50 us late.
constexpr uint32_t kStepTimerHz = 1000000;
constexpr uint32_t kStepTickUs = 50;
// Hardware task watchdog for the cube task.
constexpr uint32_t kWatchdogMs = 1000;

}  // namespace cube::board

#endif  // CUBE_PLATFORM_ESP32_BOARD_H_
