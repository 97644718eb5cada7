// Bounded text helpers for the protocol's messages: no allocation, never
// past the buffer, never half a UTF-8 sequence.
#ifndef CUBE_CORE_TEXT_H_
#define CUBE_CORE_TEXT_H_

#include <cstddef>
#include <cstdint>

namespace cube {

bool Equals(const char* a, const char* b);

// Copies src[0..len) into dst as a NUL-terminated string, cut to fit `cap`
// at a UTF-8 character boundary. Returns the bytes copied (the text may hold
// NUL bytes of its own).
size_t CopyText(char* dst, size_t cap, const char* src, size_t len);

// Replaces each run of control characters in s[0..len) (bytes 0x00..0x1F and
// 0x7F, and the two-byte UTF-8 C1 controls U+0080..U+009F) with one space,
// each byte that is not well-formed UTF-8 with '?', trims spaces at both ends, moves the text to the front of `s`, terminates
// it and returns its new length (protocol 1.1, section 5.12).
size_t SanitizeReason(char* s, size_t len);

// Small bounded text builder for error messages; what does not fit is
// dropped.
class Text {
 public:
  Text& S(const char* s);
  // `field` in double quotes.
  Text& Q(const char* field);
  Text& I(int64_t v);
  // As the replies write numbers; "?" when `v` cannot be written.
  Text& N(double v);
  const char* c_str() const { return buf_; }

 private:
  char buf_[160] = {};
  size_t n_ = 0;
};

}  // namespace cube

#endif  // CUBE_CORE_TEXT_H_
