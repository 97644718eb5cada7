// ESP32-CAM (AI-Thinker, OV2640) MJPEG camera of the V1 stepper cube.
//
//   GET /stream   multipart/x-mixed-replace JPEG stream, 320x240, ~10 fps
//   GET /status   JSON: fps, frames_served, uptime_ms, rssi_dbm, clients
//   GET /         a page showing the stream
//
// Each stream client is served by its own task, so a running stream never
// blocks /status (answered from loop()). At most kMaxStreams streams at once;
// more get 503.

#include <Arduino.h>
#include <WiFi.h>
#include <esp_camera.h>

#if __has_include("secrets.h")
#include "secrets.h"
#else
#error \
    "Copy secrets.example.h to secrets.h and set your WiFi network (docs/flashing.md)"
#endif

namespace cam {

// AI-Thinker ESP32-CAM camera pins.
constexpr int kPwdn = 32, kReset = -1, kXclk = 0, kSiod = 26, kSioc = 27;
constexpr int kY9 = 35, kY8 = 34, kY7 = 39, kY6 = 36, kY5 = 21, kY4 = 19,
              kY3 = 18, kY2 = 5, kVsync = 25, kHref = 23, kPclk = 22;
constexpr int kFlashLed = 4;

constexpr uint16_t kHttpPort = 80;
constexpr uint32_t kFrameIntervalMs = 100;  // 10 fps
constexpr int kMaxStreams = 2;
constexpr char kBoundary[] = "cubeframe";

WiFiServer server(kHttpPort);
volatile int stream_clients = 0;
volatile uint32_t frames_served = 0;
portMUX_TYPE stats_lock = portMUX_INITIALIZER_UNLOCKED;
uint32_t fps_window_start_ms = 0;
uint32_t fps_window_frames = 0;
float fps = 0.0f;

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
  c.fb_count = psramFound() ? 2 : 1;
  c.fb_location = psramFound() ? CAMERA_FB_IN_PSRAM : CAMERA_FB_IN_DRAM;
  c.grab_mode = CAMERA_GRAB_LATEST;
  return esp_camera_init(&c) == ESP_OK;
}

void CountFrame() {
  portENTER_CRITICAL(&stats_lock);
  ++frames_served;
  ++fps_window_frames;
  portEXIT_CRITICAL(&stats_lock);
}

// Updated from loop(): frames served per second over the last window.
void UpdateFps() {
  const uint32_t now = millis();
  const uint32_t span = now - fps_window_start_ms;
  if (span < 1000) return;
  portENTER_CRITICAL(&stats_lock);
  const uint32_t frames = fps_window_frames;
  fps_window_frames = 0;
  portEXIT_CRITICAL(&stats_lock);
  fps = static_cast<float>(frames) * 1000.0f / static_cast<float>(span);
  fps_window_start_ms = now;
}

void StreamTask(void* arg) {
  WiFiClient* client = static_cast<WiFiClient*>(arg);
  client->setNoDelay(true);
  client->printf(
      "HTTP/1.1 200 OK\r\n"
      "Content-Type: multipart/x-mixed-replace; boundary=%s\r\n"
      "Cache-Control: no-cache\r\n"
      "Access-Control-Allow-Origin: *\r\n"
      "Connection: close\r\n\r\n",
      kBoundary);
  TickType_t last = xTaskGetTickCount();
  while (client->connected()) {
    camera_fb_t* fb = esp_camera_fb_get();
    if (fb == nullptr) {
      vTaskDelay(pdMS_TO_TICKS(20));
      continue;
    }
    const int head = client->printf(
        "--%s\r\nContent-Type: image/jpeg\r\nContent-Length: %u\r\n\r\n",
        kBoundary, static_cast<unsigned>(fb->len));
    const size_t body = client->write(fb->buf, fb->len);
    const size_t len = fb->len;
    esp_camera_fb_return(fb);
    if (head <= 0 || body != len || client->print("\r\n") != 2) break;
    CountFrame();
    vTaskDelayUntil(&last, pdMS_TO_TICKS(kFrameIntervalMs));
  }
  client->stop();
  delete client;
  portENTER_CRITICAL(&stats_lock);
  --stream_clients;
  portEXIT_CRITICAL(&stats_lock);
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
  client.printf(
      "HTTP/1.1 200 OK\r\nContent-Type: application/json\r\n"
      "Access-Control-Allow-Origin: *\r\nCache-Control: no-cache\r\n"
      "Content-Length: %d\r\nConnection: close\r\n\r\n",
      n);
  client.write(reinterpret_cast<const uint8_t*>(body), static_cast<size_t>(n));
}

void SendText(WiFiClient& client, const char* status, const char* type,
              const char* text) {
  client.printf(
      "HTTP/1.1 %s\r\nContent-Type: %s\r\nContent-Length: %u\r\n"
      "Connection: close\r\n\r\n%s",
      status, type, static_cast<unsigned>(strlen(text)), text);
}

// Reads the request line ("GET /path HTTP/1.1") and skips the headers.
bool ReadRequest(WiFiClient& client, String* path) {
  client.setTimeout(1000);
  const String line = client.readStringUntil('\n');
  if (!line.startsWith("GET ")) return false;
  const int end = line.indexOf(' ', 4);
  *path = end > 4 ? line.substring(4, end) : line.substring(4);
  while (client.connected()) {
    const String h = client.readStringUntil('\n');
    if (h.length() <= 1) break;  // blank line ("\r")
  }
  return true;
}

void HandleClient(WiFiClient client) {
  String path;
  if (!ReadRequest(client, &path)) {
    SendText(client, "400 Bad Request", "text/plain", "bad request\n");
    client.stop();
    return;
  }
  const int q = path.indexOf('?');
  if (q >= 0) path = path.substring(0, q);
  if (path == "/status") {
    SendStatus(client);
  } else if (path == "/stream") {
    bool admitted = false;
    portENTER_CRITICAL(&stats_lock);
    if (stream_clients < kMaxStreams) {
      ++stream_clients;
      admitted = true;
    }
    portEXIT_CRITICAL(&stats_lock);
    if (!admitted) {
      SendText(client, "503 Service Unavailable", "text/plain",
               "too many stream clients\n");
    } else {
      WiFiClient* owned = new WiFiClient(client);
      if (xTaskCreatePinnedToCore(StreamTask, "stream", 6144, owned, 2, nullptr,
                                  1) != pdPASS) {
        delete owned;
        portENTER_CRITICAL(&stats_lock);
        --stream_clients;
        portEXIT_CRITICAL(&stats_lock);
        SendText(client, "503 Service Unavailable", "text/plain",
                 "no memory for a stream\n");
      }
      return;  // the task owns the connection now
    }
  } else if (path == "/") {
    SendText(client, "200 OK", "text/html",
             "<!doctype html><title>cube camera</title>"
             "<img src=\"/stream\" width=320 height=240>");
  } else {
    SendText(client, "404 Not Found", "text/plain", "not found\n");
  }
  client.stop();
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
  Serial.println("/stream");
  cam::server.begin();
  cam::fps_window_start_ms = millis();
}

void loop() {
  cam::UpdateFps();
#if ESP_ARDUINO_VERSION_MAJOR >= 3
  WiFiClient client = cam::server.accept();
#else
  WiFiClient client = cam::server.available();
#endif
  if (client) cam::HandleClient(client);
  static uint32_t last_reconnect_ms = 0;
  if (WiFi.status() != WL_CONNECTED && millis() - last_reconnect_ms > 10000) {
    last_reconnect_ms = millis();
    WiFi.reconnect();
  }
  delay(2);
}
