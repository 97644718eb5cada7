// Copy this file to secrets.h (same folder; it is not committed) and fill it
// in before compiling. See docs/flashing.md.
#ifndef CUBE_SECRETS_H_
#define CUBE_SECRETS_H_

// WiFi network the cube joins (2.4 GHz).
#define CUBE_WIFI_SSID "your-network"
#define CUBE_WIFI_PASSWORD "your-password"

// Pre-shared key for authenticated requests (docs/protocol.md section 8):
// 1..64 bytes written as hex. Required: generate one with
//   openssl rand -hex 32
// and give the same key to the host (PhysicalHAL's `key` option). The build
// stops while it is empty or malformed.
#define CUBE_KEY_HEX ""

// Or, instead of a key, the explicit opt-out: no authentication at all, so
// anyone who can reach the robot's UDP port 4210 can move it, stop it and
// clear its emergency stop. For a bench on a network you alone use.
// #define CUBE_ALLOW_UNAUTHENTICATED 1

#endif  // CUBE_SECRETS_H_
