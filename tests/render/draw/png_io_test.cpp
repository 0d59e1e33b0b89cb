// PNG files: what is written reads back the same, the same image always gives the same bytes, and
// a file that cannot be read or written is an error naming it.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "render/draw/png_io.h"

namespace fs = std::filesystem;

namespace {

// a picture with flat areas, a gradient and noise, like a frame with anti-aliased edges
render::draw::Image testImage() {
  render::draw::Image i(64, 48);
  unsigned seed = 12345;
  for (int y = 0; y < i.height; ++y)
    for (int x = 0; x < i.width; ++x) {
      uint8_t* p = i.pixel(x, y);
      seed = seed * 1103515245u + 12345u;
      p[0] = static_cast<uint8_t>(x * 4);
      p[1] = static_cast<uint8_t>(y < 24 ? 200 : (seed >> 16) & 0xff);
      p[2] = static_cast<uint8_t>(x == y ? 0 : 255);
    }
  return i;
}

fs::path scratchDir() {
  const fs::path d = fs::temp_directory_path() / ("rigidreel_png_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST_CASE("an image written reads back identical, opaque") {
  const fs::path dir = scratchDir();
  const render::draw::Image image = testImage();
  render::draw::writePng(image, (dir / "a.png").string());
  const render::draw::Image back = render::draw::readPng((dir / "a.png").string());
  CHECK(back == image);
  // nothing else is left beside it (the temporary name was renamed)
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}) == 1);
  fs::remove_all(dir);
}

TEST_CASE("every setting gives the same pixels, and the same image the same bytes") {
  const render::draw::Image image = testImage();
  const auto bytes = render::draw::encodePng(image);
  CHECK(render::draw::encodePng(image) == bytes);
  // the signature
  REQUIRE(bytes.size() > 8);
  CHECK(bytes[1] == 'P');
  CHECK(bytes[2] == 'N');
  CHECK(bytes[3] == 'G');
}

TEST_CASE("unreadable and unwritable paths are errors that name the path") {
  CHECK_THROWS_WITH_AS(render::draw::readPng("/nonexistent/x.png"), doctest::Contains("/nonexistent/x.png"), std::runtime_error);
  CHECK_THROWS_WITH_AS(render::draw::writePng(testImage(), "/nonexistent/x.png"), doctest::Contains("/nonexistent/x.png"),
                       std::runtime_error);
  const fs::path dir = scratchDir();
  std::ofstream(dir / "not.png") << "not a png";
  CHECK_THROWS_AS(render::draw::readPng((dir / "not.png").string()), std::runtime_error);
  fs::remove_all(dir);
}
