// Declarations for a signature check (see Arduino.h): mirrors
// cores/esp32/esp32-hal-timer.h of espressif/arduino-esp32 3.0.7, the 3.x
// timer API: a timer counts at `frequency` Hz. The 2.x calls
// (timerBegin(num, divider, countUp), timerAlarmWrite) do not exist in 3.x,
// so they are not declared (selftest/old_timer_api.cpp).
#ifndef BOARD_CHECK_ESP32_HAL_TIMER_H_
#define BOARD_CHECK_ESP32_HAL_TIMER_H_
#include <stdbool.h>
#include <stdint.h>
extern "C" {
struct timer_struct_t;
typedef struct timer_struct_t hw_timer_t;
hw_timer_t *timerBegin(uint32_t frequency);
void timerEnd(hw_timer_t *timer);
void timerStart(hw_timer_t *timer);
void timerStop(hw_timer_t *timer);
void timerRestart(hw_timer_t *timer);
void timerWrite(hw_timer_t *timer, uint64_t val);
uint64_t timerRead(hw_timer_t *timer);
uint32_t timerGetFrequency(hw_timer_t *timer);
void timerAttachInterrupt(hw_timer_t *timer, void (*userFunc)(void));
void timerAttachInterruptArg(hw_timer_t *timer, void (*userFunc)(void *),
                             void *arg);
void timerDetachInterrupt(hw_timer_t *timer);
void timerAlarm(hw_timer_t *timer, uint64_t alarm_value, bool autoreload,
                uint64_t reload_count);
}
#endif  // BOARD_CHECK_ESP32_HAL_TIMER_H_
