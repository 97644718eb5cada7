#include "reply.h"

#include <cstring>

#include "text.h"

namespace cube {

JsonWriter& Reply::Ok() {
  if (!started_) {
    Begin();
    w_.Key("ok");
    w_.Bool(true);
    WriteCmd();
    started_ = true;
  }
  return w_;
}

void Reply::Fail(const char* code, const char* message) {
  if (failed_ || started_) return;
  failed_ = true;
  code_ = code;
  CopyText(message_, sizeof(message_), message, std::strlen(message));
}

void Reply::DetailInt(const char* key, int64_t v) {
  Detail* d = Add(key);
  if (d != nullptr) {
    d->kind = Detail::kInt;
    d->i = v;
  }
}

void Reply::DetailNum(const char* key, double v) {
  Detail* d = Add(key);
  if (d != nullptr) {
    d->kind = Detail::kNum;
    d->d = v;
  }
}

void Reply::DetailStr(const char* key, const char* v) {
  Detail* d = Add(key);
  if (d != nullptr) {
    d->kind = Detail::kStr;
    CopyText(d->s, sizeof(d->s), v, std::strlen(v));
  }
}

void Reply::DetailBool(const char* key, bool v) {
  Detail* d = Add(key);
  if (d != nullptr) {
    d->kind = Detail::kBool;
    d->i = v ? 1 : 0;
  }
}

bool Reply::Close() {
  if (failed_) {
    Begin();
    w_.Key("ok");
    w_.Bool(false);
    WriteCmd();
    w_.Key("error");
    w_.BeginObject();
    w_.Key("code");
    w_.String(code_);
    w_.Key("message");
    w_.String(message_);
    w_.Key("details");
    w_.BeginObject();
    for (size_t i = 0; i < ndetails_; ++i) {
      const Detail& d = details_[i];
      w_.Key(d.key);
      switch (d.kind) {
        case Detail::kInt:
          w_.Int(d.i);
          break;
        case Detail::kNum:
          w_.Double(d.d);
          break;
        case Detail::kStr:
          w_.String(d.s);
          break;
        case Detail::kBool:
          w_.Bool(d.i != 0);
          break;
      }
    }
    w_.EndObject();
    w_.EndObject();
  } else {
    Ok();
  }
  w_.EndObject();
  return w_.ok();
}

Reply::Detail* Reply::Add(const char* key) {
  if (ndetails_ >= kMaxDetails) return nullptr;
  Detail* d = &details_[ndetails_++];
  d->key = key;
  return d;
}

void Reply::Begin() {
  w_.BeginObject();
  if (has_seq) {
    w_.Key("seq");
    w_.Uint(seq);
  }
  if (has_sid) {
    w_.Key("sid");
    w_.Uint(sid);
  }
}

void Reply::WriteCmd() {
  if (cmd != nullptr) {
    w_.Key("cmd");
    w_.String(cmd, cmd_len);
  }
}

}  // namespace cube
