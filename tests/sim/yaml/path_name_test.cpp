// Scene and variant names become file names: only one plain path component passes.
#include "sim/yaml/path_name.h"

#include <doctest/doctest.h>

#include <string>

using sim::yaml::pathNameFault;

TEST_CASE("plain names pass") {
  for (const char* name : {"ball", "poll_bar_impulse", "end-2", "Ünïcode", "a.b"}) CHECK(pathNameFault(name) == "");
  CHECK(pathNameFault(std::string(sim::yaml::kMaxNameBytes, 'a')) == "");
}

TEST_CASE("names that leave the folder, hide, read as options or break the file system are refused") {
  CHECK(pathNameFault("") == "is empty");
  CHECK(pathNameFault("../escaped").starts_with("starts with '.'"));
  CHECK(pathNameFault("..").starts_with("starts with '.'"));
  CHECK(pathNameFault(".hidden").starts_with("starts with '.'"));
  CHECK(pathNameFault("/tmp/abs") == "contains '/' (a folder separator)");
  CHECK(pathNameFault("a/b") == "contains '/' (a folder separator)");
  CHECK(pathNameFault("a\\b") == "contains '\\' (a folder separator)");
  CHECK(pathNameFault("-y").starts_with("starts with '-'"));
  CHECK(pathNameFault(std::string("a\nb")) == "contains a control character");
  CHECK(pathNameFault(std::string(sim::yaml::kMaxNameBytes + 1, 'a')).starts_with("is longer than"));
}
