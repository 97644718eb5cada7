// Declarations for a signature check (see Arduino.h): mirrors
// libraries/ESPmDNS/src/ESPmDNS.h of espressif/arduino-esp32 3.0.7, the
// members the stepper sketch calls to announce itself (docs/discovery.md),
// with the real overload sets: begin and setInstanceName take a String or
// a C string; addService and addServiceTxt have char*, const char* and
// String forms (the char* addServiceTxt returns bool, the others void).
#ifndef BOARD_CHECK_ESPMDNS_H_
#define BOARD_CHECK_ESPMDNS_H_
#include <stdint.h>

#include "Arduino.h"

class MDNSResponder {
 public:
  MDNSResponder();
  ~MDNSResponder();
  bool begin(const String &hostName);
  bool begin(const char *hostName);
  void end();
  void setInstanceName(String name);
  void setInstanceName(const char *name);
  void setInstanceName(char *name);
  bool addService(char *service, char *proto, uint16_t port);
  bool addService(const char *service, const char *proto, uint16_t port);
  bool addService(String service, String proto, uint16_t port);
  bool addServiceTxt(char *name, char *proto, char *key, char *value);
  void addServiceTxt(const char *name, const char *proto, const char *key,
                     const char *value);
  void addServiceTxt(String name, String proto, String key, String value);
};

extern MDNSResponder MDNS;
#endif  // BOARD_CHECK_ESPMDNS_H_
