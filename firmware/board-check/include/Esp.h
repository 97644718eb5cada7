// Declarations for a signature check (see Arduino.h): mirrors
// cores/esp32/Esp.h of espressif/arduino-esp32 3.0.7 (EspClass, `ESP`),
// the members the sketches call.
#ifndef BOARD_CHECK_ESP_H_
#define BOARD_CHECK_ESP_H_
#include <stdint.h>
class EspClass {
 public:
  EspClass();
  ~EspClass();
  void restart();
  uint32_t getHeapSize();
  uint32_t getFreeHeap();
  uint32_t getMinFreeHeap();
  uint32_t getMaxAllocHeap();
  uint32_t getPsramSize();
  uint32_t getFreePsram();
  uint64_t getEfuseMac();
};
extern EspClass ESP;
#endif  // BOARD_CHECK_ESP_H_
