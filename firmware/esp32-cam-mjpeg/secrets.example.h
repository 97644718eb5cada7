// Copy this file to secrets.h (same folder; it is not committed) and fill it
// in before compiling. See docs/flashing.md.
#ifndef CAM_SECRETS_H_
#define CAM_SECRETS_H_

#define CAM_WIFI_SSID "your-network"
#define CAM_WIFI_PASSWORD "your-password"

#endif  // CAM_SECRETS_H_
