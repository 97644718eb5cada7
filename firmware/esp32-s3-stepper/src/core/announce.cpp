#include "announce.h"

#include <cstring>

#include "json_number.h"

namespace cube {

bool Announcement::Add(const char* key, const char* value, size_t value_len) {
  const size_t key_len = std::strlen(key);
  if (count_ >= kMaxTxtEntries || key_len == 0 || key_len > kMaxTxtKeyLen ||
      key_len + 1 + value_len > kMaxTxtEntryLen) {
    return false;
  }
  TxtEntry& e = entries_[count_];
  std::memcpy(e.key, key, key_len);
  e.key[key_len] = '\0';
  std::memcpy(e.value, value, value_len);
  e.value[value_len] = '\0';
  ++count_;
  return true;
}

// Packs the capabilities, comma-separated, into caps, caps1, caps2, ...
bool Announcement::AddCapabilities(const CapabilityList& caps) {
  char value[kMaxTxtEntryLen] = {};
  size_t len = 0;
  size_t part = 0;
  char key[kMaxTxtKeyLen + 1] = "caps";
  for (size_t i = 0; i < caps.count; ++i) {
    const char* cap = caps.items[i];
    const size_t cap_len = std::strlen(cap);
    if (cap_len == 0 || std::strchr(cap, ',') != nullptr) return false;
    // "capsN=" is at most 5 + 2 + 1 bytes; a capability must fit alone.
    const size_t room = kMaxTxtEntryLen - std::strlen(key) - 1;
    if (len > 0 && len + 1 + cap_len > room) {
      if (!Add(key, value, len)) return false;
      ++part;
      len = 0;
      std::memcpy(key, "caps", 4);
      const size_t n = FormatUint(part, key + 4, sizeof(key) - 5);
      key[4 + n] = '\0';
    }
    const size_t free_room = kMaxTxtEntryLen - std::strlen(key) - 1;
    if ((len > 0 ? len + 1 : 0) + cap_len > free_room) return false;
    if (len > 0) value[len++] = ',';
    std::memcpy(value + len, cap, cap_len);
    len += cap_len;
  }
  return Add(key, value, len);
}

bool Announcement::Build(const char* device_id, AuthMode auth,
                         const CapabilityList& caps) {
  count_ = 0;
  const size_t id_len = device_id == nullptr ? 0 : std::strlen(device_id);
  const char* auth_name = AuthModeName(auth);
  const bool ok =
      id_len > 0 && Add("txtvers", kTxtVersion, std::strlen(kTxtVersion)) &&
      Add("device_id", device_id, id_len) &&
      Add("proto", kProtocolVersion, std::strlen(kProtocolVersion)) &&
      Add("auth", auth_name, std::strlen(auth_name)) && AddCapabilities(caps);
  if (!ok) count_ = 0;
  return ok;
}

bool Announcement::Build(const Cube& robot) {
  CapabilityList caps;
  ListCapabilities(robot.config().geometry, &caps);
  return Build(robot.device_id(), robot.auth_mode(), caps);
}

}  // namespace cube
