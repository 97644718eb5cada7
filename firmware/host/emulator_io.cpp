#include "emulator_io.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "announce.h"

namespace cube {

bool IsLoopbackAddress(const std::string& address) {
  in_addr a{};
  if (inet_pton(AF_INET, address.c_str(), &a) != 1) return false;
  return (ntohl(a.s_addr) >> 24) == 127;
}

UdpEndpoint::~UdpEndpoint() {
  if (fd_ >= 0) close(fd_);
}

bool UdpEndpoint::Open(const std::string& address, uint16_t port,
                       std::string* error) {
  fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd_ < 0) {
    *error = std::string("socket: ") + std::strerror(errno);
    return false;
  }
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(port);
  if (inet_pton(AF_INET, address.c_str(), &addr.sin_addr) != 1) {
    *error = "bad --bind address: " + address;
    return false;
  }
  if (bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) != 0) {
    *error = "bind " + address + ":" + std::to_string(port) + ": " +
             std::strerror(errno);
    return false;
  }
  socklen_t len = sizeof(addr);
  getsockname(fd_, reinterpret_cast<sockaddr*>(&addr), &len);
  port_ = ntohs(addr.sin_port);
  // the kernel's receive time of each datagram (best effort: without it a
  // datagram counts as received when it is read)
  const int on = 1;
  setsockopt(fd_, SOL_SOCKET, SO_TIMESTAMPNS, &on, sizeof(on));
  return true;
}

long UdpEndpoint::Receive(uint8_t* buf, size_t cap, sockaddr_in* from,
                          std::chrono::steady_clock::time_point* arrived) {
  iovec iov{buf, cap};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(timespec))];
  msghdr msg{};
  msg.msg_name = from;
  msg.msg_namelen = sizeof(*from);
  msg.msg_iov = &iov;
  msg.msg_iovlen = 1;
  msg.msg_control = control;
  msg.msg_controllen = sizeof(control);
  const long got = static_cast<long>(recvmsg(fd_, &msg, MSG_TRUNC));
  if (got < 0 || arrived == nullptr) return got;
  const auto steady_now = std::chrono::steady_clock::now();
  *arrived = steady_now;
  for (cmsghdr* c = CMSG_FIRSTHDR(&msg); c != nullptr;
       c = CMSG_NXTHDR(&msg, c)) {
    if (c->cmsg_level != SOL_SOCKET || c->cmsg_type != SCM_TIMESTAMPNS) {
      continue;
    }
    timespec ts{};
    std::memcpy(&ts, CMSG_DATA(c), sizeof(ts));
    // the stamp is on the system clock: taken back to steady_clock by its
    // age, and never in the future
    const auto stamped = std::chrono::system_clock::time_point(
        std::chrono::duration_cast<std::chrono::system_clock::duration>(
            std::chrono::seconds(ts.tv_sec) +
            std::chrono::nanoseconds(ts.tv_nsec)));
    const auto age = std::chrono::system_clock::now() - stamped;
    if (age.count() > 0) {
      *arrived = steady_now -
                 std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                     age);
    }
  }
  return got;
}

void UdpEndpoint::SendTo(const uint8_t* data, size_t len,
                         const sockaddr_in& to) {
  sendto(fd_, data, len, 0, reinterpret_cast<const sockaddr*>(&to), sizeof(to));
}

Pty::~Pty() {
  if (slave_ >= 0) close(slave_);
  if (master_ >= 0) close(master_);
}

