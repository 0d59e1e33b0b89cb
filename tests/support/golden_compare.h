// Frames compared with the PNGs in tests/golden/, with a tolerance for rasterizer round-off
// (render/draw/image_compare.h; see tests/golden/README.md): shared by golden_test.cpp (frames of inline scenes) and
// lecture_golden_test.cpp (a frame of each lecture scene).
#pragma once

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "render/draw/image.h"
#include "render/draw/image_compare.h"
#include "render/draw/png_io.h"

namespace golden {

namespace fs = std::filesystem;
using render::draw::Image;

// the tolerance of every golden frame (render/draw/image_compare.h, shared with `rigidreel golden`)
inline constexpr render::draw::PixelTolerance kTolerance{};

inline const fs::path kSource = RIGIDREEL_SOURCE_DIR;

inline bool updating() {
  const char* v = std::getenv("RIGIDREEL_UPDATE_GOLDEN");
  return v && *v && std::string(v) != "0";
}

// `actual` against tests/golden/<name>.png, or written there when updating
inline void checkGolden(const std::string& name, const Image& actual) {
  const fs::path golden = kSource / "tests" / "golden" / (name + ".png");
  if (updating()) {
    fs::create_directories(golden.parent_path());
    render::draw::writePng(actual, golden.string());
    MESSAGE("wrote " << golden.string());
    return;
  }
  INFO("golden image ", golden.string(), " (regenerate on purpose with `make golden`)");
  REQUIRE(fs::exists(golden));
  const Image expected = render::draw::readPng(golden.string());
  REQUIRE(expected.width == actual.width);
  REQUIRE(expected.height == actual.height);
  const render::draw::ImageComparison c = render::draw::compareImages(expected, actual, kTolerance);
  if (!c.passed()) {
    const fs::path dir = kSource / "out" / "golden-diff";
    fs::create_directories((dir / name).parent_path());
    render::draw::writePng(actual, (dir / (name + "-actual.png")).string());
    render::draw::writePng(c.diff, (dir / (name + "-diff.png")).string());
    FAIL_CHECK(name << ": " << c.differing << " pixels differ by more than " << kTolerance.channel << " (at most " << c.allowed
                    << " may); see " << (dir / (name + "-actual.png")).string() << " and "
                    << (dir / (name + "-diff.png")).string());
  }
}

}  // namespace golden
