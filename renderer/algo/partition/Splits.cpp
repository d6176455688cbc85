// Split distances for z-partitioning: uniform, logarithmic (Lloyd et al. 2006, Fig. 9)
// and practical (lambda blend).
#include "Splits.h"

#include <cmath>
#include <stdexcept>

namespace sl::partition {

const char* splitSchemeName(SplitScheme s) {
  switch (s) {
    case SplitScheme::Uniform:
      return "uniform";
    case SplitScheme::Log:
      return "log";
    case SplitScheme::Practical:
      return "practical";
  }
  return "?";
}

std::optional<SplitScheme> parseSplitScheme(const std::string& name) {
  if (name == "uniform") return SplitScheme::Uniform;
  if (name == "log") return SplitScheme::Log;
  if (name == "practical") return SplitScheme::Practical;
  return std::nullopt;
}

std::vector<double> splitDistances(SplitScheme scheme, double n, double f, int k, double lambda) {
  if (!(n > 0.0) || !(f > n) || !std::isfinite(f))
    throw std::invalid_argument("splits: need 0 < near < far (finite)");
  if (k < 1 || k > 64) throw std::invalid_argument("splits: partitions must be in 1..64");
  if (!(lambda >= 0.0 && lambda <= 1.0))
    throw std::invalid_argument("splits: lambda must be in [0, 1]");
  std::vector<double> z(std::size_t(k) + 1);
  for (int i = 0; i <= k; ++i) {
    const double u = n + (f - n) * double(i) / k;
    const double l = n * std::pow(f / n, double(i) / k);
    z[std::size_t(i)] = scheme == SplitScheme::Uniform ? u
                        : scheme == SplitScheme::Log   ? l
                                                       : lambda * l + (1.0 - lambda) * u;
  }
  z.front() = n;  // exact ends whatever the rounding
  z.back() = f;
  return z;
}

}  // namespace sl::partition
