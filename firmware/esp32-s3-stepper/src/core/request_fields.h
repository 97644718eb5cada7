// Typed readers for a request's parameters. Each reads one field of the
// parsed request (Reply::req) and, when it is mistyped or out of range,
// fails the reply with INVALID_PARAMETER or RANGE_EXCEEDED and the field's
// details (docs/protocol.md, "Errors").
#ifndef CUBE_CORE_REQUEST_FIELDS_H_
#define CUBE_CORE_REQUEST_FIELDS_H_

#include <cstdint>

#include "json_reader.h"
#include "reply.h"

namespace cube {

// What a reader found. kError means the reply has already failed.
enum class Got { kAbsent, kOk, kError };

// Fail the reply with the field's details.
void RangeError(Reply& r, const char* field, double min, double max,
                double value, const char* unit);
void TypeError(Reply& r, const char* field, const char* what);
void Missing(Reply& r, const char* field);

// An integer in min..max (`unit` names it in the error message).
Got GetInt(Reply& r, const char* key, int64_t min, int64_t max,
           const char* unit, int64_t* out);
// Any finite number; range checks are the caller's.
Got GetNumber(Reply& r, const char* key, double* out);
// A number in min..max.
Got GetRangedNumber(Reply& r, const char* key, double min, double max,
                    const char* unit, double* out);
Got GetString(Reply& r, const char* key, const JsonField** out);

// True when the field was read; fails the reply with "is required" when it
// was absent.
bool Required(Reply& r, Got g, const char* key);

}  // namespace cube

#endif  // CUBE_CORE_REQUEST_FIELDS_H_
