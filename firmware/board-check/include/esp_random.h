// Declarations for a signature check (see Arduino.h): mirrors ESP-IDF 5.1
// components/esp_hw_support/include/esp_random.h (espressif/esp32-arduino-
// libs, <chip>/include/esp_hw_support/include/esp_random.h).
#ifndef BOARD_CHECK_ESP_RANDOM_H_
#define BOARD_CHECK_ESP_RANDOM_H_
#include <stddef.h>
#include <stdint.h>
extern "C" {
uint32_t esp_random(void);
void esp_fill_random(void *buf, size_t len);
}
#endif  // BOARD_CHECK_ESP_RANDOM_H_
