// A bounded, allocation-free JSON writer: JsonWriter appends JSON to a
// caller-owned buffer and records overflow instead of writing past it.
#ifndef CUBE_CORE_JSON_WRITER_H_
#define CUBE_CORE_JSON_WRITER_H_

#include <cstddef>
#include <cstdint>

namespace cube {

class JsonWriter {
 public:
  // Containers nest at most this deep: a top-level container and the eight
  // levels inside it that JsonReader accepts.
  static constexpr int kMaxDepth = 9;

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
  bool first_[kMaxDepth + 1] = {};  // [depth]: no value written there yet
  bool after_key_ = false;
};

}  // namespace cube

#endif  // CUBE_CORE_JSON_WRITER_H_
