// Declarations for a signature check (see Arduino.h): mirrors ESP-IDF 5.1
// components/esp_timer/include/esp_timer.h (espressif/esp32-arduino-libs,
// <chip>/include/esp_timer/include/esp_timer.h), the one call used.
#ifndef BOARD_CHECK_ESP_TIMER_H_
#define BOARD_CHECK_ESP_TIMER_H_
#include <stdint.h>
extern "C" {
int64_t esp_timer_get_time(void);
}
#endif  // BOARD_CHECK_ESP_TIMER_H_
