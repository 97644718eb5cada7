// Declarations for a signature check (see include/Arduino.h): mirrors
// variants/esp32s3/pins_arduino.h of espressif/arduino-esp32 3.0.7, the
// ESP32-S3-DevKitC-1 variant. The RGB LED's pin is numbered above the
// GPIOs (SOC_GPIO_PIN_COUNT + 48), which the core maps back to GPIO48;
// LED_BUILTIN is a constant that a macro of the same name makes testable
// with #ifdef, and RGB_BUILTIN names it.
#ifndef BOARD_CHECK_PINS_ARDUINO_H_
#define BOARD_CHECK_PINS_ARDUINO_H_
#include <stdint.h>

#include "soc/soc_caps.h"

#define PIN_RGB_LED 48
static const uint8_t LED_BUILTIN = SOC_GPIO_PIN_COUNT + PIN_RGB_LED;
#define BUILTIN_LED LED_BUILTIN
#define LED_BUILTIN LED_BUILTIN
#define RGB_BUILTIN LED_BUILTIN
#define RGB_BRIGHTNESS 64

static const uint8_t TX = 43;
static const uint8_t RX = 44;
static const uint8_t SDA = 8;
static const uint8_t SCL = 9;
#endif  // BOARD_CHECK_PINS_ARDUINO_H_
