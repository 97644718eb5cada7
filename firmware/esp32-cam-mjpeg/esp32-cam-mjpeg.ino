// ESP32-CAM (AI-Thinker, OV2640) MJPEG camera of the V1 stepper cube.
//
//   GET /stream   multipart/x-mixed-replace JPEG stream, 320x240, ~10 fps
//   GET /status   JSON: fps, frames_served, uptime_ms, rssi_dbm, clients
//   GET /         a page showing the stream
//
// With CAM_TOKEN set in secrets.h, /stream and /status need it (?token= or
// "Authorization: Bearer"); with CAM_ALLOW_ORIGIN set, responses carry that
// Access-Control-Allow-Origin, and none otherwise (docs/security.md).
//
// loop() never blocks on a client: it holds up to kMaxPending connections
// whose request heads arrive at their own pace, each bounded in size and
// time (src/cam_http.h), and answers /status itself. Each stream is served
// by its own task, so a running stream never delays /status. At most
// kMaxStreams streams at once; more get 503.

#include <Arduino.h>
#include <WiFi.h>
#include <esp_camera.h>

#include "src/cam_http.h"

#if __has_include("secrets.h")
#include "secrets.h"
#else
#error \
    "Copy secrets.example.h to secrets.h and set your WiFi network (docs/flashing.md)"
#endif

// Older secrets.h files have neither: no token, no CORS header.
#ifndef CAM_TOKEN
#define CAM_TOKEN ""
#endif
#ifndef CAM_ALLOW_ORIGIN
#define CAM_ALLOW_ORIGIN ""
#endif
static_assert(cam::IsValidToken(CAM_TOKEN),
              "CAM_TOKEN: at most 128 of A-Z a-z 0-9 - . _ ~");
static_assert(cam::IsValidOrigin(CAM_ALLOW_ORIGIN),
              "CAM_ALLOW_ORIGIN: one origin such as http://192.168.1.20:5173");

