#include "json_reader.h"

#include <cstring>

#include "json_number.h"

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

bool IsDigit(char c) { return c >= '0' && c <= '9'; }

int HexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

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
  JsonNumber v;
  const JsonNumberScan r = ScanJsonNumber(&buf_[pos_], len_ - pos_, &used, &v);
  if (r == JsonNumberScan::kTruncated) {
    error_ = JsonError::kTruncated;
    return false;
  }
  if (r == JsonNumberScan::kBad) {
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

}  // namespace cube
