// Declarations for a signature check, not the Arduino-ESP32 core.
//
// firmware/board-check/ holds our own declarations (no definitions, no
// behaviour) of the Arduino-ESP32 core APIs the board sketches use. Each file
// stands for one real header of the pinned core, esp32:esp32 3.0.7, and its
// first comment names that header: a path in espressif/arduino-esp32 (the
// core), espressif/esp32-camera, or the ESP-IDF 5.1 headers the core ships
// (espressif/esp32-arduino-libs, <chip>/include/...). Every declaration has
// the real one's signature, default arguments, virtual or not, static or
// member, and attributes, deprecations included, so that the check refuses
// what the real core would refuse under the project's strict flags. Only
// the names the sketches can reach are declared; nothing is copied from the
// real headers. docs/firmware.md says what was read and how to refresh it.
//
// The firmware's test command compiles every board source against them with
// -fsyntax-only and the project's warnings (scripts/board-check.sh). Nothing
// here is linked or run; it is not a build for the chip.
//
// This file mirrors cores/esp32/Arduino.h of espressif/arduino-esp32 3.0.7:
// the C library headers it includes, then the HAL and the C++ classes.
#ifndef BOARD_CHECK_ARDUINO_H_
#define BOARD_CHECK_ARDUINO_H_

#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "esp_arduino_version.h"
#include "esp32-hal.h"
#include "freertos/FreeRTOS.h"
#include "freertos/task.h"
#include "pins_arduino.h"

#include "Esp.h"
#include "HardwareSerial.h"
#include "IPAddress.h"
#include "Print.h"
#include "Stream.h"
#include "WString.h"

#endif  // BOARD_CHECK_ARDUINO_H_
