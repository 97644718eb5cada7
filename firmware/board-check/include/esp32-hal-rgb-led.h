// Declarations for a signature check (see Arduino.h): mirrors
// cores/esp32/esp32-hal-rgb-led.h of espressif/arduino-esp32 3.0.7.
// rgbLedWrite is the 3.0.5 name; neopixelWrite, the only name in 3.0.0 to
// 3.0.4, carries the deprecation 3.0.5 gave it.
#ifndef BOARD_CHECK_ESP32_HAL_RGB_LED_H_
#define BOARD_CHECK_ESP32_HAL_RGB_LED_H_
#include <stdint.h>
extern "C" {
#ifndef RGB_BRIGHTNESS
#define RGB_BRIGHTNESS 64
#endif
#ifndef RGB_BUILTIN_LED_COLOR_ORDER
#define RGB_BUILTIN_LED_COLOR_ORDER LED_COLOR_ORDER_GRB
#endif
typedef enum {
  LED_COLOR_ORDER_RGB,
  LED_COLOR_ORDER_BGR,
  LED_COLOR_ORDER_BRG,
  LED_COLOR_ORDER_RBG,
  LED_COLOR_ORDER_GBR,
  LED_COLOR_ORDER_GRB
} rgb_led_color_order_t;
void rgbLedWriteOrdered(uint8_t pin, rgb_led_color_order_t order,
                        uint8_t red_val, uint8_t green_val, uint8_t blue_val);
void rgbLedWrite(uint8_t pin, uint8_t red_val, uint8_t green_val,
                 uint8_t blue_val);
[[deprecated("Use rgbLedWrite() instead.")]]
void neopixelWrite(uint8_t p, uint8_t r, uint8_t g, uint8_t b);
}
#endif  // BOARD_CHECK_ESP32_HAL_RGB_LED_H_
