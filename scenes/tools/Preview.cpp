// A CPU ray-cast look at a loaded scene from each of its camera bookmarks (Lambert + exact
// ray-traced shadows of the scene's light, alpha masks honoured): lets one check a scene without a
// GPU.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "scene/Scene.h"

#ifdef SHADOWLAB_HAVE_STB_WRITE
extern "C" int stbi_write_png(char const* filename, int w, int h, int comp, const void* data,
                              int stride_in_bytes);
#endif

namespace sl::gen {

namespace {

struct Hit {
  float t = std::numeric_limits<float>::infinity();
  const MeshPrimitive* prim = nullptr;
  std::size_t tri = 0;
  float u = 0.0f, v = 0.0f;
};

class Tracer {
 public:
  explicit Tracer(const Scene& scene) : scene_(scene) {
    for (const MeshPrimitive& p : scene.primitives) {
      Aabb box;
      for (const glm::vec3& v : p.positions) box.extend(v);
      boxes_.push_back(box);
    }
  }

  /// Nearest hit beyond `tMin`, skipping texels an alpha mask cuts away.
  Hit trace(const glm::vec3& o, const glm::vec3& d, float tMin, bool anyHit) const {
    Hit best;
    glm::vec3 inv = 1.0f / d;
    for (std::size_t pi = 0; pi < scene_.primitives.size(); ++pi) {
      if (!hitsBox(boxes_[pi], o, inv, best.t)) continue;
      const MeshPrimitive& p = scene_.primitives[pi];
      for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
        const glm::vec3& a = p.positions[p.indices[t]];
        glm::vec3 e1 = p.positions[p.indices[t + 1]] - a, e2 = p.positions[p.indices[t + 2]] - a;
        glm::vec3 pv = glm::cross(d, e2);
        float det = glm::dot(e1, pv);
        if (std::abs(det) < 1e-14f) continue;
        float invDet = 1.0f / det;
        glm::vec3 tv = o - a;
        float u = glm::dot(tv, pv) * invDet;
        if (u < 0.0f || u > 1.0f) continue;
        glm::vec3 qv = glm::cross(tv, e1);
        float v = glm::dot(d, qv) * invDet;
        if (v < 0.0f || u + v > 1.0f) continue;
        float dist = glm::dot(e2, qv) * invDet;
        if (dist <= tMin || dist >= best.t) continue;
        Hit h{dist, &p, t, u, v};
        if (alpha(h) < cutoff(p)) continue;
        best = h;
        if (anyHit) return best;
      }
    }
    return best;
  }

  glm::vec4 baseColor(const Hit& h) const {
    const Material& m = scene_.materialOf(*h.prim);
    glm::vec4 c = m.baseColorFactor;
    if (m.baseColorTexture >= 0 && !h.prim->uvs.empty()) c *= texel(m.baseColorTexture, uvAt(h));
    return c;
  }

  glm::vec3 normal(const Hit& h) const {
    const MeshPrimitive& p = *h.prim;
    float w = 1.0f - h.u - h.v;
    return glm::normalize(w * p.normals[p.indices[h.tri]] + h.u * p.normals[p.indices[h.tri + 1]] +
                          h.v * p.normals[p.indices[h.tri + 2]]);
  }

 private:
  static bool hitsBox(const Aabb& b, const glm::vec3& o, const glm::vec3& inv, float tMax) {
    glm::vec3 t0 = (b.min - o) * inv, t1 = (b.max - o) * inv;
    glm::vec3 lo = glm::min(t0, t1), hi = glm::max(t0, t1);
    float enter = std::max({lo.x, lo.y, lo.z, 0.0f});
    float exit = std::min({hi.x, hi.y, hi.z, tMax});
    return enter <= exit * 1.0001f + 1e-5f;
  }

  float cutoff(const MeshPrimitive& p) const {
    const Material& m = scene_.materialOf(p);
    return m.alphaMode == AlphaMode::Mask ? m.alphaCutoff : -1.0f;
  }

  glm::vec2 uvAt(const Hit& h) const {
    const MeshPrimitive& p = *h.prim;
    float w = 1.0f - h.u - h.v;
    return w * p.uvs[p.indices[h.tri]] + h.u * p.uvs[p.indices[h.tri + 1]] +
           h.v * p.uvs[p.indices[h.tri + 2]];
  }

