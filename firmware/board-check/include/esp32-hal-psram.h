// Declarations for a signature check (see Arduino.h): mirrors
// cores/esp32/esp32-hal-psram.h of espressif/arduino-esp32 3.0.7.
#ifndef BOARD_CHECK_ESP32_HAL_PSRAM_H_
#define BOARD_CHECK_ESP32_HAL_PSRAM_H_
#include <stdbool.h>
extern "C" {
bool psramFound();
}
#endif  // BOARD_CHECK_ESP32_HAL_PSRAM_H_
