// The shadow-map tile mapping map (SMTMM) of fitted virtual shadow maps (Giegl & Wimmer 2007,
// §4.3; CPU reference: sl::fvsm::smtmmEntry / buildSmtmm, algo/fvsm/Fvsm.cpp, which this
// mirrors line by line in float): one invocation per entry, sampling the pixel at the centre
// of the entry's block. Linear eye depth is read from the eye-space depth buffer (step 1,
// common/tiled/eye_depth.comp); the pixel's footprint is the parallelogram P ± a ± b built
// from the signed depth step towards the neighbour nearer in depth, each corner an eye-space
// position by eq. 1 (common/tiled/eye_depth.glsl: eyeDepthAt, eyePosition), projected into
// the virtual map's uv. Built with SL_FVSM_PACKED_ENTRY it writes the paper's 4-byte entry
// (sl::fvsm::packSmtmmEntry) instead of four floats.
#include "common/shared_constants.h"
layout(local_size_x = 8, local_size_y = 8) in;
#ifdef SL_FVSM_PACKED_ENTRY
layout(r32ui, binding = SL_IMAGE_FVSM_SMTMM) writeonly uniform uimage2D o_smtmm;
#else
layout(rgba32f, binding = SL_IMAGE_FVSM_SMTMM) writeonly uniform image2D o_smtmm;
#endif
uniform ivec2 u_frameSize;
uniform ivec2 u_smtmmSize;
uniform mat4 u_eyeToSmUv;    // eye -> the virtual map's uv (x, y; w divided)
uniform int u_footprint;     // SL_FVSM_FOOTPRINT_BOX or _CHORD (fvsm.need.footprint)

#include "common/tiled/eye_depth.glsl"

vec2 toSmUv(vec3 e) {
  vec4 c = u_eyeToSmUv * vec4(e, 1.0);
  return c.xy / c.w;
}

// sl::fvsm signedDepthStep: the depth step along +step towards whichever neighbour is nearer
// in depth (zn - z to the next pixel, z - zn from the previous: negative where the depth
// falls); 0 when neither has a surface; a tie keeps the previous pixel's.
float signedDepthStep(ivec2 p, ivec2 step, float z) {
  bool found = false;
  float best = 0.0;
  for (int s = -1; s <= 1; s += 2) {
    ivec2 q = p + s * step;
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, u_frameSize))) continue;
    float zn = eyeDepthAt(q);
    if (zn <= 0.0) continue;
    float d = float(s) * (zn - z);
    if (!found || abs(d) < abs(best)) best = d;
    found = true;
  }
  return best;
}

// sl::fvsm::quantiseNeedLog2.
float quantise(float halfExtent) {
  if (!(halfExtent > 0.0)) return float(SL_FVSM_MAX_NEED_LOG2);
  return clamp(ceil(-log2(halfExtent)), 0.0, float(SL_FVSM_MAX_NEED_LOG2));
}

// One entry: sm uv and the two needs (integers), or empty (need < 0). The 4-byte entry is
// sl::fvsm::packSmtmmEntry: the column and row of 256 holding uv, then the needs.
void storeEntry(ivec2 entry, vec2 uv, vec2 need) {
#ifdef SL_FVSM_PACKED_ENTRY
  uint word = (SL_FVSM_ENTRY_EMPTY << 16) | (SL_FVSM_ENTRY_EMPTY << 24);
  if (need.x >= 0.0) {
    uvec2 cell = uvec2(clamp(floor(uv * 256.0), 0.0, 255.0));
    uvec2 n = uvec2(need);
    word = cell.x | (cell.y << 8) | (n.x << 16) | (n.y << 24);
  }
  imageStore(o_smtmm, entry, uvec4(word));
#else
  imageStore(o_smtmm, entry, vec4(uv, need));
#endif
}

void main() {
  ivec2 entry = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(entry, u_smtmmSize))) return;
  // sl::fvsm::smtmmSamplePixel
  ivec2 pixel = min(ivec2(floor((vec2(entry) + 0.5) * vec2(u_frameSize) / vec2(u_smtmmSize))),
                    u_frameSize - 1);
  float z = eyeDepthAt(pixel);
  if (!(z > 0.0)) {
    storeEntry(entry, vec2(0.0), vec2(-1.0));
    return;
  }
  vec2 centre = vec2(pixel) + 0.5;
  vec3 p = eyePosition(centre, z);
  vec2 uv = toSmUv(p);
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) {
    storeEntry(entry, vec2(0.0), vec2(-1.0));
    return;
  }
  float dzX = signedDepthStep(pixel, ivec2(1, 0), z);  // signed: the footprint tilts with
  float dzY = signedDepthStep(pixel, ivec2(0, 1), z);  // the receiver
  vec3 a = 0.5 * (eyePosition(centre + vec2(0.5, 0.0), z + 0.5 * dzX) -
                  eyePosition(centre - vec2(0.5, 0.0), z - 0.5 * dzX));
  vec3 b = 0.5 * (eyePosition(centre + vec2(0.0, 0.5), z + 0.5 * dzY) -
                  eyePosition(centre - vec2(0.0, 0.5), z - 0.5 * dzY));
  vec2 lo = vec2(1e30), hi = vec2(-1e30), smA = vec2(0.0), smB = vec2(0.0);
  for (int sa = -1; sa <= 1; sa += 2) {
    for (int sb = -1; sb <= 1; sb += 2) {
      vec2 c = toSmUv(p + float(sa) * a + float(sb) * b);
      lo = min(lo, c);
      hi = max(hi, c);
      smA += 0.25 * float(sa) * c;
      smB += 0.25 * float(sb) * c;
    }
  }
  vec2 halfExtent = 0.5 * (hi - lo);
  if (u_footprint == SL_FVSM_FOOTPRINT_CHORD) {  // sl::fvsm::footprintHalfExtent
    vec2 box = abs(smA) + abs(smB);
    float det = abs(smA.x * smB.y - smA.y * smB.x);
    float acrossU = max(abs(smA.y), abs(smB.y)), acrossV = max(abs(smA.x), abs(smB.x));
    halfExtent = vec2(acrossU > 0.0 ? det / acrossU : box.x, acrossV > 0.0 ? det / acrossV : box.y);
  }
  storeEntry(entry, uv, vec2(quantise(halfExtent.x), quantise(halfExtent.y)));
}
