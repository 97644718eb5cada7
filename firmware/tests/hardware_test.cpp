// Against a real cube on the network. Skipped unless CUBE_UDP_ADDR is set
// (e.g. CUBE_UDP_ADDR=192.168.1.50:4210); CUBE_KEY_HEX if it has a key.
// The robot moves 200 steps per wheel: lift it or give it room.
#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <thread>

#include "harness.h"

namespace cube::testing {
namespace {

class RealCube {
 public:
  bool Open() {
    const char* addr = std::getenv("CUBE_UDP_ADDR");
    if (addr == nullptr || *addr == '\0') return false;
    const std::string a = addr;
    const size_t colon = a.rfind(':');
    const std::string host = colon == std::string::npos ? a : a.substr(0, colon);
    const int port = colon == std::string::npos ? 4210 : std::atoi(a.c_str() + colon + 1);
    const char* key = std::getenv("CUBE_KEY_HEX");
    if (key != nullptr && *key != '\0') key_ = FromHex(key);
    fd_ = socket(AF_INET, SOCK_DGRAM, 0);
    to_.sin_family = AF_INET;
    to_.sin_port = htons(static_cast<uint16_t>(port));
    return inet_pton(AF_INET, host.c_str(), &to_.sin_addr) == 1;
  }
  ~RealCube() {
    if (fd_ >= 0) close(fd_);
  }

  // Sends with up to three attempts (the same bytes: exactly-once retries).
  json Send(const json& req) {
    std::string text = req.dump();
    if (!key_.empty()) text += "#" + MacHex(key_, text);
    for (int attempt = 0; attempt < 3; ++attempt) {
      sendto(fd_, text.data(), text.size(), 0, reinterpret_cast<sockaddr*>(&to_), sizeof(to_));
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, 2000) <= 0) continue;
      char buf[2048];
      const ssize_t n = recv(fd_, buf, sizeof(buf), 0);
      if (n <= 0) continue;
      std::string reply(buf, static_cast<size_t>(n));
      if (!key_.empty() && reply.size() > 33) reply.resize(reply.size() - 33);
      return json::parse(reply);
    }
    return json();
  }

  json Call(const std::string& cmd, json params = json::object()) {
    params["cmd"] = cmd;
    params["seq"] = ++seq_;
    params["sid"] = sid_;
    return Send(params);
  }

  json Hello() {
    seq_ = 1;
    const json r = Send({{"cmd", "hello"}, {"seq", 1}, {"nonce", std::to_string(std::rand())}});
    if (r.is_object() && r.value("ok", false)) sid_ = r["sid"];
    return r;
  }

 private:
  int fd_ = -1;
  sockaddr_in to_{};
  std::vector<uint8_t> key_;
  uint32_t sid_ = 0;
  uint32_t seq_ = 0;
};

TEST(RealCube, AnswersHelloAndMovesExactlyOnceWhenARequestIsRepeated) {
  RealCube cube;
  if (!cube.Open()) GTEST_SKIP() << "set CUBE_UDP_ADDR=ip[:port] to run against a real cube";
  const json hello = cube.Hello();
  ASSERT_TRUE(hello.is_object()) << "no reply from the cube";
  EXPECT_EQ(hello["protocol_version"], "1.1");
  const json before = cube.Call("get_status");
  ASSERT_TRUE(before.value("ok", false)) << before.dump();
  const int64_t left0 = before["left_steps"];
  const json move = cube.Call("move_steps", {{"left", 200}, {"right", 200}, {"speed", 400}});
  ASSERT_TRUE(move.value("ok", false)) << move.dump();
  const json again = cube.Send({{"cmd", "move_steps"}, {"seq", move["seq"]}, {"sid", move["sid"]},
                                {"left", 200}, {"right", 200}, {"speed", 400}});
  EXPECT_EQ(again, move);
  json status;
  for (int i = 0; i < 40; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    status = cube.Call("get_status");  // also keeps the host timeout away
    if (status.is_object() && !status["running"].get<bool>()) break;
  }
  EXPECT_EQ(status["left_steps"].get<int64_t>(), left0 + 200);
  EXPECT_EQ(status["move_outcome"], "done");
}

}  // namespace
}  // namespace cube::testing
