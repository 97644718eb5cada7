// Entry points of the board glue, called by esp32-s3-stepper.ino.
#ifndef CUBE_PLATFORM_ESP32_APP_H_
#define CUBE_PLATFORM_ESP32_APP_H_

void CubeAppSetup();
void CubeAppLoop();

#endif  // CUBE_PLATFORM_ESP32_APP_H_
