#include "json_number.h"

#include <cmath>

namespace cube {

namespace {

constexpr double kExactPow10[] = {
    1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

constexpr uint64_t kPow10U64[] = {1ULL,
                                  10ULL,
                                  100ULL,
                                  1000ULL,
                                  10000ULL,
                                  100000ULL,
                                  1000000ULL,
                                  10000000ULL,
                                  100000000ULL,
                                  1000000000ULL,
                                  10000000000ULL,
                                  100000000000ULL,
                                  1000000000000ULL,
                                  10000000000000ULL,
                                  100000000000000ULL,
                                  1000000000000000ULL,
                                  10000000000000000ULL,
                                  100000000000000000ULL,
                                  1000000000000000000ULL,
                                  10000000000000000000ULL};

bool IsDigit(char c) { return c >= '0' && c <= '9'; }

size_t AppendDigits(uint64_t v, char* out, size_t cap) {
  char tmp[24];
  size_t n = 0;
  do {
    tmp[n++] = static_cast<char>('0' + v % 10);
    v /= 10;
  } while (v != 0);
  if (n > cap) return 0;
  for (size_t i = 0; i < n; ++i) out[i] = tmp[n - 1 - i];
  return n;
}

}  // namespace

JsonNumberScan ScanJsonNumber(const char* s, size_t len, size_t* used,
                              JsonNumber* out) {
  size_t i = 0;
  bool neg = false;
  if (i < len && s[i] == '-') {
    neg = true;
    ++i;
  }
  if (i >= len) return JsonNumberScan::kTruncated;
  if (!IsDigit(s[i])) return JsonNumberScan::kBad;
  uint64_t mant = 0;
  int sig = 0;
  int64_t exp10 = 0;
  bool dropped = false;
  auto take = [&](char c, bool frac) {
    const uint64_t d = static_cast<uint64_t>(c - '0');
    if (mant == 0 && d == 0) {
      if (frac) --exp10;
      return;
    }
    if (sig < 19) {
      mant = mant * 10 + d;
      ++sig;
      if (frac) --exp10;
    } else {
      if (d != 0) dropped = true;
      if (!frac) ++exp10;
    }
  };
  if (s[i] == '0') {
    ++i;
  } else {
    while (i < len && IsDigit(s[i])) take(s[i++], false);
  }
  if (i < len && s[i] == '.') {
    ++i;
    if (i >= len) return JsonNumberScan::kTruncated;
    if (!IsDigit(s[i])) return JsonNumberScan::kBad;
    while (i < len && IsDigit(s[i])) take(s[i++], true);
  }
  if (i < len && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool eneg = false;
    if (i < len && (s[i] == '+' || s[i] == '-')) {
      eneg = s[i] == '-';
      ++i;
    }
    if (i >= len) return JsonNumberScan::kTruncated;
    if (!IsDigit(s[i])) return JsonNumberScan::kBad;
    int64_t e = 0;
    while (i < len && IsDigit(s[i])) {
      if (e < 100000) e = e * 10 + (s[i] - '0');
      ++i;
    }
    exp10 += eneg ? -e : e;
  }
  *used = i;

  // Trailing zeros carry no value: without them a mantissa written with many
  // (999999.00000000000) still fits the exact fast path below.
  while (mant != 0 && mant % 10 == 0) {
    mant /= 10;
    ++exp10;
  }

  double value;
  if (mant == 0) {
    value = 0.0;
  } else if (mant <= (1ULL << 53) && exp10 >= -22 && exp10 <= 22) {
    const double m = static_cast<double>(mant);
    value = exp10 >= 0 ? m * kExactPow10[exp10] : m / kExactPow10[-exp10];
  } else if (exp10 < -300) {
    value = static_cast<double>(mant) * std::pow(10.0, -300.0) *
            std::pow(10.0, static_cast<double>(exp10 + 300));
  } else {
    value = static_cast<double>(mant) *
            std::pow(10.0, static_cast<double>(exp10 > 400 ? 400 : exp10));
  }
  out->number = neg ? -value : value;

  out->is_integer = false;
  if (!dropped) {
    uint64_t whole = 0;
    bool exact = false;
    if (mant == 0) {
      exact = true;
    } else if (exp10 >= 0 && exp10 <= 19) {
      whole = mant;
      exact = true;
      for (int64_t k = 0; k < exp10; ++k) {
        if (whole > UINT64_MAX / 10) {
          exact = false;
          break;
        }
        whole *= 10;
      }
    } else if (exp10 < 0 && exp10 >= -19) {
      const uint64_t div = kPow10U64[-exp10];
      if (mant % div == 0) {
        whole = mant / div;
        exact = true;
      }
    }
    if (exact && whole <= static_cast<uint64_t>(INT64_MAX)) {
      out->is_integer = true;
      out->integer =
          neg ? -static_cast<int64_t>(whole) : static_cast<int64_t>(whole);
      // One correctly rounded conversion: mantissa times a power of ten
      // rounds twice above 2^53, and the two views must agree.
      out->number = static_cast<double>(out->integer);
    }
  }
  return JsonNumberScan::kOk;
}

bool ParseJsonNumber(const char* text, size_t len, double* out) {
  size_t used = 0;
  JsonNumber v;
  if (ScanJsonNumber(text, len, &used, &v) != JsonNumberScan::kOk ||
      used != len) {
    return false;
  }
  *out = v.number;
  return true;
}

size_t FormatUint(uint64_t v, char* out, size_t cap) {
  return AppendDigits(v, out, cap);
}

size_t FormatInt(int64_t v, char* out, size_t cap) {
  if (v >= 0) return AppendDigits(static_cast<uint64_t>(v), out, cap);
  if (cap < 2) return 0;
  out[0] = '-';
  const uint64_t mag = static_cast<uint64_t>(-(v + 1)) + 1;
  const size_t n = AppendDigits(mag, out + 1, cap - 1);
  return n == 0 ? 0 : n + 1;
}

size_t FormatNumber(double v, char* out, size_t cap) {
  if (!std::isfinite(v)) return 0;
  double a = std::fabs(v);
  if (a >= 1.8e19) return 0;
  uint64_t ip = static_cast<uint64_t>(std::floor(a));
  uint64_t frac = 0;
  if (a < 1e15) {
    const double f = std::floor((a - std::floor(a)) * 1e9 + 0.5);
    frac = static_cast<uint64_t>(f);
    if (frac >= 1000000000ULL) {
      frac -= 1000000000ULL;
      ip += 1;
    }
  }
  size_t n = 0;
  if (std::signbit(v) && (ip != 0 || frac != 0)) {
    if (cap < 1) return 0;
    out[n++] = '-';
  }
  const size_t d = AppendDigits(ip, out + n, cap - n);
  if (d == 0) return 0;
  n += d;
  if (frac != 0) {
    char digits[9];
    for (int i = 8; i >= 0; --i) {
      digits[i] = static_cast<char>('0' + frac % 10);
      frac /= 10;
    }
    size_t keep = 9;
    while (keep > 0 && digits[keep - 1] == '0') --keep;
    if (n + 1 + keep > cap) return 0;
    out[n++] = '.';
    for (size_t i = 0; i < keep; ++i) out[n++] = digits[i];
  }
  return n;
}

}  // namespace cube
