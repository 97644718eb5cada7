// Declarations for a signature check (see Arduino.h): mirrors
// libraries/WiFi/src/WiFiGeneric.h of espressif/arduino-esp32 3.0.7.
// persistent() is a member; mode() and getMode() are static.
#ifndef BOARD_CHECK_WIFIGENERIC_H_
#define BOARD_CHECK_WIFIGENERIC_H_
#include <stdint.h>

#include "WiFiType.h"

class WiFiGenericClass {
 public:
  WiFiGenericClass();
  int32_t channel(void);
  void persistent(bool persistent);
  void enableLongRange(bool enable);
  static bool mode(wifi_mode_t);
  static wifi_mode_t getMode();
  bool enableSTA(bool enable);
  bool enableAP(bool enable);
  bool setSleep(bool enabled);
  bool setSleep(wifi_ps_type_t sleepType);
  wifi_ps_type_t getSleep();
  static const char *getHostname();
  static bool setHostname(const char *hostname);
};
#endif  // BOARD_CHECK_WIFIGENERIC_H_
