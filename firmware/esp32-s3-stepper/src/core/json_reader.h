// A bounded, allocation-free JSON reader for the protocol's flat messages.
//
// JsonReader parses one top-level object of at most kMaxInput bytes into a
// fixed table of fields. Nested objects and arrays are checked for syntax and
// skipped (type kNested), so unknown structured fields are ignored.
#ifndef CUBE_CORE_JSON_READER_H_
#define CUBE_CORE_JSON_READER_H_

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
  JsonError error_ = JsonError::kOk;
  JsonField fields_[kMaxFields];
  size_t count_ = 0;
};

}  // namespace cube

#endif  // CUBE_CORE_JSON_READER_H_
