// Declarations for a signature check (see include/Arduino.h): mirrors the
// output set/clear registers of ESP-IDF 5.1 components/soc/esp32s3/include/
// soc/gpio_reg.h (espressif/esp32-arduino-libs, esp32s3/include/soc/
// esp32s3/include/soc/gpio_reg.h), which includes soc.h for REG_WRITE.
#ifndef BOARD_CHECK_SOC_GPIO_REG_H_
#define BOARD_CHECK_SOC_GPIO_REG_H_
#include "soc.h"
#define GPIO_OUT_REG (DR_REG_GPIO_BASE + 0x4)
#define GPIO_OUT_W1TS_REG (DR_REG_GPIO_BASE + 0x8)
#define GPIO_OUT_W1TC_REG (DR_REG_GPIO_BASE + 0xC)
#endif  // BOARD_CHECK_SOC_GPIO_REG_H_
