// Declarations for a signature check (see Arduino.h): mirrors ESP-IDF 5.1
// components/esp_wifi/include/esp_wifi_types.h (espressif/esp32-arduino-libs,
// <chip>/include/esp_wifi/include/esp_wifi_types.h): the WiFi mode and
// power-save enums the WiFi library's API takes.
#ifndef BOARD_CHECK_ESP_WIFI_TYPES_H_
#define BOARD_CHECK_ESP_WIFI_TYPES_H_
extern "C" {
typedef enum {
  WIFI_MODE_NULL = 0,
  WIFI_MODE_STA,
  WIFI_MODE_AP,
  WIFI_MODE_APSTA,
  WIFI_MODE_NAN,
  WIFI_MODE_MAX
} wifi_mode_t;
typedef enum {
  WIFI_PS_NONE,
  WIFI_PS_MIN_MODEM,
  WIFI_PS_MAX_MODEM,
} wifi_ps_type_t;
}
#endif  // BOARD_CHECK_ESP_WIFI_TYPES_H_
