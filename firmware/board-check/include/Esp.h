// Declarations for a signature check (see Arduino.h): EspClass, `ESP`.
#ifndef BOARD_CHECK_ESP_H_
#define BOARD_CHECK_ESP_H_
#include <stdint.h>
class EspClass {
 public:
  void restart();
  uint32_t getFreeHeap();
  uint32_t getFreePsram();
  uint64_t getEfuseMac();
};
extern EspClass ESP;
#endif  // BOARD_CHECK_ESP_H_
