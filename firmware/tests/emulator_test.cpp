// cube-emulator as a process: real UDP socket, real pseudo-terminal.
#include <arpa/inet.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <vector>

#include "frame.h"
#include "harness.h"

namespace cube::testing {
namespace {

using Clock = std::chrono::steady_clock;

class Emulator {
 public:
  explicit Emulator(std::vector<std::string> extra = {}) {
    int in[2];
    int out[2];
    EXPECT_EQ(pipe(in), 0);
    EXPECT_EQ(pipe(out), 0);
    const auto t0 = Clock::now();
    pid_ = fork();
    if (pid_ == 0) {
      dup2(in[0], STDIN_FILENO);
      dup2(out[1], STDOUT_FILENO);
      close(in[1]);
      close(out[0]);
      std::vector<std::string> args = {CUBE_EMULATOR_PATH, "--udp-port", "0",
                                       "--exit-on-stdin-eof"};
      args.insert(args.end(), extra.begin(), extra.end());
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(argv[0], argv.data());
      _exit(127);
    }
    close(in[0]);
    close(out[1]);
    stdin_ = in[1];
    stdout_ = out[0];
    ready = json::parse(ReadLine(2000));
    startup_ms =
        std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    udp_ = socket(AF_INET, SOCK_DGRAM, 0);
    addr_.sin_family = AF_INET;
    addr_.sin_port = htons(ready["udp_port"].get<uint16_t>());
    inet_pton(AF_INET, "127.0.0.1", &addr_.sin_addr);
  }

  ~Emulator() {
    if (pid_ > 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (udp_ >= 0) close(udp_);
    if (stdin_ >= 0) close(stdin_);
    if (stdout_ >= 0) close(stdout_);
  }

  std::string ReadLine(int timeout_ms) {
    const auto deadline = Clock::now() + std::chrono::milliseconds(timeout_ms);
    while (true) {
      const size_t nl = buffer_.find('\n');
      if (nl != std::string::npos) {
        std::string line = buffer_.substr(0, nl);
        buffer_.erase(0, nl + 1);
        return line;
      }
      const int left = static_cast<int>(
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline -
                                                                Clock::now())
              .count());
      if (left <= 0) return "";
      pollfd p{stdout_, POLLIN, 0};
      if (poll(&p, 1, left) <= 0) return "";
      char tmp[4096];
      const ssize_t n = read(stdout_, tmp, sizeof(tmp));
      if (n <= 0) return "";
      buffer_.append(tmp, static_cast<size_t>(n));
    }
  }

  // Waits for an event line with this name.
  json WaitEvent(const std::string& name, int timeout_ms) {
    const auto deadline = Clock::now() + std::chrono::milliseconds(timeout_ms);
    while (Clock::now() < deadline) {
      const std::string line = ReadLine(100);
      if (line.empty()) continue;
      const json e = json::parse(line);
      if (e["event"] == name) return e;
    }
    return json();
  }

  std::string Udp(const std::string& bytes) {
    sendto(udp_, bytes.data(), bytes.size(), 0,
           reinterpret_cast<sockaddr*>(&addr_), sizeof(addr_));
    pollfd p{udp_, POLLIN, 0};
    if (poll(&p, 1, 2000) <= 0) return "";
    char buf[2048];
    const ssize_t n = recv(udp_, buf, sizeof(buf), 0);
    return n > 0 ? std::string(buf, static_cast<size_t>(n)) : "";
  }

  int Terminate(int sig) {
    kill(pid_, sig);
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
    return status;
  }

  int CloseStdinAndWait() {
    close(stdin_);
    stdin_ = -1;
    int status = 0;
    for (int i = 0; i < 200; ++i) {
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        return status;
      }
      usleep(10000);
    }
    return -1;
  }

  json ready;
  double startup_ms = 0;

