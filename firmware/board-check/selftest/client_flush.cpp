// Must NOT compile under the board check's flags: NetworkClient::flush()
// is deprecated in the 3.x core ("Use clear() instead."). ctest's
// BoardCheck.RefusesTheDeprecatedClientFlush expects the error.
#include <WiFi.h>

void DropInput(WiFiClient& client) { client.flush(); }
