// Declarations for a signature check (see Arduino.h): stands for ESP-IDF
// 5.1 components/driver/ledc/include/driver/ledc.h, which esp_camera.h
// includes; the camera sketch needs only its types (hal/ledc_types.h).
#ifndef BOARD_CHECK_DRIVER_LEDC_H_
#define BOARD_CHECK_DRIVER_LEDC_H_
#include "hal/ledc_types.h"
#endif  // BOARD_CHECK_DRIVER_LEDC_H_