namespace cam {

// AI-Thinker ESP32-CAM camera pins.
constexpr int kPwdn = 32, kReset = -1, kXclk = 0, kSiod = 26, kSioc = 27;
constexpr int kY9 = 35, kY8 = 34, kY7 = 39, kY6 = 36, kY5 = 21, kY4 = 19,
              kY3 = 18, kY2 = 5, kVsync = 25, kHref = 23, kPclk = 22;
constexpr int kFlashLed = 4;

constexpr uint16_t kHttpPort = 80;
constexpr uint32_t kFrameIntervalMs = 100;  // 10 fps
constexpr int kMaxStreams = 2;
constexpr int kMaxPending = 4;

const HttpConfig kHttp = {CAM_TOKEN, CAM_ALLOW_ORIGIN};

WiFiServer server(kHttpPort);
// Shared between loop() and the stream tasks, always under stats_lock.
int stream_clients = 0;
uint32_t frames_served = 0;
uint32_t fps_window_frames = 0;
portMUX_TYPE stats_lock = portMUX_INITIALIZER_UNLOCKED;
// loop() only.
uint32_t fps_window_start_ms = 0;
float fps = 0.0f;

// A connection whose request head is still arriving.
struct Pending {
  bool used = false;
  WiFiClient client;
  RequestReader reader;
};
Pending pending[kMaxPending];

uint32_t NowMs() { return static_cast<uint32_t>(millis()); }

bool InitCamera() {
  camera_config_t c = {};
  c.pin_pwdn = kPwdn;
  c.pin_reset = kReset;
  c.pin_xclk = kXclk;
  c.pin_sccb_sda = kSiod;
  c.pin_sccb_scl = kSioc;
  c.pin_d7 = kY9;
  c.pin_d6 = kY8;
  c.pin_d5 = kY7;
  c.pin_d4 = kY6;
  c.pin_d3 = kY5;
  c.pin_d2 = kY4;
  c.pin_d1 = kY3;
  c.pin_d0 = kY2;
  c.pin_vsync = kVsync;
  c.pin_href = kHref;
  c.pin_pclk = kPclk;
  c.xclk_freq_hz = 20000000;
  c.ledc_timer = LEDC_TIMER_0;
  c.ledc_channel = LEDC_CHANNEL_0;
  c.pixel_format = PIXFORMAT_JPEG;
  c.frame_size = FRAMESIZE_QVGA;  // 320x240
  c.jpeg_quality = 12;
  const bool psram = psramFound();
  c.fb_count = psram ? 2u : 1u;
  c.fb_location = psram ? CAMERA_FB_IN_PSRAM : CAMERA_FB_IN_DRAM;
  c.grab_mode = CAMERA_GRAB_LATEST;
  return esp_camera_init(&c) == ESP_OK;
}

void CountFrame() {
  portENTER_CRITICAL(&stats_lock);
  ++frames_served;
  ++fps_window_frames;
  portEXIT_CRITICAL(&stats_lock);
}

void ChangeStreams(int delta) {
  portENTER_CRITICAL(&stats_lock);
  stream_clients += delta;
  portEXIT_CRITICAL(&stats_lock);
}

// Updated from loop(): frames served per second over the last window.
void UpdateFps() {
  const uint32_t now = NowMs();
  const uint32_t span = now - fps_window_start_ms;
  if (span < 1000) return;
  portENTER_CRITICAL(&stats_lock);
  const uint32_t frames = fps_window_frames;
  fps_window_frames = 0;
  portEXIT_CRITICAL(&stats_lock);
  fps = static_cast<float>(frames) * 1000.0f / static_cast<float>(span);
  fps_window_start_ms = now;
}

bool SendHead(WiFiClient& client, const ResponseHead& head) {
  char text[512];
  const size_t n = FormatHead(head, kHttp, text, sizeof(text));
  return n > 0 && client.write(reinterpret_cast<const uint8_t*>(text), n) == n;
}

void SendFixed(WiFiClient& client, Route route) {
  const FixedReply reply = FixedReplyFor(route);
  if (SendHead(client, reply.head)) client.print(reply.body);
}

void StreamTask(void* arg) {
  WiFiClient* client = static_cast<WiFiClient*>(arg);
  client->setNoDelay(true);
  TickType_t last = xTaskGetTickCount();
  bool ok = SendHead(*client, StreamHead());
  while (ok && client->connected()) {
    camera_fb_t* fb = esp_camera_fb_get();
    if (fb == nullptr) {
      vTaskDelay(pdMS_TO_TICKS(20));
      continue;
    }
    const size_t head = client->printf(
        "--%s\r\nContent-Type: image/jpeg\r\nContent-Length: %u\r\n\r\n",
        kBoundary, static_cast<unsigned>(fb->len));
    const size_t body = client->write(fb->buf, fb->len);
    const size_t len = fb->len;
    esp_camera_fb_return(fb);
    ok = head > 0 && body == len && client->print("\r\n") == 2;
    if (ok) CountFrame();
    vTaskDelayUntil(&last, pdMS_TO_TICKS(kFrameIntervalMs));
  }
  client->stop();
  delete client;
  ChangeStreams(-1);
  vTaskDelete(nullptr);
}

void SendStatus(WiFiClient& client) {
  char body[256];
  portENTER_CRITICAL(&stats_lock);
  const uint32_t served = frames_served;
  const int clients = stream_clients;
  portEXIT_CRITICAL(&stats_lock);
  const int n =
      snprintf(body, sizeof(body),
               "{\"fps\":%.1f,\"frames_served\":%lu,\"uptime_ms\":%lu,"
               "\"rssi_dbm\":%d,\"stream_clients\":%d,\"width\":320,"
               "\"height\":240}",
               static_cast<double>(fps), static_cast<unsigned long>(served),
               static_cast<unsigned long>(millis()),
               static_cast<int>(WiFi.RSSI()), clients);
  if (n <= 0 || static_cast<size_t>(n) >= sizeof(body)) return;
  ResponseHead head;
  head.content_type = "application/json";
  head.content_length = n;
  head.no_cache = true;
  if (SendHead(client, head)) {
    client.write(reinterpret_cast<const uint8_t*>(body),
                 static_cast<size_t>(n));
  }
}

// Hands the connection to a stream task; false (and 503) when none is free.
void StartStream(WiFiClient& client) {
  bool admitted = false;
  portENTER_CRITICAL(&stats_lock);
  if (stream_clients < kMaxStreams) {
    ++stream_clients;
    admitted = true;
  }
  portEXIT_CRITICAL(&stats_lock);
  if (!admitted) {
    SendFixed(client, Route::kBusy);
    client.stop();
    return;
  }
  WiFiClient* owned = new WiFiClient(client);
  if (xTaskCreatePinnedToCore(StreamTask, "stream", 6144, owned, 2, nullptr,
                              1) != pdPASS) {
    delete owned;
    ChangeStreams(-1);
    SendFixed(client, Route::kBusy);
    client.stop();
  }
  // Otherwise the task owns the connection now.
}

void Answer(WiFiClient& client, const RequestReader& reader) {
  const Route route = Decide(ParseRequest(reader.head(), reader.size()), kHttp);
  if (route == Route::kStream) {
    StartStream(client);
    return;
  }
  if (route == Route::kStatus) {
    SendStatus(client);
  } else {
    SendFixed(client, route);
  }
  client.stop();
}

// Takes new connections into free slots; with none free, answers 503.
void AcceptClients() {
  for (int i = 0; i < kMaxPending; ++i) {
    WiFiClient client = server.accept();
    if (!client) return;
    Pending* slot = nullptr;
    for (Pending& p : pending) {
      if (!p.used) {
        slot = &p;
        break;
      }
    }
    if (slot == nullptr) {
      SendFixed(client, Route::kBusy);
      client.stop();
      continue;
    }
    slot->used = true;
    slot->client = client;
    slot->reader.Start(NowMs());
  }
}

// Reads what each pending connection has sent, without waiting for more.
void ServePending() {
  for (Pending& p : pending) {
    if (!p.used) continue;
    RequestReader::State state = p.reader.Poll(NowMs());
    const int available = p.client.available();
    if (state == RequestReader::State::kReading && available > 0) {
      uint8_t buf[256];
      size_t want = static_cast<size_t>(available);
      if (want > sizeof(buf)) want = sizeof(buf);
      if (want > p.reader.Room()) want = p.reader.Room();
      const int got = p.client.read(buf, want);
      if (got > 0) {
        state = p.reader.Feed(buf, static_cast<size_t>(got), NowMs());
      }
    } else if (state == RequestReader::State::kReading &&
               !p.client.connected()) {
      p.client.stop();
      p.used = false;
      continue;
    }
    switch (state) {
      case RequestReader::State::kReading:
        continue;
      case RequestReader::State::kComplete:
        Answer(p.client, p.reader);
        break;
      case RequestReader::State::kTooLarge:
        SendFixed(p.client, Route::kTooLarge);
        p.client.stop();
        break;
      case RequestReader::State::kTimedOut:
        SendFixed(p.client, Route::kTimeout);
        p.client.stop();
        break;
    }
    p.client = WiFiClient();
    p.used = false;
  }
}

}  // namespace cam

void setup() {
  pinMode(cam::kFlashLed, OUTPUT);
  digitalWrite(cam::kFlashLed, LOW);
  Serial.begin(115200);
  if (!cam::InitCamera()) {
    Serial.println("camera init failed; restarting");
    delay(2000);
    ESP.restart();
  }
  WiFi.persistent(false);
  WiFi.mode(WIFI_STA);
  WiFi.setSleep(false);
  WiFi.begin(CAM_WIFI_SSID, CAM_WIFI_PASSWORD);
  while (WiFi.status() != WL_CONNECTED) delay(200);
  Serial.print("camera at http://");
  Serial.print(WiFi.localIP());
  Serial.println(cam::kHttp.token[0] != '\0' ? "/stream (token required)"
                                             : "/stream");
  cam::server.begin();
  cam::fps_window_start_ms = cam::NowMs();
}

void loop() {
  cam::UpdateFps();
  cam::AcceptClients();
  cam::ServePending();
  static unsigned long last_reconnect_ms = 0;
  if (WiFi.status() != WL_CONNECTED && millis() - last_reconnect_ms > 10000) {
    last_reconnect_ms = millis();
    WiFi.reconnect();
  }
  delay(2);
}
