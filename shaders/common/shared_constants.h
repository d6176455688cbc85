// Constants shared by the C++ renderer and the GLSL shaders, declared once: C++ includes
// this file (the shaders folder is on shadowlab_algo's include path) and GLSL includes it
// through gl::ShaderLibrary (#include "common/shared_constants.h"). Only #defines and
// comments: both preprocessors must read it. Unsigned values carry a `u` (valid in both).
#ifndef SL_SHARED_CONSTANTS_H
#define SL_SHARED_CONSTANTS_H

// --- Hard shadow mask (R8UI resolve target, Embree reference, metrics).
#define SL_MASK_SHADOWED 0u
#define SL_MASK_LIT 1u
#define SL_MASK_EMPTY 255u  // no surface under the pixel

// --- Texture units. The scene's material texture (SceneGpu::draw) takes SL_UNIT_MATERIAL;
// the G-buffer and resolve targets keep one unit each in every pass that reads them
// (resolve, composite, deferred resolves, RTW's analysis).
#define SL_UNIT_MATERIAL 0
#define SL_UNIT_G_POSITION 1
#define SL_UNIT_G_NORMAL 2
#define SL_UNIT_G_ALBEDO 3
#define SL_UNIT_VISIBILITY 4     // filtered visibility (resolve target 1)
#define SL_UNIT_HARD 5           // hard mask (resolve target 0; last frame's for RTW's edges)
#define SL_UNIT_REFERENCE 6      // Embree reference mask (error overlay)
#define SL_UNIT_ALIASING 7       // m per pixel (resolve target 2)
#define SL_UNIT_TEXEL 8          // selected map's uv per pixel (resolve target 3)
#define SL_UNIT_MAP_INDEX 9      // selected map's index per pixel (resolve target 4)
#define SL_UNIT_LOOKUP_FIRST 10  // a technique's lookup textures start here

// --- Image units of a deferred resolve (Technique::resolveDeferred writes these).
#define SL_IMAGE_RESOLVE_HARD 0      // r8ui
#define SL_IMAGE_RESOLVE_FILTERED 1  // r8
#define SL_IMAGE_RESOLVE_ALIASING 2  // r32f
#define SL_IMAGE_RESOLVE_TEXEL 3     // rg32f
#define SL_IMAGE_RESOLVE_MAP 4       // r8ui: the selected map's index (partition overlay)

// --- Multi-map lookups (shaders/common/depth_map_test.glsl): per-map uniform arrays.
// face-partition (techniques/facepartition) uses SL_FACE_SLOTS maps per depth slice (near,
// -x, +x, -y, +y) and up to SL_FACE_MAX_ZSPLITS slices (face.zsplits): the most of any
// technique. Cascades keep at most SL_MAX_CASCADES partitions, the paged maps
// SL_PAGED_LOOKUP_LEVELS levels (one lookup map each).
#define SL_FACE_SLOTS 5
#define SL_FACE_MAX_ZSPLITS 4
#define SL_MAX_DEPTH_MAPS 20  // SL_FACE_SLOTS * SL_FACE_MAX_ZSPLITS
#define SL_MAX_CASCADES 8
#define SL_PAGED_LOOKUP_LEVELS 8

