// One reply of protocol 1.0 (docs/protocol.md): the envelope (seq, sid,
// cmd), then either the command's data or one error with its details.
#ifndef CUBE_CORE_REPLY_H_
#define CUBE_CORE_REPLY_H_

#include <cstddef>
#include <cstdint>

#include "json_reader.h"
#include "json_writer.h"

namespace cube {

// Error codes.
constexpr const char* kMalformed = "MALFORMED";
constexpr const char* kUnknownCommand = "UNKNOWN_COMMAND";
constexpr const char* kInvalidParameter = "INVALID_PARAMETER";
constexpr const char* kRangeExceeded = "RANGE_EXCEEDED";
constexpr const char* kEmergencyStopped = "EMERGENCY_STOPPED";
constexpr const char* kStaleSequence = "STALE_SEQUENCE";
constexpr const char* kInterrupted = "INTERRUPTED";
constexpr const char* kSessionMismatch = "SESSION_MISMATCH";
constexpr const char* kAuthFailed = "AUTH_FAILED";
constexpr const char* kHardwareError = "HARDWARE_ERROR";

// Builds one reply into a caller-owned buffer. A command either writes its
// data through Ok() or calls Fail() (the first failure wins, and nothing
// fails once data is written); Close() finishes the text.
class Reply {
 public:
  struct Detail {
    const char* key = nullptr;
    enum Kind : uint8_t { kInt, kNum, kStr, kBool } kind = kInt;
    int64_t i = 0;
    double d = 0.0;
    char s[64] = {};
  };

  Reply(char* buf, size_t cap) : w_(buf, cap) {}

  bool has_seq = false;
  uint32_t seq = 0;
  bool has_sid = false;
  uint32_t sid = 0;
  const char* cmd = nullptr;  // NUL-terminated (from the reader)
  size_t cmd_len = 0;
  const JsonReader* req = nullptr;

  bool failed() const { return failed_; }
  const char* code() const { return code_; }

  // Starts the success reply (once) and returns the writer for its data.
  JsonWriter& Ok();
  void Fail(const char* code, const char* message);

  // Entries of the error's "details" object (at most six).
  void DetailInt(const char* key, int64_t v);
  void DetailNum(const char* key, double v);
  void DetailStr(const char* key, const char* v);
  void DetailBool(const char* key, bool v);

  // Closes the reply; returns false if it did not fit.
  bool Close();

  size_t size() const { return w_.size(); }

 private:
  Detail* Add(const char* key);
  void Begin();
  void WriteCmd();

  static constexpr size_t kMaxDetails = 6;
  JsonWriter w_;
  bool started_ = false;
  bool failed_ = false;
  const char* code_ = "";
  char message_[160] = {};
  Detail details_[kMaxDetails];
  size_t ndetails_ = 0;
};

}  // namespace cube

#endif  // CUBE_CORE_REPLY_H_
