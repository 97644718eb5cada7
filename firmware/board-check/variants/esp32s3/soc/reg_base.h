// Declarations for a signature check (see include/Arduino.h): mirrors the
// GPIO base address of ESP-IDF 5.1 components/soc/esp32s3/include/soc/
// reg_base.h (espressif/esp32-arduino-libs, esp32s3/include/soc/esp32s3/
// include/soc/reg_base.h).
#ifndef BOARD_CHECK_SOC_REG_BASE_H_
#define BOARD_CHECK_SOC_REG_BASE_H_
#define DR_REG_GPIO_BASE 0x60004000
#endif  // BOARD_CHECK_SOC_REG_BASE_H_
