// The lookup contract's coordinate (shaders/common/resolve.frag): which of the technique's
// maps serves the pixel and where in it. Techniques with one map always say map 0.
struct ShadowCoord {
  int map;   // index of the selected map (a layer, an atlas tile, a cube face, a cascade...)
  vec3 uvz;  // the selected map's texture uv (through any warp or page table) and depth
};
