// Renderer core on a headless EGL context: shaders (#include, file:line errors, last good
// program kept), bad input that must not break the renderer, GL debug output clean.
#include <algorithm>
#include <cstdlib>
#include <fstream>

#include "GlTestEnv.h"
#include "gl/ShaderLibrary.h"

namespace sl {
namespace {

using test::eglContext;

TEST(ShaderLibrary, IncludesAndReportsFileAndLine) {
  eglContext().makeCurrent();
  auto dir = test::testOut("shaders");
  std::filesystem::create_directories(dir / "lib");
  std::ofstream(dir / "lib/common.glsl") << "float half_(float x) { return x * 0.5; }\n";
  std::ofstream(dir / "good.frag") << "#include \"lib/common.glsl\"\nout vec4 c;\n"
                                      "void main() { c = vec4(half_(1.0)); }\n";
  std::ofstream(dir / "bad.frag") << "#include \"lib/common.glsl\"\nout vec4 c;\n"
                                     "void main() { c = vec4(undefined_thing); }\n";
  gl::ShaderLibrary lib(dir);
  gl::ProgramDesc good{"good", {{GL_FRAGMENT_SHADER, "good.frag"}}, {}, {}};
  gl::Program prog(lib, good);
  EXPECT_TRUE(prog);
  try {
    gl::ProgramDesc bad{"bad", {{GL_FRAGMENT_SHADER, "bad.frag"}}, {}, {}};
    gl::Program p(lib, bad);
    FAIL() << "a broken shader compiled";
  } catch (const gl::ShaderError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.frag:3"), std::string::npos) << e.what();
  }
  // Hot reload with a broken file keeps the last good program.
  GLuint before = prog.id();
  std::ofstream(dir / "good.frag") << "void main() { broken }\n";
  auto err = prog.rebuild(lib);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("good.frag:1"), std::string::npos) << *err;
  EXPECT_EQ(prog.id(), before);
}

TEST(Renderer, BadInputKeepsRendererWorking) {
  auto r = test::makeRenderer("plane-box", "uniform");
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->renderFrame(0, 0, 0));  // zero-size window
  EXPECT_TRUE(r->setTechnique("no-such-technique"));
  EXPECT_EQ(r->techniqueId(), "uniform");
  Camera good = r->camera();
  Camera bad = good;
  bad.target = bad.position;  // degenerate camera
  r->setCamera(bad);
  auto err = r->renderFrame(64, 48, 0);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("camera"), std::string::npos) << *err;
  r->setCamera(good);
  EXPECT_FALSE(r->renderFrame(64, 48, 0));
  test::expectNoGlErrors(*r);
}

TEST(Renderer, ReportsTimingAndMemory) {
  auto r = test::makeRenderer("plane-box", "uniform");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("resolution", 1024));
  // Two frames: timer queries (real GPUs) give the first frame's times with the second.
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  glFinish();
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  const FrameStats& st = r->stats();
  EXPECT_EQ(st.memory.texels(), 1048576u);  // uniform at 1024^2 (issue 3's figure)
  EXPECT_EQ(st.memory.bytes(), 4u * 1048576u);
  EXPECT_FALSE(st.timingMethod.empty());
  EXPECT_GT(st.passMs("shadow map"), 0.0);
  EXPECT_GT(st.totalMs, 0.0);
  test::expectNoGlErrors(*r);
}

RendererOptions timedBy(TimingMethod method) {
  RendererOptions options;
  options.timing = method;
  return options;
}

std::vector<std::string> passNames(const std::vector<PassTiming>& passes) {
  std::vector<std::string> names;
  for (const PassTiming& p : passes) names.push_back(p.name);
  return names;
}

// Timer queries (real GPUs; forced here with RendererOptions::timing, which llvmpipe
// accepts): results are read a frame late, never waited on, and name the passes.
TEST(Renderer, TimerQueriesAreReadAFrameLateWithoutWaiting) {
  auto r = test::makeRenderer("plane-box", "rtw-backward", timedBy(TimingMethod::TimerQuery));
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->renderFrame(160, 90, 0));
  EXPECT_EQ(r->stats().timingMethod, "GL_TIME_ELAPSED");
  EXPECT_TRUE(r->stats().passes.empty()) << "the first frame has no finished queries yet";
  for (int f = 0; f < 3; ++f) {
    glFinish();  // the previous frame's queries are done: the next read finds them
    ASSERT_FALSE(r->renderFrame(160, 90, 0));
    EXPECT_EQ(r->stats().timingFramesLate, 1);
    std::vector<std::string> names;
    for (const PassTiming& p : r->stats().passes) {
      names.push_back(p.name);
      EXPECT_GE(p.ms, 0.0) << p.name;
    }
    for (const char* want : {"gbuffer", "importance", "warped shadow map", "resolve"})
      EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
  }
  test::expectNoGlErrors(*r);
}

