// Declarations for a signature check (see Arduino.h): FreeRTOS task API as
// ESP-IDF 5.1 declares it (xTaskCreatePinnedToCore is the SMP addition).
#ifndef BOARD_CHECK_FREERTOS_TASK_H_
#define BOARD_CHECK_FREERTOS_TASK_H_
#include "FreeRTOS.h"
extern "C" {
struct tskTaskControlBlock;
typedef struct tskTaskControlBlock* TaskHandle_t;
typedef void (*TaskFunction_t)(void*);
#define tskNO_AFFINITY ((BaseType_t)0x7FFFFFFF)
BaseType_t xTaskCreatePinnedToCore(TaskFunction_t pxTaskCode,
                                   const char* const pcName,
                                   const uint32_t usStackDepth,
                                   void* const pvParameters,
                                   UBaseType_t uxPriority,
                                   TaskHandle_t* const pxCreatedTask,
                                   const BaseType_t xCoreID);
void vTaskDelete(TaskHandle_t xTaskToDelete);
void vTaskDelay(const TickType_t xTicksToDelay);
BaseType_t xTaskDelayUntil(TickType_t* const pxPreviousWakeTime,
                           const TickType_t xTimeIncrement);
#define vTaskDelayUntil(pxPreviousWakeTime, xTimeIncrement)         \
  do {                                                              \
    (void)xTaskDelayUntil((pxPreviousWakeTime), (xTimeIncrement)); \
  } while (0)
TickType_t xTaskGetTickCount(void);
TaskHandle_t xTaskGetCurrentTaskHandle(void);
}
#endif  // BOARD_CHECK_FREERTOS_TASK_H_
