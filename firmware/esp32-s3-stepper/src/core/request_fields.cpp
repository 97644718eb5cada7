#include "request_fields.h"

#include <cmath>

#include "text.h"

namespace cube {

void RangeError(Reply& r, const char* field, double min, double max,
                double value, const char* unit) {
  Text t;
  t.Q(field).S(" must be ").N(min).S("..").N(max);
  if (unit[0] != '\0') t.S(" ").S(unit);
  r.Fail(kRangeExceeded, t.c_str());
  r.DetailStr("field", field);
  r.DetailNum("min", min);
  r.DetailNum("max", max);
  r.DetailNum("value", value);
}

void TypeError(Reply& r, const char* field, const char* what) {
  Text t;
  t.Q(field).S(" must be ").S(what);
  r.Fail(kInvalidParameter, t.c_str());
  r.DetailStr("field", field);
}

void Missing(Reply& r, const char* field) {
  Text t;
  t.Q(field).S(" is required");
  r.Fail(kInvalidParameter, t.c_str());
  r.DetailStr("field", field);
}

Got GetInt(Reply& r, const char* key, int64_t min, int64_t max,
           const char* unit, int64_t* out) {
  const JsonField* f = r.req->Find(key);
  if (f == nullptr) return Got::kAbsent;
  if (f->type != JsonType::kNumber || !f->is_integer) {
    TypeError(r, key, "an integer");
    return Got::kError;
  }
  if (f->integer < min || f->integer > max) {
    RangeError(r, key, static_cast<double>(min), static_cast<double>(max),
               f->number, unit);
    return Got::kError;
  }
  *out = f->integer;
  return Got::kOk;
}

Got GetNumber(Reply& r, const char* key, double* out) {
  const JsonField* f = r.req->Find(key);
  if (f == nullptr) return Got::kAbsent;
  if (f->type != JsonType::kNumber) {
    TypeError(r, key, "a number");
    return Got::kError;
  }
  // A literal beyond the double range (1e400) reads as infinity; the
  // protocol's numbers are finite.
  if (!std::isfinite(f->number)) {
    TypeError(r, key, "a finite number");
    return Got::kError;
  }
  *out = f->number;
  return Got::kOk;
}

Got GetRangedNumber(Reply& r, const char* key, double min, double max,
                    const char* unit, double* out) {
  double v = 0;
  const Got g = GetNumber(r, key, &v);
  if (g != Got::kOk) return g;
  if (!(v >= min && v <= max)) {
    RangeError(r, key, min, max, v, unit);
    return Got::kError;
  }
  *out = v;
  return Got::kOk;
}

Got GetString(Reply& r, const char* key, const JsonField** out) {
  const JsonField* f = r.req->Find(key);
  if (f == nullptr) return Got::kAbsent;
  if (f->type != JsonType::kString) {
    TypeError(r, key, "a string");
    return Got::kError;
  }
  *out = f;
  return Got::kOk;
}

bool Required(Reply& r, Got g, const char* key) {
  if (g == Got::kAbsent) {
    Missing(r, key);
    return false;
  }
  return g == Got::kOk;
}

}  // namespace cube
