// The capability strings the robot declares, `{domain}.{type}:v{major}.{minor}`
// with optional `:metadata` (docs/protocol.md): one list for hello's reply and
// for the mDNS announcement (announce.h), so the two can never disagree.
#ifndef CUBE_CORE_CAPABILITIES_H_
#define CUBE_CORE_CAPABILITIES_H_

#include <cstddef>

#include "kinematics.h"

namespace cube {

constexpr size_t kMaxCapabilities = 8;
constexpr size_t kMaxCapabilityLen = 64;  // with the terminating NUL

struct CapabilityList {
  char items[kMaxCapabilities][kMaxCapabilityLen] = {};
  size_t count = 0;
};

// Fills `out` with the V1 cube's capabilities for this geometry (the stepper
// capability carries steps_per_rev).
void ListCapabilities(const Geometry& geometry, CapabilityList* out);

}  // namespace cube

#endif  // CUBE_CORE_CAPABILITIES_H_
