// Declarations for a signature check (see Arduino.h): the options of the
// ESP-IDF sdkconfig.h the 3.0.7 core is built with
// (espressif/esp32-arduino-libs, <chip>/<flash mode>/include/sdkconfig.h)
// that the declarations here depend on.
#ifndef BOARD_CHECK_SDKCONFIG_H_
#define BOARD_CHECK_SDKCONFIG_H_
#define CONFIG_FREERTOS_HZ 1000
#define CONFIG_ARDUINO_RUNNING_CORE 1
// CONFIG_ARDUINO_ISR_IRAM is not set.
#endif  // BOARD_CHECK_SDKCONFIG_H_
