#include "strict_json.h"

namespace cube::fuzz {

namespace {

constexpr int kDepthLimit = 64;  // the oracle's own recursion bound

class Parser {
 public:
  Parser(const char* s, size_t n, Document* doc) : s_(s), n_(n), doc_(doc) {}

  bool Whole() {
    Space();
    if (i_ < n_ && s_[i_] == '{') doc_->is_object = true;
    if (!Value(1, doc_->is_object)) return false;
    Space();
    return i_ == n_;
  }

 private:
  void Space() {
    while (i_ < n_ && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' ||
                       s_[i_] == '\r')) {
      ++i_;
    }
  }

  bool Literal(const char* word) {
    for (size_t k = 0; word[k] != '\0'; ++k, ++i_) {
      if (i_ >= n_ || s_[i_] != word[k]) return false;
    }
    return true;
  }

  static void Utf8(uint32_t cp, std::string* out) {
    if (cp < 0x80) {
      *out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      *out += static_cast<char>(0xC0 | (cp >> 6));
      *out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      *out += static_cast<char>(0xE0 | (cp >> 12));
      *out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      *out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      *out += static_cast<char>(0xF0 | (cp >> 18));
      *out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      *out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      *out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  bool Hex4(uint32_t* v) {
    *v = 0;
    for (int k = 0; k < 4; ++k, ++i_) {
      if (i_ >= n_) return false;
      const char c = s_[i_];
      uint32_t d;
      if (c >= '0' && c <= '9') {
        d = static_cast<uint32_t>(c - '0');
      } else if (c >= 'a' && c <= 'f') {
        d = static_cast<uint32_t>(c - 'a' + 10);
      } else if (c >= 'A' && c <= 'F') {
        d = static_cast<uint32_t>(c - 'A' + 10);
      } else {
        return false;
      }
      *v = (*v << 4) | d;
    }
    return true;
  }

  // Decodes a string; lone surrogates become U+FFFD in `out`.
  bool String(std::string* out) {
    ++i_;  // opening quote
    while (true) {
      if (i_ >= n_) return false;
      const unsigned char c = static_cast<unsigned char>(s_[i_++]);
      if (c == '"') return true;
      if (c < 0x20) return false;
      if (c != '\\') {
        *out += static_cast<char>(c);
        continue;
      }
      if (i_ >= n_) return false;
      const char e = s_[i_++];
      switch (e) {
        case '"': *out += '"'; break;
        case '\\': *out += '\\'; break;
        case '/': *out += '/'; break;
        case 'b': *out += '\b'; break;
        case 'f': *out += '\f'; break;
        case 'n': *out += '\n'; break;
        case 'r': *out += '\r'; break;
        case 't': *out += '\t'; break;
        case 'u': {
          uint32_t cp;
          if (!Hex4(&cp)) return false;
          if (cp >= 0xD800 && cp <= 0xDBFF && i_ + 1 < n_ && s_[i_] == '\\' &&
              s_[i_ + 1] == 'u') {
            const size_t save = i_;
            i_ += 2;
            uint32_t lo;
            if (!Hex4(&lo)) return false;
            if (lo >= 0xDC00 && lo <= 0xDFFF) {
              cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
            } else {
              i_ = save;
              cp = 0xFFFD;
            }
          } else if (cp >= 0xD800 && cp <= 0xDFFF) {
            cp = 0xFFFD;
          }
          if (cp == 0) doc_->has_nul_escape = true;
          Utf8(cp, out);
          break;
        }
        default:
          return false;
      }
    }
  }

  bool Digits() {
    const size_t start = i_;
    while (i_ < n_ && s_[i_] >= '0' && s_[i_] <= '9') ++i_;
    return i_ > start;
  }

  bool Number() {
    if (i_ < n_ && s_[i_] == '-') ++i_;
    if (i_ >= n_) return false;
    if (s_[i_] == '0') {
      ++i_;
    } else if (!Digits()) {
      return false;
    }
    if (i_ < n_ && s_[i_] == '.') {
      ++i_;
      if (!Digits()) return false;
    }
    if (i_ < n_ && (s_[i_] == 'e' || s_[i_] == 'E')) {
      ++i_;
      if (i_ < n_ && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
      if (!Digits()) return false;
    }
    return true;
  }

  // One value at nesting `depth` (objects and arrays count one level);
  // `top` records the members of the outermost object.
  bool Value(int depth, bool top, Member* m = nullptr) {
    Space();
    if (i_ >= n_) return false;
    const size_t start = i_;
    const char c = s_[i_];
    Kind kind;
    bool ok;
    std::string str;
    if (c == '{' || c == '[') {
      if (depth > kDepthLimit) return false;
      if (depth > doc_->max_depth) doc_->max_depth = depth;
      kind = c == '{' ? Kind::kObject : Kind::kArray;
      ok = Container(c == '{', depth, top);
    } else if (c == '"') {
      kind = Kind::kString;
      ok = String(&str);
    } else if (c == 't' || c == 'f') {
      kind = Kind::kBool;
      ok = Literal(c == 't' ? "true" : "false");
    } else if (c == 'n') {
      kind = Kind::kNull;
      ok = Literal("null");
    } else {
      kind = Kind::kNumber;
      ok = Number();
    }
    if (ok && m != nullptr) {
      m->kind = kind;
      m->text.assign(s_ + start, i_ - start);
      m->str = str;
      m->boolean = c == 't';
    }
    return ok;
  }

  bool Container(bool object, int depth, bool top) {
    const char close = object ? '}' : ']';
    ++i_;
    Space();
    if (i_ < n_ && s_[i_] == close) {
      ++i_;
      return true;
    }
    while (true) {
      Space();
      Member m;
      if (object) {
        if (i_ >= n_ || s_[i_] != '"' || !String(&m.key)) return false;
        Space();
        if (i_ >= n_ || s_[i_] != ':') return false;
        ++i_;
      }
      if (!Value(depth + 1, false, &m)) return false;
      if (top) doc_->members.push_back(m);
      Space();
      if (i_ >= n_) return false;
      if (s_[i_] == ',') {
        ++i_;
        continue;
      }
      if (s_[i_] != close) return false;
      ++i_;
      return true;
    }
  }

  const char* s_;
  size_t n_;
  Document* doc_;
  size_t i_ = 0;
};

}  // namespace

Document ParseStrict(const char* text, size_t len) {
  Document doc;
  Parser p(text, len, &doc);
  doc.valid = p.Whole();
  if (!doc.valid) doc.members.clear();
  return doc;
}

bool IsValidUtf8(const char* text, size_t len) {
  const auto* s = reinterpret_cast<const unsigned char*>(text);
  size_t i = 0;
  while (i < len) {
    const unsigned char c = s[i];
    size_t extra;
    uint32_t cp;
    if (c < 0x80) {
      ++i;
      continue;
    } else if ((c & 0xE0) == 0xC0) {
      extra = 1;
      cp = c & 0x1Fu;
    } else if ((c & 0xF0) == 0xE0) {
      extra = 2;
      cp = c & 0x0Fu;
    } else if ((c & 0xF8) == 0xF0) {
      extra = 3;
      cp = c & 0x07u;
    } else {
      return false;
    }
    for (size_t k = 1; k <= extra; ++k) {
      if (i + k >= len || (s[i + k] & 0xC0) != 0x80) return false;
      cp = (cp << 6) | (s[i + k] & 0x3Fu);
    }
    static const uint32_t kMin[] = {0, 0x80, 0x800, 0x10000};
    if (cp < kMin[extra] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) {
      return false;
    }
    i += extra + 1;
  }
  return true;
}

}  // namespace cube::fuzz
