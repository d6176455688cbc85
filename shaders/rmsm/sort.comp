// RMSM step 4, sort (C++: RmsmShadowMap::sortUnique; reference std::sort in
// sl::pages::sortUnique): one compare-exchange step (k, j) of a bitonic sort of u_count keys
// (a power of two, padded with SL_PAGE_NONE, which sorts last), ascending. The C++ dispatches
// the steps k = 2, 4, .., count and j = k/2, .., 1 with a storage barrier between them.
#include "common/shared_constants.h"
layout(local_size_x = SL_RMSM_SORT_GROUP) in;
layout(std430, binding = SL_RMSM_BUFFER_SORT) buffer Keys {
  uint keys[];
};
uniform uint u_count;
uniform uint u_k;
uniform uint u_j;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_count) return;
  uint l = i ^ u_j;
  if (l <= i) return;
  uint a = keys[i], b = keys[l];
  bool ascending = (i & u_k) == 0u;
  if ((a > b) == ascending) {
    keys[i] = b;
    keys[l] = a;
  }
}
