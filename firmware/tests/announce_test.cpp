// The mDNS announcement (announce.h, docs/discovery.md): the TXT entries the
// board and the emulator publish, built from the robot itself.
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <string>

#include "announce.h"
#include "harness.h"

namespace cube::testing {
namespace {

const std::vector<uint8_t> kKey = {0x00, 0x11, 0x22, 0x33, 0x44, 0x55,
                                   0x66, 0x77, 0x88, 0x99, 0xaa, 0xbb};

std::map<std::string, std::string> Entries(const Announcement& a) {
  std::map<std::string, std::string> out;
  for (size_t i = 0; i < a.count(); ++i) {
    out[a.entry(i).key] = a.entry(i).value;
  }
  return out;
}

CapabilityList Caps(size_t count, size_t len, char fill = 'x') {
  CapabilityList caps;
  for (size_t i = 0; i < count; ++i) {
    std::memset(caps.items[i], fill, len);
    caps.items[i][len] = '\0';
  }
  caps.count = count;
  return caps;
}

TEST(Announcement, CarriesTheDeviceIdProtocolAuthAndHellosCapabilities) {
  Device d;
  Announcement a;
  ASSERT_TRUE(a.Build(*d.cube));
  const auto e = Entries(a);
  EXPECT_EQ(e.at("txtvers"), "1");
  EXPECT_EQ(e.at("device_id"), "cube-test");
  EXPECT_EQ(e.at("proto"), kProtocolVersion);
  EXPECT_EQ(e.at("auth"), "none");
  EXPECT_EQ(e.count("caps1"), 0u);

  const json hello = d.Hello();
  std::string joined;
  for (const auto& cap : hello["capabilities"]) {
    joined += (joined.empty() ? "" : ",") + cap.get<std::string>();
  }
  EXPECT_EQ(e.at("caps"), joined);
}

TEST(Announcement, SaysARobotWithAKeyRequiresOne) {
  Device d(kKey);
  Announcement a;
  ASSERT_TRUE(a.Build(*d.cube));
  EXPECT_EQ(Entries(a).at("auth"), "hmac-sha256");
}

TEST(Announcement, FollowsTheConfiguredStepsPerRevolution) {
  Device d;
  CubeConfig config;
  config.geometry.steps_per_revolution = 2048;
  d.cube->Configure(config);
  Announcement a;
  ASSERT_TRUE(a.Build(*d.cube));
  EXPECT_NE(Entries(a).at("caps").find("steps_per_rev=2048"),
            std::string::npos);
}

TEST(Announcement, KeepsEveryEntryWithin255BytesAndSplitsCapabilitiesWhole) {
  // Eight 63-byte capabilities (511 bytes with commas) do not fit one entry.
  const CapabilityList caps = Caps(8, 63);
  Announcement a;
  ASSERT_TRUE(a.Build("cube-1", AuthMode::kNone, caps));
  const auto e = Entries(a);
  std::string joined;
  for (size_t i = 0; i < a.count(); ++i) {
    const std::string key = a.entry(i).key;
    const std::string value = a.entry(i).value;
    EXPECT_LE(key.size() + 1 + value.size(), kMaxTxtEntryLen) << key;
    if (key.rfind("caps", 0) == 0) {
      joined += (joined.empty() ? "" : ",") + value;
      // No capability cut in two: every part is whole 63-byte items.
      EXPECT_EQ((value.size() + 1) % 64, 0u) << key;
    }
  }
  EXPECT_TRUE(e.count("caps1") == 1 && e.count("caps2") == 1);
  EXPECT_EQ(joined.size(), 8u * 64u - 1u);
}

TEST(Announcement, RefusesACapabilityWithACommaAndLeavesNoEntries) {
  CapabilityList caps = Caps(2, 10);
  caps.items[1][3] = ',';
  Announcement a;
  EXPECT_FALSE(a.Build("cube-1", AuthMode::kNone, caps));
  EXPECT_EQ(a.count(), 0u);
}

TEST(Announcement, RefusesAnEmptyDeviceId) {
  Announcement a;
  EXPECT_FALSE(a.Build("", AuthMode::kNone, Caps(1, 10)));
  EXPECT_FALSE(a.Build(nullptr, AuthMode::kNone, Caps(1, 10)));
  EXPECT_EQ(a.count(), 0u);
}

TEST(Announcement, NamesTheServiceAsDnsSdLabels) {
  EXPECT_STREQ(kMdnsService, "_hal-cube");
  EXPECT_STREQ(kMdnsProto, "_udp");
  // A DNS-SD service name is at most 15 characters after the underscore.
  EXPECT_LE(std::strlen(kMdnsService) - 1, 15u);
}

}  // namespace
}  // namespace cube::testing
