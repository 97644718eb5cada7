// Board glue of the stepper cube: connects the portable core (src/core) to
// the ESP32-S3's timer, GPIOs, WiFi, serial port, LED and watchdog.
//   - a 20 kHz hardware timer interrupt executes the planned steps
//     (Cube::Tick), so WiFi traffic cannot stall the motors;
//   - a task pinned to the application core (core 1) reads UDP and serial,
//     answers requests and keeps the step queue filled (Cube::Poll), and is
//     watched by the task watchdog;
//   - WiFi runs on core 0 as usual; loop() watches the connection and, once
//     it is up, announces the robot with mDNS (docs/discovery.md).
// The serial port carries protocol frames only, but for one text line at
// boot, before the link starts, that says how the robot authenticates (a
// receiver drops it as garbage while hunting for a frame).

#if defined(ARDUINO_ARCH_ESP32)

#include "app.h"

#include <Arduino.h>
#include <ESPmDNS.h>
#include <WiFi.h>
#include <WiFiUdp.h>
#include <esp_random.h>

#include "../../core/announce.h"
#include "../../core/cube.h"
#include "../../core/frame.h"
#include "board.h"
#include "esp32_hal.h"

#if __has_include("../../secrets.h")
#include "../../secrets.h"
#else
#error \
    "Copy src/secrets.example.h to src/secrets.h and set your WiFi network and key (docs/flashing.md)"
#endif
// After secrets.h: checks CUBE_KEY_HEX / CUBE_ALLOW_UNAUTHENTICATED at
// compile time.
#include "../build_auth.h"

// The 3.x timer API (timerBegin(frequency)) and the Network library's
// NetworkUDP::clear() exist from core 3.0.0; docs/flashing.md pins 3.0.7.
#if !defined(ESP_ARDUINO_VERSION) || \
    ESP_ARDUINO_VERSION < ESP_ARDUINO_VERSION_VAL(3, 0, 0)
#error "The cube firmware needs the Arduino-ESP32 core 3.0.0 or newer (3.0.7 is the pinned one, docs/flashing.md)"
#endif

namespace {

cube::Esp32Clock clock_source;
cube::Esp32Motors motors;
cube::Esp32Led led;
cube::Esp32Watchdog watchdog;
cube::Esp32Random random_source;
cube::Esp32Mac mac;
cube::SerialSink serial_sink;

cube::Cube* robot = nullptr;
cube::SerialLink* serial_link = nullptr;
WiFiUDP udp;
hw_timer_t* step_timer = nullptr;

uint8_t rx_buf[cube::kMaxMessage + 64];
uint8_t reply_buf[cube::kMaxMessage];

class SerialBridge : public cube::LinkHandler {
 public:
  void OnMessage(const uint8_t* data, size_t len) override {
    const size_t n = robot->Handle(data, len, out_, sizeof(out_));
    serial_link->Send(out_, n, millis());
  }
  void OnOversize(size_t announced) override {
    const size_t n = robot->HandleOversize(announced, out_, sizeof(out_));
    serial_link->Send(out_, n, millis());
  }

