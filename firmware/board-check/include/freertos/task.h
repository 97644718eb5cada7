// Declarations for a signature check (see Arduino.h): mirrors ESP-IDF 5.1
// FreeRTOS-Kernel/include/freertos/task.h (espressif/esp32-arduino-libs,
// <chip>/include/freertos/FreeRTOS-Kernel/include/freertos/task.h), the
// task calls the sketches use; xTaskCreatePinnedToCore is the SMP form.
// vTaskDelayUntil is, as there, a bare block, not a do/while statement.
#ifndef BOARD_CHECK_FREERTOS_TASK_H_
#define BOARD_CHECK_FREERTOS_TASK_H_
#include "FreeRTOS.h"
extern "C" {
#define tskNO_AFFINITY (0x7FFFFFFF)
struct tskTaskControlBlock;
typedef struct tskTaskControlBlock *TaskHandle_t;
typedef void (*TaskFunction_t)(void *);
BaseType_t xTaskCreatePinnedToCore(TaskFunction_t pxTaskCode,
                                   const char *const pcName,
                                   const configSTACK_DEPTH_TYPE usStackDepth,
                                   void *const pvParameters,
                                   UBaseType_t uxPriority,
                                   TaskHandle_t *const pvCreatedTask,
                                   const BaseType_t xCoreID);
void vTaskDelete(TaskHandle_t xTaskToDelete);
void vTaskDelay(const TickType_t xTicksToDelay);
BaseType_t xTaskDelayUntil(TickType_t *const pxPreviousWakeTime,
                           const TickType_t xTimeIncrement);
#define vTaskDelayUntil(pxPreviousWakeTime, xTimeIncrement)       \
  {                                                               \
    (void)xTaskDelayUntil(pxPreviousWakeTime, xTimeIncrement); \
  }
TickType_t xTaskGetTickCount(void);
TaskHandle_t xTaskGetCurrentTaskHandle(void);
}
#endif  // BOARD_CHECK_FREERTOS_TASK_H_
