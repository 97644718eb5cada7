#include "host_hal.h"

#include <mbedtls/md.h>

namespace cube {

bool MbedtlsMac::HmacSha256(const uint8_t* key, size_t key_len,
                            const uint8_t* data, size_t len, uint8_t* out) {
  const mbedtls_md_info_t* info = mbedtls_md_info_from_type(MBEDTLS_MD_SHA256);
  if (info == nullptr) return false;
  return mbedtls_md_hmac(info, key, key_len, data, len, out) == 0;
}

SystemRandom::SystemRandom() : engine_(std::random_device{}()) {}

uint32_t SystemRandom::NextU32() { return static_cast<uint32_t>(engine_()); }

ScaledClock::ScaledClock(double scale)
    : start_(std::chrono::steady_clock::now()), scale_(scale) {}

uint64_t ScaledClock::NowUs() {
  const auto at = held_ ? held_at_ : std::chrono::steady_clock::now();
  const auto real =
      std::chrono::duration_cast<std::chrono::microseconds>(at - start_)
          .count();
  const uint64_t us =
      real <= 0 ? 0
                : static_cast<uint64_t>(static_cast<double>(real) * scale_);
  if (us > last_us_) last_us_ = us;
  return last_us_;
}

void ScaledClock::HoldAt(std::chrono::steady_clock::time_point t) {
  held_ = true;
  held_at_ = t;
}

void ScaledClock::Release() { held_ = false; }

uint64_t ScaledClock::StartSteadyUs() const {
  return static_cast<uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(
          start_.time_since_epoch())
          .count());
}

bool ParseHex(const std::string& hex, std::vector<uint8_t>* out) {
  if (hex.size() % 2 != 0) return false;
  out->clear();
  auto nibble = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  for (size_t i = 0; i < hex.size(); i += 2) {
    const int hi = nibble(hex[i]);
    const int lo = nibble(hex[i + 1]);
    if (hi < 0 || lo < 0) return false;
    out->push_back(static_cast<uint8_t>((hi << 4) | lo));
  }
  return true;
}

std::string MacHex(const std::vector<uint8_t>& key, const std::string& json) {
  MbedtlsMac mac;
  uint8_t digest[32];
  mac.HmacSha256(key.data(), key.size(),
                 reinterpret_cast<const uint8_t*>(json.data()), json.size(),
                 digest);
  static const char kHex[] = "0123456789abcdef";
  std::string s;
  for (int i = 0; i < 16; ++i) {
    s += kHex[digest[i] >> 4];
    s += kHex[digest[i] & 0xF];
  }
  return s;
}

}  // namespace cube
