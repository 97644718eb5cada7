// Declarations for a signature check (see Arduino.h): mirrors
// cores/esp32/WString.h of espressif/arduino-esp32 3.0.7: F() and the
// members of String the board code can meet (Print's overloads,
// Stream::readString*, IPAddress::toString), with the real overload sets
// (indexOf has two overloads, not a default argument; the numeric
// constructors are explicit).
#ifndef BOARD_CHECK_WSTRING_H_
#define BOARD_CHECK_WSTRING_H_
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "pgmspace.h"

class __FlashStringHelper;
#define FPSTR(str_pointer) \
  (reinterpret_cast<const __FlashStringHelper *>(str_pointer))
#define F(string_literal) (FPSTR(PSTR(string_literal)))

class StringSumHelper;

class String {
 public:
  String(const char *cstr = "");
  String(const char *cstr, unsigned int length);
  String(const String &str);
  String(const __FlashStringHelper *str);
  String(String &&rval);
  explicit String(char c);
  explicit String(unsigned char, unsigned char base = 10);
  explicit String(int, unsigned char base = 10);
  explicit String(unsigned int, unsigned char base = 10);
  explicit String(long, unsigned char base = 10);
  explicit String(unsigned long, unsigned char base = 10);
  explicit String(float, unsigned int decimalPlaces = 2);
  explicit String(double, unsigned int decimalPlaces = 2);
  explicit String(long long, unsigned char base = 10);
  explicit String(unsigned long long, unsigned char base = 10);
  ~String(void);

  unsigned int length(void) const;
  bool isEmpty(void) const;

  String &operator=(const String &rhs);
  String &operator=(const char *cstr);
  String &operator=(const __FlashStringHelper *str);
  String &operator=(String &&rval);

  bool operator==(const String &rhs) const;
  bool operator==(const char *cstr) const;
  bool operator!=(const String &rhs) const;
  bool operator!=(const char *cstr) const;

  bool startsWith(const String &prefix) const;
  bool startsWith(const char *prefix) const;
  bool startsWith(const __FlashStringHelper *prefix) const;
  bool startsWith(const String &prefix, unsigned int offset) const;

  const char *c_str() const;

  int indexOf(char ch) const;
  int indexOf(char ch, unsigned int fromIndex) const;
  String substring(unsigned int beginIndex) const;
  String substring(unsigned int beginIndex, unsigned int endIndex) const;
};
#endif  // BOARD_CHECK_WSTRING_H_
