// Declarations for a signature check (see Arduino.h): the pinned core 3.0.7.
#ifndef BOARD_CHECK_ESP_ARDUINO_VERSION_H_
#define BOARD_CHECK_ESP_ARDUINO_VERSION_H_
#define ESP_ARDUINO_VERSION_MAJOR 3
#define ESP_ARDUINO_VERSION_MINOR 0
#define ESP_ARDUINO_VERSION_PATCH 7
#endif  // BOARD_CHECK_ESP_ARDUINO_VERSION_H_
