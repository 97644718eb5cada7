// Declarations for a signature check (see include/Arduino.h): mirrors the
// ESP32-S3 capabilities of ESP-IDF 5.1 components/soc/esp32s3/include/soc/
// soc_caps.h (espressif/esp32-arduino-libs, esp32s3/include/soc/esp32s3/
// include/soc/soc_caps.h) that the declarations depend on.
#ifndef BOARD_CHECK_SOC_CAPS_H_
#define BOARD_CHECK_SOC_CAPS_H_
#define SOC_WIFI_SUPPORTED 1
#define SOC_GPIO_PIN_COUNT 49
#define SOC_LEDC_CHANNEL_NUM (8)
#define SOC_UART_NUM (3)
#endif  // BOARD_CHECK_SOC_CAPS_H_
