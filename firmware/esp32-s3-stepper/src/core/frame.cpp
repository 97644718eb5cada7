#include "frame.h"

#include <cstring>

namespace cube {

uint16_t Crc16CcittFalse(const uint8_t* data, size_t len, uint16_t crc) {
  uint32_t c = crc;
  for (size_t i = 0; i < len; ++i) {
    c ^= static_cast<uint32_t>(data[i]) << 8;
    for (int b = 0; b < 8; ++b) {
      c = (c & 0x8000u) != 0 ? ((c << 1) ^ 0x1021u) : (c << 1);
    }
    c &= 0xFFFFu;
  }
  return static_cast<uint16_t>(c);
}

const char* FrameErrorName(FrameError e) {
  switch (e) {
    case FrameError::kOk:
      return "ok";
    case FrameError::kIncomplete:
      return "incomplete";
    case FrameError::kBadSync:
      return "bad_sync";
    case FrameError::kBadType:
      return "bad_type";
    case FrameError::kBadLength:
      return "bad_length";
    case FrameError::kOversize:
      return "oversize";
    case FrameError::kBadCrc:
      return "bad_crc";
  }
  return "unknown";
}

size_t EncodeFrame(uint8_t type, uint16_t seq, const uint8_t* payload,
                   size_t len, uint8_t* out, size_t cap) {
  if (len > kFrameMaxPayload) return 0;
  const size_t total = kFrameHeaderSize + len + kFrameCrcSize;
  if (total > cap) return 0;
  const uint16_t l = static_cast<uint16_t>(len);
  const uint16_t linv = static_cast<uint16_t>(l ^ 0xFFFFu);
  out[0] = kFrameSync0;
  out[1] = kFrameSync1;
  out[2] = type;
  out[3] = static_cast<uint8_t>(seq & 0xFF);
  out[4] = static_cast<uint8_t>(seq >> 8);
  out[5] = static_cast<uint8_t>(l & 0xFF);
  out[6] = static_cast<uint8_t>(l >> 8);
  out[7] = static_cast<uint8_t>(linv & 0xFF);
  out[8] = static_cast<uint8_t>(linv >> 8);
  if (len > 0) std::memcpy(out + kFrameHeaderSize, payload, len);
  const uint16_t crc = Crc16CcittFalse(out, kFrameHeaderSize + len);
  out[kFrameHeaderSize + len] = static_cast<uint8_t>(crc >> 8);
  out[kFrameHeaderSize + len + 1] = static_cast<uint8_t>(crc & 0xFF);
  return total;
}

FrameError DecodeFrame(const uint8_t* data, size_t len, Frame* frame,
                       size_t* used) {
  *used = 0;
  if (len < 1) return FrameError::kIncomplete;
  if (data[0] != kFrameSync0) return FrameError::kBadSync;
  if (len < 2) return FrameError::kIncomplete;
  if (data[1] != kFrameSync1) return FrameError::kBadSync;
  if (len < 3) return FrameError::kIncomplete;
  const uint8_t type = data[2];
  if (type != kFrameData && type != kFrameAck) return FrameError::kBadType;
  if (len < kFrameHeaderSize) return FrameError::kIncomplete;
  const uint16_t seq = static_cast<uint16_t>(data[3] | (data[4] << 8));
  const uint16_t plen = static_cast<uint16_t>(data[5] | (data[6] << 8));
  const uint16_t linv = static_cast<uint16_t>(data[7] | (data[8] << 8));
  if (static_cast<uint16_t>(plen ^ 0xFFFFu) != linv) {
    return FrameError::kBadLength;
  }
  if (type == kFrameAck && plen != 0) return FrameError::kBadLength;
  if (plen > kFrameMaxPayload) {
    frame->len = plen;
    return FrameError::kOversize;
  }
  const size_t total = kFrameHeaderSize + plen + kFrameCrcSize;
  if (len < total) return FrameError::kIncomplete;
  const uint16_t want = Crc16CcittFalse(data, kFrameHeaderSize + plen);
  const uint16_t got = static_cast<uint16_t>(
      (data[kFrameHeaderSize + plen] << 8) | data[kFrameHeaderSize + plen + 1]);
  if (want != got) return FrameError::kBadCrc;
  frame->type = type;
  frame->seq = seq;
  frame->payload = data + kFrameHeaderSize;
  frame->len = plen;
  *used = total;
  return FrameError::kOk;
}

void FrameParser::Drop(size_t count) {
  if (count >= n_) {
    dropped_ += static_cast<uint32_t>(n_);
    n_ = 0;
    return;
  }
  std::memmove(buf_, buf_ + count, n_ - count);
  n_ -= count;
  dropped_ += static_cast<uint32_t>(count);
}

void FrameParser::Process(FrameSink& sink) {
  while (n_ > 0) {
    Frame f;
    size_t used = 0;
    const FrameError r = DecodeFrame(buf_, n_, &f, &used);
    if (r == FrameError::kOk) {
      sink.OnFrame(f);
      std::memmove(buf_, buf_ + used, n_ - used);
      n_ -= used;
      continue;
    }
    if (r == FrameError::kIncomplete) return;
    if (r == FrameError::kOversize) sink.OnOversize(f.len);
    if (r == FrameError::kBadSync) {
      // Skip straight to the next candidate sync byte.
      size_t skip = 1;
      while (skip < n_ && buf_[skip] != kFrameSync0) ++skip;
      Drop(skip);
      continue;
    }
    Drop(1);
  }
}

void FrameParser::Push(const uint8_t* data, size_t len, uint64_t now_ms,
                       FrameSink& sink) {
  if (len > 0) last_byte_ms_ = now_ms;
  for (size_t i = 0; i < len; ++i) {
    if (n_ == sizeof(buf_)) {
      Process(sink);
      if (n_ == sizeof(buf_)) Drop(1);
    }
    buf_[n_++] = data[i];
    // Only a complete frame or a header can be judged; process lazily.
    if (n_ >= kFrameHeaderSize || buf_[0] != kFrameSync0) Process(sink);
  }
  Process(sink);
}

void FrameParser::Poll(uint64_t now_ms, FrameSink& sink) {
  while (n_ > 0 && now_ms - last_byte_ms_ >= kStallMs) {
    Drop(1);
    Process(sink);
  }
}

SerialLink::SerialLink(ByteSink& out, LinkHandler& handler, uint16_t first_seq)
    : out_(out), handler_(handler), next_seq_(first_seq) {}

void SerialLink::Receive(const uint8_t* data, size_t len, uint64_t now_ms) {
  now_ms_ = now_ms;
  parser_.Push(data, len, now_ms, *this);
}

void SerialLink::OnFrame(const Frame& frame) {
  if (frame.type == kFrameAck) {
    if (in_flight_ && count_ > 0 && frame.seq == queue_[head_].seq) {
      in_flight_ = false;
      head_ = (head_ + 1) % kQueue;
      --count_;
      if (count_ > 0) Transmit(now_ms_);
    }
    return;
  }
  uint8_t ack[kFrameHeaderSize + kFrameCrcSize];
  const size_t n =
      EncodeFrame(kFrameAck, frame.seq, nullptr, 0, ack, sizeof(ack));
  out_.Write(ack, n);
  if (have_last_rx_ && frame.seq == last_rx_seq_) {
    ++duplicates_;
    return;
  }
  have_last_rx_ = true;
  last_rx_seq_ = frame.seq;
  handler_.OnMessage(frame.payload, frame.len);
}

void SerialLink::OnOversize(size_t announced_len) {
  handler_.OnOversize(announced_len);
}

bool SerialLink::Send(const uint8_t* payload, size_t len, uint64_t now_ms) {
  if (len > kFrameMaxPayload || count_ >= kQueue) return false;
  Outgoing& o = queue_[(head_ + count_) % kQueue];
  o.seq = next_seq_++;
  o.size =
      EncodeFrame(kFrameData, o.seq, payload, len, o.bytes, sizeof(o.bytes));
  ++count_;
  if (!in_flight_) Transmit(now_ms);
  return true;
}

void SerialLink::Transmit(uint64_t now_ms) {
  const Outgoing& o = queue_[head_];
  out_.Write(o.bytes, o.size);
  in_flight_ = true;
  attempts_ = 1;
  sent_ms_ = now_ms;
}

void SerialLink::Poll(uint64_t now_ms) {
  now_ms_ = now_ms;
  parser_.Poll(now_ms, *this);
  if (!in_flight_ || now_ms - sent_ms_ < kRetryMs) return;
  if (attempts_ < kAttempts) {
    const Outgoing& o = queue_[head_];
    out_.Write(o.bytes, o.size);
    ++attempts_;
    ++retransmits_;
    sent_ms_ = now_ms;
    return;
  }
  ++given_up_;
  in_flight_ = false;
  head_ = (head_ + 1) % kQueue;
  --count_;
  if (count_ > 0) Transmit(now_ms);
}

}  // namespace cube
