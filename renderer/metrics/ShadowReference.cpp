// Exact hard shadows with Embree 3: one triangle geometry per scene primitive, an occlusion
// filter for alpha-masked materials, occlusion rays in streams on every hardware thread.
#include "metrics/ShadowReference.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include <embree3/rtcore.h>

#include "metrics/ErrorMetrics.h"

namespace sl {

namespace {

/// Alpha test of one Mask primitive, called from Embree's occlusion filter.
struct AlphaMask {
  std::vector<std::uint32_t> indices;  ///< 3 per triangle
  std::vector<glm::vec2> uvs;          ///< TEXCOORD_0 per vertex; empty: uv (0, 0)
  int width = 0, height = 0;           ///< texture size; 0: no texture (alpha 1)
  std::vector<std::uint8_t> alpha;     ///< texture alpha, row 0 = v 0
  float factorAlpha = 1.0f;            ///< baseColorFactor.a
  float cutoff = 0.5f;

  float texel(int x, int y) const { return alpha[std::size_t(y) * width + x] * (1.0f / 255.0f); }

  /// Texture alpha at uv: bilinear between texel centres (GL_LINEAR), REPEAT wrap.
  float sampleTexture(glm::vec2 uv) const {
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = glm::vec2(0.0f);
    float x = uv.x * width - 0.5f, y = uv.y * height - 0.5f;
    x -= width * std::floor(x / width);  // now in [0, width]
    y -= height * std::floor(y / height);
    const float fx0 = std::floor(x), fy0 = std::floor(y);
    const float fx = x - fx0, fy = y - fy0;
    const int x0 = static_cast<int>(fx0) % width, y0 = static_cast<int>(fy0) % height;
    const int x1 = (x0 + 1) % width, y1 = (y0 + 1) % height;
    const float top = texel(x0, y0) + fx * (texel(x1, y0) - texel(x0, y0));
    const float bottom = texel(x0, y1) + fx * (texel(x1, y1) - texel(x0, y1));
    return top + fy * (bottom - top);
  }

  /// Alpha at barycentrics (u, v) of triangle `prim` (Embree: p = (1-u-v) p0 + u p1 + v p2).
  float alphaAt(unsigned prim, float u, float v) const {
    float a = factorAlpha;
    if (width > 0) {
      glm::vec2 uv(0.0f);
      if (!uvs.empty()) {
        const std::uint32_t* t = indices.data() + 3 * std::size_t(prim);
        uv = (1.0f - u - v) * uvs[t[0]] + u * uvs[t[1]] + v * uvs[t[2]];
      }
      a *= sampleTexture(uv);
    }
    return a;
  }
};

void alphaOcclusionFilter(const RTCFilterFunctionNArguments* args) {
  const auto* mask = static_cast<const AlphaMask*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
    const float u = RTCHitN_u(args->hit, args->N, i);
    const float v = RTCHitN_v(args->hit, args->N, i);
    if (mask->alphaAt(prim, u, v) < mask->cutoff) args->valid[i] = 0;  // glTF: alpha < cutoff
  }
}

const char* embreeErrorName(RTCError e) {
  switch (e) {
    case RTC_ERROR_NONE:
      return "no error";
    case RTC_ERROR_UNKNOWN:
      return "unknown error";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
  }
  return "unrecognised error";
}

const Material& materialOf(const Scene& scene, const MeshPrimitive& prim) {
  static const Material kDefault{};
  if (prim.material >= 0 && std::size_t(prim.material) < scene.materials.size())
    return scene.materials[std::size_t(prim.material)];
  return kDefault;
}

/// The occlusion ray of isLit() (both paths build it here so they agree bit for bit).
/// Returns false when the point faces away from the light or lies outside its cone or
/// range. Directional: towards `light`'s unit direction `dirTowards`, to infinity; spot and
/// point: towards the light's position, ending tnear short of it.
/// A few float spacings of p's largest coordinate: Embree intersects in float, so a hit
/// distance errs by about one spacing there (4 mm at 5e4 m), and a ray starting closer to
/// its own surface than that can hit it.
float precisionOffset(const glm::vec3& p) {
  const float a = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return 4.0f * (std::nextafter(a, std::numeric_limits<float>::infinity()) - a);
}

bool makeShadowRay(const glm::vec3& p, const glm::vec3& n, const Light& light,
                   const glm::vec3& dirTowards, float sceneOffset, float sceneTnear, RTCRay& ray) {
  // The scene's offset (a share of its size) unless float precision at p needs more: an
  // offset scaled by the distance from the origin moved every shadow border of a scene
  // placed 5e4 m away by 0.7 m (2.1 % error instead of 0.16 %).
  const float normalOffset = std::max(sceneOffset, precisionOffset(p));
  const float tnear = std::max(sceneTnear, normalOffset);
  const bool positional = light.type != LightType::Directional;
  const glm::vec3 lightDir = positional ? light.towardsLight(p) : dirTowards;
  const float nDotL = glm::dot(n, lightDir);
  if (!(nDotL > 0.0f)) return false;  // facing away (or NaN)
  if (positional && !light.illuminates(p)) return false;
  const glm::vec3 origin = p + normalOffset * glm::normalize(n);
  glm::vec3 dir = lightDir;
  float tfar = std::numeric_limits<float>::infinity();
  if (positional) {
    const glm::vec3 toLight = light.positionM - origin;
    const float dist = glm::length(toLight);
    if (!(dist > 2.0f * tnear)) {  // at the light: nothing can lie between (tfar < tnear)
      ray.tnear = tnear;
      ray.tfar = 0.0f;
      return true;
    }
    dir = toLight / dist;
    tfar = dist - tnear;
  }
  ray.org_x = origin.x, ray.org_y = origin.y, ray.org_z = origin.z;
  ray.dir_x = dir.x, ray.dir_y = dir.y, ray.dir_z = dir.z;
  ray.tnear = tnear;
  ray.tfar = tfar;
  ray.time = 0.0f;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
  return true;
}

/// Unit direction towards the light, or nothing when zero / not finite.
std::optional<glm::vec3> unitLightDir(const glm::vec3& towardsLight) {
  const float len = glm::length(towardsLight);
  if (!(len > 0.0f) || !std::isfinite(len)) return std::nullopt;
  return towardsLight / len;
}

}  // namespace

