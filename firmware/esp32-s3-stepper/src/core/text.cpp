#include "text.h"

#include <cstring>

#include "json_number.h"

namespace cube {

bool Equals(const char* a, const char* b) { return std::strcmp(a, b) == 0; }

void CopyText(char* dst, size_t cap, const char* src, size_t len) {
  if (cap == 0) return;
  size_t n = len < cap - 1 ? len : cap - 1;
  // Do not cut a UTF-8 sequence in half.
  while (n > 0 && n < len &&
         (static_cast<unsigned char>(src[n]) & 0xC0) == 0x80) {
    --n;
  }
  std::memcpy(dst, src, n);
  dst[n] = '\0';
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