// --- view.overlay (rendererParamDecls' enum order; composite.frag).
#define SL_OVERLAY_NONE 0
#define SL_OVERLAY_ERROR 1
#define SL_OVERLAY_ALIASING 2
#define SL_OVERLAY_GRID 3
#define SL_OVERLAY_PARTITION 4  // each pixel coloured by the index of the map it selected
#define SL_OVERLAY_CHANGED 5    // pixels lit in one frame and shadowed in the next (flicker)
#define SL_OVERLAY_PAGES 6      // the borders of the page each pixel uses (paged maps)
#define SL_CHANGED_COLOUR 1.00, 0.95, 0.00      // the changed overlay's vivid yellow (RGB 0..1)
#define SL_PAGE_BORDER_COLOUR 1.00, 0.35, 0.00  // the pages overlay's borders (RGB 0..1)
#define SL_PARTITION_COLOURS 8  // distinct overlay colours (composite.frag); index mod 8
// Their RGB (0..1): composite.frag and the Partitions panel (ui/panels/partition).
#define SL_PARTITION_COLOUR_0 0.90, 0.20, 0.20  // red
#define SL_PARTITION_COLOUR_1 0.20, 0.75, 0.25  // green
#define SL_PARTITION_COLOUR_2 0.25, 0.40, 0.95  // blue
#define SL_PARTITION_COLOUR_3 0.95, 0.85, 0.20  // yellow
#define SL_PARTITION_COLOUR_4 0.85, 0.25, 0.85  // magenta
#define SL_PARTITION_COLOUR_5 0.20, 0.85, 0.90  // cyan
#define SL_PARTITION_COLOUR_6 1.00, 0.55, 0.10  // orange
#define SL_PARTITION_COLOUR_7 0.55, 0.35, 0.85  // violet
#define SL_GRID_LINES_PER_MAP 16  // the grid overlay: a line every 1/16 of the selected map
// --- Outside view (view.outside; algo/OutsideView, common/outline.frag, the viewport's legend):
// line colours (RGB 0..1). A shadow map's light frustum takes its partition colour above.
#define SL_OUTLINE_CAMERA_COLOUR 1.00, 1.00, 1.00  // the main camera's frustum: white
#define SL_OUTLINE_SPLIT_COLOUR 0.62, 0.62, 0.66   // split planes of a multi-map technique: grey
#define SL_OUTLINE_WARP_COLOUR 0.35, 0.95, 1.00    // a warped map's frustum (PSM/LiSPSM/TSM): cyan

// --- Aliasing statistics (common/aliasing_stats.comp, the renderer's "aliasing.*"
// publication; CPU mirror sl::Log2Histogram): a histogram of log2 m over the covered pixels,
// SL_ALIASING_BINS_PER_OCTAVE bins per octave from 2^SL_ALIASING_LOG2_MIN up (values outside
// fall in the end bins), the count and the exact maximum. Buffer: 4 uints, then the bins.
#define SL_ALIASING_BINS 1024
#define SL_ALIASING_BINS_PER_OCTAVE 32
#define SL_ALIASING_LOG2_MIN (-16)
#define SL_ALIASING_GROUP 16        // local_size_x/y
#define SL_BUFFER_ALIASING_STATS 7  // SSBO binding (the renderer's, after the technique's)

// --- Mask change (common/mask_change.comp, the changed overlay, the renderer's "mask.*"
// publication; CPU mirror sl::compareConsecutiveMasks): the previous frame's hard mask is
// copied before the resolve; pixels covered in both frames are counted, and those whose
// lit/shadowed state differs. Buffer: compared, changed (uint).
#define SL_UNIT_PREV_HARD 10     // last frame's hard mask (composite, mask_change.comp)
#define SL_MASK_CHANGE_GROUP 16  // local_size_x/y
#define SL_BUFFER_MASK_CHANGE 8  // SSBO binding

// --- Cascades (techniques/cascades, shaders/cascades).
#define SL_CASCADE_BUFFER_DEPTH_RANGE 0  // min, max view depth (float bits as uint)
#define SL_CASCADE_GROUP 8               // local_size_x/y of the depth-range reduction
#define SL_CASCADE_BUFFER_M_STATS 1      // per map: histogram of log2 m, count, max m bits
#define SL_CASCADE_M_BINS 128            // histogram bins over log2 m in [-8, 8): 1/8 octave
#define SL_CASCADE_M_LOG2_MIN -8.0
#define SL_CASCADE_M_LOG2_MAX 8.0

