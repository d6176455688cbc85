// The readback helpers every technique publishes through: each reads one requested key
// from the GPU into the Publication and adds the bytes it asked GL for to
// Publication::readbackBytes (FrameStats::publicationBytes). Nothing is read when the key
// is not requested (FrameContext::wants).
#pragma once

#include <string>
#include <vector>

#include "core/Technique.h"

namespace sl {

/// A depth texture as a float image (0..1). False (nothing read) when not requested. A map
/// larger than kMaxPublishedImageSide per side is published nearest-sampled to
/// publishedImageSize (FloatImage::sourceWidth/sourceHeight give the map's own size).
bool publishDepth(FrameContext& ctx, const std::string& key, const gl::Texture& depth);
/// One layer of a depth array texture (cascades, faces) as a float image (0..1), bounded the
/// same way.
bool publishDepthLayer(FrameContext& ctx, const std::string& key, const gl::Texture& depth,
                       int layer);
/// The red channel of a colour texture (R32F, or the first channel of any float-readable
/// format) as a float image.
bool publishRed(FrameContext& ctx, const std::string& key, const gl::Texture& texture);
/// An R32UI texture that holds float bits (atomicMax importance) as a float image.
bool publishFloatBits(FrameContext& ctx, const std::string& key, const gl::Texture& texture);
/// `count` floats of `buffer` from float `offset` on as a curve.
bool publishCurve(FrameContext& ctx, const std::string& key, const gl::Buffer& buffer,
                  std::size_t offset, std::size_t count);
/// `count` floats of `buffer` from float `offset` on, counted as publication readback (for
/// data a technique splits into several keys itself).
std::vector<float> readPublishedFloats(FrameContext& ctx, const gl::Buffer& buffer,
                                       std::size_t offset, std::size_t count);
/// Values computed on the CPU as a curve (no readback); false when not requested.
bool publishValues(FrameContext& ctx, const std::string& key, std::vector<float> values);
/// An image computed on the CPU (no readback; row 0 = the bottom row, as a GL texture's);
/// false when not requested.
bool publishImage(FrameContext& ctx, const std::string& key, int width, int height,
                  std::vector<float> values);
/// A number (no readback); false when not requested.
bool publishNumber(FrameContext& ctx, const std::string& key, double value);

}  // namespace sl
