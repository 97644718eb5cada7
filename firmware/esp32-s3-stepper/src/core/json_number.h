// JSON number text, both ways: scanning a number token into a double (and an
// exact integer when it is one), and writing numbers the way the protocol's
// replies carry them. No allocation, no locale, no exponent on output.
#ifndef CUBE_CORE_JSON_NUMBER_H_
#define CUBE_CORE_JSON_NUMBER_H_

#include <cstddef>
#include <cstdint>

namespace cube {

enum class JsonNumberScan : uint8_t { kOk, kBad, kTruncated };

struct JsonNumber {
  double number = 0.0;
  bool is_integer = false;  // integral and fits int64 exactly
  int64_t integer = 0;
};

// Scans a JSON number at s[0..len) and reports how many bytes it used.
JsonNumberScan ScanJsonNumber(const char* s, size_t len, size_t* used,
                              JsonNumber* out);

// Parses a JSON number token (as produced by the writer) into a double.
// Returns false when `text` is not a complete JSON number.
bool ParseJsonNumber(const char* text, size_t len, double* out);

// Writes `v` as text (no quotes) into `out`; the same format as
// JsonWriter::Double. Returns the length, or 0 when it does not fit.
size_t FormatNumber(double v, char* out, size_t cap);
size_t FormatInt(int64_t v, char* out, size_t cap);
size_t FormatUint(uint64_t v, char* out, size_t cap);

}  // namespace cube

#endif  // CUBE_CORE_JSON_NUMBER_H_
