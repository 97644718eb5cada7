// A small, strict RFC 8259 JSON checker for the fuzz targets: an oracle
// written independently of the firmware's JsonReader. It validates a whole
// document and, for a top-level object, lists its members (decoded keys,
// value kind, decoded string values, raw value text).
//
// Test code only: it allocates (std::string, std::vector) freely.
#ifndef CUBE_FUZZ_STRICT_JSON_H_
#define CUBE_FUZZ_STRICT_JSON_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cube::fuzz {

enum class Kind { kNull, kBool, kNumber, kString, kObject, kArray };

struct Member {
  std::string key;   // decoded (UTF-8)
  Kind kind = Kind::kNull;
  std::string text;  // the raw value text as it appears in the document
  std::string str;   // decoded value when kind == kString
  bool boolean = false;
};

struct Document {
  bool valid = false;
  bool is_object = false;
  int max_depth = 0;          // 1 for a flat object
  bool has_nul_escape = false;  // a "\u0000" somewhere in a string
  std::vector<Member> members;  // top level, in order (objects only)

  // The first member named `key`, or nullptr.
  const Member* Find(const std::string& key) const {
    for (const Member& m : members) {
      if (m.key == key) return &m;
    }
    return nullptr;
  }
};

// Parses `text` strictly: one value, optional surrounding whitespace,
// nothing else. Bytes >= 0x80 inside strings are taken as they are (escapes
// may hold lone surrogates, as RFC 8259 tolerates); check UTF-8 apart.
Document ParseStrict(const char* text, size_t len);

// True when `text` is well-formed UTF-8 (no overlongs, no surrogates).
bool IsValidUtf8(const char* text, size_t len);

}  // namespace cube::fuzz

#endif  // CUBE_FUZZ_STRICT_JSON_H_
