// Declarations for a signature check (see Arduino.h): mirrors ESP-IDF 5.1
// components/esp_common/include/esp_err.h (espressif/esp32-arduino-libs,
// <chip>/include/esp_common/include/esp_err.h), the codes the sketches test.
#ifndef BOARD_CHECK_ESP_ERR_H_
#define BOARD_CHECK_ESP_ERR_H_
extern "C" {
typedef int esp_err_t;
#define ESP_OK 0
#define ESP_FAIL -1
#define ESP_ERR_NO_MEM 0x101
#define ESP_ERR_INVALID_ARG 0x102
#define ESP_ERR_INVALID_STATE 0x103
}
#endif  // BOARD_CHECK_ESP_ERR_H_
