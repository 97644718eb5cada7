// Declarations for a signature check (see Arduino.h): the Arduino-ESP32
// 3.0.7 WiFi library as the sketches use it. In 3.x the TCP classes live in
// the Network library (NetworkClient, NetworkServer) and WiFiClient and
// WiFiServer are their WiFi names.
#ifndef BOARD_CHECK_WIFI_H_
#define BOARD_CHECK_WIFI_H_
#include <stddef.h>
#include <stdint.h>

#include "Arduino.h"
#include "IPAddress.h"

typedef enum {
  WIFI_MODE_NULL = 0,
  WIFI_MODE_STA,
  WIFI_MODE_AP,
  WIFI_MODE_APSTA,
  WIFI_MODE_MAX
} wifi_mode_t;
#define WIFI_OFF WIFI_MODE_NULL
#define WIFI_STA WIFI_MODE_STA
#define WIFI_AP WIFI_MODE_AP
#define WIFI_AP_STA WIFI_MODE_APSTA

typedef enum {
  WL_NO_SHIELD = 255,
  WL_STOPPED = 254,
  WL_IDLE_STATUS = 0,
  WL_NO_SSID_AVAIL = 1,
  WL_SCAN_COMPLETED = 2,
  WL_CONNECTED = 3,
  WL_CONNECT_FAILED = 4,
  WL_CONNECTION_LOST = 5,
  WL_DISCONNECTED = 6
} wl_status_t;

class WiFiClass {
 public:
  static void persistent(bool persistent);
  static bool mode(wifi_mode_t);
  static wifi_mode_t getMode();
  bool setSleep(bool enabled);
  wl_status_t begin(const char* ssid, const char* passphrase = NULL,
                    int32_t channel = 0, const uint8_t* bssid = NULL,
                    bool connect = true);
  bool reconnect();
  bool disconnect(bool wifioff = false, bool eraseap = false);
  static wl_status_t status();
  IPAddress localIP();
  uint8_t* macAddress(uint8_t* mac);
  String macAddress();
  int8_t RSSI();
};
extern WiFiClass WiFi;

class Client : public Stream {
 public:
  virtual int connect(IPAddress ip, uint16_t port) = 0;
  virtual int connect(const char* host, uint16_t port) = 0;
  virtual void stop() = 0;
  virtual uint8_t connected() = 0;
  virtual operator bool() = 0;
};

class NetworkClient : public Client {
 public:
  NetworkClient();
  NetworkClient(const NetworkClient&);
  NetworkClient& operator=(const NetworkClient&);
  ~NetworkClient();
  int connect(IPAddress ip, uint16_t port) override;
  int connect(const char* host, uint16_t port) override;
  size_t write(uint8_t data) override;
  size_t write(const uint8_t* buf, size_t size) override;
  int available() override;
  int read() override;
  int read(uint8_t* buf, size_t size);
  size_t readBytes(char* buffer, size_t length) override;
  size_t readBytes(uint8_t* buffer, size_t length) override;
  int peek() override;
  void clear();
  void stop() override;
  uint8_t connected() override;
  operator bool() override;
  void setConnectionTimeout(uint32_t milliseconds);
  int setNoDelay(bool nodelay);
  IPAddress remoteIP() const;
  uint16_t remotePort() const;
  using Print::write;
};
using WiFiClient = NetworkClient;

class NetworkServer {
 public:
  NetworkServer(uint16_t port = 80, uint8_t max_clients = 4);
  NetworkClient available() __attribute__((deprecated("Renamed to accept().")));
  NetworkClient accept();
  void begin(uint16_t port = 0);
  void setNoDelay(bool nodelay);
  bool hasClient();
  void end();
  void stop();
  operator bool();
};
using WiFiServer = NetworkServer;

#endif  // BOARD_CHECK_WIFI_H_
