// Declarations for a signature check (see Arduino.h): mirrors
// cores/esp32/Printable.h of espressif/arduino-esp32 3.0.7.
#ifndef BOARD_CHECK_PRINTABLE_H_
#define BOARD_CHECK_PRINTABLE_H_
#include <stddef.h>

class Print;

class Printable {
 public:
  virtual ~Printable();
  virtual size_t printTo(Print &p) const = 0;
};
#endif  // BOARD_CHECK_PRINTABLE_H_