struct ShadowReference::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<std::unique_ptr<AlphaMask>> masks;  ///< geometry user data (stable addresses)
  std::size_t triangles = 0;
  std::size_t alphaTriangles = 0;
  float normalOffset = 0.0f;
  float tnear = 0.0f;
  std::mutex errorMutex;
  std::string lastError;  ///< from Embree's error callback

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  /// Throws with Embree's error. rtcGetDeviceError() clears the code, so callers that
  /// already read it pass it in.
  [[noreturn]] void fail(const std::string& what, std::optional<RTCError> code = std::nullopt) {
    if (!code) code = rtcGetDeviceError(device);  // device may be null: thread-local error
    std::string detail;
    {
      std::lock_guard lock(errorMutex);
      detail = lastError;
    }
    std::string msg = "ShadowReference: " + what + " failed (Embree: " + embreeErrorName(*code);
    if (!detail.empty()) msg += ": " + detail;
    throw std::runtime_error(msg + ")");
  }

  void check(const std::string& what) {
    const RTCError code = rtcGetDeviceError(device);
    if (code != RTC_ERROR_NONE) fail(what, code);
  }

  void addPrimitive(const Scene& s, const MeshPrimitive& prim, std::size_t primIndex);
};

void ShadowReference::Impl::addPrimitive(const Scene& s, const MeshPrimitive& prim,
                                         std::size_t primIndex) {
  const std::string label =
      "primitive " + std::to_string(primIndex) + (prim.name.empty() ? "" : " '" + prim.name + "'");
  std::vector<std::uint32_t> indices = prim.indices;
  if (indices.empty() && prim.positions.size() % 3 == 0) {  // non-indexed triangle list
    indices.resize(prim.positions.size());
    for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = std::uint32_t(i);
  }
  indices.resize(indices.size() - indices.size() % 3);
  if (indices.empty() || prim.positions.empty()) return;
  for (std::uint32_t i : indices)
    if (i >= prim.positions.size())
      throw std::runtime_error("ShadowReference: " + label + " has index " + std::to_string(i) +
                               " but only " + std::to_string(prim.positions.size()) + " vertices");

  // Alpha test: Mask materials only (Blend casts opaque shadows, see the header).
  const Material& mat = materialOf(s, prim);
  std::unique_ptr<AlphaMask> mask;
  if (mat.alphaMode == AlphaMode::Mask) {
    mask = std::make_unique<AlphaMask>();
    mask->factorAlpha = mat.baseColorFactor.a;
    mask->cutoff = mat.alphaCutoff;
    const bool hasTexture =
        mat.baseColorTexture >= 0 && std::size_t(mat.baseColorTexture) < s.images.size();
    std::uint8_t minAlpha = 255;
    if (hasTexture) {
      const SceneImage& img = s.images[std::size_t(mat.baseColorTexture)];
      const std::size_t n =
          std::size_t(std::max(img.width, 0)) * std::size_t(std::max(img.height, 0));
      if (n > 0 && img.rgba.size() == n * 4) {
        mask->width = img.width;
        mask->height = img.height;
        mask->alpha.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
          mask->alpha[i] = img.rgba[4 * i + 3];
          minAlpha = std::min(minAlpha, mask->alpha[i]);
        }
      }
    }
    if (mask->factorAlpha < mask->cutoff) return;  // alpha <= factor < cutoff: never casts
    if (mask->factorAlpha * (minAlpha / 255.0f) >= mask->cutoff) {
      mask.reset();  // never below the cutoff: opaque, no filter needed
    } else {
      mask->indices = indices;
      if (prim.uvs.size() == prim.positions.size()) mask->uvs = prim.uvs;
    }
  }

  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  if (!geom) fail("creating the geometry of " + label);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               prim.positions.size()));
  auto* tris = static_cast<std::uint32_t*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(std::uint32_t), indices.size() / 3));
  if (!vertices || !tris) {
    rtcReleaseGeometry(geom);
    fail("allocating the buffers of " + label);
  }
  for (std::size_t i = 0; i < prim.positions.size(); ++i) {
    vertices[3 * i + 0] = prim.positions[i].x;
    vertices[3 * i + 1] = prim.positions[i].y;
    vertices[3 * i + 2] = prim.positions[i].z;
  }
  std::copy(indices.begin(), indices.end(), tris);
  if (mask) {
    rtcSetGeometryUserData(geom, mask.get());
    rtcSetGeometryOccludedFilterFunction(geom, alphaOcclusionFilter);
    alphaTriangles += indices.size() / 3;
    masks.push_back(std::move(mask));
  }
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  triangles += indices.size() / 3;
  check("adding " + label);
}

