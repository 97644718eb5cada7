// Declarations for a signature check (see Arduino.h): mirrors
// libraries/WiFi/src/WiFi.h of espressif/arduino-esp32 3.0.7: WiFiClass
// derives from the generic, station, scan and access-point classes, and
// the header brings in the TCP and UDP classes under their WiFi names.
#ifndef BOARD_CHECK_WIFI_H_
#define BOARD_CHECK_WIFI_H_
#include "soc/soc_caps.h"
#if SOC_WIFI_SUPPORTED
#include <stdint.h>

#include "IPAddress.h"
#include "Print.h"
#include "WiFiAP.h"
#include "WiFiClient.h"
#include "WiFiGeneric.h"
#include "WiFiSTA.h"
#include "WiFiScan.h"
#include "WiFiServer.h"
#include "WiFiType.h"
#include "WiFiUdp.h"

class WiFiClass : public WiFiGenericClass,
                  public WiFiSTAClass,
                  public WiFiScanClass,
                  public WiFiAPClass {
 public:
  WiFiClass();
  using WiFiSTAClass::RSSI;
  using WiFiScanClass::RSSI;
  void printDiag(Print &dest);
  void enableProv(bool status);
  bool isProvEnabled();
};

extern WiFiClass WiFi;
#endif  // SOC_WIFI_SUPPORTED
#endif  // BOARD_CHECK_WIFI_H_
