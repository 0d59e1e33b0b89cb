// Output names (output_names.cpp): one scheme for every output of a run, times written short but
// never so short that two different times share a name, and -0 never written "-0".
#include "render/video/output_names.h"

#include <doctest/doctest.h>

#include <set>
#include <string>
#include <vector>

using namespace render::video;

TEST_CASE("a run's base name is the scene's, with the variant's after a dash") {
  CHECK(outputBase("drop", "") == "drop");
  CHECK(outputBase("drop", "heavy") == "drop-heavy");
  sim::scene::SceneDef def;
  def.name = "cradle";
  def.variant = "five";
  CHECK(outputBase(def) == "cradle-five");
}

TEST_CASE("poll panels and strobe stills are named from their parts") {
  CHECK(strobeSuffix(0) == "");
  CHECK(strobeSuffix(4) == "-strobe4");
  CHECK(panelsFileName("drop", "-t1.5", 0) == "drop-panels-t1.5.png");
  CHECK(panelsFileName("drop", "-impact2", 3) == "drop-panels-impact2-strobe3.png");
}

TEST_CASE("a time in a name: shortest form to 6 significant digits, -0 written 0") {
  CHECK(timeForName(0.5) == "0.5");
  CHECK(timeForName(1.0010000000000001) == "1.001");
  CHECK(timeForName(1.234567) == "1.23457");
  CHECK(timeForName(100.0) == "100");
  CHECK(timeForName(0.0) == "0");
  CHECK(timeForName(-0.0) == "0");
  CHECK(timeForName(-1.5) == "-1.5");
}

TEST_CASE("several times get as many digits as tell every two apart") {
  CHECK(timesForNames({0.5, 1.0}) == std::vector<std::string>{"0.5", "1"});
  CHECK(timesForNames({100.0001, 100.0004}) == std::vector<std::string>{"100.0001", "100.0004"});
  // one time given twice keeps one name (the plan refuses the repeat, not the namer)
  CHECK(timesForNames({2.0, 2.0}) == std::vector<std::string>{"2", "2"});
  // 0 and -0 are the same time, both "0"
  CHECK(timesForNames({0.0, -0.0}) == std::vector<std::string>{"0", "0"});
  // neighbouring doubles: 17 digits tell them apart
  const double a = 1.0, b = 1.0000000000000002;
  const std::vector<std::string> names = timesForNames({a, b});
  CHECK(names[0] != names[1]);
  const std::vector<double> many = {1.0, 1.1, 1.11, 1.111, 1.1111, 1.11111, 1.111111, 1.1111111};
  const std::vector<std::string> manyNames = timesForNames(many);
  CHECK(std::set<std::string>(manyNames.begin(), manyNames.end()).size() == many.size());
}
