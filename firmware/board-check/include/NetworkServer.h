// Declarations for a signature check (see Arduino.h): mirrors
// libraries/Network/src/NetworkServer.h of espressif/arduino-esp32 3.0.7.
// In 3.x it derives from nothing, and available() is deprecated in favour
// of accept().
#ifndef BOARD_CHECK_NETWORKSERVER_H_
#define BOARD_CHECK_NETWORKSERVER_H_
#include <stdint.h>

#include "Arduino.h"
#include "IPAddress.h"
#include "NetworkClient.h"

class NetworkServer {
 public:
  NetworkServer(uint16_t port = 80, uint8_t max_clients = 4);
  NetworkServer(const IPAddress &addr, uint16_t port = 80,
                uint8_t max_clients = 4);
  ~NetworkServer();
  NetworkClient available() __attribute__((deprecated("Renamed to accept().")));
  NetworkClient accept();
  void begin(uint16_t port = 0);
  void begin(uint16_t port, int reuse_enable);
  void setNoDelay(bool nodelay);
  bool getNoDelay();
  bool hasClient();
  void end();
  void close();
  void stop();
  operator bool();
  int setTimeout(uint32_t seconds);
};
#endif  // BOARD_CHECK_NETWORKSERVER_H_
