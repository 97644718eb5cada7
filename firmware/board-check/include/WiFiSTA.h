// Declarations for a signature check (see Arduino.h): mirrors
// libraries/WiFi/src/WiFiSTA.h of espressif/arduino-esp32 3.0.7, the
// WiFiSTAClass ("old STA API") that WiFi derives from. status() is a
// member (it was static in 2.x); disconnect() has the 3.x timeoutLength.
#ifndef BOARD_CHECK_WIFISTA_H_
#define BOARD_CHECK_WIFISTA_H_
#include <stddef.h>
#include <stdint.h>

#include "IPAddress.h"
#include "WString.h"
#include "WiFiGeneric.h"
#include "WiFiType.h"

class WiFiSTAClass {
 public:
  wl_status_t begin(const char *ssid, const char *passphrase = NULL,
                    int32_t channel = 0, const uint8_t *bssid = NULL,
                    bool connect = true);
  wl_status_t begin(const String &ssid,
                    const String &passphrase = (const char *)NULL,
                    int32_t channel = 0, const uint8_t *bssid = NULL,
                    bool connect = true);
  wl_status_t begin();
  bool reconnect();
  bool disconnectAsync(bool wifioff = false, bool eraseap = false);
  bool disconnect(bool wifioff = false, bool eraseap = false,
                  unsigned long timeoutLength = 100);
  bool eraseAP(void);
  bool isConnected();
  bool setAutoReconnect(bool autoReconnect);
  bool getAutoReconnect();
  uint8_t waitForConnectResult(unsigned long timeoutLength = 60000);
  wl_status_t status();
  String SSID() const;
  int8_t RSSI();
  IPAddress localIP();
  uint8_t *macAddress(uint8_t *mac);
  String macAddress();
  IPAddress subnetMask();
  IPAddress gatewayIP();
};
#endif  // BOARD_CHECK_WIFISTA_H_