  float alpha(const Hit& h) const {
    const Material& m = scene_.materialOf(*h.prim);
    if (m.alphaMode != AlphaMode::Mask) return 1.0f;
    return baseColor(h).a;
  }

  glm::vec4 texel(int image, glm::vec2 uv) const {
    const SceneImage& img = scene_.images[std::size_t(image)];
    if (img.width <= 0) return glm::vec4(1.0f);
    float fu = uv.x - std::floor(uv.x), fv = uv.y - std::floor(uv.y);  // repeat
    int x = std::min(int(fu * float(img.width)), img.width - 1);
    int y = std::min(int(fv * float(img.height)), img.height - 1);
    const std::uint8_t* p =
        &img.rgba[(std::size_t(y) * std::size_t(img.width) + std::size_t(x)) * 4];
    return glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
  }

  const Scene& scene_;
  std::vector<Aabb> boxes_;
};

std::string fileSafe(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '_';
  return s;
}

}  // namespace

int writePreviews(const Scene& scene, const std::filesystem::path& dir) {
#ifndef SHADOWLAB_HAVE_STB_WRITE
  (void)scene;
  (void)dir;
  std::fprintf(stderr, "previews need stb (libstb-dev), which this build did not find\n");
  return 1;
#else
  const int width = 480, height = 270;
  Tracer tracer(scene);
  const Light light = scene.light ? *scene.light : Light{};
  for (const CameraBookmark& bookmark : scene.cameras) {
    const Camera& cam = bookmark.camera;
    glm::vec3 fw = cam.forward();
    glm::vec3 right = glm::normalize(glm::cross(fw, cam.up));
    glm::vec3 up = glm::cross(right, fw);
    float tanHalf = std::tan(glm::radians(cam.fovYDeg) * 0.5f);
    float aspect = float(width) / float(height);
    std::vector<std::uint8_t> rgb(std::size_t(width) * std::size_t(height) * 3);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        float sx = (2.0f * (float(x) + 0.5f) / float(width) - 1.0f) * tanHalf * aspect;
        float sy = (1.0f - 2.0f * (float(y) + 0.5f) / float(height)) * tanHalf;
        glm::vec3 d = glm::normalize(fw + sx * right + sy * up);
        // Clip like the camera's near/far planes (distances along the view axis).
        float axial = glm::dot(d, fw);
        Hit h = tracer.trace(cam.position, d, cam.nearM / axial, false);
        glm::vec3 color(0.62f, 0.75f, 0.90f);  // sky
        if (h.prim && h.t * axial <= cam.farM) {
          glm::vec3 p = cam.position + h.t * d;
          glm::vec3 n = tracer.normal(h);
          if (glm::dot(n, d) > 0.0f) n = -n;  // the side we see
          const glm::vec3 toLight = light.towardsLight(p);
          float lambert = std::max(glm::dot(n, toLight), 0.0f) * light.falloff(p);
          float lit = 0.0f;
          if (lambert > 0.0f) {
            glm::vec3 origin = p + n * (1e-4f * std::max(1.0f, h.t));
            const bool positional = light.type != LightType::Directional;
            Hit blocker =
                tracer.trace(origin, toLight, 0.0f, !positional);  // nearest if positional
            const float toLightM = glm::length(light.positionM - origin);
            lit = blocker.prim && (!positional || blocker.t < toLightM) ? 0.0f : 1.0f;
          }
          glm::vec3 base = glm::vec3(tracer.baseColor(h));
          color = base * (0.30f + 0.75f * lambert * lit);
        }
        color = glm::pow(glm::clamp(color, 0.0f, 1.0f), glm::vec3(1.0f / 1.3f));
        std::size_t at = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
        for (int c = 0; c < 3; ++c)
          rgb[at + std::size_t(c)] = std::uint8_t(std::lround(color[c] * 255.0f));
      }
    }
    std::filesystem::path out =
        dir / (fileSafe(scene.name) + "." + fileSafe(bookmark.name) + ".png");
    if (!stbi_write_png(out.string().c_str(), width, height, 3, rgb.data(), width * 3)) {
      std::fprintf(stderr, "could not write %s\n", out.string().c_str());
      return 1;
    }
    std::printf("  preview %s\n", out.string().c_str());
  }
  return 0;
#endif
}

}  // namespace sl::gen
