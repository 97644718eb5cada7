// cube-emulator's listening address: keyless on loopback (the tests' robot),
// and never keyless beyond it unless told --insecure.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <vector>

#include "harness.h"

namespace cube::testing {
namespace {

using Clock = std::chrono::steady_clock;

struct Outcome {
  int exit_code = -1;  // -1: still running after its ready line (then killed)
  std::string out;     // stdout: the first line, the ready event
  std::string err;
};

// Starts the emulator with `extra` arguments and waits (at most 5 s) until
// it prints its ready line (then kills it) or exits.
Outcome Start(const std::vector<std::string>& extra) {
  int out[2];
  int err[2];
  EXPECT_EQ(pipe(out), 0);
  EXPECT_EQ(pipe(err), 0);
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(out[1], STDOUT_FILENO);
    dup2(err[1], STDERR_FILENO);
    close(out[0]);
    close(err[0]);
    std::vector<std::string> args = {CUBE_EMULATOR_PATH, "--udp-port", "0",
                                     "--no-pty"};
    args.insert(args.end(), extra.begin(), extra.end());
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  close(out[1]);
  close(err[1]);
  Outcome run;
  bool out_open = true;
  bool err_open = true;
  const auto deadline = Clock::now() + std::chrono::seconds(5);
  while ((out_open || err_open) && Clock::now() < deadline &&
         run.out.find('\n') == std::string::npos) {
    pollfd p[2] = {{out_open ? out[0] : -1, POLLIN, 0},
                   {err_open ? err[0] : -1, POLLIN, 0}};
    if (poll(p, 2, 100) <= 0) continue;
    char buf[1024];
    for (int i = 0; i < 2; ++i) {
      if ((p[i].revents & (POLLIN | POLLHUP)) == 0) continue;
      const ssize_t n = read(p[i].fd, buf, sizeof(buf));
      if (n <= 0) {
        (i == 0 ? out_open : err_open) = false;
        continue;
      }
      (i == 0 ? run.out : run.err).append(buf, static_cast<size_t>(n));
    }
  }
  close(out[0]);
  close(err[0]);
  int status = 0;
  if (run.out.find('\n') != std::string::npos) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    return run;
  }
  while (waitpid(pid, &status, WNOHANG) != pid) {
    if (Clock::now() >= deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      return run;
    }
    usleep(5000);
  }
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

json Ready(const Outcome& run) {
  return json::parse(run.out.substr(0, run.out.find('\n')));
}

TEST(EmulatorBind, RefusesToListenBeyondLoopbackWithoutAKey) {
  const Outcome any = Start({"--bind", "0.0.0.0"});
  EXPECT_EQ(any.exit_code, 2);
  EXPECT_EQ(any.out, "") << "it never listened";
  EXPECT_NE(any.err.find("refusing to listen on 0.0.0.0 without a key"),
            std::string::npos)
      << any.err;
  EXPECT_NE(any.err.find("--insecure"), std::string::npos) << any.err;
  const Outcome lan = Start({"--bind", "192.168.1.20"});
  EXPECT_EQ(lan.exit_code, 2) << lan.err;
}

TEST(EmulatorBind, ListensBeyondLoopbackWithAKeyOrWhenToldInsecure) {
  const Outcome keyed = Start(
      {"--bind", "0.0.0.0", "--key", "000102030405060708090a0b0c0d0e0f"});
  ASSERT_EQ(keyed.exit_code, -1) << keyed.err;
  EXPECT_EQ(Ready(keyed)["auth"], "hmac-sha256");
  const Outcome insecure = Start({"--bind", "0.0.0.0", "--insecure"});
  ASSERT_EQ(insecure.exit_code, -1) << insecure.err;
  EXPECT_EQ(Ready(insecure)["auth"], "none");
}

TEST(EmulatorBind, StaysKeylessOnAnyLoopbackAddress) {
  for (const char* address : {"127.0.0.1", "127.0.0.2"}) {
    const Outcome run = Start({"--bind", address});
    ASSERT_EQ(run.exit_code, -1) << address << ": " << run.err;
    EXPECT_EQ(Ready(run)["auth"], "none") << address;
  }
}

}  // namespace
}  // namespace cube::testing
