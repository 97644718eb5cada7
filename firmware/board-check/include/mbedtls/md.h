// Declarations for a signature check (see Arduino.h): mirrors
// include/mbedtls/md.h of Mbed TLS 3.5 as ESP-IDF 5.1 ships it
// (espressif/esp32-arduino-libs, <chip>/include/mbedtls/mbedtls/include/
// mbedtls/md.h, MBEDTLS_VERSION_STRING "3.5.2"). Since 3.5 the digest
// types carry the PSA algorithm numbers (SHA-256 is 0x09), not 0, 1, 2...
// MBEDTLS_CHECK_RETURN_TYPICAL, on mbedtls_md_hmac there, expands to
// nothing in IDF's configuration.
#ifndef BOARD_CHECK_MBEDTLS_MD_H_
#define BOARD_CHECK_MBEDTLS_MD_H_
#include <stddef.h>
extern "C" {
typedef enum {
  MBEDTLS_MD_NONE = 0,
  MBEDTLS_MD_MD5 = 0x03,
  MBEDTLS_MD_RIPEMD160 = 0x04,
  MBEDTLS_MD_SHA1 = 0x05,
  MBEDTLS_MD_SHA224 = 0x08,
  MBEDTLS_MD_SHA256 = 0x09,
  MBEDTLS_MD_SHA384 = 0x0a,
  MBEDTLS_MD_SHA512 = 0x0b,
  MBEDTLS_MD_SHA3_224 = 0x10,
  MBEDTLS_MD_SHA3_256 = 0x11,
  MBEDTLS_MD_SHA3_384 = 0x12,
  MBEDTLS_MD_SHA3_512 = 0x13,
} mbedtls_md_type_t;
typedef struct mbedtls_md_info_t mbedtls_md_info_t;
const mbedtls_md_info_t *mbedtls_md_info_from_type(mbedtls_md_type_t md_type);
int mbedtls_md_hmac(const mbedtls_md_info_t *md_info, const unsigned char *key,
                    size_t keylen, const unsigned char *input, size_t ilen,
                    unsigned char *output);
}
#endif  // BOARD_CHECK_MBEDTLS_MD_H_
