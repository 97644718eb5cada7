// The camera's HTTP request handling without the network: a bounded reader
// of the request head, its parser, the token check and the route choice, and
// the response head writer. Portable C++ with no Arduino header, so the host
// tests (firmware/tests/cam_http_test.cpp) run the code the sketch ships.
#ifndef CAM_HTTP_H_
#define CAM_HTTP_H_

#include <cstddef>
#include <cstdint>

namespace cam {

// The request line and all headers must fit in this many bytes...
constexpr size_t kMaxRequestHead = 1024;
// ...and arrive within this long after the connection was accepted.
constexpr uint32_t kRequestTimeoutMs = 2000;
constexpr size_t kMaxTokenLen = 128;
constexpr size_t kMaxOriginLen = 128;

// What the camera is configured with (secrets.h). An empty token lets every
// client in; an empty origin sends no Access-Control-Allow-Origin header.
struct HttpConfig {
  const char* token;
  const char* allow_origin;
};

// A token uses URL-safe characters only (A-Z a-z 0-9 - . _ ~), so it needs no
// escaping in a query string. Empty means no token.
constexpr bool IsValidToken(const char* token) {
  size_t n = 0;
  for (; token[n] != '\0'; ++n) {
    const char c = token[n];
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ||
                    (c >= '0' && c <= '9') || c == '-' || c == '.' ||
                    c == '_' || c == '~';
    if (!ok || n >= kMaxTokenLen) return false;
  }
  return true;
}

// An origin is visible ASCII without spaces ("http://host:port"), so it can
// never break a header line. Empty means no CORS header.
constexpr bool IsValidOrigin(const char* origin) {
  size_t n = 0;
  for (; origin[n] != '\0'; ++n) {
    if (origin[n] <= ' ' || origin[n] > '~' || n >= kMaxOriginLen) return false;
  }
  return true;
}

// Collects one request head (up to the blank line) into a fixed buffer, and
// gives up when it grows past kMaxRequestHead or takes longer than
// kRequestTimeoutMs, so one slow or huge client cannot hold the server.
class RequestReader {
 public:
  enum class State { kReading, kComplete, kTooLarge, kTimedOut };

  void Start(uint32_t now_ms);
  // Appends received bytes (at most Room() are kept) and returns the state.
  State Feed(const uint8_t* data, size_t len, uint32_t now_ms);
  // The state when nothing arrived: times out after kRequestTimeoutMs.
  State Poll(uint32_t now_ms);
  // How many more bytes the head may have.
  size_t Room() const { return kMaxRequestHead - len_; }
  State state() const { return state_; }
  const char* head() const { return buf_; }
  size_t size() const { return len_; }

 private:
  char buf_[kMaxRequestHead + 1] = {};
  size_t len_ = 0;
  uint32_t start_ms_ = 0;
  State state_ = State::kReading;
};

enum class Method { kGet, kOptions, kOther };

// A parsed request head; the pointers point into the reader's buffer.
struct Request {
  bool valid = false;
  Method method = Method::kOther;
  const char* path = nullptr;  // without the query
  size_t path_len = 0;
  const char* query = nullptr;  // after '?', may be empty
  size_t query_len = 0;
  const char* bearer = nullptr;  // the token of "Authorization: Bearer ..."
  size_t bearer_len = 0;
};

Request ParseRequest(const char* head, size_t len);

// The token check: the query parameter `token` or an `Authorization: Bearer`
// header, compared with the configured token in constant time. True when
// no token is configured.
bool Authorized(const Request& request, const HttpConfig& config);

// Compares in time that depends only on expected_len, never on where the
// first difference is.
bool ConstantTimeEquals(const char* expected, size_t expected_len,
                        const char* given, size_t given_len);

enum class Route {
  kIndex,             // GET /
  kStatus,            // GET /status
  kStream,            // GET /stream
  kPreflight,         // OPTIONS, when an origin is configured
  kBadRequest,        // 400
  kUnauthorized,      // 401: a token is configured and did not match
  kNotFound,          // 404
  kMethodNotAllowed,  // 405
  kTimeout,           // 408: the head did not arrive in time
  kTooLarge,          // 431: the head is larger than kMaxRequestHead
  kBusy,              // 503: no free connection slot or stream
};

Route Decide(const Request& request, const HttpConfig& config);

// A response head: status line, the given headers, Connection: close, and
// the CORS header only when the config names an origin. A 401 adds the
// Bearer challenge; a 204 (the CORS preflight) the allowed method and header.
struct ResponseHead {
  int status = 200;
  const char* reason = "OK";
  const char* content_type = "text/plain";
  long content_length = -1;  // < 0: no Content-Length (a stream)
  bool no_cache = false;
};

// Writes the head into out (NUL-terminated); returns its length, or 0 when
// it does not fit.
size_t FormatHead(const ResponseHead& head, const HttpConfig& config,
                  char* out, size_t cap);

// The fixed responses: every route but kStatus and kStream has a fixed body
// (those two get a 500, as the sketch never asks for them).
struct FixedReply {
  ResponseHead head;
  const char* body = "";
};
FixedReply FixedReplyFor(Route route);

// The MJPEG stream: multipart/x-mixed-replace, parts separated by kBoundary.
constexpr char kBoundary[] = "cubeframe";
constexpr char kStreamContentType[] =
    "multipart/x-mixed-replace; boundary=cubeframe";
ResponseHead StreamHead();

}  // namespace cam

#endif  // CAM_HTTP_H_
