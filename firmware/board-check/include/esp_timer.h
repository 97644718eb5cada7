// Declarations for a signature check (see Arduino.h): ESP-IDF 5.1 esp_timer.h.
#ifndef BOARD_CHECK_ESP_TIMER_H_
#define BOARD_CHECK_ESP_TIMER_H_
#include <stdint.h>
extern "C" int64_t esp_timer_get_time(void);
#endif  // BOARD_CHECK_ESP_TIMER_H_
