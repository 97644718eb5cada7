// Declarations for a signature check (see Arduino.h): mirrors the parts of
// ESP-IDF 5.1's FreeRTOS the sketches use (espressif/esp32-arduino-libs,
// <chip>/include/freertos/): the port types and critical sections of
// FreeRTOS-Kernel/portable/xtensa/include/freertos/portmacro.h, the
// spinlock of esp_hw_support/include/spinlock.h, the tick rate and stack
// depth type of esp_additions/include/freertos/FreeRTOSConfig.h and the
// pd* macros of FreeRTOS-Kernel/include/freertos/projdefs.h.
#ifndef BOARD_CHECK_FREERTOS_H_
#define BOARD_CHECK_FREERTOS_H_
#include <stdint.h>

#include "sdkconfig.h"
extern "C" {
#define portBASE_TYPE int
typedef portBASE_TYPE BaseType_t;
typedef unsigned portBASE_TYPE UBaseType_t;
typedef uint32_t TickType_t;
#define portMAX_DELAY (TickType_t)0xffffffffUL
#define configTICK_RATE_HZ CONFIG_FREERTOS_HZ
#define configSTACK_DEPTH_TYPE uint32_t
#define pdMS_TO_TICKS(xTimeInMs)                                           \
  ((TickType_t)(((TickType_t)(xTimeInMs) * (TickType_t)configTICK_RATE_HZ) / \
                (TickType_t)1000U))
#define pdFALSE ((BaseType_t)0)
#define pdTRUE ((BaseType_t)1)
#define pdPASS (pdTRUE)
#define pdFAIL (pdFALSE)

typedef struct {
  volatile uint32_t owner;
  volatile uint32_t count;
} spinlock_t;
#define SPINLOCK_FREE 0xB33FFFFF
#define SPINLOCK_INITIALIZER {.owner = SPINLOCK_FREE, .count = 0}
typedef spinlock_t portMUX_TYPE;
#define portMUX_INITIALIZER_UNLOCKED SPINLOCK_INITIALIZER
void vPortEnterCritical(portMUX_TYPE *mux);
void vPortExitCritical(portMUX_TYPE *mux);
#define portENTER_CRITICAL(mux) vPortEnterCritical(mux)
#define portEXIT_CRITICAL(mux) vPortExitCritical(mux)
#define portENTER_CRITICAL_ISR(mux) vPortEnterCritical(mux)
#define portEXIT_CRITICAL_ISR(mux) vPortExitCritical(mux)
}
#endif  // BOARD_CHECK_FREERTOS_H_