// --- RTW (techniques/rtw, shaders/rtw).
#define SL_RTW_BUFFER_COLLAPSED 0  // 1D importance [x n][y n], float bits as uint
#define SL_RTW_BUFFER_BLURRED 1
#define SL_RTW_BUFFER_WARP 2           // n + 1 edges per axis
#define SL_RTW_BUFFER_MOMENTS 3        // DA-RTW moment chain, 6 floats per texel
#define SL_RTW_BUFFER_INVERSE 4        // inverse warp tables
#define SL_RTW_BUFFER_MOMENT_COUNTS 5  // DA-RTW: pixels and edge-normal bins per moment IM texel
#define SL_RTW_IMAGE_IM 0              // r32ui 2D importance map
#define SL_RTW_IMAGE_MOMENT_IM 1       // r32ui DA-RTW moment IM
#define SL_RTW_LINEAR_GROUP 64         // local_size_x of the 1D passes (collapse, blur, inverse)
#define SL_RTW_MOMENT_GROUP 8          // local_size_x/y of the moment passes
// Largest blur radius: rtw::gaussianWeights clamps to it, blur.comp holds 2r + 1 weights.
#define SL_BLUR_MAX_RADIUS 32
// Largest importance map (im.resolution): scan_warp.comp scans it in shared memory with
// one work group of SL_IM_MAX_RESOLUTION / 2 invocations per axis.
#define SL_IM_MAX_RESOLUTION 2048
// DA-RTW's PCA reads the IM reduced to at most this size (block maxima).
#define SL_MOMENT_IM_MAX 128
// DA-RTW's turn prediction (algo/rtw/TurnPrediction.h): the shadow-edge pixels of the last
// frame counted per moment IM texel in this many bins of their light-plane normal's angle
// (over 180 degrees), each pixel split between its two nearest bins in this many parts.
#define SL_RTW_EDGE_BINS 4
#define SL_RTW_EDGE_ONE 256
// ... and the sum of their importance in 64-bit fixed point (two uints, low word first), one
// unit = 1 / SL_RTW_IMPORTANCE_ONE; a pixel's importance is clamped to SL_RTW_IMPORTANCE_MAX
// so that one pixel's share fits 32 bits.
#define SL_RTW_IMPORTANCE_ONE 16777216.0
#define SL_RTW_IMPORTANCE_MAX 255.0
// Planes of the counts buffer, each momentRes^2 uints: pixels, the importance sum's low and
// high words, then the SL_RTW_EDGE_BINS edge bins.
#define SL_RTW_COUNT_PLANES (3 + SL_RTW_EDGE_BINS)
// Counted are every SL_RTW_COUNT_STRIDE-th scattering pixel in x and y (the weights are
// relative: a quarter of the atomics on the hottest texels, the same shares).
#define SL_RTW_COUNT_STRIDE 2
// Largest tessellation level of the warped pass. GL guarantees 64, but llvmpipe corrupts
// the warped map at levels 32-64 (measured: corridor, tolerance 0.01: 55.6 % error at cap
// 64, 0.73 % at cap 16). SceneGpu splits long triangles so that 16 suffices.
#define SL_MAX_TESSELLATION_LEVEL 16

