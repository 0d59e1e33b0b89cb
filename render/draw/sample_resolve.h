// The four samples of a pixel averaged as llvmpipe's multisample resolve averages them, to the bit:
// GlContext draws a frame four times, each shifted to one of the four sample positions, and this
// turns the four drawings into the frame that 4× multisampling and a resolving blit would give.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace render::draw {

// the 4-sample pattern of llvmpipe (Direct3D's standard one), in pixels from a pixel's lower-left
// corner, as glGetMultisamplefv(GL_SAMPLE_POSITION) reports it
constexpr std::array<std::array<float, 2>, 4> kSamplePositions{
    {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}}};

// the 2-sample pattern (Direct3D's standard one), in the same coordinates: a cheaper edge, measured
// against the four in rigidreel_bench --antialiasing
constexpr std::array<std::array<float, 2>, 2> kTwoSamplePositions{{{0.75f, 0.25f}, {0.25f, 0.75f}}};

// out[i] = the resolve of samples[0][i] .. samples[3][i], for `bytes` 8-bit channels; `out` may be
// samples[0]
void resolveSamples(const std::array<const uint8_t*, 4>& samples, uint8_t* out, size_t bytes);
// out[i] = the mean of a[i] and b[i], halves rounded up; `out` may be a
void resolveTwoSamples(const uint8_t* a, const uint8_t* b, uint8_t* out, size_t bytes);

}  // namespace render::draw
