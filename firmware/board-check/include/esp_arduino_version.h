// Declarations for a signature check (see Arduino.h): mirrors
// cores/esp32/esp_arduino_version.h of espressif/arduino-esp32 at the
// pinned release, 3.0.7, with its comparison macros.
#ifndef BOARD_CHECK_ESP_ARDUINO_VERSION_H_
#define BOARD_CHECK_ESP_ARDUINO_VERSION_H_
#define ESP_ARDUINO_VERSION_MAJOR 3
#define ESP_ARDUINO_VERSION_MINOR 0
#define ESP_ARDUINO_VERSION_PATCH 7
#define ESP_ARDUINO_VERSION_VAL(major, minor, patch) \
  ((major << 16) | (minor << 8) | (patch))
#define ESP_ARDUINO_VERSION                                \
  ESP_ARDUINO_VERSION_VAL(ESP_ARDUINO_VERSION_MAJOR,       \
                          ESP_ARDUINO_VERSION_MINOR,       \
                          ESP_ARDUINO_VERSION_PATCH)
#endif  // BOARD_CHECK_ESP_ARDUINO_VERSION_H_
