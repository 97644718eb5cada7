// Must NOT compile against the declarations: in the 3.x core WiFi.status()
// is a member of WiFiSTAClass, not the static function of 2.x. ctest's
// BoardCheck.RefusesThe2xStaticWifiStatus expects the error.
#include <WiFi.h>

bool Connected() { return WiFiClass::status() == WL_CONNECTED; }
