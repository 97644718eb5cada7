// Must NOT compile under the board check's flags: the camera driver's
// legacy pin_sscb_* names are deprecated in favour of pin_sccb_*. ctest's
// BoardCheck.RefusesTheLegacyCameraPins expects the error.
#include <esp_camera.h>

void SetCameraBus(camera_config_t& c) {
  c.pin_sscb_sda = 26;
  c.pin_sscb_scl = 27;
}
