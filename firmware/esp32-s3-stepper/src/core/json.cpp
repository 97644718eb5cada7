#include "json.h"

#include <cmath>
#include <cstring>

namespace cube {

const char* JsonErrorText(JsonError e) {
  switch (e) {
    case JsonError::kOk:
      return "ok";
    case JsonError::kEmpty:
      return "empty message";
    case JsonError::kTooLong:
      return "message longer than 1024 bytes";
    case JsonError::kNotAnObject:
      return "message is not a JSON object";
    case JsonError::kSyntax:
      return "invalid JSON";
    case JsonError::kTruncated:
      return "truncated JSON";
    case JsonError::kTooDeep:
      return "JSON nested deeper than 8 levels";
    case JsonError::kTooManyFields:
      return "more than 32 fields";
    case JsonError::kDuplicateKey:
      return "duplicated key";
    case JsonError::kTrailingData:
      return "data after the JSON object";
  }
  return "invalid JSON";
}

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

int HexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

enum class NumScan : uint8_t { kOk, kBad, kTruncated };

struct NumberValue {
  double number = 0.0;
  bool is_integer = false;
  int64_t integer = 0;
};

// Scans a JSON number at s[0..len) and reports how many bytes it used.
NumScan ScanNumber(const char* s, size_t len, size_t* used, NumberValue* out) {
  size_t i = 0;
  bool neg = false;
  if (i < len && s[i] == '-') {
    neg = true;
    ++i;
  }
  if (i >= len) return NumScan::kTruncated;
  if (!IsDigit(s[i])) return NumScan::kBad;
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
    if (i >= len) return NumScan::kTruncated;
    if (!IsDigit(s[i])) return NumScan::kBad;
    while (i < len && IsDigit(s[i])) take(s[i++], true);
  }
  if (i < len && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool eneg = false;
    if (i < len && (s[i] == '+' || s[i] == '-')) {
      eneg = s[i] == '-';
      ++i;
    }
    if (i >= len) return NumScan::kTruncated;
    if (!IsDigit(s[i])) return NumScan::kBad;
    int64_t e = 0;
    while (i < len && IsDigit(s[i])) {
      if (e < 100000) e = e * 10 + (s[i] - '0');
      ++i;
    }
    exp10 += eneg ? -e : e;
  }
  *used = i;

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
    }
  }
  return NumScan::kOk;
}

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

bool ParseJsonNumber(const char* text, size_t len, double* out) {
  size_t used = 0;
  NumberValue v;
  if (ScanNumber(text, len, &used, &v) != NumScan::kOk || used != len) {
    return false;
  }
  *out = v.number;
  return true;
}

void JsonReader::SkipSpace() {
  while (pos_ < len_) {
    const char c = buf_[pos_];
    if (c != ' ' && c != '\t' && c != '\n' && c != '\r') break;
    ++pos_;
  }
}

