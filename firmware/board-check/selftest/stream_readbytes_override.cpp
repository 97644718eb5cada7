// Must NOT compile against the declarations: Stream::readBytes is not
// virtual in the core, so a subclass's readBytes hides it and cannot be
// marked override (a call through Stream& reaches Stream's own). ctest's
// BoardCheck.RefusesAReadBytesOverride expects the error.
#include <Arduino.h>

class Source : public Stream {
 public:
  int available() override { return 0; }
  int read() override { return -1; }
  int peek() override { return -1; }
  size_t write(uint8_t) override { return 0; }
  size_t readBytes(char* buffer, size_t length) override;
};
