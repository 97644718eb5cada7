// Declarations for a signature check (see Arduino.h): mirrors
// libraries/WiFi/src/WiFiUdp.h of espressif/arduino-esp32 3.0.7, where
// WiFiUDP is the WiFi name of the Network library's NetworkUDP.
#ifndef BOARD_CHECK_WIFIUDP_H_
#define BOARD_CHECK_WIFIUDP_H_
#include "NetworkUdp.h"
typedef NetworkUDP WiFiUDP;
#endif  // BOARD_CHECK_WIFIUDP_H_
