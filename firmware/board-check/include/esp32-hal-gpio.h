// Declarations for a signature check (see Arduino.h): mirrors
// cores/esp32/esp32-hal-gpio.h of espressif/arduino-esp32 3.0.7.
#ifndef BOARD_CHECK_ESP32_HAL_GPIO_H_
#define BOARD_CHECK_ESP32_HAL_GPIO_H_
#include <stdint.h>

extern "C" {
#define LOW 0x0
#define HIGH 0x1
#define INPUT 0x01
#define OUTPUT 0x03
#define PULLUP 0x04
#define INPUT_PULLUP 0x05
#define PULLDOWN 0x08
#define INPUT_PULLDOWN 0x09
void pinMode(uint8_t pin, uint8_t mode);
void digitalWrite(uint8_t pin, uint8_t val);
int digitalRead(uint8_t pin);
}
#endif  // BOARD_CHECK_ESP32_HAL_GPIO_H_
