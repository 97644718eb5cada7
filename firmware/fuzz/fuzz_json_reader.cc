// Fuzz target: the firmware's JsonReader, checked against an independent
// strict JSON parser (strict_json.h).
//
// Properties:
// - the reader accepts only valid JSON objects, and then reports exactly
//   the strict parser's members: same keys, types, decoded strings, booleans
//   and (finite) numbers;
// - it accepts every valid object within its documented limits (1024 bytes,
//   32 fields, depth 8, no duplicate key, no "\u0000");
// - parsing is deterministic and independent of the previous parse.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>

#include "check.h"
#include "json_reader.h"
#include "strict_json.h"

namespace {

using cube::JsonError;
using cube::JsonField;
using cube::JsonReader;
using cube::JsonType;
using cube::fuzz::Document;
using cube::fuzz::Kind;
using cube::fuzz::Member;

JsonType Expected(Kind k) {
  switch (k) {
    case Kind::kNull: return JsonType::kNull;
    case Kind::kBool: return JsonType::kBool;
    case Kind::kNumber: return JsonType::kNumber;
    case Kind::kString: return JsonType::kString;
    case Kind::kObject:
    case Kind::kArray: return JsonType::kNested;
  }
  return JsonType::kNull;
}

void CheckMember(const JsonReader& r, const Member& m) {
  const JsonField* f = r.Find(m.key.c_str());
  if (m.kind == Kind::kNull) {
    FUZZ_CHECK(f == nullptr, "null member \"%s\" must read as absent",
               m.key.c_str());
    return;
  }
  FUZZ_CHECK(f != nullptr, "member \"%s\" missing", m.key.c_str());
  FUZZ_CHECK(f->type == Expected(m.kind), "member \"%s\" has the wrong type",
             m.key.c_str());
  FUZZ_CHECK(f->key_len == m.key.size() &&
                 std::memcmp(f->key, m.key.data(), m.key.size()) == 0,
             "Find(\"%s\") returned another key", m.key.c_str());
  switch (m.kind) {
    case Kind::kString:
      FUZZ_CHECK(f->str_len == m.str.size() &&
                     std::memcmp(f->str, m.str.data(), m.str.size()) == 0,
                 "string \"%s\" decoded differently", m.key.c_str());
      FUZZ_CHECK(f->str[f->str_len] == '\0', "string \"%s\" not terminated",
                 m.key.c_str());
      break;
    case Kind::kBool:
      FUZZ_CHECK(f->boolean == m.boolean, "bool \"%s\" differs",
                 m.key.c_str());
      break;
    case Kind::kNumber: {
      const double want = std::strtod(m.text.c_str(), nullptr);
      if (f->is_integer) {
        FUZZ_CHECK(static_cast<double>(f->integer) == f->number,
                   "integer and number of \"%s\" disagree", m.key.c_str());
      }
      // Out-of-range numbers (1e400) are the number parser's own concern.
      if (std::isfinite(want) && std::isfinite(f->number)) {
        const double tol = 1e-12 * std::fabs(want) + 1e-300;
        FUZZ_CHECK(std::fabs(f->number - want) <= tol,
                   "number %s read as %.17g", m.text.c_str(), f->number);
      }
      break;
    }
    default:
      break;
  }
}

bool WithinLimits(const Document& d, size_t len) {
  if (len > JsonReader::kMaxInput || d.has_nul_escape) return false;
  if (d.max_depth > JsonReader::kMaxDepth) return false;
  if (d.members.size() > JsonReader::kMaxFields) return false;
  std::set<std::string> keys;
  for (const Member& m : d.members) {
    if (!keys.insert(m.key).second) return false;
  }
  return true;
}

JsonReader g_reader;
JsonReader g_other;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const char* text = reinterpret_cast<const char*>(data);
  const JsonError e = g_reader.Parse(text, size);
  const Document d = cube::fuzz::ParseStrict(text, size);

  if (size > JsonReader::kMaxInput) {
    FUZZ_CHECK(e == JsonError::kTooLong, "an over-long input must be kTooLong");
    return 0;
  }
  if (e == JsonError::kOk) {
    FUZZ_CHECK(d.valid && d.is_object, "accepted a text that is not a JSON "
                                       "object");
    FUZZ_CHECK(WithinLimits(d, size), "accepted a text beyond its limits");
    FUZZ_CHECK(g_reader.size() == d.members.size(), "%zu fields, want %zu",
               g_reader.size(), d.members.size());
    for (const Member& m : d.members) CheckMember(g_reader, m);
  } else if (d.valid && d.is_object) {
    FUZZ_CHECK(!WithinLimits(d, size), "refused a valid object: %s",
               cube::JsonErrorText(e));
  }

  // The same text read by a reader that parsed something else first gives
  // the same answer.
  static const char kOther[] = "{\"cmd\":\"get_status\",\"seq\":7}";
  g_other.Parse(kOther, sizeof(kOther) - 1);
  FUZZ_CHECK(g_other.Parse(text, size) == e, "parse is not deterministic");
  FUZZ_CHECK(g_other.size() == (e == JsonError::kOk ? g_reader.size() : 0) ||
                 e != JsonError::kOk,
             "field count differs between parses");
  return 0;
}
