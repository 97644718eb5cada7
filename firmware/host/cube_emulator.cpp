// cube-emulator: the stepper cube's firmware core on this computer. It
// listens on UDP and on a pseudo-terminal (serial framing), moves virtual
// steppers on a real (or scaled) clock and prints JSON lines about what the
// robot does. See docs/firmware.md.
#include <poll.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "cube.h"
#include "emulator_io.h"
#include "frame.h"
#include "host_hal.h"
#include "settings.h"

namespace {

volatile std::sig_atomic_t g_stop = 0;

void OnSignal(int) { g_stop = 1; }

struct Options {
  std::string bind = "127.0.0.1";
  long udp_port = 4210;
  double time_scale = 1.0;
  std::string key_hex;
  long host_timeout_ms = 2000;
  std::string device_id = "cube-emulator";
  bool exit_on_stdin_eof = false;
  bool pty = true;
  bool insecure = false;
  long report_wheels_ms = 0;
};

void Usage(FILE* f) {
  std::fprintf(
      f,
      "usage: cube-emulator [options]\n"
      "  --udp-port N          UDP port on the bind address (default 4210, "
      "0 = a free port)\n"
      "  --bind ADDR           IPv4 address to listen on (default "
      "127.0.0.1); an address\n"
      "                        other than 127.x.x.x needs --key or "
      "--insecure\n"
      "  --time-scale X        run the robot's clock X times faster (default "
      "1)\n"
      "  --key HEX             pre-shared key: requests must carry a MAC\n"
      "                        (without it: no authentication, as a board "
      "built with\n"
      "                        CUBE_ALLOW_UNAUTHENTICATED)\n"
      "  --insecure            allow a non-loopback --bind without --key: "
      "anyone on\n"
      "                        that network can command the robot\n"
      "  --host-timeout-ms N   host timeout, 500..10000 (default 2000)\n"
      "  --device-id ID        device_id reported by hello (default "
      "cube-emulator)\n"
      "  --no-pty              do not open a pseudo-terminal\n"
      "  --report-wheels-ms N  print a `wheels` event with the wheel "
      "positions\n"
      "                        when they changed, at most every N ms (1..10000;\n"
      "                        default: never)\n"
      "  --exit-on-stdin-eof   exit when standard input closes\n");
}

bool ParseArgs(int argc, char** argv, Options* o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "cube-emulator: %s needs a value\n", name);
        return nullptr;
      }
      return argv[++i];
    };
    if (a == "--help" || a == "-h") {
      Usage(stdout);
      std::exit(0);
    } else if (a == "--udp-port") {
      const char* v = value("--udp-port");
      if (v == nullptr) return false;
      char* end = nullptr;
      o->udp_port = std::strtol(v, &end, 10);
      if (*end != '\0' || o->udp_port < 0 || o->udp_port > 65535) {
        std::fprintf(stderr, "cube-emulator: --udp-port must be 0..65535\n");
        return false;
      }
    } else if (a == "--bind") {
      const char* v = value("--bind");
      if (v == nullptr) return false;
      o->bind = v;
    } else if (a == "--time-scale") {
      const char* v = value("--time-scale");
      if (v == nullptr) return false;
      char* end = nullptr;
      o->time_scale = std::strtod(v, &end);
      if (*end != '\0' || !(o->time_scale > 0 && o->time_scale <= 1000)) {
        std::fprintf(stderr,
                     "cube-emulator: --time-scale must be a number in "
                     "(0, 1000]\n");
        return false;
      }
    } else if (a == "--key") {
      const char* v = value("--key");
      if (v == nullptr) return false;
      o->key_hex = v;
    } else if (a == "--host-timeout-ms") {
      const char* v = value("--host-timeout-ms");
      if (v == nullptr) return false;
      char* end = nullptr;
      o->host_timeout_ms = std::strtol(v, &end, 10);
      const double ms = static_cast<double>(o->host_timeout_ms);
      if (*end != '\0' || ms < cube::kHostTimeoutMs.min ||
          ms > cube::kHostTimeoutMs.max) {
        std::fprintf(stderr,
                     "cube-emulator: --host-timeout-ms must be 500..10000\n");
        return false;
      }
    } else if (a == "--device-id") {
      const char* v = value("--device-id");
      if (v == nullptr) return false;
      o->device_id = v;
    } else if (a == "--report-wheels-ms") {
      const char* v = value("--report-wheels-ms");
      if (v == nullptr) return false;
      char* end = nullptr;
      o->report_wheels_ms = std::strtol(v, &end, 10);
      if (*end != '\0' || o->report_wheels_ms < 1 ||
          o->report_wheels_ms > 10000) {
        std::fprintf(stderr,
                     "cube-emulator: --report-wheels-ms must be 1..10000\n");
        return false;
      }
    } else if (a == "--insecure") {
      o->insecure = true;
    } else if (a == "--no-pty") {
      o->pty = false;
    } else if (a == "--exit-on-stdin-eof") {
      o->exit_on_stdin_eof = true;
    } else {
      std::fprintf(stderr, "cube-emulator: unknown option %s\n", a.c_str());
      Usage(stderr);
      return false;
    }
  }
  return true;
}

