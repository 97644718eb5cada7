// Declarations for a signature check, not the Arduino-ESP32 core.
//
// firmware/board-check/ holds declarations (no definitions, no behaviour) of
// exactly the Arduino-ESP32 3.0.7 and ESP-IDF 5.1 APIs the board sketches
// use, with the signatures the core's documentation and headers give. The
// firmware's test command compiles every board source against them with
// -fsyntax-only and the project's warnings (scripts/board-check.sh), so a
// typo, a wrong argument or a narrowing conversion in the board code fails
// on the host. Nothing here is linked or run; it is not a build for the chip.
// When a sketch needs another core API, declare it here as the core does.
#ifndef BOARD_CHECK_ARDUINO_H_
#define BOARD_CHECK_ARDUINO_H_

#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "esp_arduino_version.h"
#include "esp_attr.h"
#include "esp_err.h"
#include "freertos/FreeRTOS.h"
#include "freertos/task.h"
#include "pins_arduino.h"

// esp32-hal.h: ISR functions go to IRAM when CONFIG_ARDUINO_ISR_IRAM is set.
#define ARDUINO_ISR_ATTR IRAM_ATTR

// The esp32-hal-*.h functions have C linkage.
extern "C" {

// esp32-hal-gpio.h
#define LOW 0x0
#define HIGH 0x1
#define INPUT 0x01
#define OUTPUT 0x03
#define INPUT_PULLUP 0x05
void pinMode(uint8_t pin, uint8_t mode);
void digitalWrite(uint8_t pin, uint8_t val);
int digitalRead(uint8_t pin);

// esp32-hal-misc.c / esp32-hal.h
unsigned long micros();
unsigned long millis();
void delay(uint32_t ms);
void delayMicroseconds(uint32_t us);

// esp32-hal-psram.h
bool psramFound();

// esp32-hal-rgb-led.h (3.x; neopixelWrite is its deprecated 2.x name)
void rgbLedWrite(uint8_t pin, uint8_t red_val, uint8_t green_val,
                 uint8_t blue_val);

// esp32-hal-timer.h, the 3.x timer API: a timer counts at `frequency` Hz.
struct timer_struct_t;
typedef struct timer_struct_t hw_timer_t;
hw_timer_t* timerBegin(uint32_t frequency);
void timerEnd(hw_timer_t* timer);
void timerAttachInterrupt(hw_timer_t* timer, void (*userFunc)(void));
void timerAttachInterruptArg(hw_timer_t* timer, void (*userFunc)(void*),
                             void* arg);
void timerDetachInterrupt(hw_timer_t* timer);
void timerAlarm(hw_timer_t* timer, uint64_t alarm_value, bool autoreload,
                uint64_t reload_count);

}  // extern "C"

#include "Esp.h"
#include "HardwareSerial.h"
#include "IPAddress.h"
#include "Print.h"
#include "Stream.h"
#include "WString.h"

#endif  // BOARD_CHECK_ARDUINO_H_