 private:
  pid_t pid_ = -1;
  int stdin_ = -1;
  int stdout_ = -1;
  int udp_ = -1;
  sockaddr_in addr_{};
  std::string buffer_;
};

TEST(Emulator, StartsInWellUnderASecondAndSaysWhereItListens) {
  Emulator e;
  ASSERT_EQ(e.ready["event"], "ready");
  EXPECT_GT(e.ready["udp_port"].get<int>(), 0);
  EXPECT_EQ(e.ready["pty"].get<std::string>().rfind("/dev/pts/", 0), 0u);
  EXPECT_LT(e.startup_ms, 500.0);
}

TEST(Emulator, ExecutesARetriedUdpMoveOnceAndReportsItsSteps) {
  Emulator e({"--time-scale", "20", "--host-timeout-ms", "10000"});
  const json hello =
      json::parse(e.Udp(R"({"cmd":"hello","seq":1,"nonce":"x"})"));
  const uint32_t sid = hello["sid"];
  const std::string move = json({{"cmd", "move_cm"},
                                 {"seq", 2},
                                 {"sid", sid},
                                 {"left_cm", 10},
                                 {"right_cm", 10}})
                               .dump();
  const std::string first = e.Udp(move);
  EXPECT_EQ(e.Udp(move), first);
  const json started = e.WaitEvent("move_started", 1000);
  EXPECT_EQ(started["left_steps"], 2172);
  const json done = e.WaitEvent("move_finished", 3000);
  EXPECT_EQ(done["outcome"], "done");
  EXPECT_EQ(done["left_position"], 2172);
  EXPECT_EQ(done["right_position"], 2172);
  EXPECT_TRUE(e.WaitEvent("move_started", 300).is_null()) << "executed once";
}

TEST(Emulator, AnswersGarbageTruncatedAndOversizedDatagramsAndKeepsRunning) {
  Emulator e;
  for (const std::string bad :
       {std::string("garbage"), std::string("{\"cmd\":\"stop\""),
        std::string(3000, 'x')}) {
    const json r = json::parse(e.Udp(bad));
    EXPECT_EQ(r["error"]["code"], "MALFORMED");
  }
  EXPECT_EQ(json::parse(e.Udp(R"({"cmd":"heartbeat"})"))["ok"], true);
}

std::vector<uint8_t> Frame(uint8_t type, uint16_t seq,
                           const std::string& payload) {
  std::vector<uint8_t> out(kFrameMaxSize);
  out.resize(EncodeFrame(type, seq,
                         reinterpret_cast<const uint8_t*>(payload.data()),
                         payload.size(), out.data(), out.size()));
  return out;
}

TEST(Emulator, AnswersSeedCommandsInFramesOverThePty) {
  Emulator e({"--time-scale", "10", "--host-timeout-ms", "10000"});
  const int fd =
      open(e.ready["pty"].get<std::string>().c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(fd, 0);
  termios t{};
  tcgetattr(fd, &t);
  cfmakeraw(&t);
  tcsetattr(fd, TCSANOW, &t);
  // Garbage first: the device must resynchronise.
  const std::vector<uint8_t> junk = {0x00, 0xA5, 0x13, 0x5A, 0xFF};
  ASSERT_EQ(write(fd, junk.data(), junk.size()),
            static_cast<ssize_t>(junk.size()));
  const auto req =
      Frame(kFrameData, 40,
            R"({"cmd":"move_steps","left":300,"right":-300,"speed":1000})");
  ASSERT_EQ(write(fd, req.data(), req.size()),
            static_cast<ssize_t>(req.size()));

  std::vector<uint8_t> in;
  bool acked = false;
  std::string reply;
  const auto deadline = Clock::now() + std::chrono::seconds(3);
  while ((!acked || reply.empty()) && Clock::now() < deadline) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, 100) <= 0) continue;
    uint8_t buf[2048];
    const ssize_t n = read(fd, buf, sizeof(buf));
    if (n > 0) in.insert(in.end(), buf, buf + n);
    size_t pos = 0;
    while (pos < in.size()) {
      cube::Frame f;
      size_t used = 0;
      if (DecodeFrame(in.data() + pos, in.size() - pos, &f, &used) !=
          FrameError::kOk)
        break;
      if (f.type == kFrameAck && f.seq == 40) acked = true;
      if (f.type == kFrameData) {
        reply.assign(reinterpret_cast<const char*>(f.payload), f.len);
        const auto ack = Frame(kFrameAck, f.seq, "");
        ASSERT_EQ(write(fd, ack.data(), ack.size()),
                  static_cast<ssize_t>(ack.size()));
      }
      pos += used;
    }
    in.erase(in.begin(), in.begin() + static_cast<long>(pos));
  }
  close(fd);
  EXPECT_TRUE(acked);
  ASSERT_FALSE(reply.empty());
  const json r = json::parse(reply);
  EXPECT_EQ(r["ok"], true);
  EXPECT_EQ(r["left_steps"], 300);
  EXPECT_EQ(r["right_steps"], -300);
  const json done = e.WaitEvent("move_finished", 3000);
  EXPECT_EQ(done["left_position"], 300);
  EXPECT_EQ(done["right_position"], -300);
}

