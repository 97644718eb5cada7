#include "capabilities.h"

#include <cstring>

#include "json_number.h"
#include "text.h"

namespace cube {
namespace {

void Add(CapabilityList* out, const char* text) {
  if (out->count >= kMaxCapabilities) return;
  CopyText(out->items[out->count], kMaxCapabilityLen, text, std::strlen(text));
  ++out->count;
}

}  // namespace

void ListCapabilities(const Geometry& geometry, CapabilityList* out) {
  out->count = 0;
  Add(out, "locomotion.differential:v1.0");
  char stepper[kMaxCapabilityLen] = "locomotion.stepper:v1.0:steps_per_rev=";
  const size_t base = std::strlen(stepper);
  const size_t n = FormatNumber(geometry.steps_per_revolution, stepper + base,
                                sizeof(stepper) - base - 1);
  stepper[base + n] = '\0';
  Add(out, stepper);
  Add(out, "communication.led:v1.0");
  Add(out, "safety.estop:v1.0");
  Add(out, "safety.host_timeout:v1.0");
}

}  // namespace cube
