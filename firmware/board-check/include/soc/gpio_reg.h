// Declarations for a signature check (see Arduino.h): the ESP32-S3 GPIO
// output set/clear registers and ESP-IDF's REG_WRITE (soc/soc.h). The
// address goes through uintptr_t so the host's 64-bit pointers accept it.
#ifndef BOARD_CHECK_SOC_GPIO_REG_H_
#define BOARD_CHECK_SOC_GPIO_REG_H_
#include <stdint.h>
#define DR_REG_GPIO_BASE 0x60004000
#define GPIO_OUT_REG (DR_REG_GPIO_BASE + 0x4)
#define GPIO_OUT_W1TS_REG (DR_REG_GPIO_BASE + 0x8)
#define GPIO_OUT_W1TC_REG (DR_REG_GPIO_BASE + 0xc)
#define REG_WRITE(_r, _v)                         \
  do {                                            \
    (*(volatile uint32_t*)(uintptr_t)(_r)) = (_v); \
  } while (0)
#define REG_READ(_r) (*(volatile uint32_t*)(uintptr_t)(_r))
#endif  // BOARD_CHECK_SOC_GPIO_REG_H_
