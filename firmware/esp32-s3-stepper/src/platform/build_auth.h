// The sketch's authentication setting, checked at compile time. Include it
// after secrets.h. The robot is closed by default: the build needs either a
// well-formed key,
//   #define CUBE_KEY_HEX "<2..128 hex digits>"      (e.g. openssl rand -hex 32)
// or the explicit opt-out
//   #define CUBE_ALLOW_UNAUTHENTICATED 1
// with which anyone who can reach the robot's UDP port commands it. Anything
// else (no key, an empty key, a key that is not whole hex bytes or is longer
// than 64 bytes, both settings) stops the build with a message that says
// what to fix. See docs/flashing.md.
#ifndef CUBE_PLATFORM_BUILD_AUTH_H_
#define CUBE_PLATFORM_BUILD_AUTH_H_

#include "../core/key_hex.h"

#ifndef CUBE_KEY_HEX
#define CUBE_KEY_HEX ""
#endif

namespace cube::build {

// CUBE_KEY_HEX must be a string literal.
constexpr char kKeyHex[] = CUBE_KEY_HEX;

#if defined(CUBE_ALLOW_UNAUTHENTICATED)
static_assert(CUBE_ALLOW_UNAUTHENTICATED == 1,
              "CUBE_ALLOW_UNAUTHENTICATED must be defined as 1, or not at all");
static_assert(kKeyHex[0] == '\0',
              "CUBE_KEY_HEX and CUBE_ALLOW_UNAUTHENTICATED are both set: "
              "remove CUBE_ALLOW_UNAUTHENTICATED to use the key");
constexpr bool kUnauthenticated = true;
#else
static_assert(CheckKeyHex(kKeyHex) != KeyHexError::kEmpty,
              "CUBE_KEY_HEX is empty: set a key in secrets.h (generate one "
              "with: openssl rand -hex 32), or define "
              "CUBE_ALLOW_UNAUTHENTICATED 1 to let anyone on the network "
              "command the robot (docs/flashing.md)");
static_assert(CheckKeyHex(kKeyHex) != KeyHexError::kNotHex,
              "CUBE_KEY_HEX is not hex: use only the digits 0-9 and a-f");
static_assert(CheckKeyHex(kKeyHex) != KeyHexError::kOddLength,
              "CUBE_KEY_HEX has an odd number of hex digits: a key is whole "
              "bytes, two digits each");
static_assert(CheckKeyHex(kKeyHex) != KeyHexError::kTooLong,
              "CUBE_KEY_HEX is longer than 64 bytes (128 hex digits)");
constexpr bool kUnauthenticated = false;
#endif

// The key's bytes (len 0 with the opt-out).
constexpr KeyBytes kKey = ParseKeyHex(kKeyHex);

}  // namespace cube::build

#endif  // CUBE_PLATFORM_BUILD_AUTH_H_
