#include "cam_http.h"

#include <cstdio>
#include <cstring>

namespace cam {

namespace {

bool StartsWith(const char* s, size_t len, const char* prefix) {
  const size_t n = std::strlen(prefix);
  return len >= n && std::memcmp(s, prefix, n) == 0;
}

char Lower(char c) {
  return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

// Case-insensitive prefix match (header names and the auth scheme).
bool StartsWithNoCase(const char* s, size_t len, const char* prefix) {
  const size_t n = std::strlen(prefix);
  if (len < n) return false;
  for (size_t i = 0; i < n; ++i) {
    if (Lower(s[i]) != Lower(prefix[i])) return false;
  }
  return true;
}

bool Equals(const char* s, size_t len, const char* text) {
  return len == std::strlen(text) && std::memcmp(s, text, len) == 0;
}

const char* Find(const char* s, size_t len, char c) {
  return static_cast<const char*>(std::memchr(s, c, len));
}

// The value of `name` in a query string "a=1&token=x", or nullptr.
const char* QueryParam(const char* query, size_t len, const char* name,
                       size_t* value_len) {
  const size_t name_len = std::strlen(name);
  size_t i = 0;
  while (i < len) {
    const char* amp = Find(query + i, len - i, '&');
    const size_t end = amp == nullptr ? len : static_cast<size_t>(amp - query);
    const char* pair = query + i;
    const size_t pair_len = end - i;
    if (pair_len > name_len && std::memcmp(pair, name, name_len) == 0 &&
        pair[name_len] == '=') {
      *value_len = pair_len - name_len - 1;
      return pair + name_len + 1;
    }
    i = end + 1;
  }
  return nullptr;
}

// Appends to a caller's buffer, remembering when something did not fit.
struct HeadWriter {
  char* out;
  size_t cap;
  size_t len = 0;
  bool fits = true;

  void Text(const char* text) {
    const size_t n = std::strlen(text);
    if (!fits || n + 1 > cap - len) {
      fits = false;
      return;
    }
    std::memcpy(out + len, text, n + 1);
    len += n;
  }
  void Number(long value) {
    char digits[24];
    std::snprintf(digits, sizeof(digits), "%ld", value);
    Text(digits);
  }
};

}  // namespace

void RequestReader::Start(uint32_t now_ms) {
  len_ = 0;
  buf_[0] = '\0';
  start_ms_ = now_ms;
  state_ = State::kReading;
}

RequestReader::State RequestReader::Feed(const uint8_t* data, size_t len,
                                         uint32_t now_ms) {
  if (state_ != State::kReading) return state_;
  const size_t take = len < Room() ? len : Room();
  const size_t scan_from = len_ >= 3 ? len_ - 3 : 0;
  std::memcpy(buf_ + len_, data, take);
  len_ += take;
  buf_[len_] = '\0';
  // The head ends at the first blank line ("\r\n\r\n", or "\n\n").
  for (size_t i = scan_from; i + 1 < len_; ++i) {
    if (buf_[i] != '\n') continue;
    if (buf_[i + 1] == '\n' ||
        (buf_[i + 1] == '\r' && i + 2 < len_ && buf_[i + 2] == '\n')) {
      state_ = State::kComplete;
      return state_;
    }
  }
  if (len_ >= kMaxRequestHead) {
    state_ = State::kTooLarge;
  } else {
    Poll(now_ms);
  }
  return state_;
}

RequestReader::State RequestReader::Poll(uint32_t now_ms) {
  if (state_ == State::kReading &&
      static_cast<uint32_t>(now_ms - start_ms_) >= kRequestTimeoutMs) {
    state_ = State::kTimedOut;
  }
  return state_;
}

Request ParseRequest(const char* head, size_t len) {
  Request r;
  const char* eol = Find(head, len, '\n');
  if (eol == nullptr) return r;
  size_t line_len = static_cast<size_t>(eol - head);
  if (line_len > 0 && head[line_len - 1] == '\r') --line_len;
  // "METHOD SP target SP HTTP/x.y"
  const char* sp1 = Find(head, line_len, ' ');
  if (sp1 == nullptr) return r;
  const size_t method_len = static_cast<size_t>(sp1 - head);
  const char* target = sp1 + 1;
  const size_t rest = line_len - method_len - 1;
  const char* sp2 = Find(target, rest, ' ');
  if (sp2 == nullptr) return r;
  const size_t target_len = static_cast<size_t>(sp2 - target);
  if (target_len == 0 || target[0] != '/') return r;
  if (!StartsWith(sp2 + 1, rest - target_len - 1, "HTTP/1.")) return r;
  r.method = Equals(head, method_len, "GET")       ? Method::kGet
             : Equals(head, method_len, "OPTIONS") ? Method::kOptions
                                                   : Method::kOther;
  const char* q = Find(target, target_len, '?');
  r.path = target;
  r.path_len = q == nullptr ? target_len : static_cast<size_t>(q - target);
  if (q != nullptr) {
    r.query = q + 1;
    r.query_len = target_len - r.path_len - 1;
  }
  // Headers: only Authorization matters.
  size_t pos = static_cast<size_t>(eol - head) + 1;
  while (pos < len) {
    const char* line = head + pos;
    const char* end = Find(line, len - pos, '\n');
    size_t n = end == nullptr ? len - pos : static_cast<size_t>(end - line);
    pos += n + 1;
    if (n > 0 && line[n - 1] == '\r') --n;
    if (n == 0) break;
    if (!StartsWithNoCase(line, n, "authorization:")) continue;
    size_t i = std::strlen("authorization:");
    while (i < n && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (!StartsWithNoCase(line + i, n - i, "bearer ")) continue;
    i += std::strlen("bearer ");
    while (i < n && line[i] == ' ') ++i;
    size_t value_end = n;
    while (value_end > i &&
           (line[value_end - 1] == ' ' || line[value_end - 1] == '\t')) {
      --value_end;
    }
    r.bearer = line + i;
    r.bearer_len = value_end - i;
  }
  r.valid = true;
  return r;
}

bool ConstantTimeEquals(const char* expected, size_t expected_len,
                        const char* given, size_t given_len) {
  unsigned diff = expected_len == given_len ? 0u : 1u;
  for (size_t i = 0; i < expected_len; ++i) {
    const unsigned char g =
        i < given_len ? static_cast<unsigned char>(given[i]) : 0u;
    diff |= static_cast<unsigned>(static_cast<unsigned char>(expected[i]) ^ g);
  }
  return diff == 0;
}

bool Authorized(const Request& request, const HttpConfig& config) {
  const size_t token_len = std::strlen(config.token);
  if (token_len == 0) return true;
  size_t query_len = 0;
  const char* from_query =
      request.query == nullptr
          ? nullptr
          : QueryParam(request.query, request.query_len, "token", &query_len);
  // Both candidates are always compared, so the time says nothing either.
  const bool query_ok =
      from_query != nullptr &&
      ConstantTimeEquals(config.token, token_len, from_query, query_len);
  const bool bearer_ok =
      request.bearer != nullptr &&
      ConstantTimeEquals(config.token, token_len, request.bearer,
                         request.bearer_len);
  return query_ok || bearer_ok;
}

Route Decide(const Request& request, const HttpConfig& config) {
  if (!request.valid) return Route::kBadRequest;
  if (request.method == Method::kOptions) {
    return config.allow_origin[0] != '\0' ? Route::kPreflight
                                          : Route::kMethodNotAllowed;
  }
  if (request.method != Method::kGet) return Route::kMethodNotAllowed;
  if (Equals(request.path, request.path_len, "/")) return Route::kIndex;
  const bool status = Equals(request.path, request.path_len, "/status");
  const bool stream = Equals(request.path, request.path_len, "/stream");
  if (!status && !stream) return Route::kNotFound;
  if (!Authorized(request, config)) return Route::kUnauthorized;
  return status ? Route::kStatus : Route::kStream;
}

size_t FormatHead(const ResponseHead& head, const HttpConfig& config,
                  char* out, size_t cap) {
  if (cap == 0) return 0;
  HeadWriter w{out, cap};
  w.Text("HTTP/1.1 ");
  w.Number(head.status);
  w.Text(" ");
  w.Text(head.reason);
  w.Text("\r\n");
  if (head.status != 204) {
    w.Text("Content-Type: ");
    w.Text(head.content_type);
    w.Text("\r\n");
  }
  if (head.content_length >= 0) {
    w.Text("Content-Length: ");
    w.Number(head.content_length);
    w.Text("\r\n");
  }
  if (head.no_cache) w.Text("Cache-Control: no-cache\r\n");
  if (head.status == 401) {
    w.Text("WWW-Authenticate: Bearer realm=\"cube-camera\"\r\n");
  }
  if (config.allow_origin[0] != '\0') {
    w.Text("Access-Control-Allow-Origin: ");
    w.Text(config.allow_origin);
    w.Text("\r\nVary: Origin\r\n");
    if (head.status == 204) {
      w.Text(
          "Access-Control-Allow-Methods: GET\r\n"
          "Access-Control-Allow-Headers: Authorization\r\n"
          "Access-Control-Max-Age: 600\r\n");
    }
  }
  w.Text("Connection: close\r\n\r\n");
  if (!w.fits) {
    out[0] = '\0';
    return 0;
  }
  return w.len;
}

FixedReply FixedReplyFor(Route route) {
  FixedReply r;
  switch (route) {
    case Route::kIndex:
      r.head.content_type = "text/html";
      // The page passes its own query (?token=...) on to the stream.
      r.body =
          "<!doctype html><title>cube camera</title>"
          "<img id=\"s\" width=\"320\" height=\"240\" alt=\"camera\">"
          "<script>document.getElementById('s').src="
          "'/stream'+location.search</script>";
      break;
    case Route::kPreflight:
      r.head.status = 204;
      r.head.reason = "No Content";
      r.body = "";
      break;
    case Route::kBadRequest:
      r.head.status = 400;
      r.head.reason = "Bad Request";
      r.body = "bad request\n";
      break;
    case Route::kUnauthorized:
      r.head.status = 401;
      r.head.reason = "Unauthorized";
      r.body = "a token is required: ?token= or Authorization: Bearer\n";
      break;
    case Route::kNotFound:
      r.head.status = 404;
      r.head.reason = "Not Found";
      r.body = "not found\n";
      break;
    case Route::kMethodNotAllowed:
      r.head.status = 405;
      r.head.reason = "Method Not Allowed";
      r.body = "only GET\n";
      break;
    case Route::kTimeout:
      r.head.status = 408;
      r.head.reason = "Request Timeout";
      r.body = "request head not received in time\n";
      break;
    case Route::kTooLarge:
      r.head.status = 431;
      r.head.reason = "Request Header Fields Too Large";
      r.body = "request head too large\n";
      break;
    case Route::kBusy:
      r.head.status = 503;
      r.head.reason = "Service Unavailable";
      r.body = "busy, try again\n";
      break;
    case Route::kStatus:
    case Route::kStream:
      r.head.status = 500;
      r.head.reason = "Internal Server Error";
      r.body = "no fixed reply\n";
      break;
  }
  r.head.content_length = static_cast<long>(std::strlen(r.body));
  if (route == Route::kPreflight) r.head.content_length = -1;
  return r;
}

ResponseHead StreamHead() {
  ResponseHead h;
  h.content_type = kStreamContentType;
  h.no_cache = true;
  return h;
}

}  // namespace cam
