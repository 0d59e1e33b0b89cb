#include "render/draw/sample_resolve.h"

#include <cmath>
#include <cstring>

namespace render::draw {

namespace {

// llvmpipe resolves with Mesa's blitter shader (u_simple_shaders.c, util_make_fs_msaa_resolve):
// each sample converted to float (x · 1/255), summed in sample order, times 1/4, converted back
// (× 255, rounded to nearest even). Measured against llvmpipe on 20 frames of 40 blended polygons
// (73.7 million channels): every channel equal; an integer average rounding halves up differs on
// 22,000 of them, the ties (a sum of 4k + 2) that the float sum leaves a hair above or below.
struct ToFloat {
  float value[256];
  ToFloat() {
    for (int i = 0; i < 256; ++i) value[i] = static_cast<float>(i) * (1.0f / 255.0f);
  }
};

uint8_t resolveChannel(const ToFloat& f, unsigned a, unsigned b, unsigned c, unsigned d) {
  const unsigned sum = a + b + c + d;
  // away from a tie the float rounding cannot matter (it is 1e-5 off at most, the tie 0.25 away)
  if ((sum & 3) != 2) return static_cast<uint8_t>((sum + 1) >> 2);
  // volatile: each step rounded to float as the shader's are, whatever the compiler contracts
  volatile float s = f.value[a] + f.value[b];
  s = s + f.value[c];
  s = s + f.value[d];
  volatile float quarter = s * 0.25f;
  return static_cast<uint8_t>(std::lrintf(quarter * 255.0f));
}

}  // namespace

void resolveSamples(const std::array<const uint8_t*, 4>& samples, uint8_t* out, size_t bytes) {
  static const ToFloat toFloat;
  const uint8_t *p0 = samples[0], *p1 = samples[1], *p2 = samples[2], *p3 = samples[3];
  size_t i = 0;
  // most of a frame is inside shapes or background, where the four drawings agree: 8 channels a step
  for (; i + 8 <= bytes; i += 8) {
    uint64_t a, b, c, d;
    std::memcpy(&a, p0 + i, 8), std::memcpy(&b, p1 + i, 8), std::memcpy(&c, p2 + i, 8), std::memcpy(&d, p3 + i, 8);
    if (a == b && a == c && a == d) {
      std::memcpy(out + i, &a, 8);
      continue;
    }
    for (size_t k = i; k < i + 8; ++k) out[k] = resolveChannel(toFloat, p0[k], p1[k], p2[k], p3[k]);
  }
  for (; i < bytes; ++i) out[i] = resolveChannel(toFloat, p0[i], p1[i], p2[i], p3[i]);
}

void resolveTwoSamples(const uint8_t* a, const uint8_t* b, uint8_t* out, size_t bytes) {
  for (size_t i = 0; i < bytes; ++i) out[i] = static_cast<uint8_t>((a[i] + b[i] + 1u) >> 1);
}

}  // namespace render::draw
