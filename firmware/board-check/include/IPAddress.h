// Declarations for a signature check (see Arduino.h): mirrors
// cores/esp32/IPAddress.h of espressif/arduino-esp32 3.0.7 (the 3.x
// IPAddress, IPv4 and IPv6, a Printable). Its uint32_t and const char*
// constructors are implicit, as in the core.
#ifndef BOARD_CHECK_IPADDRESS_H_
#define BOARD_CHECK_IPADDRESS_H_
#include <stddef.h>
#include <stdint.h>

#include "Printable.h"
#include "WString.h"

enum IPType { IPv4, IPv6 };

class IPAddress : public Printable {
 public:
  IPAddress();
  IPAddress(IPType ip_type);
  IPAddress(uint8_t first_octet, uint8_t second_octet, uint8_t third_octet,
            uint8_t fourth_octet);
  IPAddress(uint32_t address);
  IPAddress(const uint8_t *address);
  IPAddress(IPType ip_type, const uint8_t *address, uint8_t z = 0);
  IPAddress(const char *address);
  IPAddress(const IPAddress &address);

  bool fromString(const char *address);
  bool fromString(const String &address);

  operator uint32_t() const;
  bool operator==(const IPAddress &addr) const;
  bool operator!=(const IPAddress &addr) const;
  bool operator==(const uint8_t *addr) const;
  uint8_t operator[](int index) const;
  uint8_t &operator[](int index);
  IPAddress &operator=(const uint8_t *address);
  IPAddress &operator=(uint32_t address);
  IPAddress &operator=(const char *address);
  IPAddress &operator=(const IPAddress &address);

  virtual size_t printTo(Print &p) const;
  String toString(bool includeZone = false) const;
  IPType type() const;
};
#endif  // BOARD_CHECK_IPADDRESS_H_
