#include "text.h"

#include <cstring>

#include "json_number.h"

namespace cube {

bool Equals(const char* a, const char* b) { return std::strcmp(a, b) == 0; }

size_t CopyText(char* dst, size_t cap, const char* src, size_t len) {
  if (cap == 0) return 0;
  size_t n = len < cap - 1 ? len : cap - 1;
  // Do not cut a UTF-8 sequence in half.
  while (n > 0 && n < len &&
         (static_cast<unsigned char>(src[n]) & 0xC0) == 0x80) {
    --n;
  }
  std::memcpy(dst, src, n);
  dst[n] = '\0';
  return n;
}

namespace {

// The length of the well-formed UTF-8 sequence at s[i] (RFC 3629: no
// overlong forms, no surrogates, nothing above U+10FFFF), or 0.
size_t Utf8SequenceAt(const unsigned char* s, size_t i, size_t len) {
  const unsigned char c = s[i];
  if (c < 0x80) return 1;
  size_t n = 0;
  unsigned char lo = 0x80;
  unsigned char hi = 0xBF;
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    if (c == 0xE0) lo = 0xA0;
    if (c == 0xED) hi = 0x9F;
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    if (c == 0xF0) lo = 0x90;
    if (c == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (i + n > len) return 0;
  if (s[i + 1] < lo || s[i + 1] > hi) return 0;
  for (size_t k = 2; k < n; ++k) {
    if ((s[i + k] & 0xC0) != 0x80) return 0;
  }
  return n;
}

}  // namespace

size_t SanitizeReason(char* s, size_t len) {
  auto* u = reinterpret_cast<unsigned char*>(s);
  size_t out = 0;
  bool in_control = false;
  for (size_t i = 0; i < len;) {
    const unsigned char c = u[i];
    const size_t n = Utf8SequenceAt(u, i, len);
    const bool c1 = n == 2 && c == 0xC2 && u[i + 1] <= 0x9F;
    if (n == 1 && (c < 0x20 || c == 0x7F)) {
      if (!in_control) u[out++] = ' ';
      in_control = true;
      ++i;
      continue;
    }
    if (c1) {
      if (!in_control) u[out++] = ' ';
      in_control = true;
      i += 2;
      continue;
    }
    in_control = false;
    if (n == 0) {
      // A byte that is not well-formed UTF-8 (the reply must stay valid
      // JSON text): one '?' in its place.
      u[out++] = '?';
      ++i;
      continue;
    }
    for (size_t k = 0; k < n; ++k) u[out++] = u[i + k];
    i += n;
  }
  size_t start = 0;
  while (start < out && s[start] == ' ') ++start;
  while (out > start && s[out - 1] == ' ') --out;
  const size_t n = out - start;
  for (size_t i = 0; i < n; ++i) s[i] = s[start + i];
  s[n] = '\0';
  return n;
}

Text& Text::S(const char* s) {
  while (*s != '\0' && n_ + 1 < sizeof(buf_)) buf_[n_++] = *s++;
  // Cut inside a UTF-8 sequence: drop its first bytes too.
  if ((static_cast<unsigned char>(*s) & 0xC0) == 0x80) {
    while (n_ > 0 && (static_cast<unsigned char>(buf_[n_ - 1]) & 0xC0) == 0x80)
      --n_;
    if (n_ > 0 && (static_cast<unsigned char>(buf_[n_ - 1]) & 0xC0) == 0xC0)
      --n_;
  }
  buf_[n_] = '\0';
  return *this;
}

Text& Text::Q(const char* field) { return S("\"").S(field).S("\""); }

Text& Text::I(int64_t v) {
  char tmp[24];
  const size_t k = FormatInt(v, tmp, sizeof(tmp));
  tmp[k] = '\0';
  return S(tmp);
}

Text& Text::N(double v) {
  char tmp[40];
  const size_t k = FormatNumber(v, tmp, sizeof(tmp) - 1);
  tmp[k] = '\0';
  return S(k == 0 ? "?" : tmp);
}

}  // namespace cube
