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

size_t SanitizeReason(char* s, size_t len) {
  size_t out = 0;
  bool in_control = false;
  for (size_t i = 0; i < len; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    const bool c1 = c == 0xC2 && i + 1 < len &&
                    static_cast<unsigned char>(s[i + 1]) >= 0x80 &&
                    static_cast<unsigned char>(s[i + 1]) <= 0x9F;
    if (c < 0x20 || c == 0x7F || c1) {
      if (c1) ++i;
      if (!in_control) s[out++] = ' ';
      in_control = true;
      continue;
    }
    in_control = false;
    s[out++] = s[i];
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
