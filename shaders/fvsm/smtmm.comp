// The shadow-map tile mapping map (SMTMM) of fitted virtual shadow maps (Giegl & Wimmer 2007,
// §4.3; CPU reference: sl::fvsm::smtmmEntry / buildSmtmm, algo/fvsm/Fvsm.cpp, which this
// mirrors line by line in float): one invocation per entry, sampling the pixel at the centre
// of the entry's block. Linear eye depth is read from the eye-space depth buffer (step 1,
// virtual-tiled/eye_depth.comp); the pixel's footprint is the parallelogram P ± a ± b built
// from the signed depth step towards the neighbour nearer in depth, each corner an eye-space
// position by eq. 1 (virtual-tiled/eye_depth.glsl: eyeDepthAt, eyePosition), projected into
// the virtual map's uv.
#include "common/shared_constants.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = SL_IMAGE_FVSM_SMTMM) writeonly uniform image2D o_smtmm;
uniform ivec2 u_frameSize;
uniform ivec2 u_smtmmSize;
uniform mat4 u_eyeToSmUv;    // eye -> the virtual map's uv (x, y; w divided)
uniform int u_footprint;     // SL_FVSM_FOOTPRINT_BOX or _CHORD (fvsm.need.footprint)

#include "virtual-tiled/eye_depth.glsl"

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

void main() {
  ivec2 entry = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(entry, u_smtmmSize))) return;
  // sl::fvsm::smtmmSamplePixel
  ivec2 pixel = min(ivec2(floor((vec2(entry) + 0.5) * vec2(u_frameSize) / vec2(u_smtmmSize))),
                    u_frameSize - 1);
  vec4 empty = vec4(0.0, 0.0, -1.0, -1.0);
  float z = eyeDepthAt(pixel);
  if (!(z > 0.0)) {
    imageStore(o_smtmm, entry, empty);
    return;
  }
  vec2 centre = vec2(pixel) + 0.5;
  vec3 p = eyePosition(centre, z);
  vec2 uv = toSmUv(p);
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) {
    imageStore(o_smtmm, entry, empty);
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
  imageStore(o_smtmm, entry, vec4(uv, quantise(halfExtent.x), quantise(halfExtent.y)));
}
