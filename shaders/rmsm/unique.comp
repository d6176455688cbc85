// RMSM step 5, unique (C++: RmsmShadowMap::sortUnique; reference std::unique in
// sl::pages::sortUnique): over the sorted keys, the first of each run of equal keys (and no
// SL_PAGE_NONE) is kept, every other becomes SL_PAGE_NONE; the kept ones are counted. A second
// sort (rmsm/sort.comp) then moves the kept keys, in order, to the front.
#include "common/shared_constants.h"
layout(local_size_x = SL_RMSM_SORT_GROUP) in;
layout(std430, binding = SL_RMSM_BUFFER_SORT) readonly buffer Sorted {
  uint sorted[];
};
layout(std430, binding = SL_RMSM_BUFFER_UNIQUE) writeonly buffer Unique {
  uint keys[];
};
layout(std430, binding = SL_RMSM_BUFFER_UNIQUE_COUNT) buffer UniqueCount {
  uint count;  // cleared to 0 by the C++
};
uniform uint u_count;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_count) return;
  uint key = sorted[i];
  bool keep = key != SL_PAGE_NONE && (i == 0u || sorted[i - 1u] != key);
  keys[i] = keep ? key : SL_PAGE_NONE;
  if (keep) atomicAdd(count, 1u);
}
