#include "service/LiveReference.h"

#include <vector>

#include <QObject>

namespace sl::ui {

QString unmeasuredReason(const sl::ShadowErrorStats& stats) {
  return stats.covered == 0 ? QObject::tr("no covered pixel") : QString();
}

void LiveReference::start() {
  if (!worker_) worker_ = std::make_unique<sl::AsyncReference>(minIntervalS_, durationFactor_);
}

void LiveReference::cancel() {
  if (worker_) worker_->cancel();
  latest_.reset();
}

std::optional<sl::FinishedReference> LiveReference::takeFinished(std::string* failure) {
  if (!worker_) return std::nullopt;
  if (auto f = worker_->takeFailure(); f && failure) *failure = *f;
  auto done = worker_->takeFinished();
  if (!done) return std::nullopt;
  // The latest without its mask (a byte per pixel: not copied), the caller's with it.
  std::vector<std::uint8_t> mask = std::move(done->trace.referenceMask);
  latest_ = *done;
  done->trace.referenceMask = std::move(mask);
  return done;
}

bool LiveReference::wantsTrace(std::uint64_t viewRevision) const {
  return worker_ && worker_->wantsTrace(viewRevision);
}

void LiveReference::submit(sl::ReferenceJob job) {
  if (worker_) worker_->submit(std::move(job));
}

std::optional<LiveError> LiveReference::error(std::uint64_t viewRevision,
                                              std::uint64_t framesRendered) const {
  if (!latest_) return std::nullopt;
  LiveError e;
  e.errorPct = latest_->trace.stats.errorPct;
  e.unmeasured = unmeasuredReason(latest_->trace.stats);
  e.age =
      sl::referenceAge(*latest_, viewRevision, framesRendered, sl::AsyncReference::steadySeconds());
  return e;
}

}  // namespace sl::ui
