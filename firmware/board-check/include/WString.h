// Declarations for a signature check (see Arduino.h): the part of Arduino's
// String the board code may meet (Print's overloads, readString*).
#ifndef BOARD_CHECK_WSTRING_H_
#define BOARD_CHECK_WSTRING_H_
// Flash strings: on the ESP32 they live in the same address space, and
// F("...") is a cast the Print overloads accept.
class __FlashStringHelper;
#define PSTR(s) (s)
#define FPSTR(pstr_pointer) \
  (reinterpret_cast<const __FlashStringHelper*>(pstr_pointer))
#define F(string_literal) (FPSTR(PSTR(string_literal)))

class String {
 public:
  String(const char* cstr = "");
  String(const String& str);
  ~String();
  String& operator=(const String& rhs);
  String& operator=(const char* cstr);
  unsigned int length() const;
  const char* c_str() const;
  bool startsWith(const String& prefix) const;
  int indexOf(char ch, unsigned int fromIndex = 0) const;
  String substring(unsigned int beginIndex) const;
  String substring(unsigned int beginIndex, unsigned int endIndex) const;
  bool operator==(const char* cstr) const;
  bool operator==(const String& rhs) const;
};
#endif  // BOARD_CHECK_WSTRING_H_
