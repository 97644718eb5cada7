// Declarations for a signature check (see Arduino.h): mirrors
// libraries/WiFi/src/WiFiClient.h of espressif/arduino-esp32 3.0.7.
#ifndef BOARD_CHECK_WIFICLIENT_H_
#define BOARD_CHECK_WIFICLIENT_H_
#include "NetworkClient.h"
typedef NetworkClient WiFiClient;
#endif  // BOARD_CHECK_WIFICLIENT_H_
