// The view's adaptive internal resolution (see AdaptiveResolution.h).
#include "algo/AdaptiveResolution.h"

#include <algorithm>
#include <cmath>

namespace sl {

bool AdaptiveResolution::onFrame(double frameMs, double budgetMs) {
  if (!(frameMs >= 0.0) || !(budgetMs > 0.0)) return false;
  const int before = divisor_;
  if (frameMs > budgetMs) {
    // Cost ~ pixels ~ 1 / divisor²: the divisor that would fit, as the next power of two.
    const double needed = double(divisor_) * std::sqrt(frameMs / budgetMs);
    int d = divisor_ * 2;
    while (d < kMaxDivisor && double(d) < needed) d *= 2;
    divisor_ = std::min(d, kMaxDivisor);
    if (divisor_ != before) dropFrameMs_ = frameMs;
  } else if (divisor_ > 1 && 4.0 * frameMs < kClimbShare * budgetMs) {
    divisor_ /= 2;
  }
  return divisor_ != before;
}

void AdaptiveResolution::reset() {
  divisor_ = 1;
  dropFrameMs_ = 0.0;
}

int AdaptiveResolution::scaled(int px, int divisor) {
  return std::max(1, px / std::max(1, divisor));
}

}  // namespace sl
