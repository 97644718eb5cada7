// Declarations for a signature check (see Arduino.h): Arduino-ESP32 3.0.7
// NetworkUDP, whose WiFi name is WiFiUDP.
#ifndef BOARD_CHECK_WIFIUDP_H_
#define BOARD_CHECK_WIFIUDP_H_
#include <stddef.h>
#include <stdint.h>

#include "Arduino.h"
#include "IPAddress.h"

class UDP : public Stream {};

class NetworkUDP : public UDP {
 public:
  NetworkUDP();
  ~NetworkUDP();
  uint8_t begin(IPAddress address, uint16_t port);
  uint8_t begin(uint16_t port);
  void stop();
  int beginPacket();
  int beginPacket(IPAddress ip, uint16_t port);
  int beginPacket(const char* host, uint16_t port);
  int endPacket();
  size_t write(uint8_t) override;
  size_t write(const uint8_t* buffer, size_t size) override;
  using Print::write;
  void flush() override;
  int parsePacket();
  int available() override;
  int read() override;
  int read(unsigned char* buffer, size_t len);
  int read(char* buffer, size_t len);
  int peek() override;
  void clear();
  IPAddress remoteIP();
  uint16_t remotePort();
};
using WiFiUDP = NetworkUDP;

#endif  // BOARD_CHECK_WIFIUDP_H_
