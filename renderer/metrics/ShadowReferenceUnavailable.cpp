// ShadowReference in a build without Embree (SHADOWLAB_REFERENCE=OFF: the headless folder
// that travels to a GPU machine measures time only). Nothing can be constructed, so no
// member below ever runs on an object; each still answers honestly.
#include <stdexcept>

#include "metrics/ShadowReference.h"

namespace sl {

namespace {
constexpr const char* kReason =
    "this build has no ray-traced reference (built with SHADOWLAB_REFERENCE=OFF): timings only";
}

struct ShadowReference::Impl {};

bool ShadowReference::available() {
  return false;
}
const char* ShadowReference::unavailableReason() {
  return kReason;
}

ShadowReference::ShadowReference(const Scene&, float) {
  throw std::runtime_error(kReason);
}
ShadowReference::~ShadowReference() = default;
ShadowReference::ShadowReference(ShadowReference&&) noexcept = default;
ShadowReference& ShadowReference::operator=(ShadowReference&&) noexcept = default;

std::size_t ShadowReference::triangleCount() const {
  return 0;
}
std::size_t ShadowReference::alphaTestedTriangles() const {
  return 0;
}
float ShadowReference::normalOffsetM() const {
  return 0.0f;
}
float ShadowReference::rayTNearM() const {
  return 0.0f;
}
bool ShadowReference::isLit(const glm::vec3&, const glm::vec3&, const glm::vec3&) const {
  throw std::logic_error(kReason);
}
bool ShadowReference::isLit(const glm::vec3&, const glm::vec3&, const Light&) const {
  throw std::logic_error(kReason);
}
bool ShadowReference::isLitTowards(const glm::vec3&, const glm::vec3&, const Light&,
                                   const glm::vec3&) const {
  throw std::logic_error(kReason);
}
void ShadowReference::evaluate(std::span<const glm::vec4>, std::span<const glm::vec4>,
                               const glm::vec3&, std::vector<std::uint8_t>&) const {
  throw std::logic_error(kReason);
}
void ShadowReference::evaluate(std::span<const glm::vec4>, std::span<const glm::vec4>, const Light&,
                               std::vector<std::uint8_t>&) const {
  throw std::logic_error(kReason);
}
void ShadowReference::evaluateTowards(std::span<const glm::vec4>, std::span<const glm::vec4>,
                                      const Light&, const glm::vec3*,
                                      std::vector<std::uint8_t>&) const {
  throw std::logic_error(kReason);
}

}  // namespace sl
