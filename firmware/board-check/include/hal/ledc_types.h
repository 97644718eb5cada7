// Declarations for a signature check (see Arduino.h): mirrors the timer and
// channel enums of ESP-IDF 5.1 components/hal/include/hal/ledc_types.h
// (espressif/esp32-arduino-libs, <chip>/include/hal/include/hal/
// ledc_types.h), which the camera's XCLK configuration takes.
#ifndef BOARD_CHECK_HAL_LEDC_TYPES_H_
#define BOARD_CHECK_HAL_LEDC_TYPES_H_
#include "soc/soc_caps.h"
extern "C" {
typedef enum {
  LEDC_TIMER_0 = 0,
  LEDC_TIMER_1,
  LEDC_TIMER_2,
  LEDC_TIMER_3,
  LEDC_TIMER_MAX,
} ledc_timer_t;
typedef enum {
  LEDC_CHANNEL_0 = 0,
  LEDC_CHANNEL_1,
  LEDC_CHANNEL_2,
  LEDC_CHANNEL_3,
  LEDC_CHANNEL_4,
  LEDC_CHANNEL_5,
#if SOC_LEDC_CHANNEL_NUM > 6
  LEDC_CHANNEL_6,
  LEDC_CHANNEL_7,
#endif
  LEDC_CHANNEL_MAX,
} ledc_channel_t;
}
#endif  // BOARD_CHECK_HAL_LEDC_TYPES_H_
