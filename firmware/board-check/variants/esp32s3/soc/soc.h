// Declarations for a signature check (see include/Arduino.h): mirrors
// REG_WRITE and REG_READ of ESP-IDF 5.1 components/soc/esp32s3/include/
// soc/soc.h (espressif/esp32-arduino-libs, esp32s3/include/soc/esp32s3/
// include/soc/soc.h): a volatile 32-bit store and load at the address.
#ifndef BOARD_CHECK_SOC_SOC_H_
#define BOARD_CHECK_SOC_SOC_H_
#include <stdint.h>

#include "reg_base.h"

#define REG_WRITE(_r, _v)               \
  do {                                  \
    (*(volatile uint32_t *)(_r)) = (_v); \
  } while (0)
#define REG_READ(_r) ({ (*(volatile uint32_t *)(_r)); })
#endif  // BOARD_CHECK_SOC_SOC_H_
