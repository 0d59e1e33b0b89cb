// A hash of numbers' raw bits (FNV-1a, byte by byte): equal hashes of two runs' states mean
// bit-identical runs, which the pinned-hash tests and golden records rely on (2D and 3D alike).
#pragma once

#include <cstring>

namespace sim::core {

class BitHash {
 public:
  void mix(double value) {
    unsigned long long bits;
    std::memcpy(&bits, &value, sizeof bits);
    for (int k = 0; k < 8; ++k) {
      h_ ^= (bits >> (8 * k)) & 0xffu;
      h_ *= kPrime;
    }
  }
  unsigned long long value() const { return h_; }

 private:
  static constexpr unsigned long long kOffset = 1469598103934665603ull;
  static constexpr unsigned long long kPrime = 1099511628211ull;
  unsigned long long h_ = kOffset;
};

}  // namespace sim::core
