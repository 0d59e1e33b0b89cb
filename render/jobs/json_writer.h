// A small streaming JSON writer: numbers in shortest round-trip form, commas kept for the caller.
#pragma once

#include <charconv>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace render::jobs {

// shortest text that reads back as the same double (std::to_chars), e.g. 0.3333333333333333
inline std::string formatNumber(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) {}

  JsonWriter& beginObject() { return open('{'); }
  JsonWriter& endObject() { return close('}'); }
  JsonWriter& beginArray() { return open('['); }
  JsonWriter& endArray() { return close(']'); }

  JsonWriter& key(std::string_view k) {
    separate();
    string(k);
    out_ << ':';
    afterKey_ = true;
    return *this;
  }
  JsonWriter& value(double x) {
    separate();
    // JSON has no NaN or infinity
    if (x != x || x - x != 0.0) out_ << "null";
    else out_ << formatNumber(x);
    return *this;
  }
  JsonWriter& value(long n) {
    separate();
    out_ << n;
    return *this;
  }
  JsonWriter& value(bool b) {
    separate();
    out_ << (b ? "true" : "false");
    return *this;
  }
  JsonWriter& value(std::string_view s) {
    separate();
    string(s);
    return *this;
  }
  JsonWriter& value(const char* s) { return value(std::string_view(s)); }
  JsonWriter& null() {
    separate();
    out_ << "null";
    return *this;
  }
  template <class T>
  JsonWriter& field(std::string_view k, const T& v) {
    key(k);
    return value(v);
  }

 private:
  JsonWriter& open(char c) {
    separate();
    out_ << c;
    first_.push_back(true);
    return *this;
  }
  JsonWriter& close(char c) {
    out_ << c;
    first_.pop_back();
    return *this;
  }
  // a comma before every element but the first of its container, none after a key
  void separate() {
    if (afterKey_) {
      afterKey_ = false;
      return;
    }
    if (!first_.empty()) {
      if (!first_.back()) out_ << ',';
      first_.back() = false;
    }
  }
  void string(std::string_view s) {
    out_ << '"';
    for (char c : s) {
      if (c == '"' || c == '\\') out_ << '\\' << c;
      else if (c == '\n') out_ << "\\n";
      else if (static_cast<unsigned char>(c) < 0x20) {
        const char* hex = "0123456789abcdef";
        out_ << "\\u00" << hex[(c >> 4) & 0xf] << hex[c & 0xf];
      } else out_ << c;
    }
    out_ << '"';
  }

  std::ostream& out_;
  std::vector<bool> first_;
  bool afterKey_ = false;
};

}  // namespace render::jobs
