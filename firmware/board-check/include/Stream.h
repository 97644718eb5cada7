// Declarations for a signature check (see Arduino.h): Arduino Stream.
#ifndef BOARD_CHECK_STREAM_H_
#define BOARD_CHECK_STREAM_H_
#include "Print.h"
#include "WString.h"

class Stream : public Print {
 public:
  virtual int available() = 0;
  virtual int read() = 0;
  virtual int peek() = 0;
  void setTimeout(unsigned long timeout);
  unsigned long getTimeout(void);
  virtual size_t readBytes(char* buffer, size_t length);
  virtual size_t readBytes(uint8_t* buffer, size_t length);
  String readString();
  String readStringUntil(char terminator);
};
#endif  // BOARD_CHECK_STREAM_H_
