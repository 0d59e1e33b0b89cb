// CSV fields as RFC 4180 writes them (csv_field.h): plain when nothing in them could split a row,
// else in double quotes with each quote doubled; read back by the RFC's rule they are the name.
#include "render/jobs/csv_field.h"

#include <doctest/doctest.h>

#include <string>

using render::jobs::csvField;

namespace {

// one quoted or plain field read back by RFC 4180's rule (the reader a spreadsheet uses)
std::string readBack(const std::string& field) {
  if (field.empty() || field.front() != '"') return field;
  std::string out;
  for (size_t i = 1; i + 1 < field.size(); ++i) {
    if (field[i] == '"') ++i;  // a doubled quote is one quote
    out += field[i];
  }
  return out;
}

}  // namespace

TEST_CASE("a field with nothing that splits a row is written as it is") {
  CHECK(csvField("ball") == "ball");
  CHECK(csvField("") == "");
  CHECK(csvField("a b;c") == "a b;c");
  CHECK(csvField("ballé") == "ballé");
}

TEST_CASE("a comma, a quote, a CR or an LF puts the field in quotes, its quotes doubled") {
  CHECK(csvField("a,b") == "\"a,b\"");
  CHECK(csvField("say \"hi\"") == "\"say \"\"hi\"\"\"");
  CHECK(csvField("two\nlines") == "\"two\nlines\"");
  CHECK(csvField("cr\rhere") == "\"cr\rhere\"");
  CHECK(csvField("\"") == "\"\"\"\"");
}

TEST_CASE("every quoted field reads back as the name it was made from") {
  for (const std::string name : {"a,b", "\"", "x\"y,z\n", ",,,", "\r\n"}) {
    CAPTURE(name);
    const std::string field = csvField(name);
    CHECK(field.front() == '"');
    CHECK(field.back() == '"');
    CHECK(readBack(field) == name);
  }
}
