// Declarations for a signature check (see include/Arduino.h): the core's
// esp32s3 variant (ESP32-S3-DevKitC-1), the RGB LED on GPIO48.
#ifndef BOARD_CHECK_PINS_ARDUINO_H_
#define BOARD_CHECK_PINS_ARDUINO_H_
#include <stdint.h>
#define SOC_GPIO_PIN_COUNT 49
#define PIN_RGB_LED 48
// The core's RGB LED pins are numbered above the GPIOs; rgbLedWrite maps back.
#define RGB_BUILTIN (SOC_GPIO_PIN_COUNT + PIN_RGB_LED)
#define LED_BUILTIN RGB_BUILTIN
#endif  // BOARD_CHECK_PINS_ARDUINO_H_