TEST(Emulator, RunsTheSeedCommandsOverUdpWithTheirStepCounts) {
  Emulator e({"--time-scale", "20", "--host-timeout-ms", "10000"});
  json r = json::parse(
      e.Udp(R"({"cmd":"move_steps","left":1000,"right":-1000,"speed":800})"));
  EXPECT_EQ(r["ok"], true);
  EXPECT_FALSE(r.contains("seq"));
  json done = e.WaitEvent("move_finished", 3000);
  EXPECT_EQ(done["left_position"], 1000);
  EXPECT_EQ(done["right_position"], -1000);
  r = json::parse(
      e.Udp(R"({"cmd":"move_cm","left_cm":10,"right_cm":10,"speed":1024})"));
  EXPECT_EQ(r["left_steps"], 2172);
  done = e.WaitEvent("move_finished", 3000);
  EXPECT_EQ(done["left_steps"], 2172);
  r = json::parse(e.Udp(R"({"cmd":"rotate_deg","degrees":90,"speed":1024})"));
  EXPECT_EQ(r["left_steps"], -1706);
  done = e.WaitEvent("move_finished", 3000);
  EXPECT_EQ(done["right_steps"], 1707)
      << "the accumulator carries the 10 cm move's fraction";
  r = json::parse(e.Udp(
      R"({"cmd":"set_config","wheel_diameter_cm":6.0,"wheel_base_cm":10.0})"));
  EXPECT_EQ(r["ok"], true);
  r = json::parse(e.Udp(R"({"cmd":"stop"})"));
  EXPECT_EQ(r["ok"], true);
  r = json::parse(e.Udp(R"({"cmd":"get_status"})"));
  EXPECT_EQ(r["left_steps"], 1000 + 2172 - 1706);
  EXPECT_EQ(r["right_steps"], -1000 + 2172 + 1707);
  EXPECT_EQ(r["running"], false);
}

TEST(Emulator, ReportsTheWheelPositionsWhileTheyTurnWhenAsked) {
  Emulator e({"--time-scale", "5", "--report-wheels-ms", "20", "--no-pty",
              "--host-timeout-ms", "10000"});
  const json first = e.WaitEvent("wheels", 1000);
  ASSERT_FALSE(first.is_null()) << "no wheels event at start";
  EXPECT_EQ(first["left_position"], 0);
  EXPECT_EQ(first["right_position"], 0);
  const json r = json::parse(
      e.Udp(R"({"cmd":"move_steps","left":1000,"right":-1000,"speed":800})"));
  EXPECT_EQ(r["ok"], true);
  int between = 0;
  int64_t last = 0;
  for (int i = 0; i < 400 && last != 1000; ++i) {
    const json w = e.WaitEvent("wheels", 3000);
    ASSERT_FALSE(w.is_null()) << "the wheels stopped being reported at " << last;
    const int64_t left = w["left_position"].get<int64_t>();
    EXPECT_EQ(w["right_position"].get<int64_t>(), -left);
    EXPECT_GE(left, last) << "positions only grow in this move";
    if (left > 0 && left < 1000) ++between;
    last = left;
  }
  EXPECT_EQ(last, 1000) << "the last report is where the wheels stopped";
  EXPECT_GE(between, 2) << "positions are reported while the wheels turn";
  EXPECT_TRUE(e.WaitEvent("wheels", 300).is_null())
      << "nothing is reported while the wheels stand still";
}

