#if defined(ARDUINO_ARCH_ESP32)

#include "esp32_hal.h"

#include <Arduino.h>
#include <esp_random.h>
#include <esp_task_wdt.h>
#include <esp_timer.h>
#include <mbedtls/md.h>
#include <soc/gpio_reg.h>

#include "board.h"

namespace cube {

uint64_t IRAM_ATTR Esp32Clock::NowUs() {
  return static_cast<uint64_t>(esp_timer_get_time());
}

void Esp32Motors::Begin() {
  const uint8_t* pins[2] = {board::kLeftPins, board::kRightPins};
  for (int w = 0; w < 2; ++w) {
    all_[w] = 0;
    for (int i = 0; i < 4; ++i) {
      pinMode(pins[w][i], OUTPUT);
      digitalWrite(pins[w][i], LOW);
      masks_[w][i] = 1u << pins[w][i];
      all_[w] |= masks_[w][i];
    }
  }
}

void IRAM_ATTR Esp32Motors::WriteCoils(Wheel wheel, uint8_t pattern) {
  const int w = wheel == Wheel::kLeft ? 0 : 1;
  uint32_t on = 0;
  for (int i = 0; i < 4; ++i) {
    if ((pattern >> i) & 1u) on |= masks_[w][i];
  }
  REG_WRITE(GPIO_OUT_W1TC_REG, all_[w] & ~on);
  REG_WRITE(GPIO_OUT_W1TS_REG, on);
}

void Esp32Led::SetRgb(uint8_t r, uint8_t g, uint8_t b) {
#if defined(RGB_BUILTIN)
  const uint8_t pin = board::kRgbLedPinSet ? board::kRgbLedPin : RGB_BUILTIN;
#else
  const uint8_t pin = board::kRgbLedPin;
#endif
  // rgbLedWrite arrived in core 3.0.5, which deprecated neopixelWrite, the
  // name cores 3.0.0 to 3.0.4 have.
#if ESP_ARDUINO_VERSION >= ESP_ARDUINO_VERSION_VAL(3, 0, 5)
  rgbLedWrite(pin, r, g, b);
#else
  neopixelWrite(pin, r, g, b);
#endif
}

void Esp32Watchdog::Begin(uint32_t timeout_ms) {
  esp_task_wdt_config_t config = {};
  config.timeout_ms = timeout_ms;
  config.idle_core_mask = 0;
  config.trigger_panic = true;  // restart: the GPIOs reset, coils off
  if (esp_task_wdt_init(&config) == ESP_ERR_INVALID_STATE) {
    esp_task_wdt_reconfigure(&config);
  }
  esp_task_wdt_add(nullptr);
}

void Esp32Watchdog::Feed() { esp_task_wdt_reset(); }

uint32_t Esp32Random::NextU32() { return esp_random(); }

bool Esp32Mac::HmacSha256(const uint8_t* key, size_t key_len,
                          const uint8_t* data, size_t len, uint8_t* out) {
  const mbedtls_md_info_t* info = mbedtls_md_info_from_type(MBEDTLS_MD_SHA256);
  if (info == nullptr) return false;
  return mbedtls_md_hmac(info, key, key_len, data, len, out) == 0;
}

void SerialSink::Write(const uint8_t* data, size_t len) {
  Serial.write(data, len);
}

}  // namespace cube

#endif  // ARDUINO_ARCH_ESP32
