// Declarations for a signature check (see Arduino.h): mirrors
// libraries/Network/src/NetworkClient.h of espressif/arduino-esp32 3.0.7.
// flush() is deprecated there ("Use clear() instead."); readBytes hides
// Stream's. Copying is the implicit copy of the core's shared handles.
#ifndef BOARD_CHECK_NETWORKCLIENT_H_
#define BOARD_CHECK_NETWORKCLIENT_H_
#include <stddef.h>
#include <stdint.h>

#include "Arduino.h"
#include "Client.h"

class ESPLwIPClient : public Client {
 public:
  virtual int connect(IPAddress ip, uint16_t port, int32_t timeout) = 0;
  virtual int connect(const char *host, uint16_t port, int32_t timeout) = 0;
  virtual void setConnectionTimeout(uint32_t milliseconds) = 0;
};

class NetworkClient : public ESPLwIPClient {
 public:
  NetworkClient();
  NetworkClient(int fd);
  ~NetworkClient();
  int connect(IPAddress ip, uint16_t port);
  int connect(IPAddress ip, uint16_t port, int32_t timeout_ms);
  int connect(const char *host, uint16_t port);
  int connect(const char *host, uint16_t port, int32_t timeout_ms);
  size_t write(uint8_t data);
  size_t write(const uint8_t *buf, size_t size);
  size_t write_P(PGM_P buf, size_t size);
  size_t write(Stream &stream);
  [[deprecated("Use clear() instead.")]]
  void flush();
  int available();
  int read();
  int read(uint8_t *buf, size_t size);
  size_t readBytes(char *buffer, size_t length);
  size_t readBytes(uint8_t *buffer, size_t length);
  int peek();
  void clear();
  void stop();
  uint8_t connected();
  operator bool();
  bool operator==(const bool value);
  bool operator!=(const bool value);
  bool operator==(const NetworkClient &);
  bool operator!=(const NetworkClient &rhs);
  virtual int fd() const;
  void setConnectionTimeout(uint32_t milliseconds);
  int setNoDelay(bool nodelay);
  bool getNoDelay();
  IPAddress remoteIP() const;
  uint16_t remotePort() const;
  IPAddress localIP() const;
  uint16_t localPort() const;
  using Print::write;
};
#endif  // BOARD_CHECK_NETWORKCLIENT_H_
