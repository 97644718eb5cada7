// Declarations for a signature check (see Arduino.h): mirrors
// cores/esp32/Stream.h of espressif/arduino-esp32 3.0.7. Only available(),
// read() and peek() are virtual: readBytes is a plain member, so a
// subclass's readBytes hides it rather than overriding it, and a call
// through a Stream& reaches Stream's own.
#ifndef BOARD_CHECK_STREAM_H_
#define BOARD_CHECK_STREAM_H_
#include <stddef.h>
#include <stdint.h>

#include "Print.h"
#include "WString.h"

enum LookaheadMode { SKIP_ALL, SKIP_NONE, SKIP_WHITESPACE };

class Stream : public Print {
 public:
  virtual int available() = 0;
  virtual int read() = 0;
  virtual int peek() = 0;
  Stream();
  void setTimeout(unsigned long timeout);
  unsigned long getTimeout(void);
  bool find(const char *target);
  bool find(const char *target, size_t length);
  long parseInt(LookaheadMode lookahead = SKIP_ALL, char ignore = '\x01');
  float parseFloat(LookaheadMode lookahead = SKIP_ALL, char ignore = '\x01');
  size_t readBytes(char *buffer, size_t length);
  size_t readBytes(uint8_t *buffer, size_t length);
  size_t readBytesUntil(char terminator, char *buffer, size_t length);
  size_t readBytesUntil(char terminator, uint8_t *buffer, size_t length);
  String readString();
  String readStringUntil(char terminator);
};
#endif  // BOARD_CHECK_STREAM_H_
