// Declarations for a signature check (see Arduino.h): mirrors
// cores/esp32/HardwareSerial.h of espressif/arduino-esp32 3.0.7.
// SERIAL_8N1 and the other frame formats are values of enum SerialConfig;
// begin()'s rxfifo_full_thrhd defaults to 112. readBytes hides Stream's (it
// is not virtual there). `Serial` is a macro: with USB CDC on boot off (the
// sketches' FQBN default) it names Serial0, UART0.
#ifndef BOARD_CHECK_HARDWARESERIAL_H_
#define BOARD_CHECK_HARDWARESERIAL_H_
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "Stream.h"
#include "soc/soc_caps.h"

enum SerialConfig {
  SERIAL_5N1 = 0x8000010,
  SERIAL_6N1 = 0x8000014,
  SERIAL_7N1 = 0x8000018,
  SERIAL_8N1 = 0x800001c,
  SERIAL_5N2 = 0x8000030,
  SERIAL_6N2 = 0x8000034,
  SERIAL_7N2 = 0x8000038,
  SERIAL_8N2 = 0x800003c,
  SERIAL_5E1 = 0x8000012,
  SERIAL_6E1 = 0x8000016,
  SERIAL_7E1 = 0x800001a,
  SERIAL_8E1 = 0x800001e,
  SERIAL_5E2 = 0x8000032,
  SERIAL_6E2 = 0x8000036,
  SERIAL_7E2 = 0x800003a,
  SERIAL_8E2 = 0x800003e,
  SERIAL_5O1 = 0x8000013,
  SERIAL_6O1 = 0x8000017,
  SERIAL_7O1 = 0x800001b,
  SERIAL_8O1 = 0x800001f,
  SERIAL_5O2 = 0x8000033,
  SERIAL_6O2 = 0x8000037,
  SERIAL_7O2 = 0x800003b,
  SERIAL_8O2 = 0x800003f
};

class HardwareSerial : public Stream {
 public:
  HardwareSerial(uint8_t uart_nr);
  ~HardwareSerial();
  bool setRxTimeout(uint8_t symbols_timeout);
  bool setRxFIFOFull(uint8_t fifoBytes);
  void begin(unsigned long baud, uint32_t config = SERIAL_8N1,
             int8_t rxPin = -1, int8_t txPin = -1, bool invert = false,
             unsigned long timeout_ms = 20000UL,
             uint8_t rxfifo_full_thrhd = 112);
  void end(void);
  void updateBaudRate(unsigned long baud);
  int available(void);
  int availableForWrite(void);
  int peek(void);
  int read(void);
  size_t read(uint8_t *buffer, size_t size);
  size_t read(char *buffer, size_t size);
  size_t readBytes(uint8_t *buffer, size_t length);
  size_t readBytes(char *buffer, size_t length);
  void flush(void);
  void flush(bool txOnly);
  size_t write(uint8_t);
  size_t write(const uint8_t *buffer, size_t size);
  size_t write(const char *buffer, size_t size);
  size_t write(const char *s);
  size_t write(unsigned long n);
  size_t write(long n);
  size_t write(unsigned int n);
  size_t write(int n);
  uint32_t baudRate();
  operator bool() const;
  void setDebugOutput(bool);
  void setRxInvert(bool);
  bool setPins(int8_t rxPin, int8_t txPin, int8_t ctsPin = -1,
               int8_t rtsPin = -1);
  size_t setRxBufferSize(size_t new_size);
  size_t setTxBufferSize(size_t new_size);
};

#ifndef ARDUINO_USB_CDC_ON_BOOT
#define ARDUINO_USB_CDC_ON_BOOT 0
#endif
#if ARDUINO_USB_CDC_ON_BOOT
// The core then makes Serial the USB CDC port (HWCDCSerial or USBSerial),
// which these declarations do not cover.
#error "board-check declares the UART0 Serial only: build with ARDUINO_USB_CDC_ON_BOOT=0"
#endif
#define Serial Serial0
extern HardwareSerial Serial0;
#if SOC_UART_NUM > 1
extern HardwareSerial Serial1;
#endif
#if SOC_UART_NUM > 2
extern HardwareSerial Serial2;
#endif
#endif  // BOARD_CHECK_HARDWARESERIAL_H_
