// sim/yaml/first_document: yaml-cpp's nodes from one parse, and a second document found, not read.
#include <doctest/doctest.h>

#include "sim/yaml/first_document.h"

TEST_CASE("the one parse keeps each node's line, an alias's node, and finds a second document where it starts") {
  const sim::yaml::FirstDocument one = sim::yaml::loadFirstDocument("a: &x [1, {b: 2}]\nc:\n  - *x\n  - ~\n");
  REQUIRE(one.root.IsMap());
  CHECK(!one.second);
  CHECK(one.root["a"][1]["b"].Mark().line == 0);
  CHECK(one.root["a"][1]["b"].Mark().column == 14);
  CHECK(one.root["c"][0].is(one.root["a"]));
  CHECK(one.root["c"][1].IsNull());
  CHECK(one.root["c"].Mark().line == 2);
  // a second document, marked or not, is found where it starts and not read ([ never closes)
  const sim::yaml::FirstDocument two = sim::yaml::loadFirstDocument("a: 1\n---\nb: [\n");
  REQUIRE(two.second);
  CHECK(two.second->line == 1);
  const sim::yaml::FirstDocument flow = sim::yaml::loadFirstDocument("[1]\n[2]\n");
  REQUIRE(flow.second);
  CHECK(flow.second->line == 1);
  CHECK(flow.root.size() == 1);
  CHECK(sim::yaml::loadFirstDocument("").root.IsNull());
}