bool Pty::Open(std::string* error) {
  master_ = posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (master_ < 0 || grantpt(master_) != 0 || unlockpt(master_) != 0) {
    *error = std::string("posix_openpt: ") + std::strerror(errno);
    return false;
  }
  const char* name = ptsname(master_);
  if (name == nullptr) {
    *error = "ptsname failed";
    return false;
  }
  path_ = name;
  slave_ = open(name, O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (slave_ < 0) {
    *error = "open " + path_ + ": " + std::strerror(errno);
    return false;
  }
  termios t{};
  tcgetattr(slave_, &t);
  cfmakeraw(&t);
  cfsetispeed(&t, B115200);
  cfsetospeed(&t, B115200);
  tcsetattr(slave_, TCSANOW, &t);
  const int flags = fcntl(master_, F_GETFL);
  fcntl(master_, F_SETFL, flags | O_NONBLOCK);
  return true;
}

void Pty::Write(const uint8_t* data, size_t len) {
  // Like a UART with no one listening: when the terminal's buffer is full
  // (no client reads it), stale bytes are discarded rather than stalling the
  // robot. The link layer's retries recover what a live client missed.
  size_t done = 0;
  bool flushed = false;
  while (done < len) {
    const ssize_t n = write(master_, data + done, len - done);
    if (n > 0) {
      done += static_cast<size_t>(n);
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else if (n < 0 && errno == EAGAIN && !flushed) {
      tcflush(slave_, TCIFLUSH);
      flushed = true;
    } else {
      return;
    }
  }
}

void EventLog::Emit(JsonWriter& w, char* buf) {
  w.EndObject();
  if (!w.ok()) return;
  buf[w.size()] = '\n';
  fwrite(buf, 1, w.size() + 1, stdout);
  fflush(stdout);
}

void EventLog::Ready(uint16_t udp_port, const std::string& pty,
                     const std::string& device_id, double time_scale,
                     const char* auth, uint64_t uptime_origin_us) {
  char buf[4096];
  JsonWriter w(buf, sizeof(buf) - 1);
  w.BeginObject();
  w.Key("event");
  w.String("ready");
  w.Key("udp_port");
  w.Uint(udp_port);
  w.Key("pty");
  w.String(pty.c_str());
  w.Key("device_id");
  w.String(device_id.c_str());
  w.Key("time_scale");
  w.Double(time_scale);
  w.Key("auth");
  w.String(auth);
  w.Key("protocol_version");
  w.String(kProtocolVersion);
  // CLOCK_MONOTONIC (steady_clock) microseconds at the robot's uptime 0, so
  // a process on this machine can read the robot's clock (at time scale 1).
  w.Key("uptime_origin_us");
  w.Int(static_cast<int64_t>(uptime_origin_us));
  // What the robot announces over mDNS (announce.h): there is no mDNS
  // responder in this program; the host-side announcer (`hal emulate`)
  // publishes exactly these entries for it (docs/discovery.md).
  w.Key("mdns");
  Announcement announcement;
  if (announcement.Build(cube_)) {
    w.BeginObject();
    w.Key("service");
    char service[32];
    std::snprintf(service, sizeof(service), "%s.%s", kMdnsService,
                  kMdnsProto);
    w.String(service);
    w.Key("port");
    w.Uint(udp_port);
    w.Key("txt");
    w.BeginObject();
    for (size_t i = 0; i < announcement.count(); ++i) {
      w.Key(announcement.entry(i).key);
      w.String(announcement.entry(i).value);
    }
    w.EndObject();
    w.EndObject();
  } else {
    w.Null();
  }
  Emit(w, buf);
}

void EventLog::OnMotionStarted(const MotionReport& r) {
  char buf[512];
  JsonWriter w(buf, sizeof(buf) - 1);
  w.BeginObject();
  w.Key("event");
  w.String("move_started");
  w.Key("move_id");
  w.Uint(r.move_id);
  w.Key("kind");
  w.String(r.velocity ? "drive" : "move");
  if (r.velocity) {
    w.Key("left_sps");
    w.Int(r.left_sps);
    w.Key("right_sps");
    w.Int(r.right_sps);
  } else {
    w.Key("left_steps");
    w.Int(r.planned_left);
    w.Key("right_steps");
    w.Int(r.planned_right);
    w.Key("speed");
    w.Double(r.speed);
  }
  w.Key("duration_us");
  w.Int(r.duration_us);
  w.Key("left_position");
  w.Int(r.left_position);
  w.Key("right_position");
  w.Int(r.right_position);
  w.Key("t_ms");
  w.Uint(cube_.uptime_ms());
  w.Key("t_us");
  w.Int(static_cast<int64_t>(cube_.uptime_us()));
  Emit(w, buf);
}

void EventLog::OnMotionFinished(const MotionReport& r) {
  char buf[512];
  JsonWriter w(buf, sizeof(buf) - 1);
  w.BeginObject();
  w.Key("event");
  w.String("move_finished");
  w.Key("move_id");
  w.Uint(r.move_id);
  w.Key("kind");
  w.String(r.velocity ? "drive" : "move");
  w.Key("outcome");
  w.String(MoveOutcomeName(r.outcome));
  w.Key("left_steps");
  w.Int(r.done_left);
  w.Key("right_steps");
  w.Int(r.done_right);
  w.Key("left_position");
  w.Int(r.left_position);
  w.Key("right_position");
  w.Int(r.right_position);
  const Pose& p = cube_.pose();
  w.Key("x_cm");
  w.Double(p.x_cm);
  w.Key("y_cm");
  w.Double(p.y_cm);
  w.Key("heading_rad");
  w.Double(p.heading_rad);
  w.Key("t_ms");
  w.Uint(cube_.uptime_ms());
  Emit(w, buf);
}

void EventLog::OnTrip(const SafetyTrip& trip) {
  char buf[512];
  JsonWriter w(buf, sizeof(buf) - 1);
  w.BeginObject();
  w.Key("event");
  w.String("trip");
  w.Key("reason");
  w.String(trip.reason);
  w.Key("detail");
  w.String(trip.detail);
  w.Key("estop");
  w.Bool(cube_.estopped());
  w.Key("t_ms");
  w.Uint(trip.uptime_ms);
  Emit(w, buf);
}

void EventLog::CheckConfig() {
  const CubeConfig& c = cube_.config();
  const bool same = seen_any_ &&
                    c.geometry.wheel_diameter_cm ==
                        seen_.geometry.wheel_diameter_cm &&
                    c.geometry.wheel_base_cm == seen_.geometry.wheel_base_cm &&
                    c.geometry.steps_per_revolution ==
                        seen_.geometry.steps_per_revolution &&
                    c.max_speed_sps == seen_.max_speed_sps &&
                    c.accel_sps2 == seen_.accel_sps2 &&
                    c.host_timeout_ms == seen_.host_timeout_ms;
  const bool first = !seen_any_;
  seen_ = c;
  seen_any_ = true;
  if (same || first) return;  // the configuration at boot is in hello
  char buf[512];
  JsonWriter w(buf, sizeof(buf) - 1);
  w.BeginObject();
  w.Key("event");
  w.String("config");
  WriteConfigFields(w, c);  // as the config reply writes them
  w.Key("t_ms");
  w.Uint(cube_.uptime_ms());
  Emit(w, buf);
}

void EventLog::Wheels() {
  char buf[256];
  JsonWriter w(buf, sizeof(buf) - 1);
  w.BeginObject();
  w.Key("event");
  w.String("wheels");
  w.Key("left_position");
  w.Int(cube_.left_position());
  w.Key("right_position");
  w.Int(cube_.right_position());
  w.Key("t_us");
  w.Int(static_cast<int64_t>(cube_.uptime_us()));
  Emit(w, buf);
}

void EventLog::Stopping(const char* why) {
  char buf[256];
  JsonWriter w(buf, sizeof(buf) - 1);
  w.BeginObject();
  w.Key("event");
  w.String("exit");
  w.Key("reason");
  w.String(why);
  Emit(w, buf);
}

}  // namespace cube
