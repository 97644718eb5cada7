// Declarations for a signature check (see include/Arduino.h): mirrors
// variants/esp32/pins_arduino.h of espressif/arduino-esp32 3.0.7, the
// esp32 variant the AI-Thinker ESP32-CAM board uses (no LED_BUILTIN).
#ifndef BOARD_CHECK_PINS_ARDUINO_H_
#define BOARD_CHECK_PINS_ARDUINO_H_
#include <stdint.h>

static const uint8_t TX = 1;
static const uint8_t RX = 3;
static const uint8_t SDA = 21;
static const uint8_t SCL = 22;
#endif  // BOARD_CHECK_PINS_ARDUINO_H_
