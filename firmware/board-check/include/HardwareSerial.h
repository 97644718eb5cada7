// Declarations for a signature check (see Arduino.h): Arduino-ESP32 3.0.7
// HardwareSerial. With USB CDC on boot disabled (the sketches' FQBN
// default), `Serial` is UART0.
#ifndef BOARD_CHECK_HARDWARESERIAL_H_
#define BOARD_CHECK_HARDWARESERIAL_H_
#include <stddef.h>
#include <stdint.h>

#include "Stream.h"

#define SERIAL_8N1 0x800001c

class HardwareSerial : public Stream {
 public:
  explicit HardwareSerial(uint8_t uart_nr);
  ~HardwareSerial();
  void begin(unsigned long baud, uint32_t config = SERIAL_8N1,
             int8_t rxPin = -1, int8_t txPin = -1, bool invert = false,
             unsigned long timeout_ms = 20000UL,
             uint8_t rxfifo_full_thrhd = 120);
  void end();
  int available() override;
  int availableForWrite() override;
  int peek() override;
  int read() override;
  size_t read(uint8_t* buffer, size_t size);
  size_t readBytes(uint8_t* buffer, size_t length) override;
  size_t readBytes(char* buffer, size_t length) override;
  void flush() override;
  size_t write(uint8_t) override;
  size_t write(const uint8_t* buffer, size_t size) override;
  using Print::write;
  size_t setRxBufferSize(size_t new_size);
  size_t setTxBufferSize(size_t new_size);
  void setDebugOutput(bool);
  operator bool() const;
};

extern HardwareSerial Serial;
#endif  // BOARD_CHECK_HARDWARESERIAL_H_
