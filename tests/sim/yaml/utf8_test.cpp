// UTF-8 as RFC 3629 defines it (utf8.h): well-formed text passes whole; the first byte of anything
// else (a Latin-1 byte, a cut sequence, an overlong form, a surrogate, past U+10FFFF) is found.
#include "sim/yaml/utf8.h"

#include <doctest/doctest.h>

#include <string>

using sim::yaml::invalidUtf8At;
constexpr size_t kNone = std::string_view::npos;

TEST_CASE("well-formed UTF-8 of one to four bytes a character passes") {
  CHECK(invalidUtf8At("") == kNone);
  CHECK(invalidUtf8At("ball") == kNone);
  CHECK(invalidUtf8At("balle \xC3\xA9t\xC3\xA9") == kNone);  // é, two bytes
  CHECK(invalidUtf8At("\xE2\x88\x92"
                      "1") == kNone);                          // U+2212 minus, three bytes
  CHECK(invalidUtf8At("\xF0\x9F\x8E\xB1") == kNone);           // U+1F3B1, four bytes
  CHECK(invalidUtf8At("\xF4\x8F\xBF\xBF") == kNone);           // U+10FFFF, the last code point
  CHECK(invalidUtf8At("\xED\x9F\xBF") == kNone);               // U+D7FF, just below the surrogates
  CHECK(invalidUtf8At(std::string_view("a\0b", 3)) == kNone);  // NUL is a character
}

TEST_CASE("the offset of the first byte that is not UTF-8") {
  CHECK(invalidUtf8At("caf\xE9") == 3);    // Latin-1 é
  CHECK(invalidUtf8At("ab\x80") == 2);     // a lone continuation byte
  CHECK(invalidUtf8At("\xC3") == 0);       // a sequence cut at the end
  CHECK(invalidUtf8At("x\xE2\x88") == 1);  // three bytes announced, two there
  CHECK(invalidUtf8At("\xC3(") == 0);      // a continuation that is not one
  CHECK(invalidUtf8At("\xFF") == 0);
  CHECK(invalidUtf8At("\xF8\x88\x80\x80\x80") == 0);  // a five-byte form
}

TEST_CASE("overlong forms, surrogates and code points past U+10FFFF are refused") {
  CHECK(invalidUtf8At("\xC0\xAF") == 0);  // '/' in two bytes
  CHECK(invalidUtf8At("\xC1\xBF") == 0);
  CHECK(invalidUtf8At("\xE0\x80\xAF") == 0);      // '/' in three bytes
  CHECK(invalidUtf8At("\xF0\x80\x80\xAF") == 0);  // '/' in four bytes
  CHECK(invalidUtf8At("ok\xED\xA0\x80") == 2);    // U+D800, a UTF-16 surrogate
  CHECK(invalidUtf8At("\xF4\x90\x80\x80") == 0);  // U+110000
  CHECK(invalidUtf8At("\xF5\x80\x80\x80") == 0);
}
