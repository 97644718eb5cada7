// Declarations for a signature check (see Arduino.h): mirrors PSTR of
// cores/esp32/pgmspace.h of espressif/arduino-esp32 3.0.7. On the ESP32,
// flash and RAM share one address space, so PSTR is the string itself.
#ifndef BOARD_CHECK_PGMSPACE_H_
#define BOARD_CHECK_PGMSPACE_H_
#define PGM_P const char *
#define PSTR(s) (s)
#endif  // BOARD_CHECK_PGMSPACE_H_
