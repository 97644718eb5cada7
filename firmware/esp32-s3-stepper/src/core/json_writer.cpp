#include "json_writer.h"

#include <cstring>

#include "json_number.h"

namespace cube {

JsonWriter::JsonWriter(char* buf, size_t cap) : buf_(buf), cap_(cap) {}

void JsonWriter::Put(char c) {
  if (len_ + 1 > cap_) {
    ok_ = false;
    return;
  }
  buf_[len_++] = c;
}

void JsonWriter::Put(const char* s, size_t n) {
  if (len_ + n > cap_) {
    ok_ = false;
    return;
  }
  std::memcpy(buf_ + len_, s, n);
  len_ += n;
}

void JsonWriter::BeforeValue() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (depth_ > 0) {
    if (!first_[depth_]) Put(',');
    first_[depth_] = false;
  }
}

void JsonWriter::BeginObject() {
  BeforeValue();
  Put('{');
  if (depth_ + 1 >= static_cast<int>(sizeof(first_))) {
    ok_ = false;
    return;
  }
  first_[++depth_] = true;
}

void JsonWriter::EndObject() {
  Put('}');
  if (depth_ > 0) --depth_;
}

void JsonWriter::BeginArray() {
  BeforeValue();
  Put('[');
  if (depth_ + 1 >= static_cast<int>(sizeof(first_))) {
    ok_ = false;
    return;
  }
  first_[++depth_] = true;
}

void JsonWriter::EndArray() {
  Put(']');
  if (depth_ > 0) --depth_;
}

void JsonWriter::Key(const char* key) {
  BeforeValue();
  PutQuoted(key, std::strlen(key));
  Put(':');
  after_key_ = true;
}

void JsonWriter::String(const char* s) { String(s, std::strlen(s)); }

void JsonWriter::String(const char* s, size_t n) {
  BeforeValue();
  PutQuoted(s, n);
}

void JsonWriter::PutQuoted(const char* s, size_t n) {
  Put('"');
  for (size_t i = 0; i < n; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c == '"' || c == '\\') {
      Put('\\');
      Put(static_cast<char>(c));
    } else if (c == '\n') {
      Put("\\n", 2);
    } else if (c == '\r') {
      Put("\\r", 2);
    } else if (c == '\t') {
      Put("\\t", 2);
    } else if (c < 0x20) {
      static const char kHex[] = "0123456789abcdef";
      char esc[6] = {'\\', 'u', '0', '0', kHex[c >> 4], kHex[c & 0xF]};
      Put(esc, 6);
    } else {
      Put(static_cast<char>(c));
    }
  }
  Put('"');
}

void JsonWriter::Int(int64_t v) {
  BeforeValue();
  char tmp[24];
  Put(tmp, FormatInt(v, tmp, sizeof(tmp)));
}

void JsonWriter::Uint(uint64_t v) {
  BeforeValue();
  char tmp[24];
  Put(tmp, FormatUint(v, tmp, sizeof(tmp)));
}

void JsonWriter::Double(double v) {
  char tmp[40];
  const size_t n = FormatNumber(v, tmp, sizeof(tmp));
  if (n == 0) {
    Null();
    return;
  }
  BeforeValue();
  Put(tmp, n);
}

void JsonWriter::Bool(bool v) {
  BeforeValue();
  if (v) {
    Put("true", 4);
  } else {
    Put("false", 5);
  }
}

void JsonWriter::Null() {
  BeforeValue();
  Put("null", 4);
}

void JsonWriter::Raw(const char* s, size_t n) {
  BeforeValue();
  Put(s, n);
}

}  // namespace cube