ShadowReference::ShadowReference(const Scene& scene, float normalOffsetFraction)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.device = rtcNewDevice(nullptr);
  if (!m.device) m.fail("creating the device");
  rtcSetDeviceErrorFunction(
      m.device,
      [](void* user, RTCError, const char* str) {
        auto* impl = static_cast<Impl*>(user);
        std::lock_guard lock(impl->errorMutex);
        impl->lastError = str ? str : "";
      },
      &m);
  m.scene = rtcNewScene(m.device);
  if (!m.scene) m.fail("creating the scene");
  rtcSetSceneBuildQuality(m.scene, RTC_BUILD_QUALITY_HIGH);
  rtcSetSceneFlags(m.scene, RTC_SCENE_FLAG_ROBUST);  // no cracks between adjacent triangles
  m.check("configuring the scene");

  // Scale of the scene for the self-shadowing offset: the bounds diagonal (the precision
  // of coordinates far from the origin is added per ray: makeShadowRay).
  Aabb bounds;
  for (const MeshPrimitive& prim : scene.primitives)
    for (const glm::vec3& p : prim.positions)
      if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) bounds.extend(p);
  float scale = 0.0f;
  if (bounds.valid()) {
    scale = glm::length(bounds.size());
  }
  m.normalOffset = std::max(normalOffsetFraction * scale, 1e-6f);
  m.tnear = m.normalOffset;

  for (std::size_t i = 0; i < scene.primitives.size(); ++i)
    m.addPrimitive(scene, scene.primitives[i], i);
  rtcCommitScene(m.scene);
  m.check("building the BVH of " + std::to_string(m.triangles) + " triangles");
}

bool ShadowReference::available() {
  return true;
}
const char* ShadowReference::unavailableReason() {
  return "";
}

ShadowReference::~ShadowReference() = default;
ShadowReference::ShadowReference(ShadowReference&&) noexcept = default;
ShadowReference& ShadowReference::operator=(ShadowReference&&) noexcept = default;

std::size_t ShadowReference::triangleCount() const {
  return impl_->triangles;
}
std::size_t ShadowReference::alphaTestedTriangles() const {
  return impl_->alphaTriangles;
}
float ShadowReference::normalOffsetM() const {
  return impl_->normalOffset;
}
float ShadowReference::rayTNearM() const {
  return impl_->tnear;
}

