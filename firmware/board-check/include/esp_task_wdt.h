// Declarations for a signature check (see Arduino.h): mirrors ESP-IDF 5.1
// components/esp_system/include/esp_task_wdt.h (espressif/esp32-arduino-
// libs, <chip>/include/esp_system/include/esp_task_wdt.h): the 5.x
// configuration struct and the task functions.
#ifndef BOARD_CHECK_ESP_TASK_WDT_H_
#define BOARD_CHECK_ESP_TASK_WDT_H_
#include <stdbool.h>
#include <stdint.h>

#include "esp_err.h"
#include "freertos/FreeRTOS.h"
#include "freertos/task.h"
extern "C" {
typedef struct {
  uint32_t timeout_ms;
  uint32_t idle_core_mask;
  bool trigger_panic;
} esp_task_wdt_config_t;
esp_err_t esp_task_wdt_init(const esp_task_wdt_config_t *config);
esp_err_t esp_task_wdt_reconfigure(const esp_task_wdt_config_t *config);
esp_err_t esp_task_wdt_deinit(void);
esp_err_t esp_task_wdt_add(TaskHandle_t task_handle);
esp_err_t esp_task_wdt_reset(void);
esp_err_t esp_task_wdt_delete(TaskHandle_t task_handle);
esp_err_t esp_task_wdt_status(TaskHandle_t task_handle);
}
#endif  // BOARD_CHECK_ESP_TASK_WDT_H_
