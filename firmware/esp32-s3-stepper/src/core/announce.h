// What a robot announces on the local network with mDNS / DNS-SD
// (docs/discovery.md): the service `_hal-cube._udp` on the robot's UDP port,
// and a TXT record built here, once, for the board (ESPmDNS) and the
// emulator (which prints it for the host-side announcer).
//
// TXT entries, each `key=value` at most 255 bytes (RFC 6763 section 6.1):
//   txtvers=1              the layout of this record
//   device_id=cube-a1b2c3  hello's device_id
//   proto=1.1              the wire protocol version
//   auth=hmac-sha256       or `none` (anyone may command it) or
//                          `unconfigured` (closed: only stop and estop)
//   caps=a,b,c             the capability strings, comma-separated; when
//   caps1=d,e              they do not fit in one entry they continue in
//                          caps1, caps2, ... A capability is never split.
#ifndef CUBE_CORE_ANNOUNCE_H_
#define CUBE_CORE_ANNOUNCE_H_

#include <cstddef>

#include "capabilities.h"
#include "cube.h"

namespace cube {

// ESPmDNS's addService() takes the two labels apart.
constexpr const char* kMdnsService = "_hal-cube";
constexpr const char* kMdnsProto = "_udp";
constexpr const char* kTxtVersion = "1";
// key=value bytes of one TXT entry (its length is one byte on the wire).
constexpr size_t kMaxTxtEntryLen = 255;
constexpr size_t kMaxTxtKeyLen = 9;  // RFC 6763 section 6.4
constexpr size_t kMaxTxtEntries = 12;

struct TxtEntry {
  char key[kMaxTxtKeyLen + 1] = {};
  char value[kMaxTxtEntryLen] = {};  // key=value <= 255, so value < 255
};

class Announcement {
 public:
  // Builds the TXT entries. Returns false, with no entries, when something
  // cannot be announced within the limits (an empty device id, a capability
  // that holds a comma or does not fit in one entry, too many entries).
  bool Build(const char* device_id, AuthMode auth, const CapabilityList& caps);
  // The same, for a running robot: its device id, auth mode and capabilities.
  bool Build(const Cube& robot);

  size_t count() const { return count_; }
  const TxtEntry& entry(size_t i) const { return entries_[i]; }

 private:
  bool Add(const char* key, const char* value, size_t value_len);
  bool AddCapabilities(const CapabilityList& caps);

  TxtEntry entries_[kMaxTxtEntries];
  size_t count_ = 0;
};

}  // namespace cube

#endif  // CUBE_CORE_ANNOUNCE_H_
