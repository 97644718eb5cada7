// A bounded, allocation-free JSON codec for the protocol's flat messages.
//
// JsonReader parses one top-level object of at most kMaxInput bytes into a
// fixed table of fields. Nested objects and arrays are checked for syntax and
// skipped (type kNested), so unknown structured fields are ignored.
// JsonWriter appends JSON to a caller-owned buffer and records overflow.
#ifndef CUBE_CORE_JSON_H_
#define CUBE_CORE_JSON_H_

#include <cstddef>
#include <cstdint>

namespace cube {

enum class JsonType : uint8_t { kNull, kBool, kNumber, kString, kNested };

struct JsonField {
  const char* key = nullptr;
  size_t key_len = 0;
  JsonType type = JsonType::kNull;
  bool boolean = false;
  double number = 0.0;
  bool is_integer = false;  // number is integral and fits int64 exactly
  int64_t integer = 0;
  const char* str = nullptr;  // NUL-terminated, decoded (escapes resolved)
  size_t str_len = 0;
};

enum class JsonError : uint8_t {
  kOk,
  kEmpty,
  kTooLong,
  kNotAnObject,
  kSyntax,
  kTruncated,
  kTooDeep,
  kTooManyFields,
  kDuplicateKey,
  kTrailingData,
};

// Human-readable reason for a parse error.
const char* JsonErrorText(JsonError e);

class JsonReader {
 public:
  static constexpr size_t kMaxInput = 1024;
  static constexpr size_t kMaxFields = 32;
  static constexpr int kMaxDepth = 8;

  JsonError Parse(const char* data, size_t len);

  // The field named `key`, or nullptr. A field whose value is null counts as
  // absent.
  const JsonField* Find(const char* key) const;
  size_t size() const { return count_; }

 private:
  bool ParseValue(JsonField* out, int depth);
  bool ParseString(const char** out, size_t* out_len);
  bool ParseNumber(JsonField* out);
  bool SkipNested(int depth);
  void SkipSpace();

  char buf_[kMaxInput + 1] = {};
  size_t len_ = 0;
  size_t pos_ = 0;
  size_t write_ = 0;  // decode cursor for strings, never ahead of pos_
  JsonError error_ = JsonError::kOk;
  JsonField fields_[kMaxFields];
  size_t count_ = 0;
};

// Parses a JSON number token (as produced by the writer) into a double.
// Returns false when `text` is not a complete JSON number.
bool ParseJsonNumber(const char* text, size_t len, double* out);

class JsonWriter {
 public:
  JsonWriter(char* buf, size_t cap);

  void BeginObject();
  void EndObject();
  void BeginArray();
  void EndArray();
  void Key(const char* key);
  void String(const char* s);
  void String(const char* s, size_t len);
  void Int(int64_t v);
  void Uint(uint64_t v);
  // Finite numbers with at most 9 decimals; non-finite ones as null.
  void Double(double v);
  void Bool(bool v);
  void Null();
  // Appends raw, already valid JSON text as a value.
  void Raw(const char* s, size_t len);

  bool ok() const { return ok_; }
  size_t size() const { return len_; }
  const char* data() const { return buf_; }

 private:
  void BeforeValue();
  void Put(char c);
  void Put(const char* s, size_t n);
  void PutQuoted(const char* s, size_t n);

  char* buf_;
  size_t cap_;
  size_t len_ = 0;
  bool ok_ = true;
  int depth_ = 0;
  bool first_[JsonReader::kMaxDepth + 2] = {};
  bool after_key_ = false;
};

// Writes `v` as text (no quotes) into `out`; the same format as
// JsonWriter::Double. Returns the length, or 0 when it does not fit.
size_t FormatNumber(double v, char* out, size_t cap);
size_t FormatInt(int64_t v, char* out, size_t cap);
size_t FormatUint(uint64_t v, char* out, size_t cap);

}  // namespace cube

#endif  // CUBE_CORE_JSON_H_
