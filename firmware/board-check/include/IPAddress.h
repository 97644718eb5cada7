// Declarations for a signature check (see Arduino.h): IPAddress (Printable).
#ifndef BOARD_CHECK_IPADDRESS_H_
#define BOARD_CHECK_IPADDRESS_H_
#include <stdint.h>

#include "Print.h"
#include "WString.h"

class IPAddress : public Printable {
 public:
  IPAddress();
  IPAddress(uint8_t first_octet, uint8_t second_octet, uint8_t third_octet,
            uint8_t fourth_octet);
  explicit IPAddress(uint32_t address);
  operator uint32_t() const;
  bool operator==(const IPAddress& addr) const;
  uint8_t operator[](int index) const;
  size_t printTo(Print& p) const override;
  String toString(bool includeZone = false) const;
};
#endif  // BOARD_CHECK_IPADDRESS_H_
