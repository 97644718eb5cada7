#include "harness.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace cube::testing {

Device::Device() { Init(); }

Device::Device(const std::vector<uint8_t>& k) : key(k) { Init(); }

void Device::Init() {
  CubeDeps deps;
  deps.clock = &clock;
  deps.motors = &motors;
  deps.random = &random;
  deps.led = &led;
  deps.watchdog = &watchdog;
  deps.mac = &mac;
  cube = std::make_unique<Cube>(deps, "cube-test");
  cube->set_observer(&observer);
  // Without a key the tests run the robot as the emulator does on
  // loopback: the explicit unauthenticated opt-out.
  if (key.empty()) {
    cube->AllowUnauthenticated();
  } else {
    cube->SetKey(key.data(), key.size());
  }
}

std::string Device::Raw(const std::string& bytes) {
  uint8_t out[kMaxMessage + 64];
  const size_t n = cube->Handle(reinterpret_cast<const uint8_t*>(bytes.data()),
                                bytes.size(), out, sizeof(out));
  last_raw_reply.assign(reinterpret_cast<const char*>(out), n);
  return last_raw_reply;
}

json Device::Send(const json& request) {
  std::string text = request.dump();
  if (!key.empty()) text += "#" + MacHex(key, text);
  std::string reply = Raw(text);
  if (!key.empty()) {
    if (reply.size() < 33 || reply[reply.size() - 33] != '#') {
      throw std::runtime_error("reply has no MAC: " + reply);
    }
    const std::string body = reply.substr(0, reply.size() - 33);
    if (MacHex(key, body) != reply.substr(reply.size() - 32)) {
      throw std::runtime_error("reply MAC is wrong: " + reply);
    }
    reply = body;
  }
  return json::parse(reply);
}

json Device::Hello() {
  seq = 1;
  json req = {{"cmd", "hello"}, {"seq", seq}, {"client", "gtest"}};
  if (!key.empty()) req["nonce"] = "n" + std::to_string(++hellos_);
  json r = Send(req);
  if (r.value("ok", false)) sid = r["sid"].get<uint32_t>();
  return r;
}

json Device::Call(const std::string& cmd, json params) {
  params["cmd"] = cmd;
  params["seq"] = ++seq;
  params["sid"] = sid;
  return Send(params);
}

void Device::Run(uint64_t ms, bool heartbeat) {
  for (uint64_t i = 0; i < ms; ++i) {
    for (int t = 0; t < 4; ++t) {
      clock.now_us += 250;
      cube->Tick();
    }
    cube->Poll();
    if (heartbeat && ++since_heartbeat_ms_ >= 500) {
      since_heartbeat_ms_ = 0;
      if (key.empty()) {
        Raw("{\"cmd\":\"heartbeat\"}");
      } else {
        Call("heartbeat");
      }
    }
  }
}

uint64_t Device::RunUntilIdle(uint64_t max_ms, bool heartbeat) {
  uint64_t ran = 0;
  while (cube->running() && ran < max_ms) {
    Run(1, heartbeat);
    ++ran;
  }
  return ran;
}

std::string VectorPath(const std::string& name) {
  const char* dir = std::getenv("CUBE_VECTORS_DIR");
  return std::string(dir != nullptr ? dir : CUBE_VECTORS_DIR) + "/" + name;
}

std::string ReadVectorFile(const std::string& name) {
  std::ifstream f(VectorPath(name));
  if (!f) return "";
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

std::vector<uint8_t> FromHex(const std::string& hex) {
  std::vector<uint8_t> out;
  if (!ParseHex(hex, &out)) throw std::runtime_error("bad hex: " + hex);
  return out;
}

std::string ToHexString(const uint8_t* data, size_t len) {
  static const char kHex[] = "0123456789abcdef";
  std::string s;
  for (size_t i = 0; i < len; ++i) {
    s += kHex[data[i] >> 4];
    s += kHex[data[i] & 0xF];
  }
  return s;
}

}  // namespace cube::testing
