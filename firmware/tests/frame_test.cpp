#include "frame.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "harness.h"

namespace cube {
namespace {

using testing::FromHex;
using testing::json;

std::vector<uint8_t> Bytes(const std::string& s) {
  return std::vector<uint8_t>(s.begin(), s.end());
}

std::vector<uint8_t> Encode(uint8_t type, uint16_t seq, const std::string& p) {
  std::vector<uint8_t> out(kFrameMaxSize);
  const size_t n =
      EncodeFrame(type, seq, reinterpret_cast<const uint8_t*>(p.data()),
                  p.size(), out.data(), out.size());
  out.resize(n);
  return out;
}

json GoldenFrames() {
  const std::string text = testing::ReadVectorFile("serial-frames.json");
  EXPECT_FALSE(text.empty()) << "tests/vectors/serial-frames.json is missing";
  return text.empty() ? json::array() : json::parse(text);
}

TEST(Crc16, MatchesTheStandardCheckValues) {
  const std::string check = "123456789";
  EXPECT_EQ(Crc16CcittFalse(reinterpret_cast<const uint8_t*>(check.data()),
                            check.size()),
            0x29B1);
  EXPECT_EQ(Crc16CcittFalse(nullptr, 0), 0xFFFF);
  const uint8_t a = 'A';
  EXPECT_EQ(Crc16CcittFalse(&a, 1), 0xB915);
}

TEST(Frame, EncoderReproducesEveryGoldenFrame) {
  for (const json& v : GoldenFrames()) {
    if (!v.contains("decoded")) continue;
    const json& d = v["decoded"];
    const uint8_t type = d["type"] == "data" ? kFrameData : kFrameAck;
    EXPECT_EQ(
        Encode(type, d["seq"].get<uint16_t>(), d["payload"].get<std::string>()),
        FromHex(v["hex"].get<std::string>()))
        << v["name"];
  }
}

TEST(Frame, DecoderReadsEveryGoldenFrameAsRecorded) {
  for (const json& v : GoldenFrames()) {
    if (!v.contains("decoded")) continue;
    const std::vector<uint8_t> bytes = FromHex(v["hex"].get<std::string>());
    Frame f;
    size_t used = 0;
    ASSERT_EQ(DecodeFrame(bytes.data(), bytes.size(), &f, &used),
              FrameError::kOk)
        << v["name"];
    EXPECT_EQ(used, bytes.size());
    EXPECT_EQ(f.type == kFrameData ? "data" : "ack", v["decoded"]["type"]);
    EXPECT_EQ(f.seq, v["decoded"]["seq"].get<uint16_t>());
    EXPECT_EQ(std::string(reinterpret_cast<const char*>(f.payload), f.len),
              v["decoded"]["payload"].get<std::string>());
  }
}

TEST(Frame, InvalidGoldenFramesFailWithTheRecordedError) {
  int checked = 0;
  for (const json& v : GoldenFrames()) {
    if (!v.contains("error")) continue;
    const std::vector<uint8_t> bytes = FromHex(v["hex"].get<std::string>());
    Frame f;
    size_t used = 0;
    EXPECT_STREQ(
        FrameErrorName(DecodeFrame(bytes.data(), bytes.size(), &f, &used)),
        v["error"].get<std::string>().c_str())
        << v["name"];
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

TEST(Frame, RejectsEverySingleBitFlipOfEveryGoldenFrame) {
  int flips = 0;
  for (const json& v : GoldenFrames()) {
    if (!v.contains("decoded")) continue;
    const std::vector<uint8_t> good = FromHex(v["hex"].get<std::string>());
    for (size_t i = 0; i < good.size(); ++i) {
      for (int b = 0; b < 8; ++b) {
        std::vector<uint8_t> bad = good;
        bad[i] = static_cast<uint8_t>(bad[i] ^ (1u << b));
        Frame f;
        size_t used = 0;
        ASSERT_NE(DecodeFrame(bad.data(), bad.size(), &f, &used),
                  FrameError::kOk)
            << v["name"] << " byte " << i << " bit " << b;
        ++flips;
      }
    }
  }
  EXPECT_GT(flips, 10000);
}

TEST(Frame, RefusesToEncodeAPayloadOver1024Bytes) {
  std::vector<uint8_t> out(2000);
  std::vector<uint8_t> payload(1025, 'x');
  EXPECT_EQ(EncodeFrame(kFrameData, 1, payload.data(), payload.size(),
                        out.data(), out.size()),
            0u);
}

class Collect : public FrameSink {
 public:
  void OnFrame(const Frame& f) override {
    payloads.emplace_back(reinterpret_cast<const char*>(f.payload), f.len);
    seqs.push_back(f.seq);
  }
  void OnOversize(size_t n) override { oversize.push_back(n); }
  std::vector<std::string> payloads;
  std::vector<uint16_t> seqs;
  std::vector<size_t> oversize;
};

TEST(FrameParser, ResynchronisesAfterGarbage) {
  FrameParser p;
  Collect c;
  std::vector<uint8_t> stream = {0x00, 0xA5, 0xA5, 0x5A,
                                 0x07, 0xFF, 0x5A, 0xA5};
  const auto f1 = Encode(kFrameData, 1, R"({"cmd":"stop"})");
  stream.insert(stream.end(), f1.begin(), f1.end());
  const std::vector<uint8_t> junk = {0x13, 0xA5, 0x5A, 0x01, 0x02};
  stream.insert(stream.end(), junk.begin(), junk.end());
  const auto f2 = Encode(kFrameData, 2, R"({"cmd":"get_status"})");
  stream.insert(stream.end(), f2.begin(), f2.end());
  p.Push(stream.data(), stream.size(), 0, c);
  ASSERT_EQ(c.payloads.size(), 2u);
  EXPECT_EQ(c.payloads[0], R"({"cmd":"stop"})");
  EXPECT_EQ(c.payloads[1], R"({"cmd":"get_status"})");
}

TEST(FrameParser, FindsTheNextFrameAfterACorruptedOne) {
  FrameParser p;
  Collect c;
  auto bad =
      Encode(kFrameData, 1, R"({"cmd":"move_steps","left":10,"right":10})");
  bad[12] ^= 0x40;
  const auto good = Encode(kFrameData, 2, R"({"cmd":"stop"})");
  std::vector<uint8_t> stream = bad;
  stream.insert(stream.end(), good.begin(), good.end());
  for (uint8_t b : stream) p.Push(&b, 1, 0, c);  // one byte at a time
  ASSERT_EQ(c.payloads.size(), 1u);
  EXPECT_EQ(c.seqs[0], 2);
}

TEST(FrameParser, DeliversEveryValidFrameBuriedInRandomGarbage) {
  std::mt19937 rng(3);
  FrameParser p;
  Collect c;
  std::vector<uint8_t> stream;
  for (uint16_t i = 0; i < 200; ++i) {
    const size_t junk = rng() % 40;
    for (size_t k = 0; k < junk; ++k) {
      // Garbage rich in sync bytes, without forming a valid header by luck.
      const uint8_t choices[] = {0xA5, 0x5A, 0x01, 0x00, 0xFF, 0x13};
      stream.push_back(choices[rng() % 6]);
    }
    const auto f = Encode(kFrameData, i, "{\"n\":" + std::to_string(i) + "}");
    stream.insert(stream.end(), f.begin(), f.end());
  }
  for (size_t pos = 0; pos < stream.size();) {
    const size_t chunk = 1 + rng() % 64;
    const size_t n = std::min(chunk, stream.size() - pos);
    p.Push(stream.data() + pos, n, 0, c);
    pos += n;
  }
  // A garbage tail may hold back a frame behind a false header; the stall
  // timeout releases it.
  p.Poll(1000, c);
  ASSERT_EQ(c.seqs.size(), 200u);
  for (uint16_t i = 0; i < 200; ++i) EXPECT_EQ(c.seqs[i], i);
}

TEST(FrameParser, AbandonsAStalledPartialFrameAfter200Ms) {
  FrameParser p;
  Collect c;
  // A header announcing 500 bytes, then silence: the sender died.
  const auto big = Encode(kFrameData, 1, std::string(500, 'x'));
  p.Push(big.data(), 40, 0, c);
  EXPECT_EQ(p.buffered(), 40u);
  p.Poll(199, c);
  EXPECT_EQ(p.buffered(), 40u);
  p.Poll(200, c);
  EXPECT_EQ(p.buffered(), 0u);
  const auto good = Encode(kFrameData, 2, R"({"cmd":"stop"})");
  p.Push(good.data(), good.size(), 300, c);
  ASSERT_EQ(c.payloads.size(), 1u);
}

TEST(FrameParser, ReportsAnOversizeHeader) {
  FrameParser p;
  Collect c;
  const std::vector<uint8_t> hdr = {0xA5, 0x5A, 0x01, 0x01, 0x00,
                                    0x00, 0x08, 0xFF, 0xF7};
  p.Push(hdr.data(), hdr.size(), 0, c);
  ASSERT_EQ(c.oversize.size(), 1u);
  EXPECT_EQ(c.oversize[0], 2048u);
}

class Wire : public ByteSink {
 public:
  void Write(const uint8_t* d, size_t n) override {
    bytes.insert(bytes.end(), d, d + n);
  }
  std::vector<uint8_t> bytes;
};

class Inbox : public LinkHandler {
 public:
  void OnMessage(const uint8_t* d, size_t n) override {
    messages.emplace_back(reinterpret_cast<const char*>(d), n);
  }
  void OnOversize(size_t n) override { oversize.push_back(n); }
  std::vector<std::string> messages;
  std::vector<size_t> oversize;
};

std::vector<std::pair<uint8_t, uint16_t>> FramesIn(
    const std::vector<uint8_t>& wire) {
  std::vector<std::pair<uint8_t, uint16_t>> out;
  size_t pos = 0;
  while (pos < wire.size()) {
    Frame f;
    size_t used = 0;
    if (DecodeFrame(wire.data() + pos, wire.size() - pos, &f, &used) !=
        FrameError::kOk)
      break;
    out.emplace_back(f.type, f.seq);
    pos += used;
  }
  return out;
}

TEST(SerialLink, AcksEachDataFrameAndDeliversIt) {
  Wire wire;
  Inbox inbox;
  SerialLink link(wire, inbox, 100);
  const auto f = Encode(kFrameData, 7, R"({"cmd":"stop"})");
  link.Receive(f.data(), f.size(), 0);
  ASSERT_EQ(inbox.messages.size(), 1u);
  const auto frames = FramesIn(wire.bytes);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].first, kFrameAck);
  EXPECT_EQ(frames[0].second, 7);
}

TEST(SerialLink, AcksARepeatedSeqAgainButDeliversItOnce) {
  Wire wire;
  Inbox inbox;
  SerialLink link(wire, inbox, 100);
  const auto f =
      Encode(kFrameData, 7, R"({"cmd":"move_steps","left":100,"right":100})");
  link.Receive(f.data(), f.size(), 0);
  link.Receive(f.data(), f.size(), 10);
  EXPECT_EQ(inbox.messages.size(), 1u);
  EXPECT_EQ(FramesIn(wire.bytes).size(), 2u);
  EXPECT_EQ(link.duplicates(), 1u);
  const auto g = Encode(kFrameData, 8, R"({"cmd":"stop"})");
  link.Receive(g.data(), g.size(), 20);
  EXPECT_EQ(inbox.messages.size(), 2u);
}

TEST(SerialLink, RetriesAnUnackedFrameEvery2000MsThreeAttemptsInAll) {
  Wire wire;
  Inbox inbox;
  SerialLink link(wire, inbox, 0xFFFF);
  const std::string msg = R"({"ok":true})";
  ASSERT_TRUE(
      link.Send(reinterpret_cast<const uint8_t*>(msg.data()), msg.size(), 0));
  EXPECT_EQ(FramesIn(wire.bytes).size(), 1u);
  link.Poll(1999);
  EXPECT_EQ(FramesIn(wire.bytes).size(), 1u);
  link.Poll(2000);
  EXPECT_EQ(FramesIn(wire.bytes).size(), 2u);
  link.Poll(4000);
  EXPECT_EQ(FramesIn(wire.bytes).size(), 3u);
  link.Poll(6000);
  EXPECT_EQ(FramesIn(wire.bytes).size(), 3u) << "three attempts in all";
  EXPECT_EQ(link.given_up(), 1u);
  EXPECT_EQ(link.pending(), 0u);
  for (const auto& fr : FramesIn(wire.bytes)) EXPECT_EQ(fr.second, 0xFFFF);
}

TEST(SerialLink, SendsTheNextQueuedFrameWhenTheAckArrives) {
  Wire wire;
  Inbox inbox;
  SerialLink link(wire, inbox, 10);
  const std::string a = R"({"n":1})";
  const std::string b = R"({"n":2})";
  link.Send(reinterpret_cast<const uint8_t*>(a.data()), a.size(), 0);
  link.Send(reinterpret_cast<const uint8_t*>(b.data()), b.size(), 0);
  EXPECT_EQ(FramesIn(wire.bytes).size(), 1u);
  const auto ack = Encode(kFrameAck, 10, "");
  link.Receive(ack.data(), ack.size(), 5);
  const auto frames = FramesIn(wire.bytes);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[1].second, 11);
  const auto ack2 = Encode(kFrameAck, 11, "");
  link.Receive(ack2.data(), ack2.size(), 6);
  EXPECT_EQ(link.pending(), 0u);
  link.Poll(10000);
  EXPECT_EQ(link.retransmits(), 0u);
}

TEST(SerialLink, PassesAnOversizeHeaderToTheHandler) {
  Wire wire;
  Inbox inbox;
  SerialLink link(wire, inbox, 1);
  const std::vector<uint8_t> hdr = {0xA5, 0x5A, 0x01, 0x01, 0x00,
                                    0x01, 0x04, 0xFE, 0xFB};
  link.Receive(hdr.data(), hdr.size(), 0);
  ASSERT_EQ(inbox.oversize.size(), 1u);
  EXPECT_EQ(inbox.oversize[0], 1025u);
}

}  // namespace
}  // namespace cube
