// Copy this file to board_options.h (same folder; it is not committed) to
// change what differs between boards. Without board_options.h the firmware
// builds for an ESP32-S3-DevKitC-1 v1.0. See docs/hardware.md.
#ifndef CUBE_BOARD_OPTIONS_H_
#define CUBE_BOARD_OPTIONS_H_

// The onboard WS2812 RGB LED: GPIO48 on DevKitC-1 v1.0 (the default), GPIO38
// on v1.1 (the revision is printed on the board, beside the antenna).
// #define CUBE_RGB_LED_PIN 38

#endif  // CUBE_BOARD_OPTIONS_H_
