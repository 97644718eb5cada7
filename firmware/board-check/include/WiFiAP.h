// Declarations for a signature check (see Arduino.h): mirrors
// libraries/WiFi/src/WiFiAP.h of espressif/arduino-esp32 3.0.7. The
// sketches run as stations only, so none of its members is declared.
#ifndef BOARD_CHECK_WIFIAP_H_
#define BOARD_CHECK_WIFIAP_H_
#include "WiFiType.h"
class WiFiAPClass {};
#endif  // BOARD_CHECK_WIFIAP_H_