// The method is chosen per renderer (RendererOptions::timing), not for the process: two
// renderers on one context time the same frame each their own way, and both know the frame's
// pass order at once.
TEST(Renderer, TimingMethodIsChosenPerRenderer) {
  auto finish = test::makeRenderer("plane-box", "uniform", timedBy(TimingMethod::FinishWallClock));
  auto query = test::makeRenderer("plane-box", "uniform", timedBy(TimingMethod::TimerQuery));
  ASSERT_TRUE(finish && query);
  ASSERT_FALSE(finish->renderFrame(96, 64, 0));
  ASSERT_FALSE(query->renderFrame(96, 64, 0));
  std::vector<std::string> declared;
  for (const PassDecl& p : framePassDecls(*Renderer::findTechnique("uniform")))
    declared.push_back(p.id);
  EXPECT_EQ(finish->stats().timingMethod, "glFinish+wallclock");
  EXPECT_EQ(finish->stats().timingFramesLate, 0);
  EXPECT_EQ(finish->stats().passOrder, declared);
  EXPECT_EQ(passNames(finish->stats().passes), declared) << "glFinish: this frame's times";
  EXPECT_EQ(query->stats().timingMethod, "GL_TIME_ELAPSED");
  EXPECT_EQ(query->stats().passOrder, declared);
  EXPECT_TRUE(query->stats().passes.empty()) << "no query read back yet";
  test::expectNoGlErrors(*finish);
  test::expectNoGlErrors(*query);
}

// With timer queries each frame's pass order is known at once (FrameStats::passOrder), and the
// times that arrive a frame later carry the names of the frame they timed: the technique or
// its tile count changes every frame, so frames open different passes (and different numbers
// of tile scopes), and frame f's times must name frame f-1's passes, not its own.
TEST(Renderer, TimerQueryTimesNameThePassesOfTheFrameTheyTimed) {
  auto r = test::makeRenderer("plane-box", "uniform", timedBy(TimingMethod::TimerQuery));
  ASSERT_TRUE(r);
  struct Step {
    const char* technique;
    int tiles;  ///< virtual-tiled's n (n x n tiles); 0 for others
  };
  const Step steps[] = {{"uniform", 0},      {"virtual-tiled", 2}, {"virtual-tiled", 3},
                        {"rtw-backward", 0}, {"virtual-tiled", 2}, {"uniform", 0}};
  std::vector<std::string> previousOrder;
  int previousTiles = 0;
  for (std::size_t f = 0; f < std::size(steps); ++f) {
    const Step& step = steps[f];
    SCOPED_TRACE(std::string("frame ") + std::to_string(f) + ": " + step.technique);
    ASSERT_FALSE(r->setTechnique(step.technique));
    if (step.tiles > 0) {
      ASSERT_FALSE(r->params().set("tiles", step.tiles));
      ASSERT_FALSE(r->params().set("tile.resolution", 64));
    }
    glFinish();  // the previous frame's queries are done: this frame reads them
    ASSERT_FALSE(r->renderFrame(80, 60, 0));
    const FrameStats& st = r->stats();
    EXPECT_EQ(st.timingMethod, "GL_TIME_ELAPSED");
    std::vector<std::string> declared;
    for (const PassDecl& p : framePassDecls(*Renderer::findTechnique(step.technique), r->params()))
      declared.push_back(p.id);
    EXPECT_EQ(st.passOrder, declared) << "this frame's passes, known at once";
    if (f == 0) {
      EXPECT_TRUE(st.passes.empty()) << "the first frame has no finished queries yet";
    } else {
      EXPECT_EQ(st.timingFramesLate, 1);
      EXPECT_EQ(passNames(st.passes), previousOrder) << "the times are the previous frame's";
      if (std::string(steps[f - 1].technique) != step.technique) {
        EXPECT_NE(passNames(st.passes), st.passOrder);
      }
      for (const PassTiming& p : st.passes) EXPECT_GE(p.ms, 0.0) << p.name;
      // Per scope: one "tile apply" per tile of the frame that was timed.
      const auto applies =
          std::count_if(st.passSequence.begin(), st.passSequence.end(),
                        [](const PassTiming& p) { return p.name == "tile apply"; });
      EXPECT_EQ(applies, previousTiles * previousTiles);
    }
    previousOrder = st.passOrder;
    previousTiles = step.tiles;
  }
  test::expectNoGlErrors(*r);
}

TEST(Renderer, ProbePixelReadsWhatTheLastFrameReadsBack) {
  // The view's hover readout: one pixel of each target, the same values readback() holds
  // (row 0 = top), covered or not; nothing outside the frame or before one.
  auto r = test::makeRenderer("omni-room", "cube");
  ASSERT_TRUE(r);
  EXPECT_FALSE(r->probePixel(0, 0));  // no frame yet
  ASSERT_FALSE(r->renderFrame(64, 48, 0));
  const FrameReadback f = r->readback();
  int covered = 0, faces = 0;
  for (const auto& [x, y] : {std::pair{0, 0}, {63, 0}, {0, 47}, {63, 47}, {31, 23}, {10, 40}}) {
    const std::optional<PixelProbe> p = r->probePixel(x, y);
    ASSERT_TRUE(p);
    const std::size_t i = std::size_t(y) * 64 + std::size_t(x);
    EXPECT_EQ(p->x, x);
    EXPECT_EQ(p->y, y);
    ASSERT_EQ(p->covered, f.positions[i].w > 0.0f);
    if (!p->covered) continue;
    ++covered;
    faces |= 1 << p->map;
    EXPECT_EQ(p->worldM, glm::vec3(f.positions[i]));
    EXPECT_EQ(p->hard, f.hardMask[i]);
    EXPECT_EQ(p->aliasing, f.aliasing[i]);
    EXPECT_EQ(p->map, int(f.mapIndex[i]));
    EXPECT_EQ(p->mapUv, f.texel[i]);
  }
  EXPECT_GE(covered, 5);
  EXPECT_GT(faces & (faces - 1), 0);  // more than one cube face among the pixels
  EXPECT_FALSE(r->probePixel(64, 0));
  EXPECT_FALSE(r->probePixel(0, 48));
  EXPECT_FALSE(r->probePixel(-1, 3));
  test::expectNoGlErrors(*r);
}

}  // namespace
}  // namespace sl