 private:
  uint8_t out_[cube::kMaxMessage];
};
SerialBridge bridge;

// Built in setup(), before the cube task runs, from the boot configuration.
cube::Announcement announcement;
bool announcement_ok = false;
bool announced = false;

void ARDUINO_ISR_ATTR OnStepTimer() { robot->Tick(); }

// The key (or the opt-out) was checked when the sketch was compiled
// (build_auth.h). Says on the serial port, once, which mode the robot runs.
void ConfigureAuth() {
  if (cube::build::kUnauthenticated) {
    robot->AllowUnauthenticated();
    Serial.println(
        "cube: WARNING: built with CUBE_ALLOW_UNAUTHENTICATED: no "
        "authentication, anyone who reaches UDP port 4210 can command this "
        "robot");
  } else if (robot->SetKey(cube::build::kKey.bytes, cube::build::kKey.len)) {
    Serial.printf("cube: authentication hmac-sha256 (%u-byte key)\n",
                  static_cast<unsigned>(cube::build::kKey.len));
  } else {
    // Cannot happen with a checked key; the robot then stays closed.
    Serial.println("cube: ERROR: key not accepted; only stop and estop run");
  }
}

// Announces `_hal-cube._udp` on the robot's UDP port with the core's TXT
// entries, under the device id as host and instance name (cube-a1b2c3.local).
// Once: ESPmDNS follows the WiFi reconnections itself. A failed attempt is
// undone, and loop() tries again 10 s later.
void Announce() {
  if (!announcement_ok || !MDNS.begin(robot->device_id())) return;
  MDNS.setInstanceName(robot->device_id());
  if (!MDNS.addService(cube::kMdnsService, cube::kMdnsProto,
                       cube::board::kUdpPort)) {
    MDNS.end();
    return;
  }
  for (size_t i = 0; i < announcement.count(); ++i) {
    MDNS.addServiceTxt(cube::kMdnsService, cube::kMdnsProto,
                       announcement.entry(i).key, announcement.entry(i).value);
  }
  announced = true;
}

void PollUdp() {
  for (int i = 0; i < 8; ++i) {
    const int size = udp.parsePacket();
    if (size <= 0) return;
    size_t reply_len;
    if (static_cast<size_t>(size) > cube::kMaxMessage) {
      // Drop the datagram: clear() empties the receive buffer. flush() is
      // deprecated in the 3.x cores and did nothing from 3.0.0 to 3.0.4, so
      // the datagram stayed buffered and parsePacket() kept returning 0.
      udp.clear();
      reply_len = robot->HandleOversize(static_cast<size_t>(size), reply_buf,
                                        sizeof(reply_buf));
    } else {
      const int got = udp.read(rx_buf, sizeof(rx_buf));
      reply_len = robot->Handle(rx_buf, got > 0 ? static_cast<size_t>(got) : 0,
                                reply_buf, sizeof(reply_buf));
    }
    udp.beginPacket(udp.remoteIP(), udp.remotePort());
    udp.write(reply_buf, reply_len);
    udp.endPacket();
  }
}

void PollSerial() {
  int avail = Serial.available();
  while (avail > 0) {
    const size_t want = avail > static_cast<int>(sizeof(rx_buf))
                            ? sizeof(rx_buf)
                            : static_cast<size_t>(avail);
    const size_t got = Serial.readBytes(rx_buf, want);
    if (got == 0) break;
    serial_link->Receive(rx_buf, got, millis());
    avail = Serial.available();
  }
}

// The cube task: everything but the step interrupt. Runs every millisecond
// on core 1 at a priority above loop().
void CubeTask(void*) {
  watchdog.Begin(cube::board::kWatchdogMs);
  bool udp_open = false;
  for (;;) {
    if (WiFi.status() == WL_CONNECTED) {
      if (!udp_open) udp_open = udp.begin(cube::board::kUdpPort) == 1;
      if (udp_open) PollUdp();
    } else if (udp_open) {
      udp.stop();
      udp_open = false;
    }
    PollSerial();
    robot->Poll();  // also feeds the watchdog
    serial_link->Poll(millis());
    vTaskDelay(1);
  }
}

}  // namespace

void CubeAppSetup() {
  Serial.setDebugOutput(false);
  Serial.begin(cube::board::kSerialBaud);
  motors.Begin();

  WiFi.persistent(false);  // no flash writes while the step timer runs
  WiFi.mode(WIFI_STA);     // before reading the station MAC
  WiFi.setSleep(false);    // lower, steadier UDP latency

  static char device_id[16];
  uint8_t mac_addr[6];
  WiFi.macAddress(mac_addr);
  snprintf(device_id, sizeof(device_id), "cube-%02x%02x%02x", mac_addr[3],
           mac_addr[4], mac_addr[5]);

  cube::CubeDeps deps;
  deps.clock = &clock_source;
  deps.motors = &motors;
  deps.random = &random_source;
  deps.led = &led;
  deps.watchdog = &watchdog;
  deps.mac = &mac;
  static cube::Cube cube_instance(deps, device_id);
  robot = &cube_instance;
  ConfigureAuth();
  announcement_ok = announcement.Build(*robot);
  static cube::SerialLink link_instance(serial_sink, bridge,
                                        static_cast<uint16_t>(esp_random()));
  serial_link = &link_instance;

  WiFi.begin(CUBE_WIFI_SSID, CUBE_WIFI_PASSWORD);

  step_timer = timerBegin(cube::board::kStepTimerHz);
  timerAttachInterrupt(step_timer, &OnStepTimer);
  timerAlarm(step_timer, cube::board::kStepTickUs, true, 0);

  xTaskCreatePinnedToCore(CubeTask, "cube", 8192, nullptr, 5, nullptr, 1);
}

void CubeAppLoop() {
  // WiFi reconnects by itself; the robot is announced once it is up.
  static unsigned long last_try = 0;  // millis() is unsigned long
  static unsigned long last_announce = 0;
  if (WiFi.status() == WL_CONNECTED && !announced &&
      (last_announce == 0 || millis() - last_announce > 10000)) {
    last_announce = millis();
    Announce();
  }
  if (WiFi.status() != WL_CONNECTED && millis() - last_try > 10000) {
    last_try = millis();
    WiFi.reconnect();
  }
  delay(100);
}

#endif  // ARDUINO_ARCH_ESP32
