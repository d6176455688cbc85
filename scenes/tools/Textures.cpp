// Procedural textures of the scene generator (see Textures.h).
#include "Textures.h"

#include <algorithm>

namespace sl::gen {

namespace {

/// Cheap smooth value noise in [0, 1] for wood grain and leaf tints.
float hashNoise(int x, int y) {
  std::uint32_t h = std::uint32_t(x) * 374761393u + std::uint32_t(y) * 668265263u;
  h = (h ^ (h >> 13)) * 1274126177u;
  return float((h ^ (h >> 16)) & 0xFFFFu) / 65535.0f;
}

float valueNoise(float x, float y) {
  int ix = int(std::floor(x)), iy = int(std::floor(y));
  float fx = x - float(ix), fy = y - float(iy);
  fx = fx * fx * (3.0f - 2.0f * fx);
  fy = fy * fy * (3.0f - 2.0f * fy);
  float a = hashNoise(ix, iy), b = hashNoise(ix + 1, iy);
  float c = hashNoise(ix, iy + 1), d = hashNoise(ix + 1, iy + 1);
  return (a + (b - a) * fx) * (1.0f - fy) + (c + (d - c) * fx) * fy;
}

void put(std::vector<std::uint8_t>& img, int size, int x, int y, glm::vec3 rgb, bool opaque) {
  std::size_t at = (std::size_t(y) * std::size_t(size) + std::size_t(x)) * 4;
  rgb = glm::clamp(rgb, 0.0f, 1.0f);
  img[at + 0] = std::uint8_t(std::lround(rgb.r * 255.0f));
  img[at + 1] = std::uint8_t(std::lround(rgb.g * 255.0f));
  img[at + 2] = std::uint8_t(std::lround(rgb.b * 255.0f));
  img[at + 3] = opaque ? 255 : 0;
}

}  // namespace

std::vector<std::uint8_t> makePicketTexture(int size) {
  std::vector<std::uint8_t> img(std::size_t(size) * std::size_t(size) * 4, 0);
  const glm::vec3 paint(0.94f, 0.92f, 0.87f), rail(0.86f, 0.83f, 0.77f);
  for (int y = 0; y < size; ++y) {
    float v = (float(y) + 0.5f) / float(size);  // 0 at the top
    for (int x = 0; x < size; ++x) {
      float u = (float(x) + 0.5f) / float(size);
      float cell = u * 4.0f - std::floor(u * 4.0f);  // 4 pickets per metre
      float across = std::abs(cell - 0.5f);          // 0 at a picket's centre line
      bool picket = across < 0.35f && v > 0.03f + 0.25f * across && v < 0.97f;
      bool isRail = (v > 0.24f && v < 0.31f) || (v > 0.70f && v < 0.77f);
      float grain = 0.9f + 0.1f * valueNoise(u * 90.0f, v * 6.0f);
      if (isRail) {
        put(img, size, x, y, rail * grain, true);
      } else {
        put(img, size, x, y, paint * grain, picket);
      }
    }
  }
  return img;
}

std::vector<std::uint8_t> makeLeafTexture(int size, Rng& rng) {
  std::vector<std::uint8_t> img(std::size_t(size) * std::size_t(size) * 4, 0);
  // Transparent texels carry a dark green so that filtering at the edges stays green.
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) put(img, size, x, y, glm::vec3(0.18f, 0.32f, 0.12f), false);
  struct Leaf {
    glm::vec2 center, axis;
    float length, width;
    glm::vec3 color;
  };
  std::vector<Leaf> leaves;
  for (int i = 0; i < 16; ++i) {
    float angle = rng.uniform(0.0f, 6.2831853f);
    glm::vec3 dark(0.20f, 0.42f, 0.14f), light(0.45f, 0.63f, 0.22f);
    leaves.push_back({glm::vec2(rng.uniform(0.2f, 0.8f), rng.uniform(0.2f, 0.8f)),
                      glm::vec2(std::cos(angle), std::sin(angle)), rng.uniform(0.16f, 0.26f),
                      rng.uniform(0.35f, 0.5f), glm::mix(dark, light, rng.uniform())});
  }
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      glm::vec2 p((float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size));
      for (const Leaf& leaf : leaves) {  // later leaves lie on top
        glm::vec2 d = p - leaf.center;
        float a = glm::dot(d, leaf.axis) / leaf.length;  // along, -1..1
        float b = (leaf.axis.x * d.y - leaf.axis.y * d.x) / (leaf.length * leaf.width);  // across
        if (std::abs(a) < 1.0f && std::abs(b) < (1.0f - a * a)) {
          float vein = std::abs(b) < 0.06f ? 0.8f : 1.0f;
          float tint = 0.9f + 0.2f * valueNoise(p.x * 40.0f, p.y * 40.0f);
          put(img, size, x, y, leaf.color * vein * tint, true);
        }
      }
    }
  }
  return img;
}

}  // namespace sl::gen
