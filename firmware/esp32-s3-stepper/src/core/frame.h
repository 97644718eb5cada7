// Serial framing (docs/protocol.md section 7):
//   A5 5A | type u8 | seq u16 LE | len u16 LE | len^0xFFFF u16 LE |
//   payload[len] | CRC-16/CCITT-FALSE u16 BE over sync..payload
#ifndef CUBE_CORE_FRAME_H_
#define CUBE_CORE_FRAME_H_

#include <cstddef>
#include <cstdint>

namespace cube {

constexpr uint8_t kFrameSync0 = 0xA5;
constexpr uint8_t kFrameSync1 = 0x5A;
constexpr uint8_t kFrameData = 0x01;
constexpr uint8_t kFrameAck = 0x02;
constexpr size_t kFrameHeaderSize = 9;
constexpr size_t kFrameCrcSize = 2;
constexpr size_t kFrameMaxPayload = 1024;
constexpr size_t kFrameMaxSize =
    kFrameHeaderSize + kFrameMaxPayload + kFrameCrcSize;

// CRC-16/CCITT-FALSE: poly 0x1021, init 0xFFFF, no reflection, xorout 0.
uint16_t Crc16CcittFalse(const uint8_t* data, size_t len,
                         uint16_t crc = 0xFFFF);

enum class FrameError : uint8_t {
  kOk,
  kIncomplete,  // more bytes are needed
  kBadSync,
  kBadType,
  kBadLength,  // len_inv mismatch, or an ACK with a payload
  kOversize,   // len > 1024
  kBadCrc,
};

// Stable names used by the golden vectors: "bad_crc", "bad_length", ...
const char* FrameErrorName(FrameError e);

struct Frame {
  uint8_t type = 0;
  uint16_t seq = 0;
  const uint8_t* payload = nullptr;
  size_t len = 0;
};

// Encodes one frame into `out`; returns its size, or 0 if it does not fit or
// the payload is too long.
size_t EncodeFrame(uint8_t type, uint16_t seq, const uint8_t* payload,
                   size_t len, uint8_t* out, size_t cap);

// Decodes the frame that starts at data[0]. On kOk, `*used` is the frame's
// size (bytes after it are not looked at). On kOversize, `frame->len` holds
// the announced length.
FrameError DecodeFrame(const uint8_t* data, size_t len, Frame* frame,
                       size_t* used);

// Receives what a FrameParser finds in the byte stream.
class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void OnFrame(const Frame& frame) = 0;
  // A consistent header announced a payload longer than 1024 bytes.
  virtual void OnOversize(size_t announced_len) = 0;
};

// Finds frames in a byte stream, resynchronising after garbage: on any
// error it drops one byte and hunts for the next sync. A partial frame with
// no byte for kStallMs is abandoned the same way.
class FrameParser {
 public:
  static constexpr uint64_t kStallMs = 200;

  void Push(const uint8_t* data, size_t len, uint64_t now_ms, FrameSink& sink);
  void Poll(uint64_t now_ms, FrameSink& sink);
  size_t buffered() const { return n_; }
  uint32_t dropped_bytes() const { return dropped_; }

 private:
  void Process(FrameSink& sink);
  void Drop(size_t count);

  uint8_t buf_[kFrameMaxSize] = {};
  size_t n_ = 0;
  uint64_t last_byte_ms_ = 0;
  uint32_t dropped_ = 0;
};

// Writes bytes to the serial line.
class ByteSink {
 public:
  virtual ~ByteSink() = default;
  virtual void Write(const uint8_t* data, size_t len) = 0;
};

// Receives the messages a SerialLink delivers.
class LinkHandler {
 public:
  virtual ~LinkHandler() = default;
  virtual void OnMessage(const uint8_t* data, size_t len) = 0;
  virtual void OnOversize(size_t announced_len) = 0;
};

// The acknowledged link: ACKs valid DATA frames, suppresses a repeated link
// seq, and sends its own DATA frames one at a time with retries.
class SerialLink : private FrameSink {
 public:
  static constexpr uint64_t kRetryMs = 2000;
  static constexpr int kAttempts = 3;
  static constexpr size_t kQueue = 4;

  SerialLink(ByteSink& out, LinkHandler& handler, uint16_t first_seq);

  void Receive(const uint8_t* data, size_t len, uint64_t now_ms);
  // Queues a message; false if the queue is full or it is too long.
  bool Send(const uint8_t* payload, size_t len, uint64_t now_ms);
  // Retransmits, gives up, and abandons stalled partial frames.
  void Poll(uint64_t now_ms);

  size_t pending() const { return count_; }
  uint32_t retransmits() const { return retransmits_; }
  uint32_t given_up() const { return given_up_; }
  uint32_t duplicates() const { return duplicates_; }
  const FrameParser& parser() const { return parser_; }

 private:
  struct Outgoing {
    uint16_t seq = 0;
    size_t size = 0;
    uint8_t bytes[kFrameMaxSize] = {};
  };

  void OnFrame(const Frame& frame) override;
  void OnOversize(size_t announced_len) override;
  void Transmit(uint64_t now_ms);

  ByteSink& out_;
  LinkHandler& handler_;
  FrameParser parser_;
  Outgoing queue_[kQueue];
  size_t head_ = 0;
  size_t count_ = 0;
  bool in_flight_ = false;
  int attempts_ = 0;
  uint64_t sent_ms_ = 0;
  uint64_t now_ms_ = 0;
  uint16_t next_seq_;
  bool have_last_rx_ = false;
  uint16_t last_rx_seq_ = 0;
  uint32_t retransmits_ = 0;
  uint32_t given_up_ = 0;
  uint32_t duplicates_ = 0;
};

}  // namespace cube

#endif  // CUBE_CORE_FRAME_H_
