// Declarations for a signature check (see Arduino.h): mirrors
// cores/esp32/esp32-hal.h of espressif/arduino-esp32 3.0.7 (the time
// functions, ARDUINO_ISR_ATTR, and the esp32-hal-*.h it includes that the
// sketches use).
#ifndef BOARD_CHECK_ESP32_HAL_H_
#define BOARD_CHECK_ESP32_HAL_H_
#include <stdbool.h>
#include <stdint.h>

#include "esp_attr.h"
#include "esp_err.h"
#include "sdkconfig.h"

// ISR code goes to IRAM only when the core is configured so; the 3.0.7
// libraries' sdkconfig leaves CONFIG_ARDUINO_ISR_IRAM unset.
#if CONFIG_ARDUINO_ISR_IRAM
#define ARDUINO_ISR_ATTR IRAM_ATTR
#else
#define ARDUINO_ISR_ATTR
#endif

extern "C" {
void yield(void);
unsigned long micros();
unsigned long millis();
void delay(uint32_t);
void delayMicroseconds(uint32_t us);
}

#include "esp32-hal-gpio.h"
#include "esp32-hal-psram.h"
#include "esp32-hal-rgb-led.h"
#include "esp32-hal-timer.h"

#endif  // BOARD_CHECK_ESP32_HAL_H_
