// Copy this file to secrets.h (same folder; it is not committed) and fill it
// in before compiling. See docs/flashing.md.
#ifndef CUBE_SECRETS_H_
#define CUBE_SECRETS_H_

// WiFi network the cube joins (2.4 GHz).
#define CUBE_WIFI_SSID "your-network"
#define CUBE_WIFI_PASSWORD "your-password"

// Optional pre-shared key for authenticated requests (docs/protocol.md
// section 8), 1..64 bytes written as hex. Leave empty for no authentication.
#define CUBE_KEY_HEX ""

#endif  // CUBE_SECRETS_H_
