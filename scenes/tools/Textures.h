// Procedural RGBA8 textures of the generator: a picket-fence tile and a cluster of leaves,
// both with binary alpha for alpha-MASK materials (where shadow maps alias worst).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace sl::gen {

/// A small deterministic generator (SplitMix32 style), the same on every platform.
class Rng {
 public:
  explicit Rng(std::uint32_t seed) : state_(seed) {}
  std::uint32_t next() {
    std::uint32_t z = (state_ += 0x9E3779B9u);
    z = (z ^ (z >> 16)) * 0x85EBCA6Bu;
    z = (z ^ (z >> 13)) * 0xC2B2AE35u;
    return z ^ (z >> 16);
  }
  float uniform() { return float(next() >> 8) / 16777216.0f; }  ///< [0, 1)
  float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
  glm::vec3 inBall() {
    for (;;) {
      glm::vec3 p(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      if (glm::dot(p, p) <= 1.0f) return p;
    }
  }
  glm::vec3 onSphere() {
    for (;;) {
      glm::vec3 p = inBall();
      float len = glm::length(p);
      if (len > 1e-3f) return p / len;
    }
  }

 private:
  std::uint32_t state_;
};

inline constexpr int kPicketTextureSize = 128;
inline constexpr int kLeafTextureSize = 128;

/// One metre of picket fence (u across, v down from the top): four pointed whitewashed
/// pickets with gaps, two rails. Alpha 0 in the gaps.
std::vector<std::uint8_t> makePicketTexture(int size);
/// A cluster of pointed leaves in several greens on a transparent background.
std::vector<std::uint8_t> makeLeafTexture(int size, Rng& rng);

}  // namespace sl::gen
