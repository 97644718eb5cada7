// Declarations for a signature check (see Arduino.h): mirrors
// cores/esp32/Client.h of espressif/arduino-esp32 3.0.7.
#ifndef BOARD_CHECK_CLIENT_H_
#define BOARD_CHECK_CLIENT_H_
#include <stddef.h>
#include <stdint.h>

#include "IPAddress.h"
#include "Print.h"
#include "Stream.h"

class Client : public Stream {
 public:
  virtual int connect(IPAddress ip, uint16_t port) = 0;
  virtual int connect(const char *host, uint16_t port) = 0;
  virtual size_t write(uint8_t) = 0;
  virtual size_t write(const uint8_t *buf, size_t size) = 0;
  virtual int available() = 0;
  virtual int read() = 0;
  virtual int read(uint8_t *buf, size_t size) = 0;
  virtual int peek() = 0;
  virtual void flush() = 0;
  virtual void stop() = 0;
  virtual uint8_t connected() = 0;
  virtual operator bool() = 0;
};
#endif  // BOARD_CHECK_CLIENT_H_