// Motors with no hardware: the core counts the steps itself.
class VirtualMotors : public cube::MotorDriver {
 public:
  void WriteCoils(cube::Wheel, uint8_t) override {}
};

// Serial messages go to the cube; its replies go back over the link.
class SerialBridge : public cube::LinkHandler {
 public:
  SerialBridge(cube::Cube& c, cube::ScaledClock& real)
      : cube_(c), real_(real) {}
  void set_link(cube::SerialLink* l) { link_ = l; }
  void OnMessage(const uint8_t* data, size_t len) override {
    const size_t n = cube_.Handle(data, len, out_, sizeof(out_));
    link_->Send(out_, n, real_.NowUs() / 1000);
  }
  void OnOversize(size_t announced) override {
    const size_t n = cube_.HandleOversize(announced, out_, sizeof(out_));
    link_->Send(out_, n, real_.NowUs() / 1000);
  }

 private:
  cube::Cube& cube_;
  cube::ScaledClock& real_;
  cube::SerialLink* link_ = nullptr;
  uint8_t out_[cube::kMaxMessage];
};

// The step interrupt, and with it the motion part of the task or the whole
// task, as on the board. At a high time scale more steps fall due per pass
// than the queue holds, so repeat while steps are still being made.
void CatchUpSteps(cube::Cube& robot, bool with_task) {
  for (int pass = 0; pass < 256; ++pass) {
    const int64_t l = robot.left_position();
    const int64_t r = robot.right_position();
    robot.Tick();
    if (with_task) {
      robot.Poll();
    } else {
      robot.UpdateMotion();
    }
    if (robot.left_position() == l && robot.right_position() == r) break;
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  if (!ParseArgs(argc, argv, &opt)) return 2;

  std::vector<uint8_t> key;
  if (!opt.key_hex.empty() && (!cube::ParseHex(opt.key_hex, &key) ||
                               key.empty() || key.size() > cube::kMaxKeyLen)) {
    std::fprintf(stderr,
                 "cube-emulator: --key must be 1..64 bytes written as hex\n");
    return 2;
  }

  if (key.empty() && !opt.insecure && !cube::IsLoopbackAddress(opt.bind)) {
    std::fprintf(stderr,
                 "cube-emulator: refusing to listen on %s without a key: "
                 "anyone on that network could command the robot. Give "
                 "--key HEX, bind 127.0.0.1, or pass --insecure to accept "
                 "that.\n",
                 opt.bind.c_str());
    return 2;
  }

  std::signal(SIGTERM, OnSignal);
  std::signal(SIGINT, OnSignal);
  std::signal(SIGPIPE, SIG_IGN);

  cube::ScaledClock robot_clock(opt.time_scale);
  cube::ScaledClock real_clock(1.0);
  VirtualMotors motors;
  cube::SystemRandom random;
  cube::MbedtlsMac mac;
  cube::CubeDeps deps;
  deps.clock = &robot_clock;
  deps.motors = &motors;
  deps.random = &random;
  deps.mac = &mac;
  static cube::Cube robot(deps, opt.device_id.c_str());
  cube::CubeConfig config;
  config.host_timeout_ms = opt.host_timeout_ms;
  robot.Configure(config);
  if (key.empty()) {
    robot.AllowUnauthenticated();
  } else if (!robot.SetKey(key.data(), key.size())) {
    std::fprintf(stderr, "cube-emulator: the key could not be set\n");
    return 1;
  }

  cube::EventLog log(robot, robot_clock);
  robot.set_observer(&log);
  log.CheckConfig();  // the configuration at boot: later changes are events

  cube::UdpEndpoint udp;
  std::string error;
  if (!udp.Open(opt.bind, static_cast<uint16_t>(opt.udp_port), &error)) {
    std::fprintf(stderr, "cube-emulator: %s\n", error.c_str());
    return 1;
  }
  cube::Pty pty;
  if (opt.pty && !pty.Open(&error)) {
    std::fprintf(stderr, "cube-emulator: %s\n", error.c_str());
    return 1;
  }
  SerialBridge bridge(robot, real_clock);
  uint16_t first_seq = static_cast<uint16_t>(random.NextU32());
  static cube::SerialLink link(pty, bridge, first_seq);
  bridge.set_link(&link);

  log.Ready(udp.port(), opt.pty ? pty.path() : "", opt.device_id,
            opt.time_scale, cube::AuthModeName(robot.auth_mode()),
            robot_clock.StartSteadyUs() +
                static_cast<uint64_t>(static_cast<double>(robot.boot_us()) /
                                      opt.time_scale));

  // What a second party (`hal emulate --camera`) needs to follow the body:
  // the wheel positions, printed when they changed, at most every N ms.
  int64_t reported_left = robot.left_position();
  int64_t reported_right = robot.right_position();
  uint64_t reported_at_us = real_clock.NowUs();
  if (opt.report_wheels_ms > 0) log.Wheels();

  static uint8_t buf[4096];
  static uint8_t reply[cube::kMaxMessage];
  const char* why = "signal";
  while (g_stop == 0) {
    pollfd fds[3];
    nfds_t n = 0;
    fds[n++] = {udp.fd(), POLLIN, 0};
    const int pty_index = opt.pty ? static_cast<int>(n) : -1;
    if (opt.pty) fds[n++] = {pty.fd(), POLLIN, 0};
    const int stdin_index = opt.exit_on_stdin_eof ? static_cast<int>(n) : -1;
    if (opt.exit_on_stdin_eof) fds[n++] = {STDIN_FILENO, POLLIN, 0};
    poll(fds, n, 1);

    // On the board the step interrupt runs on its own and a request is read
    // as it comes. Here the steps are made between passes of this loop, and a
    // process kept off the CPU wakes up behind. So each datagram is handled
    // at the time the kernel received it: the robot's clock is held there
    // while the steps, the task (with the host timeout) and the request run.
    if ((fds[0].revents & POLLIN) != 0) {
      for (int i = 0; i < 64; ++i) {
        sockaddr_in from{};
        std::chrono::steady_clock::time_point arrived;
        const long got = udp.Receive(buf, sizeof(buf), &from, &arrived);
        if (got < 0) break;
        robot_clock.HoldAt(arrived);
        CatchUpSteps(robot, /*with_task=*/true);
        const size_t len = static_cast<size_t>(got);
        const size_t r = len > cube::kMaxMessage
                             ? robot.HandleOversize(len, reply, sizeof(reply))
                             : robot.Handle(buf, len, reply, sizeof(reply));
        robot_clock.Release();
        udp.SendTo(reply, r, from);
      }
    }
    // The pty's bytes carry no time stamp: the steps due now are made
    // before a frame is read, so a reply counts every step the board's
    // interrupt would have made.
    if (pty_index >= 0 && (fds[pty_index].revents & POLLIN) != 0) {
      CatchUpSteps(robot, /*with_task=*/false);
      const ssize_t got = read(pty.fd(), buf, sizeof(buf));
      if (got > 0) {
        link.Receive(buf, static_cast<size_t>(got), real_clock.NowUs() / 1000);
      }
    }
    if (stdin_index >= 0 &&
        (fds[stdin_index].revents & (POLLIN | POLLHUP)) != 0) {
      const ssize_t got = read(STDIN_FILENO, buf, sizeof(buf));
      if (got <= 0) {
        why = "stdin closed";
        break;
      }
    }
    CatchUpSteps(robot, /*with_task=*/true);
    link.Poll(real_clock.NowUs() / 1000);
    log.CheckConfig();
    if (opt.report_wheels_ms > 0 &&
        (robot.left_position() != reported_left ||
         robot.right_position() != reported_right) &&
        real_clock.NowUs() - reported_at_us >=
            static_cast<uint64_t>(opt.report_wheels_ms) * 1000u) {
      reported_left = robot.left_position();
      reported_right = robot.right_position();
      reported_at_us = real_clock.NowUs();
      log.Wheels();
    }
  }
  log.Stopping(g_stop != 0 ? "signal" : why);
  return 0;
}
