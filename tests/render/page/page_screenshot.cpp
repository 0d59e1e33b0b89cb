// The browser test's screenshot of the lecture page against tests/golden/page/index.png, with the
// golden images' tolerance (RIGIDREEL_UPDATE_GOLDEN=1 writes it instead): run by
// page_browser_test.sh as `page_screenshot SCREENSHOT.png`, not by ctest alone.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdlib>
#include <iostream>

#include "render/draw/png_io.h"
#include "support/golden_compare.h"

namespace {
const char* screenshot = nullptr;
}

TEST_CASE("golden: the lecture page at 1280 px wide, as Chromium draws it") {
  REQUIRE(screenshot);
  golden::checkGolden("page/index", render::draw::readPng(screenshot));
}

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: page_screenshot SCREENSHOT.png\n";
    return 2;
  }
  screenshot = argv[1];
  doctest::Context context;
  context.setOption("no-intro", true);
  return context.run();
}
