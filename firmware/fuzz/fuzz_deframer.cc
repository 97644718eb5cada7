// Fuzz target: the serial deframer (FrameParser) and the acknowledged link
// (SerialLink) on an arbitrary byte stream.
//
// Input: byte 0 seeds how the stream is cut into chunks (and, for the link,
// whether the line stalls between chunks); the rest is the stream.
//
// Properties:
// - every frame delivered is well formed (type DATA or ACK, an ACK empty,
//   at most 1024 bytes), its re-encoding verifies (CRC and length check),
//   and those exact bytes were on the line: nothing is invented or altered;
// - how the stream is cut into reads does not change the frames found;
// - the link ACKs every DATA frame once, hands each new one to the handler
//   exactly once, and only ever writes valid ACK frames.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "check.h"
#include "frame.h"

namespace {

using cube::Frame;
using cube::FrameError;

struct Seen {
  uint8_t type;
  uint16_t seq;
  std::vector<uint8_t> payload;
  bool oversize;
  size_t announced;
  bool operator==(const Seen& o) const {
    return type == o.type && seq == o.seq && payload == o.payload &&
           oversize == o.oversize && announced == o.announced;
  }
};

bool Contains(const uint8_t* hay, size_t n, const uint8_t* needle, size_t m) {
  if (m > n) return false;
  for (size_t i = 0; i + m <= n; ++i) {
    if (std::memcmp(hay + i, needle, m) == 0) return true;
  }
  return false;
}

// Checks one delivered frame against the stream it came from.
void CheckFrame(const Frame& f, const uint8_t* stream, size_t n) {
  FUZZ_CHECK(f.type == cube::kFrameData || f.type == cube::kFrameAck,
             "frame type 0x%02x", f.type);
  FUZZ_CHECK(f.type != cube::kFrameAck || f.len == 0, "ACK with %zu bytes",
             f.len);
  FUZZ_CHECK(f.len <= cube::kFrameMaxPayload, "payload of %zu bytes", f.len);
  uint8_t enc[cube::kFrameMaxSize];
  const size_t m =
      cube::EncodeFrame(f.type, f.seq, f.payload, f.len, enc, sizeof(enc));
  FUZZ_CHECK(m == cube::kFrameHeaderSize + f.len + cube::kFrameCrcSize,
             "frame does not re-encode");
  Frame back;
  size_t used = 0;
  FUZZ_CHECK(cube::DecodeFrame(enc, m, &back, &used) == FrameError::kOk &&
                 used == m,
             "re-encoded frame does not verify");
  FUZZ_CHECK(Contains(stream, n, enc, m),
             "delivered a frame (seq %u, %zu bytes) that was not on the line",
             f.seq, f.len);
}

class Collect : public cube::FrameSink {
 public:
  Collect(const uint8_t* stream, size_t n) : stream_(stream), n_(n) {}
  void OnFrame(const Frame& f) override {
    CheckFrame(f, stream_, n_);
    seen.push_back({f.type, f.seq,
                    std::vector<uint8_t>(f.payload, f.payload + f.len), false,
                    0});
  }
  void OnOversize(size_t announced) override {
    FUZZ_CHECK(announced > cube::kFrameMaxPayload && announced <= 0xFFFF,
               "oversize of %zu bytes", announced);
    seen.push_back({0, 0, {}, true, announced});
  }
  std::vector<Seen> seen;

 private:
  const uint8_t* stream_;
  size_t n_;
};

// The link's two ends: what it writes, and what it hands up.
class LinkEnds : public cube::ByteSink, public cube::LinkHandler {
 public:
  void Write(const uint8_t* data, size_t len) override {
    Frame f;
    size_t used = 0;
    FUZZ_CHECK(cube::DecodeFrame(data, len, &f, &used) == FrameError::kOk &&
                   used == len && f.type == cube::kFrameAck,
               "the link wrote something other than one valid ACK");
    ++acks;
  }
  void OnMessage(const uint8_t* data, size_t len) override {
    (void)data;
    FUZZ_CHECK(len <= cube::kFrameMaxPayload, "message of %zu bytes", len);
    ++messages;
  }
  void OnOversize(size_t announced) override {
    FUZZ_CHECK(announced > cube::kFrameMaxPayload, "oversize %zu", announced);
  }
  size_t acks = 0;
  size_t messages = 0;
};

// Chunk sizes from a small xorshift seeded by the first input byte.
struct Chunker {
  explicit Chunker(uint8_t seed) : state(0x9E3779B9u ^ seed) {}
  size_t Next() {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return 1 + state % 48;
  }
  uint32_t state;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const uint8_t seed = data[0];
  const uint8_t* stream = data + 1;
  const size_t n = size - 1;

  Collect whole(stream, n);
  cube::FrameParser p1;
  p1.Push(stream, n, 0, whole);

  Collect chunked(stream, n);
  cube::FrameParser p2;
  Chunker c(seed);
  for (size_t i = 0; i < n;) {
    const size_t k = std::min(c.Next(), n - i);
    p2.Push(stream + i, k, 0, chunked);
    i += k;
  }
  FUZZ_CHECK(whole.seen == chunked.seen,
             "chunking changed the frames: %zu whole, %zu chunked",
             whole.seen.size(), chunked.seen.size());
  FUZZ_CHECK(p1.buffered() == p2.buffered(), "chunking changed the buffer");

  // The same frames through the link, counted from the parser's view: one
  // ACK per DATA frame, one message per DATA frame whose seq differs from
  // the previous DATA frame's.
  size_t data_frames = 0;
  size_t fresh = 0;
  bool have_last = false;
  uint16_t last = 0;
  for (const Seen& s : whole.seen) {
    if (s.oversize || s.type != cube::kFrameData) continue;
    ++data_frames;
    if (!have_last || s.seq != last) ++fresh;
    have_last = true;
    last = s.seq;
  }
  LinkEnds ends;
  cube::SerialLink link(ends, ends, 1);
  link.Receive(stream, n, 0);
  FUZZ_CHECK(ends.acks == data_frames, "%zu ACKs for %zu DATA frames",
             ends.acks, data_frames);
  FUZZ_CHECK(ends.messages == fresh, "%zu messages for %zu new DATA frames",
             ends.messages, fresh);

  // A line that stalls between chunks (seed bit 7): partial frames are
  // abandoned, but whatever is delivered is still exactly what was sent.
  if ((seed & 0x80) != 0) {
    Collect stalled(stream, n);
    cube::FrameParser p3;
    Chunker s(seed);
    uint64_t now = 0;
    for (size_t i = 0; i < n;) {
      const size_t k = std::min(s.Next(), n - i);
      p3.Push(stream + i, k, now, stalled);
      now += (s.Next() % 3 == 0) ? cube::FrameParser::kStallMs : 1;
      p3.Poll(now, stalled);
      i += k;
    }
    p3.Poll(now + cube::FrameParser::kStallMs, stalled);
    FUZZ_CHECK(p3.buffered() == 0, "a stalled partial frame was kept");
  }
  return 0;
}
