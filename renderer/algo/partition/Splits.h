// Split distances for z-partitioning (cascaded shadow maps): uniform, logarithmic (the
// self-similar split z_i = n (f/n)^(i/k) of Lloyd et al., EGSR 2006, §5.2, Fig. 9) and
// the "practical" lambda blend of the two (Zhang et al. 2006, parallel-split shadow maps).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace sl::partition {

enum class SplitScheme { Uniform, Log, Practical };

const char* splitSchemeName(SplitScheme s);
std::optional<SplitScheme> parseSplitScheme(const std::string& name);

/// The practical split's blend when nothing sets it (split.lambda's default; the storage
/// command's --lambda): halfway between logarithmic and uniform.
inline constexpr double kDefaultSplitLambda = 0.5;

/// The k + 1 distances n = z_0 < z_1 < ... < z_k = f. `lambda` in [0, 1] blends practical
/// splits: lambda * log + (1 - lambda) * uniform. Throws std::invalid_argument for
/// 0 < n < f not holding, k outside 1..64 or lambda outside [0, 1].
std::vector<double> splitDistances(SplitScheme scheme, double nearM, double farM, int k,
                                   double lambda = kDefaultSplitLambda);

}  // namespace sl::partition
