// Declarations for a signature check (see Arduino.h). On the chip IRAM_ATTR
// places a function in instruction RAM; here it only has to parse.
#ifndef BOARD_CHECK_ESP_ATTR_H_
#define BOARD_CHECK_ESP_ATTR_H_
#define IRAM_ATTR
#define DRAM_ATTR
#endif  // BOARD_CHECK_ESP_ATTR_H_
