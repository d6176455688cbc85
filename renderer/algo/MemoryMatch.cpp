#include "algo/MemoryMatch.h"

#include <algorithm>

namespace sl {

namespace {
/// The first grid index >= from where `holds` is true, `holds` being false below it and true
/// from it on; last + 1 when none. Indices doubled from `from` (never a value far larger than
/// needed), then bisected.
template <class Holds>
long long firstWhere(long long from, long long last, Holds&& holds) {
  if (from > last) return last + 1;
  if (holds(from)) return from;
  long long no = from, yes = last + 1;
  for (long long k = 1; from + k <= last; k *= 2) {
    if (holds(from + k)) {
      yes = from + k;
      break;
    }
    no = from + k;
  }
  if (yes == last + 1 && no < last && holds(last)) yes = last;
  while (yes <= last && yes - no > 1) {
    const long long mid = no + (yes - no) / 2;
    (holds(mid) ? yes : no) = mid;
  }
  return yes;
}
}  // namespace

MemoryMatchResult matchMemory(long long lo, long long hi, long long step, std::uint64_t budget,
                              const BytesAtValue& bytesAt) {
  MemoryMatchResult r;
  step = std::max<long long>(1, step);
  const long long last = hi < lo ? -1 : (hi - lo) / step;
  std::string problem;
  auto measure = [&](long long k) {
    ++r.evaluations;
    problem.clear();
    return bytesAt(lo + k * step, problem);
  };
  const long long accepted =
      firstWhere(0, last, [&](long long k) { return measure(k).has_value(); });
  if (accepted > last) {
    r.value = lo;
    r.problem = problem.empty() ? "no value of the grid is accepted" : problem;
    return r;
  }
  const long long over = firstWhere(accepted, last, [&](long long k) {
    const auto bytes = measure(k);
    return !bytes || *bytes > budget;
  });
  r.belowMinimum = over == accepted;
  const long long chosen = r.belowMinimum ? accepted : over - 1;
  r.value = lo + chosen * step;
  const auto bytes = measure(chosen);  // the technique is left at the chosen value
  if (!bytes) {
    r.problem = problem.empty() ? "the chosen value was refused" : problem;
    return r;
  }
  r.bytes = *bytes;
  return r;
}

}  // namespace sl
