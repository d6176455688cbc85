// The storage-factor scheme of a technique's frame (StorageScheme.h).
#include "measure/StorageScheme.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sl::measure {

bool StorageInputs::operator==(const StorageInputs& o) const {
  const auto& a = view;
  const auto& b = o.view;
  const auto& s = settings;
  const auto& t = o.settings;
  return a.forward == b.forward && a.up == b.up && a.nearM == b.nearM && a.farM == b.farM &&
         a.fovYRad == b.fovYRad && a.aspect == b.aspect && towardsLight == o.towardsLight &&
         s.scheme == t.scheme && s.eta == t.eta && s.partitions == t.partitions &&
         s.split == t.split && s.lambda == t.lambda && s.partitionWarp == t.partitionWarp &&
         grid == o.grid;
}

void schemeFromDeclarations(const sl::TechniqueInfo* info, const FrameValue& param,
                            const FrameValue& published, StorageInputs& out) {
  using sl::partition::Scheme;
  sl::partition::SchemeSettings s;
  const std::string id = info ? info->id : std::string("?");
  auto declared = [&](const std::string& key) -> const sl::ParamDecl* {
    if (!info) return nullptr;
    for (const sl::ParamDecl& d : info->params)
      if (d.key == key) return &d;
    return nullptr;
  };
  const std::optional<double> k = declared("partitions") ? param("partitions") : std::nullopt;
  const bool etaIsParam = declared("warp.eta") != nullptr;
  // A warp that follows from other parameters (tsm's focus) publishes the eta it used.
  const std::optional<double> eta = etaIsParam ? param("warp.eta")
                                    : info && info->findPublication("warp.eta")
                                        ? published("warp.eta")
                                        : std::nullopt;
  char buf[160];
  if (k) {
    s.scheme = Scheme::Cascades;
    s.partitions = std::max(1, int(std::lround(*k)));
    if (const sl::ParamDecl* d = declared("split"))
      if (auto v = param("split"); v && *v >= 0 && std::size_t(*v) < d->enumNames.size())
        if (auto split = sl::partition::parseSplitScheme(d->enumNames[std::size_t(*v)]))
          s.split = *split;
    if (declared("split.lambda"))
      if (auto v = param("split.lambda")) s.lambda = *v;
    if (declared("partition.warp"))
      if (auto v = param("partition.warp")) s.partitionWarp = *v != 0.0;
    std::snprintf(buf, sizeof buf, "cascades k=%d, %s split%s (%s)", s.partitions,
                  sl::partition::splitSchemeName(s.split), s.partitionWarp ? " + LiSPSM" : "",
                  id.c_str());
    out.eta.reset();
  } else if (info && info->findPublication("faces.front")) {  // face partitions (§5.1)
    // face.zsplits > 1: each log-split slice face-partitioned (the combined scheme).
    const std::optional<double> slices =
        declared("face.zsplits") ? param("face.zsplits") : std::nullopt;
    s.partitions = slices ? std::max(1, int(std::lround(*slices))) : 1;
    s.scheme = s.partitions > 1 ? Scheme::FaceCascades : Scheme::Face;
    s.split = sl::partition::SplitScheme::Log;
    if (s.partitions > 1)
      std::snprintf(buf, sizeof buf,
                    "face partitions of %d log-split slices, LiSPSM per face (%s%s)", s.partitions,
                    id.c_str(), eta && *eta != 0.0 ? ": analysed at eta 0" : "");
    else
      std::snprintf(buf, sizeof buf, "face partitions, LiSPSM per face (%s%s)", id.c_str(),
                    eta && *eta != 0.0 ? ": analysed at eta 0" : "");
    out.eta.reset();
  } else if (eta) {
    s.scheme = Scheme::Eta;
    s.eta = std::clamp(*eta, -1.0, 1.0);
    const std::optional<double> psmMethod =
        declared("psm.method") ? param("psm.method") : std::nullopt;
    if (psmMethod && *psmMethod == 0.0)  // Stamminger and Drettakis' post-perspective map
      std::snprintf(buf, sizeof buf,
                    "one warp, eta %.3g (%s: Lloyd et al.'s stand-in; its post-perspective map "
                    "is not analysed)",
                    s.eta, id.c_str());
    else if (etaIsParam)
      std::snprintf(buf, sizeof buf, "one warp, eta %.3g (%s)", s.eta, id.c_str());
    else
      std::snprintf(buf, sizeof buf, "one warp, eta %.3g (%s: the eta of its warp at this light%s)",
                    s.eta, id.c_str(), s.eta <= -1.0 ? ", uniform" : "");
    out.eta = s.eta;
  } else {
    s.scheme = Scheme::Uniform;
    std::snprintf(buf, sizeof buf, "uniform (%s%s)", id.c_str(),
                  info && info->unanalysedWarp ? ": its warp is not analysed" : "");
    out.eta = -1.0;
  }
  out.settings = s;
  out.schemeLabel = buf;
}

bool analysesScheme(const sl::TechniqueInfo& info) {
  if (std::find(info.lights.begin(), info.lights.end(), sl::LightType::Directional) ==
      info.lights.end())
    return false;
  const bool declared = std::any_of(info.params.begin(), info.params.end(), [](const auto& d) {
    return d.key == "partitions" || d.key == "warp.eta";
  });
  return info.baseline || declared || info.findPublication("warp.eta") ||
         info.findPublication("faces.front");
}

}  // namespace sl::measure
