// The split view's "Equal memory" searches each technique's declared memory knob
// (ParamDecl::memoryKnob) assuming the technique's memory() grows with it: every shipped
// technique declares at most one, an integer, and its memory is measured to grow with it.
#include <algorithm>
#include <cmath>

#include "GlTestEnv.h"

namespace sl {
namespace {

TEST(MemoryKnob, EveryTechniqueDeclaresOneAndItsMemoryGrowsWithIt) {
  std::vector<std::string> without;
  for (const TechniqueInfo& t : Renderer::techniques()) {
    const auto knobs = std::count_if(t.params.begin(), t.params.end(),
                                     [](const ParamDecl& d) { return d.memoryKnob; });
    EXPECT_LE(knobs, 1) << t.id << " declares several memory knobs";
    const ParamDecl* knob = memoryKnob(t.params);
    if (!knob) {
      without.push_back(t.id);
      continue;
    }
    EXPECT_EQ(knob->type, ParamType::Int) << t.id << ": " << knob->key;
    // A quarter and a half of the default (on the knob's step grid, within its range): small
    // enough to stay fast (virtual-tiled renders every tile at it), far enough apart to grow.
    const double step = std::max(1.0, knob->step);
    auto at = [&](double fraction) {
      return std::clamp(std::round(knob->defaultValue * fraction / step) * step, knob->minValue,
                        knob->maxValue);
    };
    const double small = at(0.25), large = at(0.5);
    ASSERT_LT(small, large) << t.id;
    const bool directional = !checkLightSupport(t, LightType::Directional).has_value();
    auto r = test::makeRenderer(directional ? "plane-box" : "omni-room", t.id);
    ASSERT_TRUE(r) << t.id;
    std::uint64_t bytes[2] = {};
    for (int i = 0; i < 2; ++i) {
      ASSERT_FALSE(r->params().set(knob->key, i == 0 ? small : large)) << t.id;
      const auto e = r->renderFrame(96, 54, 0);
      ASSERT_FALSE(e) << t.id << ": " << *e;
      bytes[i] = r->stats().memory.bytes();
    }
    EXPECT_LT(bytes[0], bytes[1]) << t.id << ": " << knob->key << " = " << small << " holds "
                                  << bytes[0] << " B, = " << large << " holds " << bytes[1] << " B";
  }
  // fvsm's textures follow each frame's needs: no parameter sets its memory.
  EXPECT_EQ(without, std::vector<std::string>{"fvsm"});
}

}  // namespace
}  // namespace sl
