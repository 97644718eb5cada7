// Must NOT compile against the declarations: the Arduino-ESP32 2.x timer
// API (timerBegin(num, divider, countUp), timerAlarmWrite), which 3.x
// replaced. ctest's BoardCheck.RefusesThe2xTimerApi expects this error, so
// the declarations stay those of the pinned 3.x core.
#include <Arduino.h>

void OldTimer() {
  hw_timer_t* timer = timerBegin(0, 80, true);
  timerAlarmWrite(timer, 50, true);
}
