// Declarations for a signature check (see Arduino.h): mirrors
// libraries/WiFi/src/WiFiServer.h of espressif/arduino-esp32 3.0.7.
#ifndef BOARD_CHECK_WIFISERVER_H_
#define BOARD_CHECK_WIFISERVER_H_
#include "NetworkServer.h"
typedef NetworkServer WiFiServer;
#endif  // BOARD_CHECK_WIFISERVER_H_