bool ShadowReference::isLit(const glm::vec3& p, const glm::vec3& n,
                            const glm::vec3& towardsLight) const {
  const auto dir = unitLightDir(towardsLight);
  if (!dir) return false;
  return isLitTowards(p, n, Light::directionalFromTowards(*dir), *dir);
}

bool ShadowReference::isLit(const glm::vec3& p, const glm::vec3& n, const Light& light) const {
  if (light.validate()) return false;
  return isLitTowards(p, n, light, light.directionalTowards());
}

bool ShadowReference::isLitTowards(const glm::vec3& p, const glm::vec3& n, const Light& light,
                                   const glm::vec3& dirTowards) const {
  RTCRay ray;
  if (!makeShadowRay(p, n, light, dirTowards, impl_->normalOffset, impl_->tnear, ray)) return false;
  if (ray.tfar < ray.tnear) return true;  // at the light itself
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(impl_->scene, &context, &ray);
  return ray.tfar >= 0.0f;  // Embree sets tfar = -inf when occluded
}

void ShadowReference::evaluate(std::span<const glm::vec4> positions,
                               std::span<const glm::vec4> normals, const glm::vec3& towardsLight,
                               std::vector<std::uint8_t>& out) const {
  const auto dir = unitLightDir(towardsLight);
  evaluateTowards(positions, normals, dir ? Light::directionalFromTowards(*dir) : Light{},
                  dir ? &*dir : nullptr, out);
}

void ShadowReference::evaluate(std::span<const glm::vec4> positions,
                               std::span<const glm::vec4> normals, const Light& light,
                               std::vector<std::uint8_t>& out) const {
  const glm::vec3 dir = light.directionalTowards();
  evaluateTowards(positions, normals, light, light.validate() ? nullptr : &dir, out);
}

void ShadowReference::evaluateTowards(std::span<const glm::vec4> positions,
                                      std::span<const glm::vec4> normals, const Light& light,
                                      const glm::vec3* dir, std::vector<std::uint8_t>& out) const {
  if (positions.size() != normals.size())
    throw std::invalid_argument("ShadowReference::evaluate: " + std::to_string(positions.size()) +
                                " positions but " + std::to_string(normals.size()) + " normals");
  const std::size_t count = positions.size();
  out.assign(count, kMaskUncovered);

  constexpr std::size_t kChunk = 4096;  // pixels per work item (and per ray stream)
  const std::size_t chunks = (count + kChunk - 1) / kChunk;
  std::atomic<std::size_t> nextChunk{0};
  const Impl& m = *impl_;

  auto work = [&]() {
    std::vector<RTCRay> rays(kChunk);
    std::vector<std::uint32_t> pixel(kChunk);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // parallel rays, neighbouring origins
    for (std::size_t c = nextChunk++; c < chunks; c = nextChunk++) {
      const std::size_t begin = c * kChunk, end = std::min(count, begin + kChunk);
      unsigned streamed = 0;
      for (std::size_t i = begin; i < end; ++i) {
        if (!(positions[i].w > 0.0f)) continue;  // stays kMaskUncovered
        out[i] = kMaskShadowed;
        if (dir && makeShadowRay(glm::vec3(positions[i]), glm::vec3(normals[i]), light, *dir,
                                 m.normalOffset, m.tnear, rays[streamed])) {
          if (rays[streamed].tfar < rays[streamed].tnear)
            out[i] = kMaskLit;  // at the light itself
          else
            pixel[streamed++] = std::uint32_t(i - begin);
        }
      }
      if (streamed == 0) continue;
      rtcOccluded1M(m.scene, &context, rays.data(), streamed, sizeof(RTCRay));
      for (unsigned k = 0; k < streamed; ++k)
        out[begin + pixel[k]] = rays[k].tfar >= 0.0f ? kMaskLit : kMaskShadowed;
    }
  };

  const unsigned threads =
      unsigned(std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()), chunks));
  if (threads <= 1) {
    work();
    return;
  }
  std::exception_ptr error;
  std::mutex errorMutex;
  auto guardedWork = [&]() {
    try {
      work();
    } catch (...) {
      std::lock_guard lock(errorMutex);
      if (!error) error = std::current_exception();
      nextChunk = chunks;  // stop the others early
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(guardedWork);
  guardedWork();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace sl