TEST(Emulator, RefusesAReportPeriodOutOfRange) {
  for (const char* bad : {"0", "10001", "x"}) {
    const std::string cmd = std::string(CUBE_EMULATOR_PATH) +
                            " --report-wheels-ms " + bad + " 2>/dev/null";
    const int status = std::system(cmd.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << bad;
  }
}

TEST(Emulator, PrintsAConfigEventOnlyWhenSetConfigChangesTheConfiguration) {
  Emulator e;
  json r = json::parse(e.Udp(
      R"({"cmd":"set_config","wheel_diameter_cm":6.0,"wheel_base_cm":10.0})"));
  EXPECT_EQ(r["ok"], true);
  r = json::parse(e.Udp(
      R"({"cmd":"set_config","wheel_diameter_cm":6.12,"wheel_base_cm":10.49})"));
  EXPECT_EQ(r["ok"], true);
  const json c = e.WaitEvent("config", 2000);
  ASSERT_FALSE(c.is_null()) << "no config event after a change";
  EXPECT_DOUBLE_EQ(c["wheel_diameter_cm"].get<double>(), 6.12);
  EXPECT_DOUBLE_EQ(c["wheel_base_cm"].get<double>(), 10.49);
  EXPECT_EQ(c["steps_per_revolution"], 4096);
  EXPECT_EQ(c["host_timeout_ms"], 2000);
  // the event carries the reply's config, written the same way (one writer)
  json fields = r["config"];
  fields.erase("max_steps_per_command");
  for (auto it = fields.begin(); it != fields.end(); ++it)
    EXPECT_EQ(c[it.key()], it.value()) << it.key();
  EXPECT_EQ(c.size(), fields.size() + 2) << c.dump();  // + event, t_ms
  // a refused set_config changes nothing, and so prints nothing
  r = json::parse(e.Udp(R"({"cmd":"set_config","wheel_base_cm":0})"));
  EXPECT_EQ(r["ok"], false);
  EXPECT_TRUE(e.WaitEvent("config", 300).is_null());
}

TEST(Emulator, AnswersAnOversizeFrameOverThePtyWithMalformed) {
  Emulator e;
  const int fd =
      open(e.ready["pty"].get<std::string>().c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(fd, 0);
  termios t{};
  tcgetattr(fd, &t);
  cfmakeraw(&t);
  tcsetattr(fd, TCSANOW, &t);
  const std::vector<uint8_t> hdr = {0xA5, 0x5A, 0x01, 0x07, 0x00,
                                    0x00, 0x08, 0xFF, 0xF7};
  ASSERT_EQ(write(fd, hdr.data(), hdr.size()),
            static_cast<ssize_t>(hdr.size()));
  std::vector<uint8_t> in;
  std::string reply;
  const auto deadline = Clock::now() + std::chrono::seconds(2);
  while (reply.empty() && Clock::now() < deadline) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, 100) <= 0) continue;
    uint8_t buf[2048];
    const ssize_t n = read(fd, buf, sizeof(buf));
    if (n > 0) in.insert(in.end(), buf, buf + n);
    cube::Frame f;
    size_t used = 0;
    if (DecodeFrame(in.data(), in.size(), &f, &used) == FrameError::kOk &&
        f.type == kFrameData) {
      reply.assign(reinterpret_cast<const char*>(f.payload), f.len);
    }
  }
  close(fd);
  ASSERT_FALSE(reply.empty());
  const json r = json::parse(reply);
  EXPECT_EQ(r["error"]["code"], "MALFORMED");
  EXPECT_EQ(r["error"]["details"]["length"], 2048);
}

TEST(Emulator, ExitsCleanlyOnSigtermAndWhenStdinCloses) {
  Emulator a;
  const int status = a.Terminate(SIGTERM);
  EXPECT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  Emulator b;
  const int s2 = b.CloseStdinAndWait();
  ASSERT_NE(s2, -1);
  EXPECT_TRUE(WIFEXITED(s2));
  EXPECT_EQ(WEXITSTATUS(s2), 0);
}

TEST(Emulator, RequiresAMacWhenStartedWithAKey) {
  Emulator e({"--key", "000102030405060708090a0b0c0d0e0f"});
  EXPECT_EQ(e.ready["auth"], "hmac-sha256");
  const std::string raw = e.Udp(R"({"cmd":"hello","seq":1,"nonce":"n"})");
  ASSERT_GT(raw.size(), 33u);
  EXPECT_EQ(json::parse(raw.substr(0, raw.size() - 33))["error"]["code"],
            "AUTH_FAILED");
  const std::vector<uint8_t> key = FromHex("000102030405060708090a0b0c0d0e0f");
  const std::string body = R"({"cmd":"hello","seq":1,"nonce":"n"})";
  const std::string ok = e.Udp(body + "#" + MacHex(key, body));
  const std::string reply = ok.substr(0, ok.size() - 33);
  EXPECT_EQ(ok.substr(ok.size() - 32), MacHex(key, reply));
  EXPECT_EQ(json::parse(reply)["ok"], true);
}

}  // namespace
}  // namespace cube::testing
