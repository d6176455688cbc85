// The split view's equal-memory match, as plain C++: the value of a technique's memory knob
// (a parameter its memory grows with, sl::memoryKnob) whose bytes come closest to a budget
// from below, found with as few measured frames as a search over the knob's value grid allows.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace sl {

/// The knob's bytes at a value (one measured frame), or nothing when the technique refuses
/// that value (e.g. a pool smaller than its coarsest level), with the reason in `problem`.
using BytesAtValue =
    std::function<std::optional<std::uint64_t>(long long value, std::string& problem)>;

struct MemoryMatchResult {
  long long value = 0;        ///< the value chosen
  std::uint64_t bytes = 0;    ///< its bytes (valid when ok())
  bool belowMinimum = false;  ///< even the smallest accepted value spends more than the budget
  int evaluations = 0;        ///< frames measured
  std::string problem;        ///< non-empty: no value was accepted (the last refusal)
  bool ok() const { return problem.empty(); }
};

/// Over the grid lo, lo + step, ..., <= hi (step >= 1): the smallest accepted value first
/// (refusals only below some value, acceptance from it on), then the largest accepted value
/// whose bytes do not exceed `budget` (bytes non-decreasing in the value); when even the
/// smallest accepted value exceeds it, that value with belowMinimum. Each search doubles its
/// step from where it starts, then bisects: O(log n) evaluations for n grid values. The chosen
/// value is measured last, so the caller's technique is left at it.
MemoryMatchResult matchMemory(long long lo, long long hi, long long step, std::uint64_t budget,
                              const BytesAtValue& bytesAt);

}  // namespace sl
