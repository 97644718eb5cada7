// Declarations for a signature check (see Arduino.h): mirrors
// libraries/Network/src/NetworkUdp.h of espressif/arduino-esp32 3.0.7.
// flush() is deprecated there ("Use clear() instead."): in cores 3.0.0 to
// 3.0.4 it did not drop the received datagram, and clear() is the call
// that empties the receive buffer. The strict flags (-Werror) turn a
// flush() call into an error (selftest/udp_flush.cpp).
#ifndef BOARD_CHECK_NETWORKUDP_H_
#define BOARD_CHECK_NETWORKUDP_H_
#include <stddef.h>
#include <stdint.h>

#include "Arduino.h"
#include "Udp.h"

class NetworkUDP : public UDP {
 public:
  NetworkUDP();
  ~NetworkUDP();
  uint8_t begin(IPAddress a, uint16_t p);
  uint8_t begin(uint16_t p);
  uint8_t beginMulticast(IPAddress a, uint16_t p);
  void stop();
  int beginMulticastPacket();
  int beginPacket();
  int beginPacket(IPAddress ip, uint16_t port);
  int beginPacket(const char *host, uint16_t port);
  int endPacket();
  size_t write(uint8_t);
  size_t write(const uint8_t *buffer, size_t size);
  [[deprecated("Use clear() instead.")]]
  void flush();
  int parsePacket();
  int available();
  int read();
  int read(unsigned char *buffer, size_t len);
  int read(char *buffer, size_t len);
  int peek();
  void clear();
  IPAddress remoteIP();
  uint16_t remotePort();
};
#endif  // BOARD_CHECK_NETWORKUDP_H_
