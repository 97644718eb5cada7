// Declarations for a signature check (see Arduino.h): mirrors
// libraries/WiFi/src/WiFiType.h of espressif/arduino-esp32 3.0.7.
#ifndef BOARD_CHECK_WIFITYPE_H_
#define BOARD_CHECK_WIFITYPE_H_
#include "esp_wifi_types.h"
#include "soc/soc_caps.h"

#define WiFiMode_t wifi_mode_t
#define WIFI_OFF WIFI_MODE_NULL
#define WIFI_STA WIFI_MODE_STA
#define WIFI_AP WIFI_MODE_AP
#define WIFI_AP_STA WIFI_MODE_APSTA

typedef enum {
  WL_NO_SHIELD = 255,
  WL_STOPPED = 254,
  WL_IDLE_STATUS = 0,
  WL_NO_SSID_AVAIL = 1,
  WL_SCAN_COMPLETED = 2,
  WL_CONNECTED = 3,
  WL_CONNECT_FAILED = 4,
  WL_CONNECTION_LOST = 5,
  WL_DISCONNECTED = 6
} wl_status_t;
#endif  // BOARD_CHECK_WIFITYPE_H_
