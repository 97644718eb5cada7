// Declarations for a signature check (see Arduino.h): the ESP-IDF 5.1
// FreeRTOS port (types, ticks, critical sections with a spinlock).
#ifndef BOARD_CHECK_FREERTOS_H_
#define BOARD_CHECK_FREERTOS_H_
#include <stdint.h>
extern "C" {
typedef int BaseType_t;
typedef unsigned int UBaseType_t;
typedef uint32_t TickType_t;
#define pdFALSE ((BaseType_t)0)
#define pdTRUE ((BaseType_t)1)
#define pdPASS (pdTRUE)
#define pdFAIL (pdFALSE)
#define portMAX_DELAY ((TickType_t)0xffffffffUL)
#define configTICK_RATE_HZ 1000
#define pdMS_TO_TICKS(xTimeInMs)                                        \
  ((TickType_t)(((TickType_t)(xTimeInMs) * (TickType_t)configTICK_RATE_HZ) / \
                (TickType_t)1000U))

typedef struct {
  volatile uint32_t owner;
  volatile uint32_t count;
} spinlock_t;
typedef spinlock_t portMUX_TYPE;
#define portMUX_FREE_VAL 0xB33FFFFF
#define portMUX_INITIALIZER_UNLOCKED {portMUX_FREE_VAL, 0}
void vPortEnterCritical(portMUX_TYPE* mux);
void vPortExitCritical(portMUX_TYPE* mux);
#define portENTER_CRITICAL(mux) vPortEnterCritical(mux)
#define portEXIT_CRITICAL(mux) vPortExitCritical(mux)
#define portENTER_CRITICAL_ISR(mux) vPortEnterCritical(mux)
#define portEXIT_CRITICAL_ISR(mux) vPortExitCritical(mux)
}
#endif  // BOARD_CHECK_FREERTOS_H_
