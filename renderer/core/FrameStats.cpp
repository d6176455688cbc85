#include "FrameStats.h"

namespace sl {

std::uint64_t MemoryStats::texels() const {
  std::uint64_t t = 0;
  for (const ResourceInfo& r : resources)
    if (!r.debugView) t += r.texels;
  return t;
}

std::uint64_t MemoryStats::bytes() const {
  std::uint64_t b = 0;
  for (const ResourceInfo& r : resources)
    if (!r.debugView) b += r.bytes;
  return b;
}

std::uint64_t MemoryStats::debugViewBytes() const {
  std::uint64_t b = 0;
  for (const ResourceInfo& r : resources)
    if (r.debugView) b += r.bytes;
  return b;
}

void MemoryStats::addDebugView(std::string name, std::string format, int width, int height,
                               int layers, int bytesPerTexel) {
  add(std::move(name), std::move(format), width, height, layers, bytesPerTexel);
  resources.back().debugView = true;
}

void MemoryStats::add(std::string name, std::string format, int width, int height, int layers,
                      int bytesPerTexel) {
  ResourceInfo r{std::move(name), std::move(format), width, height, layers, 0, 0};
  r.texels = std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(layers);
  r.bytes = r.texels * std::uint64_t(bytesPerTexel);
  resources.push_back(std::move(r));
}

double FrameStats::passMs(const std::string& name) const {
  for (const PassTiming& p : passes)
    if (p.name == name) return p.ms;
  return 0.0;
}

std::vector<float> tileTimingCurve(const std::vector<PassTiming>& sequence,
                                   const std::string& depthPass, const std::string& applyPass) {
  std::vector<float> out;
  double depthMs = 0.0;
  for (const PassTiming& p : sequence) {
    if (p.name == depthPass) {
      depthMs += p.ms;
    } else if (p.name == applyPass) {
      out.push_back(float(depthMs));
      out.push_back(float(p.ms));
      depthMs = 0.0;
    }
  }
  return out;
}

}  // namespace sl
