// Frames compared with the PNGs in tests/golden/, with a tolerance for rasterizer round-off (see
// tests/golden/README.md): shared by golden_test.cpp (frames of inline scenes) and
// lecture_golden_test.cpp (a frame of each lecture scene).
#pragma once

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "render/draw/image.h"
#include "render/draw/png_io.h"

namespace golden {

namespace fs = std::filesystem;
using render::draw::Image;

// a pixel differs when one of its channels is off by more than this (of 255)
constexpr int kChannelTolerance = 24;
// a frame differs when more than this fraction of its pixels differ (0.2%: 115 of 320 × 180)
constexpr double kPixelFraction = 0.002;

inline const fs::path kSource = RIGIDREEL_SOURCE_DIR;

inline bool updating() {
  const char* v = std::getenv("RIGIDREEL_UPDATE_GOLDEN");
  return v && *v && std::string(v) != "0";
}

// differing pixels in red over a faded copy of the expected frame
inline Image diffImage(const Image& expected, const Image& actual, long& differing) {
  Image diff(expected.width, expected.height);
  differing = 0;
  for (int y = 0; y < expected.height; ++y)
    for (int x = 0; x < expected.width; ++x) {
      const uint8_t* e = expected.pixel(x, y);
      const uint8_t* a = actual.pixel(x, y);
      uint8_t* d = diff.pixel(x, y);
      bool off = false;
      for (int c = 0; c < 3; ++c) off = off || std::abs(e[c] - a[c]) > kChannelTolerance;
      if (off) {
        ++differing;
        d[0] = 255, d[1] = 0, d[2] = 0;
      } else {
        const uint8_t gray = static_cast<uint8_t>(191 + (e[0] + e[1] + e[2]) / 12);
        d[0] = d[1] = d[2] = gray;
      }
    }
  return diff;
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
  long differing = 0;
  const Image diff = diffImage(expected, actual, differing);
  const long allowed = static_cast<long>(kPixelFraction * expected.width * expected.height);
  if (differing > allowed) {
    const fs::path dir = kSource / "out" / "golden-diff";
    fs::create_directories((dir / name).parent_path());
    render::draw::writePng(actual, (dir / (name + "-actual.png")).string());
    render::draw::writePng(diff, (dir / (name + "-diff.png")).string());
    FAIL_CHECK(name << ": " << differing << " pixels differ by more than " << kChannelTolerance << " (at most "
                    << allowed << " may); see " << (dir / (name + "-actual.png")).string() << " and "
                    << (dir / (name + "-diff.png")).string());
  }
}

}  // namespace golden
