// Sockets, pseudo-terminal and event output of cube-emulator.
#ifndef CUBE_HOST_EMULATOR_IO_H_
#define CUBE_HOST_EMULATOR_IO_H_

#include <netinet/in.h>

#include <cstdint>
#include <chrono>
#include <string>

#include "cube.h"
#include "frame.h"
#include "json_writer.h"

namespace cube {

// Whether `address` (dotted IPv4) is in 127.0.0.0/8. False when it does not
// parse (0.0.0.0, every interface, is not loopback).
bool IsLoopbackAddress(const std::string& address);

// A UDP socket bound to 127.0.0.1 (or the given address).
class UdpEndpoint {
 public:
  ~UdpEndpoint();
  // Binds; port 0 picks a free one. Returns false and sets `error`.
  bool Open(const std::string& address, uint16_t port, std::string* error);
  int fd() const { return fd_; }
  uint16_t port() const { return port_; }
  // Reads one datagram: its full length (may exceed cap: then truncated).
  // `arrived` (when given) is when the kernel received it, on steady_clock
  // (now, where the kernel gave no time stamp).
  long Receive(uint8_t* buf, size_t cap, sockaddr_in* from,
               std::chrono::steady_clock::time_point* arrived = nullptr);
  void SendTo(const uint8_t* data, size_t len, const sockaddr_in& to);

 private:
  int fd_ = -1;
  uint16_t port_ = 0;
};

// A pseudo-terminal in raw mode; the emulator keeps the master side and
// holds the slave open so that clients may come and go.
class Pty : public ByteSink {
 public:
  ~Pty() override;
  bool Open(std::string* error);
  int fd() const { return master_; }
  const std::string& path() const { return path_; }
  void Write(const uint8_t* data, size_t len) override;

 private:
  int master_ = -1;
  int slave_ = -1;
  std::string path_;
};

// Prints one JSON object per line on stdout and flushes it.
class EventLog : public CubeObserver {
 public:
  EventLog(Cube& cube, Clock& clock) : cube_(cube), clock_(clock) {}
  void Ready(uint16_t udp_port, const std::string& pty,
             const std::string& device_id, double time_scale,
             const char* auth, uint64_t uptime_origin_us);
  void OnMotionStarted(const MotionReport& r) override;
  void OnMotionFinished(const MotionReport& r) override;
  void OnTrip(const SafetyTrip& trip) override;
  // Prints a `config` event when the robot's configuration differs from the
  // last one seen (set_config over either link); call after each request.
  void CheckConfig();
  // Prints a `wheels` event: the absolute wheel positions (steps) now.
  void Wheels();
  void Stopping(const char* why);

 private:
  void Emit(JsonWriter& w, char* buf);

  Cube& cube_;
  Clock& clock_;
  CubeConfig seen_;
  bool seen_any_ = false;
};

}  // namespace cube

#endif  // CUBE_HOST_EMULATOR_IO_H_