bool JsonReader::ParseString(const char** out, size_t* out_len) {
  // buf_[pos_] is the opening quote. Decodes in place over the raw text,
  // which is never shorter than the decoded text.
  const size_t start = pos_;
  size_t w = start;
  ++pos_;
  while (true) {
    if (pos_ >= len_) {
      error_ = JsonError::kTruncated;
      return false;
    }
    const char c = buf_[pos_++];
    if (c == '"') break;
    if (static_cast<unsigned char>(c) < 0x20) {
      error_ = JsonError::kSyntax;
      return false;
    }
    if (c != '\\') {
      buf_[w++] = c;
      continue;
    }
    if (pos_ >= len_) {
      error_ = JsonError::kTruncated;
      return false;
    }
    const char e = buf_[pos_++];
    switch (e) {
      case '"':
      case '\\':
      case '/':
        buf_[w++] = e;
        break;
      case 'b':
        buf_[w++] = '\b';
        break;
      case 'f':
        buf_[w++] = '\f';
        break;
      case 'n':
        buf_[w++] = '\n';
        break;
      case 'r':
        buf_[w++] = '\r';
        break;
      case 't':
        buf_[w++] = '\t';
        break;
      case 'u': {
        auto read_hex4 = [&](uint32_t* cp) {
          if (pos_ + 4 > len_) {
            error_ = JsonError::kTruncated;
            return false;
          }
          uint32_t v = 0;
          for (int i = 0; i < 4; ++i) {
            const int h = HexValue(buf_[pos_++]);
            if (h < 0) {
              error_ = JsonError::kSyntax;
              return false;
            }
            v = (v << 4) | static_cast<uint32_t>(h);
          }
          *cp = v;
          return true;
        };
        uint32_t cp = 0;
        if (!read_hex4(&cp)) return false;
        if (cp >= 0xD800 && cp <= 0xDBFF && pos_ + 1 < len_ &&
            buf_[pos_] == '\\' && buf_[pos_ + 1] == 'u') {
          const size_t save = pos_;
          pos_ += 2;
          uint32_t lo = 0;
          if (!read_hex4(&lo)) return false;
          if (lo >= 0xDC00 && lo <= 0xDFFF) {
            cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
          } else {
            pos_ = save;
            cp = 0xFFFD;
          }
        } else if (cp >= 0xD800 && cp <= 0xDFFF) {
          cp = 0xFFFD;
        }
        if (cp == 0) {
          error_ = JsonError::kSyntax;  // NUL cannot live in a C string
          return false;
        }
        if (cp < 0x80) {
          buf_[w++] = static_cast<char>(cp);
        } else if (cp < 0x800) {
          buf_[w++] = static_cast<char>(0xC0 | (cp >> 6));
          buf_[w++] = static_cast<char>(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
          buf_[w++] = static_cast<char>(0xE0 | (cp >> 12));
          buf_[w++] = static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
          buf_[w++] = static_cast<char>(0x80 | (cp & 0x3F));
        } else {
          buf_[w++] = static_cast<char>(0xF0 | (cp >> 18));
          buf_[w++] = static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
          buf_[w++] = static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
          buf_[w++] = static_cast<char>(0x80 | (cp & 0x3F));
        }
        break;
      }
      default:
        error_ = JsonError::kSyntax;
        return false;
    }
  }
  buf_[w] = '\0';  // w < pos_: the closing quote's slot at the latest
  *out = &buf_[start];
  *out_len = w - start;
  return true;
}

bool JsonReader::ParseNumber(JsonField* out) {
  size_t used = 0;
  NumberValue v;
  const NumScan r = ScanNumber(&buf_[pos_], len_ - pos_, &used, &v);
  if (r == NumScan::kTruncated) {
    error_ = JsonError::kTruncated;
    return false;
  }
  if (r == NumScan::kBad) {
    error_ = JsonError::kSyntax;
    return false;
  }
  pos_ += used;
  out->type = JsonType::kNumber;
  out->number = v.number;
  out->is_integer = v.is_integer;
  out->integer = v.integer;
  return true;
}

bool JsonReader::SkipNested(int depth) {
  // buf_[pos_] is '{' or '['.
  if (depth > kMaxDepth) {
    error_ = JsonError::kTooDeep;
    return false;
  }
  const bool is_object = buf_[pos_] == '{';
  const char close = is_object ? '}' : ']';
  ++pos_;
  SkipSpace();
  if (pos_ >= len_) {
    error_ = JsonError::kTruncated;
    return false;
  }
  if (buf_[pos_] == close) {
    ++pos_;
    return true;
  }
  while (true) {
    SkipSpace();
    if (pos_ >= len_) {
      error_ = JsonError::kTruncated;
      return false;
    }
    if (is_object) {
      if (buf_[pos_] != '"') {
        error_ = JsonError::kSyntax;
        return false;
      }
      const char* k;
      size_t kl;
      if (!ParseString(&k, &kl)) return false;
      SkipSpace();
      if (pos_ >= len_) {
        error_ = JsonError::kTruncated;
        return false;
      }
      if (buf_[pos_] != ':') {
        error_ = JsonError::kSyntax;
        return false;
      }
      ++pos_;
    }
    JsonField scratch;
    if (!ParseValue(&scratch, depth)) return false;
    SkipSpace();
    if (pos_ >= len_) {
      error_ = JsonError::kTruncated;
      return false;
    }
    if (buf_[pos_] == ',') {
      ++pos_;
      continue;
    }
    if (buf_[pos_] == close) {
      ++pos_;
      return true;
    }
    error_ = JsonError::kSyntax;
    return false;
  }
}

bool JsonReader::ParseValue(JsonField* out, int depth) {
  SkipSpace();
  if (pos_ >= len_) {
    error_ = JsonError::kTruncated;
    return false;
  }
  const char c = buf_[pos_];
  auto literal = [&](const char* word, size_t n) {
    for (size_t i = 0; i < n; ++i) {
      if (pos_ + i >= len_) {
        error_ = JsonError::kTruncated;
        return false;
      }
      if (buf_[pos_ + i] != word[i]) {
        error_ = JsonError::kSyntax;
        return false;
      }
    }
    pos_ += n;
    return true;
  };
  switch (c) {
    case '"':
      out->type = JsonType::kString;
      return ParseString(&out->str, &out->str_len);
    case 't':
      out->type = JsonType::kBool;
      out->boolean = true;
      return literal("true", 4);
    case 'f':
      out->type = JsonType::kBool;
      out->boolean = false;
      return literal("false", 5);
    case 'n':
      out->type = JsonType::kNull;
      return literal("null", 4);
    case '{':
    case '[':
      out->type = JsonType::kNested;
      return SkipNested(depth + 1);
    default:
      if (c == '-' || IsDigit(c)) return ParseNumber(out);
      error_ = JsonError::kSyntax;
      return false;
  }
}

JsonError JsonReader::Parse(const char* data, size_t len) {
  count_ = 0;
  pos_ = 0;
  error_ = JsonError::kOk;
  if (len > kMaxInput) return JsonError::kTooLong;
  std::memcpy(buf_, data, len);
  buf_[len] = '\0';
  len_ = len;
  SkipSpace();
  if (pos_ >= len_) return JsonError::kEmpty;
  if (buf_[pos_] != '{') return JsonError::kNotAnObject;
  ++pos_;
  SkipSpace();
  if (pos_ >= len_) return JsonError::kTruncated;
  if (buf_[pos_] == '}') {
    ++pos_;
  } else {
    while (true) {
      SkipSpace();
      if (pos_ >= len_) return JsonError::kTruncated;
      if (buf_[pos_] != '"') return JsonError::kSyntax;
      JsonField f;
      if (!ParseString(&f.key, &f.key_len)) return error_;
      SkipSpace();
      if (pos_ >= len_) return JsonError::kTruncated;
      if (buf_[pos_] != ':') return JsonError::kSyntax;
      ++pos_;
      if (!ParseValue(&f, 1)) return error_;
      for (size_t i = 0; i < count_; ++i) {
        if (fields_[i].key_len == f.key_len &&
            std::memcmp(fields_[i].key, f.key, f.key_len) == 0) {
          return JsonError::kDuplicateKey;
        }
      }
      if (count_ >= kMaxFields) return JsonError::kTooManyFields;
      fields_[count_++] = f;
      SkipSpace();
      if (pos_ >= len_) return JsonError::kTruncated;
      if (buf_[pos_] == ',') {
        ++pos_;
        continue;
      }
      if (buf_[pos_] == '}') {
        ++pos_;
        break;
      }
      return JsonError::kSyntax;
    }
  }
  SkipSpace();
  if (pos_ != len_) return JsonError::kTrailingData;
  return JsonError::kOk;
}

const JsonField* JsonReader::Find(const char* key) const {
  const size_t n = std::strlen(key);
  for (size_t i = 0; i < count_; ++i) {
    const JsonField& f = fields_[i];
    if (f.key_len == n && std::memcmp(f.key, key, n) == 0) {
      return f.type == JsonType::kNull ? nullptr : &f;
    }
  }
  return nullptr;
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
