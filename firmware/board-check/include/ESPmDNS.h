// Declarations for a signature check (see Arduino.h): the Arduino-ESP32
// 3.0.7 ESPmDNS library, only the members the stepper sketch calls to
// announce itself (src/platform/esp32/app.cpp, docs/discovery.md).
#ifndef BOARD_CHECK_ESPMDNS_H_
#define BOARD_CHECK_ESPMDNS_H_
#include <stdint.h>

#include "Arduino.h"

class MDNSResponder {
 public:
  MDNSResponder();
  ~MDNSResponder();
  bool begin(const char* hostName);
  void end();
  void setInstanceName(const char* name);
  bool addService(const char* service, const char* proto, uint16_t port);
  void addServiceTxt(const char* name, const char* proto, const char* key,
                     const char* value);
};

extern MDNSResponder MDNS;

#endif  // BOARD_CHECK_ESPMDNS_H_
