// The perspective warp's shared GL-side pieces (Lloyd et al., EGSR 2006): its `warp.eta`
// parameter (eq. 11) and the outside view's outlines of a warped fit (algo/warp WarpFit).
// Shared by `psm`, `lispsm`, `tsm`, the warped partitions of `cascades` and `face-partition`.
#pragma once

#include "algo/Params.h"
#include "algo/warp/PerspectiveWarp.h"
#include "core/Technique.h"

namespace sl {

/// The `warp.eta` parameter (eq. 11) with this default: psm, lispsm, the warped partitions
/// of `cascades` and face-partition declare this one.
ParamDecl warpEtaDecl(double defaultEta);

/// The outside view's outlines of a warped fit (`fit.warped()`): the light-space box it was
/// fitted in (LightMap, coloured as map `map`) and its warping frustum (Warp). psm, lispsm,
/// tsm and every warped face of face-partition publish them.
void addWarpOutlines(const warp::WarpFit& fit, FrameOutlines& out, int map = 0);

}  // namespace sl
