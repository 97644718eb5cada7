// Declarations for a signature check (see Arduino.h): mirrors ESP-IDF 5.1
// components/esp_common/include/esp_attr.h (espressif/esp32-arduino-libs,
// <chip>/include/esp_common/include/esp_attr.h). On the chip IRAM_ATTR and
// DRAM_ATTR name linker sections; the check links nothing, so they are
// empty here.
#ifndef BOARD_CHECK_ESP_ATTR_H_
#define BOARD_CHECK_ESP_ATTR_H_
#define IRAM_ATTR
#define DRAM_ATTR
#endif  // BOARD_CHECK_ESP_ATTR_H_
