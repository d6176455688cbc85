#include "core/ViewSide.h"

#include <cstdio>
#include <stdexcept>
#include <utility>

namespace sl {

int syncParams(ParamSet& dst, const ParamSet& src) {
  int changed = 0;
  for (const ParamDecl& d : src.decls()) {
    if (!dst.has(d.key)) continue;
    const double v = src.get(d.key);
    if (dst.get(d.key) == v) continue;
    if (!dst.set(d.key, v)) ++changed;  // same declarations: cannot fail
  }
  return changed;
}

namespace {
std::string knownTechniques() {
  std::string known;
  for (const TechniqueInfo& t : Renderer::techniques()) known += (known.empty() ? "" : ", ") + t.id;
  return known;
}
}  // namespace

ViewSide::ViewSide(std::string_view techniqueId) {
  if (auto e = setTechnique(techniqueId)) throw std::invalid_argument(*e);
}

std::optional<std::string> ViewSide::setTechnique(std::string_view id) {
  const TechniqueInfo* info = Renderer::findTechnique(id);
  if (!info)
    return "unknown technique '" + std::string(id) + "' (known: " + knownTechniques() + ")";
  if (info_ && techniqueId_ == id) return std::nullopt;
  info_ = info;
  techniqueId_ = info->id;
  (void)paramsOf(techniqueId_);
  hasFrame_ = false;  // the last frame was another technique's
  error_.reset();
  ++changes_;
  return std::nullopt;
}

const ParamSet& ViewSide::params() const {
  return params_.find(techniqueId_)->second;  // made by setTechnique
}

ParamSet& ViewSide::paramsOf(std::string_view id) {
  auto it = params_.find(id);
  if (it != params_.end()) return it->second;
  const TechniqueInfo* info = Renderer::findTechnique(id);
  if (!info) throw std::out_of_range("unknown technique '" + std::string(id) + "'");
  return params_.emplace(std::string(id), ParamSet(info->params)).first->second;
}

SideRequest ViewSide::takeRequest() {
  SideRequest r;
  r.techniqueId = techniqueId_;
  r.params = params();
  r.resetTemporal = std::exchange(resetPending_, false);
  r.publications = publications_;
  return r;
}

void ViewSide::setFrame(FrameStats stats, Publication publication) {
  stats_ = std::move(stats);
  publication_ = std::move(publication);
  hasFrame_ = true;
}

void ViewSide::setError(std::optional<double> pct, std::string unmeasured,
                        std::uint64_t viewRevision) {
  error_ = Error{pct, pct ? std::string() : std::move(unmeasured), viewRevision};
}

std::optional<ViewSide::Error> ViewSide::errorFor(std::uint64_t viewRevision) const {
  if (!error_ || error_->viewRevision != viewRevision) return std::nullopt;
  return error_;
}

std::string ViewSide::nonDefaultParams() const {
  std::string out;
  const ParamSet& ps = params();
  for (const ParamDecl& d : ps.decls())
    if (ps.get(d.key) != d.defaultValue)
      out += (out.empty() ? "" : " ") + d.key + "=" + ps.format(d.key);
  return out;
}

std::string sideCaption(std::string_view techniqueId, const FrameStats& stats,
                        std::optional<double> errorPct, std::string_view note,
                        std::string_view unmeasured) {
  static const std::string dot = "  \u00b7  ";
  const TechniqueInfo* info = Renderer::findTechnique(techniqueId);
  std::string s = info ? info->name : std::string(techniqueId);
  char buf[64];
  if (errorPct) {
    std::snprintf(buf, sizeof buf, "error %.3f %%", *errorPct);
    s += dot + buf;
  } else if (unmeasured.empty()) {
    s += dot + "error \u2014";
  } else {
    s += dot + "error n/a (" + std::string(unmeasured) + ")";
  }
  if (!note.empty()) s += dot + std::string(note);
  std::snprintf(buf, sizeof buf, "%.*f ms", stats.totalMs < 10 ? 2 : 1, stats.totalMs);
  return s + dot + buf;
}

}  // namespace sl
