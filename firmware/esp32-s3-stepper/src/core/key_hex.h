// The pre-shared key written as hex (docs/protocol.md section 8), parsed at
// compile time: the sketch turns CUBE_KEY_HEX into bytes with these
// functions inside static_asserts (src/platform/build_auth.h), so a
// malformed key is a build error, never a robot that silently runs without
// authentication.
#ifndef CUBE_CORE_KEY_HEX_H_
#define CUBE_CORE_KEY_HEX_H_

#include <cstddef>
#include <cstdint>

namespace cube {

// A key is 1..64 bytes.
constexpr size_t kMaxKeyLen = 64;

enum class KeyHexError : uint8_t { kOk, kEmpty, kNotHex, kOddLength, kTooLong };

constexpr size_t ConstTextLength(const char* s) {
  size_t n = 0;
  while (s[n] != '\0') ++n;
  return n;
}

// 0..15, or -1 when `c` is not a hex digit (either case).
constexpr int HexDigitValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// What is wrong with `hex` as a key, checked in this order: empty, a
// character that is not a hex digit, an odd number of digits, more than
// kMaxKeyLen bytes.
constexpr KeyHexError CheckKeyHex(const char* hex) {
  const size_t n = ConstTextLength(hex);
  if (n == 0) return KeyHexError::kEmpty;
  for (size_t i = 0; i < n; ++i) {
    if (HexDigitValue(hex[i]) < 0) return KeyHexError::kNotHex;
  }
  if (n % 2 != 0) return KeyHexError::kOddLength;
  if (n / 2 > kMaxKeyLen) return KeyHexError::kTooLong;
  return KeyHexError::kOk;
}

struct KeyBytes {
  uint8_t bytes[kMaxKeyLen];
  size_t len;
};

// The key's bytes; len 0 when CheckKeyHex(hex) is not kOk.
constexpr KeyBytes ParseKeyHex(const char* hex) {
  KeyBytes k{};
  if (CheckKeyHex(hex) != KeyHexError::kOk) return k;
  k.len = ConstTextLength(hex) / 2;
  for (size_t i = 0; i < k.len; ++i) {
    k.bytes[i] = static_cast<uint8_t>(HexDigitValue(hex[2 * i]) * 16 +
                                      HexDigitValue(hex[2 * i + 1]));
  }
  return k;
}

}  // namespace cube

#endif  // CUBE_CORE_KEY_HEX_H_
