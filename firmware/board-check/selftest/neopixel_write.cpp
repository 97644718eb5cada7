// Must NOT compile under the board check's flags: the pinned core (3.0.7)
// deprecates neopixelWrite, renamed rgbLedWrite in 3.0.5. ctest's
// BoardCheck.RefusesNeopixelWriteOn307 expects the error.
#include <Arduino.h>

void Green() { neopixelWrite(RGB_BUILTIN, 0, 16, 0); }
