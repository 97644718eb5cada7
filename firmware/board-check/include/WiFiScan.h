// Declarations for a signature check (see Arduino.h): mirrors
// libraries/WiFi/src/WiFiScan.h of espressif/arduino-esp32 3.0.7; its
// RSSI(networkItem) is the overload WiFi.RSSI() is chosen against.
#ifndef BOARD_CHECK_WIFISCAN_H_
#define BOARD_CHECK_WIFISCAN_H_
#include <stdint.h>

#include "WiFiType.h"

class WiFiScanClass {
 public:
  int16_t scanComplete();
  void scanDelete();
  int32_t RSSI(uint8_t networkItem);
};
#endif  // BOARD_CHECK_WIFISCAN_H_
