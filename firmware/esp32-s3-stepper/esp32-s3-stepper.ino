// V1 stepper cube firmware for the ESP32-S3-DevKitC-1.
//
// All logic (protocol, motion planning, odometry, safety) is the portable
// core in src/core/, the same sources the host build tests and the
// cube-emulator runs. src/platform/esp32/ connects it to the board; see
// docs/firmware.md and docs/flashing.md.

#include "src/platform/esp32/app.h"

void setup() { CubeAppSetup(); }

void loop() { CubeAppLoop(); }