// --- Resolution-matched shadow maps (renderer/algo/pages, techniques/rmsm): a page request
// is one 32-bit key, level << 26 | y << 13 | x (level 0 = the finest pages; x, y the page's
// place in its level's grid, at most 8192 per side). SL_PAGE_NONE: no request / no page.
#define SL_PAGE_KEY_LEVEL_SHIFT 26
#define SL_PAGE_KEY_COORD_BITS 13
#define SL_PAGE_MAX_PER_SIDE 8192
#define SL_PAGE_MAX_LEVELS 14
#define SL_PAGE_NONE 0xFFFFFFFFu
#define SL_RMSM_GROUP 8            // local_size_x/y of the request and compaction passes
#define SL_RMSM_IMAGE_REQUESTS 0   // r32ui: the page key each pixel asks for (SL_PAGE_NONE: none)
#define SL_RMSM_BUFFER_REQUESTS 0  // SSBO: count, then the compacted keys
#define SL_RMSM_BUFFER_SORT 1      // SSBO: the keys a bitonic step sorts (rmsm/sort.comp)
#define SL_RMSM_BUFFER_UNIQUE 2    // SSBO: the sorted keys with repeats -> SL_PAGE_NONE
#define SL_RMSM_BUFFER_UNIQUE_COUNT 3  // SSBO: the number of keys rmsm/unique.comp kept
#define SL_RMSM_SORT_GROUP 64          // local_size_x of rmsm/sort.comp and rmsm/unique.comp
// Side in texels of an RMSM superpage (Lefohn et al. 2007): rmsm.render = superpages renders
// each 1024² block of one level holding allocated pages once, then copies its pages to the pool.
#define SL_RMSM_SUPERPAGE 1024
// lod.derivatives: the neighbour a pixel's screen derivative steps to (sl::pages::Derivatives).
#define SL_RMSM_DERIVATIVES_NEIGHBOUR 0
#define SL_RMSM_DERIVATIVES_SAME_SURFACE 1
// same-surface: a neighbour lies on the pixel's surface when its offset leaves the pixel's
// tangent plane by at most this fraction of its length and its normal is within acos(this).
#define SL_RMSM_SAME_SURFACE_PLANE 0.1
#define SL_RMSM_SAME_SURFACE_NORMAL_COS 0.9
// Adaptive shadow maps (asm): the shadow-test pass writes per pixel (mask, served page key,
// refine key, map edge) into an rgba32ui image; the edge pass turns it into one key per pixel in
// the RMSM request image (SL_RMSM_IMAGE_REQUESTS), compacted by common/paged/compact.comp. A key
// with SL_ASM_TOUCH_BIT is no request: the pixel used that page (the cache's LRU).
#define SL_ASM_IMAGE_TESTED 1
#define SL_ASM_TOUCH_BIT 0x80000000u
// asm.edge (sl::adaptive::EdgeTest): what makes a pixel an edge pixel. SCREEN: its shadow mask
// differs from a 4-neighbour's; MAP: the shadow-map texel it reads lies on a shadow edge of
// the map (Fernando et al. 2001: the depth tests at that texel and its 4 neighbours differ).
#define SL_ASM_EDGE_SCREEN 0
#define SL_ASM_EDGE_MAP 1

// --- The tiled techniques' eye-space depth buffer (virtual-tiled and fvsm: Giegl & Wimmer
// 2007 §3.2; core/tiled/EyeDepthBuffer, shaders/common/tiled/eye_depth.*): r32f,
// metres along the camera's view axis, 0 = no surface. Sampled on the unit after the tile's
// own lookup texture (SL_UNIT_LOOKUP_FIRST) by the tile apply and SMTMM passes.
#define SL_UNIT_EYE_DEPTH 11
#define SL_IMAGE_EYE_DEPTH 5  // written by common/tiled/eye_depth.comp

// --- Fitted virtual shadow maps (techniques/fvsm, shaders/fvsm; algo/fvsm).
// Cap of a quantised SMTMM need (log2 texels of the whole virtual map along one axis): a
// footprint collapsed to a line along an SM axis needs "infinite" resolution.
#define SL_FVSM_MAX_NEED_LOG2 24
// fvsm.need.footprint: a footprint's half extent per SM axis (sl::fvsm::FootprintMeasure)
#define SL_FVSM_FOOTPRINT_BOX 0
#define SL_FVSM_FOOTPRINT_CHORD 1
// The SMTMM's image: rgba32f (sm u, sm v, need log2 u, need log2 v; need -1: empty), or with
// the 4-byte entry (fvsm.smtmm.entry, sl::fvsm::EntryFormat) r32ui, one byte each from the
// lowest: u column, v row (of 256), need log2 u, need log2 v (SL_FVSM_ENTRY_EMPTY: empty)
#define SL_IMAGE_FVSM_SMTMM 0
#define SL_FVSM_ENTRY_16_BYTE 0
#define SL_FVSM_ENTRY_4_BYTE 1
#define SL_FVSM_ENTRY_EMPTY 255u
// r32f: the FVSM panel's camera thumbnail (fvsm.camera: unshadowed N.L grey, -1 without a
// surface, -2 outside the frame), written only while the panel asks for it
#define SL_IMAGE_FVSM_CAMERA 1
// Side of the FVSM panel's thumbnails (fvsm.camera, fvsm.light.depth), texels
#define SL_FVSM_THUMBNAIL 256

#endif  // SL_SHARED_CONSTANTS_H
