// Secrets headers for the build-time key check (CMake tests
// BuildAuth.*): each CUBE_KEY_CASE is one secrets.h a user might write. The
// sketch's build_auth.h must accept the good ones and stop the build with a
// clear message on the others. Compiled with -fsyntax-only, never linked.
#if CUBE_KEY_CASE == 1  // a 32-byte key, as openssl rand -hex 32 writes it
#define CUBE_KEY_HEX \
  "00112233445566778899aabbccddeeff00112233445566778899AABBCCDDEEFF"
#elif CUBE_KEY_CASE == 2  // the explicit opt-out, key left empty
#define CUBE_KEY_HEX ""
#define CUBE_ALLOW_UNAUTHENTICATED 1
#elif CUBE_KEY_CASE == 3  // the example secrets: empty key, no opt-out
#define CUBE_KEY_HEX ""
#elif CUBE_KEY_CASE == 4  // no key at all
#elif CUBE_KEY_CASE == 5
#define CUBE_KEY_HEX "0011223"
#elif CUBE_KEY_CASE == 6
#define CUBE_KEY_HEX "my secret password"
#elif CUBE_KEY_CASE == 7  // 65 bytes
#define CUBE_KEY_HEX                                                         \
  "00112233445566778899aabbccddeeff00112233445566778899aabbccddeeff"       \
  "00112233445566778899aabbccddeeff00112233445566778899aabbccddeeff" \
  "00"
#elif CUBE_KEY_CASE == 8  // a key and the opt-out
#define CUBE_KEY_HEX "00112233"
#define CUBE_ALLOW_UNAUTHENTICATED 1
#elif CUBE_KEY_CASE == 9  // a 64-byte key: the longest allowed
#define CUBE_KEY_HEX                                                   \
  "00112233445566778899aabbccddeeff00112233445566778899aabbccddeeff" \
  "00112233445566778899aabbccddeeff00112233445566778899aabbccdd0f1e"
#else
#error "CUBE_KEY_CASE must be 1..9"
#endif

#include "build_auth.h"

// The accepted cases also parse to the right bytes, at compile time.
#if CUBE_KEY_CASE == 1
static_assert(!cube::build::kUnauthenticated, "keyed");
static_assert(cube::build::kKey.len == 32, "32 bytes");
static_assert(cube::build::kKey.bytes[0] == 0x00 &&
                  cube::build::kKey.bytes[15] == 0xff &&
                  cube::build::kKey.bytes[31] == 0xFF,
              "bytes");
#elif CUBE_KEY_CASE == 2
static_assert(cube::build::kUnauthenticated, "opt-out");
static_assert(cube::build::kKey.len == 0, "no key");
#elif CUBE_KEY_CASE == 9
static_assert(cube::build::kKey.len == 64, "64 bytes");
static_assert(cube::build::kKey.bytes[63] == 0x1e, "last byte");
#endif
