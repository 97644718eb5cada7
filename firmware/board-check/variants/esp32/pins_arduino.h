// Declarations for a signature check (see include/Arduino.h): the core's
// esp32 variant, which the AI-Thinker ESP32-CAM board uses.
#ifndef BOARD_CHECK_PINS_ARDUINO_H_
#define BOARD_CHECK_PINS_ARDUINO_H_
#include <stdint.h>
#define SOC_GPIO_PIN_COUNT 40
#endif  // BOARD_CHECK_PINS_ARDUINO_H_
