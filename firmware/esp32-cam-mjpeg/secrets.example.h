// Copy this file to secrets.h (same folder; it is not committed) and fill it
// in before compiling. See docs/flashing.md and docs/security.md.
#ifndef CAM_SECRETS_H_
#define CAM_SECRETS_H_

#define CAM_WIFI_SSID "your-network"
#define CAM_WIFI_PASSWORD "your-password"

// Optional token for /stream and /status, sent as ?token=... or
// "Authorization: Bearer ...": up to 128 of A-Z a-z 0-9 - . _ ~, e.g. the
// output of `openssl rand -hex 16`. Empty: anyone on the network may watch.
// The host reads it from connection.cameraToken (docs/physical.md).
#define CAM_TOKEN ""

// Optional origin allowed to read the camera from a web page's scripts,
// e.g. "http://192.168.1.20:5173". Empty: no Access-Control-Allow-Origin
// header (an <img> tag still shows the stream; scripts on other sites
// cannot read it).
#define CAM_ALLOW_ORIGIN ""

#endif  // CAM_SECRETS_H_
