// Presets as saved sessions (issue 15 item 4): the new optional fields (the split view's
// compare technique with its own parameters, the window layout) survive presetToJson ->
// loadPreset exactly, every lesson still loads and round-trips, and a bad session is refused
// with the file and the JSON path. No GL context: core/Preset only reads the technique
// declarations (it lives in shadowlab_renderer, which the CPU test binary does not link).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "algo/Params.h"
#include "core/Preset.h"
#include "core/Renderer.h"

namespace sl {
namespace {

namespace fs = std::filesystem;

fs::path writeFile(const std::string& name, const std::string& text) {
  const fs::path dir = fs::path(SHADOWLAB_TEST_OUT) / "gl" / "preset_session";
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

Preset fullSession() {
  Preset p;
  p.title = "my session";
  p.explanation = "what to look at\n\nmore";
  p.scene = "corridor";
  p.technique = "cascades";
  p.params = {{"partitions", "3"},
              {"split", "practical"},
              {"split.lambda", "0.625"},
              {"view.overlay", "aliasing"},
              {"shading.ambient", "0.35"}};
  Camera c;
  c.position = {1.25f, 2.5f, -7.125f};
  c.target = {0.1f, 0.2f, 0.3f};
  c.up = {0.0f, 0.0f, 1.0f};
  c.fovYDeg = 37.5f;
  c.nearM = 0.05f;
  c.farM = 321.0f;
  p.camera = c;
  p.light = Light::spot({1.0f, 6.0f, 2.0f}, {0.1f, -1.0f, 0.2f}, 35.0f, 5.0f, 40.0f);
  p.compare = PresetCompare{"rtw-backward", {{"im.resolution", "256"}}};
  p.layout = PresetLayout{{"parameters", "timing", "light"}, "AAAA/wAAAAD9AAAAAw==", "timing"};
  return p;
}

void expectSame(const Preset& a, const Preset& b) {
  EXPECT_EQ(a.title, b.title);
  EXPECT_EQ(a.explanation, b.explanation);
  EXPECT_EQ(a.scene, b.scene);
  EXPECT_EQ(a.technique, b.technique);
  EXPECT_EQ(a.params, b.params);
  ASSERT_EQ(a.camera.has_value(), b.camera.has_value());
  if (a.camera) {
    EXPECT_EQ(a.camera->position, b.camera->position);
    EXPECT_EQ(a.camera->target, b.camera->target);
    EXPECT_EQ(a.camera->up, b.camera->up);
    EXPECT_EQ(a.camera->fovYDeg, b.camera->fovYDeg);
    EXPECT_EQ(a.camera->nearM, b.camera->nearM);
    EXPECT_EQ(a.camera->farM, b.camera->farM);
  }
  EXPECT_EQ(a.light, b.light);
  EXPECT_EQ(a.compare, b.compare);
  EXPECT_EQ(a.layout, b.layout);
  ASSERT_EQ(a.cases.size(), b.cases.size());
  for (std::size_t k = 0; k < a.cases.size(); ++k) expectSame(a.cases[k], b.cases[k]);
}

std::string loadError(const std::string& name, const std::string& text) {
  const fs::path p = writeFile(name, text);
  std::string error;
  EXPECT_FALSE(loadPreset(p, &error).has_value()) << name;
  const std::string prefix = p.string() + ": ";
  EXPECT_EQ(error.rfind(prefix, 0), 0u) << "the message names the file: " << error;
  return error.substr(std::min(error.size(), prefix.size()));
}

TEST(PresetSession, RoundTripOfEveryFieldIsExact) {
  const Preset saved = fullSession();
  const fs::path p = writeFile("full.json", presetToJson(saved));
  std::string error;
  const std::optional<Preset> loaded = loadPreset(p, &error);
  ASSERT_TRUE(loaded) << error;
  expectSame(saved, *loaded);
  // Written again, byte for byte the same file.
  EXPECT_EQ(presetToJson(*loaded), presetToJson(saved));
}

TEST(PresetSession, SplitViewOffAndEmptyLayoutRoundTrip) {
  Preset saved = fullSession();
  saved.compare = PresetCompare{};  // split off
  saved.layout = PresetLayout{};
  saved.light = Light::directional(-30.5f, 41.25f);
  std::string error;
  const std::optional<Preset> loaded =
      loadPreset(writeFile("off.json", presetToJson(saved)), &error);
  ASSERT_TRUE(loaded) << error;
  expectSame(saved, *loaded);
  ASSERT_TRUE(loaded->compare);
  EXPECT_TRUE(loaded->compare->technique.empty());
}

TEST(PresetSession, OldPresetHasNoCompareNorLayout) {
  std::string error;
  const std::optional<Preset> p =
      loadPreset(writeFile("old.json", R"({"scene": "corridor", "technique": "uniform",
                                "params": {"resolution": 1024, "view.overlay": "aliasing"}})"),
                 &error);
  ASSERT_TRUE(p) << error;
  EXPECT_FALSE(p->compare);
  EXPECT_FALSE(p->layout);
  EXPECT_EQ(p->params.at("resolution"), "1024");
  // Written back, still without the session fields.
  EXPECT_EQ(presetToJson(*p).find("compare"), std::string::npos);
  EXPECT_EQ(presetToJson(*p).find("layout"), std::string::npos);
}

TEST(PresetSession, EveryLessonLoadsAndRoundTrips) {
  const fs::path lessons = fs::path(SHADOWLAB_TEST_DATA) / ".." / ".." / "scenes" / "lessons";
  int count = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(lessons)) {
    if (e.path().extension() != ".json") continue;
    ++count;
    std::string error;
    const std::optional<Preset> lesson = loadPreset(e.path(), &error);
    ASSERT_TRUE(lesson) << error;
    const std::optional<Preset> again = loadPreset(
        writeFile("lesson-" + e.path().filename().string(), presetToJson(*lesson)), &error);
    ASSERT_TRUE(again) << error;
    expectSame(*lesson, *again);
  }
  EXPECT_GE(count, 10);
}

// A lesson's strip shows each parameter under its label: the lesson's texts name it so.
TEST(PresetSession, EveryLessonStripIsNamedInItsTexts) {
  const fs::path lessons = fs::path(SHADOWLAB_TEST_DATA) / ".." / ".." / "scenes" / "lessons";
  int withStrip = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(lessons)) {
    if (e.path().extension() != ".json") continue;
    std::string error;
    const std::optional<Preset> lesson = loadPreset(e.path(), &error);
    ASSERT_TRUE(lesson) << error;
    if (!lesson->layout || lesson->layout->strip.empty()) continue;
    ++withStrip;
    std::string texts = lesson->explanation;
    for (const Preset& c : lesson->cases) texts += "\n" + c.explanation;
    const TechniqueInfo* info = Renderer::findTechnique(lesson->technique);
    ASSERT_NE(info, nullptr) << e.path();
    const ParamSet own(info->params), shared(rendererParamDecls());
    for (const std::string& key : lesson->layout->strip) {
      const ParamDecl* decl = own.has(key) ? own.find(key) : shared.find(key);
      ASSERT_NE(decl, nullptr) << e.path() << ": " << key;
      EXPECT_NE(texts.find(decl->label), std::string::npos)
          << e.path().filename() << ": the strip shows '" << decl->label
          << "', which no text of the lesson names";
    }
  }
  EXPECT_GE(withStrip, 12);
}

TEST(PresetSession, BadCompareIsRefusedNamingThePath) {
  EXPECT_EQ(loadError("c1.json", R"({"compare": {"technique": "rtw-bakward"}})")
                .rfind("compare.technique: unknown technique 'rtw-bakward' (known: ", 0),
            0u);
  EXPECT_EQ(
      loadError("c2.json",
                R"({"compare": {"technique": "rtw-backward", "params": {"im.resolution": 7}}})"),
      "compare.params.im.resolution: parameter 'im.resolution' = 7 is out of range 32..2048");
  // The shared parameters are the main side's: not the compare side's to set.
  EXPECT_EQ(
      loadError("c3.json",
                R"({"compare": {"technique": "uniform", "params": {"view.overlay": "error"}}})"),
      "compare.params.view.overlay: technique 'uniform' has no parameter 'view.overlay'");
  EXPECT_EQ(loadError("c4.json", R"({"compare": {"params": {"resolution": 512}}})"),
            "compare.params: parameters for the split view need \"compare.technique\"");
  EXPECT_EQ(loadError("c5.json", R"({"compare": {"technique": "uniform", "colour": 1}})"),
            "compare.colour: unknown key 'colour' (known: technique, params)");
  EXPECT_EQ(loadError("c6.json", R"({"compare": "uniform"})"),
            "compare: expected an object {...}, got \"uniform\"");
}

TEST(PresetSession, LiveNumbersInTextsAreCheckedAtLoad) {
  EXPECT_EQ(loadError("t1.json", R"({"explanation": "error {error_pct %"})"),
            "explanation: placeholder at byte 6: '{' without '}' (write '{{' for a brace)");
  EXPECT_EQ(loadError("t2.json", R"({"explanation": "right {compare.error_pct}"})"),
            "explanation: {compare.error_pct} quotes the split view's right half, but there is "
            "no \"compare\"");
  EXPECT_EQ(loadError("t3.json", R"({"technique": "uniform", "explanation": "a",
      "cases": [{"title": "x", "explanation": "ok {error_pct:2}"},
                {"title": "y", "explanation": "{pca.e_x:9}"}]})"),
            "cases[1].explanation: placeholder at byte 0: decimals after ':' must be one digit "
            "0..6 in {pca.e_x:9}");
  std::string error;
  const auto ok = loadPreset(writeFile("t4.json", R"({"explanation": "{{a}} {compare.error_pct}",
      "compare": {"technique": "uniform"}})"),
                             &error);
  ASSERT_TRUE(ok) << error;
  EXPECT_EQ(ok->explanation, "{{a}} {compare.error_pct}");  // kept as written, filled live
}

TEST(PresetSession, BadLayoutIsRefusedNamingThePath) {
  EXPECT_EQ(loadError("l1.json", R"({"layout": {"state": "not base64!"}})"),
            "layout.state: expected the window state as base64, got not base64!");
  EXPECT_EQ(loadError("l2.json", R"({"layout": {"docks": "timing"}})"),
            "layout.docks: expected an array [...], got \"timing\"");
  EXPECT_EQ(loadError("l3.json", R"({"layout": {"docks": [3]}})"),
            "layout.docks[0]: expected a string, got 3");
  EXPECT_EQ(loadError("l4.json", R"({"layout": {"docks": [""]}})"),
            "layout.docks[0]: expected a dock name of 1..60 bytes, got \"\"");
  std::string many = R"({"layout": {"docks": [)";
  for (std::size_t i = 0; i <= kMaxPresetLayoutDocks; ++i) many += (i ? ",\"d\"" : "\"d\"");
  many += "]}}";
  EXPECT_EQ(loadError("l5.json", many),
            "layout.docks: more than 64 docks: refused (kMaxPresetLayoutDocks)");
  const std::string big(kMaxPresetLayoutStateBytes + 4, 'A');
  EXPECT_EQ(loadError("l6.json", R"({"layout": {"state": ")" + big + "\"}}"),
            "layout.state: is 65540 bytes, over the limit of 65536 (kMaxPresetLayoutStateBytes)");
  EXPECT_EQ(loadError("l7.json", R"({"layout": {"docks": [], "size": 3}})"),
            "layout.size: unknown key 'size' (known: docks, state, large, strip)");
  EXPECT_EQ(loadError("l8.json", R"({"layout": {"docks": ["lesson"], "large": "timing"}})"),
            "layout.large: names 'timing', which \"docks\" does not list");
}

// A lesson's strip: its keys are parameters of every case's technique (or shared view ones),
// at most three, none twice; the error names the case and the key.
TEST(PresetSession, LessonStripKeysAreCheckedPerCase) {
  EXPECT_EQ(loadError("s1.json", R"({"technique": "uniform",
      "layout": {"docks": ["lesson"], "strip": ["resolution", "blur.radius"]}})"),
            "layout.strip[1]: technique 'uniform' has no parameter 'blur.radius'");
  EXPECT_EQ(loadError("s2.json", R"({"technique": "da-rtw", "explanation": "a",
      "layout": {"strip": ["pca.min_anisotropy"]},
      "cases": [{"title": "turned", "explanation": "b"},
                {"title": "uniform", "explanation": "c", "technique": "uniform",
                 "params": {"resolution": 512}}]})"),
            "layout.strip[0]: case 2 ('uniform'): technique 'uniform' has no parameter "
            "'pca.min_anisotropy'");
  EXPECT_EQ(loadError("s3.json", R"({"layout": {"strip": []}})"),
            "layout.strip: expected 1 to 3 parameter keys, got 0");
  EXPECT_EQ(loadError("s4.json", R"({"layout": {"strip": ["a", "b", "c", "d"]}})"),
            "layout.strip: expected 1 to 3 parameter keys, got 4");
  EXPECT_EQ(loadError("s5.json", R"({"layout": {"strip": ["resolution", "resolution"]}})"),
            "layout.strip[1]: 'resolution' is listed twice");
  EXPECT_EQ(loadError("s6.json", R"({"layout": {"strip": [2]}})"),
            "layout.strip[0]: expected a string, got 2");
  std::string error;
  const auto ok = loadPreset(writeFile("s7.json", R"({"technique": "cascades",
      "layout": {"docks": ["lesson"], "strip": ["split", "view.overlay"]}})"),
                             &error);
  ASSERT_TRUE(ok) << error;
  ASSERT_TRUE(ok->layout);
  EXPECT_EQ(ok->layout->strip, (std::vector<std::string>{"split", "view.overlay"}));
  // Written back, read again: the same strip.
  const auto again = loadPreset(writeFile("s8.json", presetToJson(*ok)), &error);
  ASSERT_TRUE(again) << error;
  EXPECT_EQ(again->layout, ok->layout);
}

// A lesson told in cases: each case is the preset with the case's fields on top; params
// replace, a case in another scene starts from that scene's camera and light.
TEST(PresetSession, CasesAreThePresetWithTheirFieldsOnTop) {
  std::string error;
  const std::optional<Preset> p = loadPreset(writeFile("cases.json", R"({
    "title": "T", "explanation": "intro", "scene": "band-diagonal", "technique": "da-rtw",
    "params": {"resolution": 512},
    "camera": {"position": [1, 2, 3], "target": [0, 0, 0]},
    "compare": {"technique": "rtw-backward", "params": {"resolution": 512}},
    "cases": [
      {"title": "wins", "explanation": "a"},
      {"title": "does not", "explanation": "b", "scene": "diagonal",
       "params": {"pca.min_anisotropy": 0}},
      {"title": "same scene", "explanation": "c", "technique": "uniform",
       "params": {"resolution": 2048}}]})"),
                                             &error);
  ASSERT_TRUE(p) << error;
  ASSERT_EQ(p->cases.size(), 3u);
  const Preset& wins = p->cases[0];
  EXPECT_EQ(wins.title, "wins");
  EXPECT_EQ(wins.explanation, "a");
  EXPECT_EQ(wins.scene, "band-diagonal");
  EXPECT_EQ(wins.params, p->params);
  ASSERT_TRUE(wins.camera);
  EXPECT_EQ(wins.compare, p->compare);
  const Preset& other = p->cases[1];
  EXPECT_EQ(other.scene, "diagonal");
  EXPECT_FALSE(other.camera) << "another scene: its own camera";
  EXPECT_EQ(other.params, (std::map<std::string, std::string>{{"pca.min_anisotropy", "0"}}));
  EXPECT_EQ(other.technique, "da-rtw");
  EXPECT_EQ(other.compare, p->compare);
  const Preset& same = p->cases[2];
  EXPECT_TRUE(same.camera) << "the same scene keeps the preset's camera";
  EXPECT_EQ(same.technique, "uniform");
  for (const Preset& c : p->cases) {
    EXPECT_FALSE(c.layout);
    EXPECT_TRUE(c.cases.empty());
  }
  // Written and read again: the same cases.
  const std::optional<Preset> again =
      loadPreset(writeFile("cases-again.json", presetToJson(*p)), &error);
  ASSERT_TRUE(again) << error;
  expectSame(*p, *again);
}

TEST(PresetSession, BadCasesAreRefusedNamingThePath) {
  EXPECT_EQ(loadError("k1.json", R"({"cases": [{"title": "a", "explanation": "b"}]})"),
            "cases: expected 2 to 8 cases, got 1");
  EXPECT_EQ(loadError("k2.json", R"({"cases": [{"title": "a", "explanation": "b"},
                                               {"title": "c"}]})"),
            "cases[1]: a case needs \"explanation\"");
  EXPECT_EQ(loadError("k3.json", R"({"cases": [{"title": "a", "explanation": "b"},
                                               {"title": "c", "explanation": "d", "layout": {}}]})"),
            "cases[1].layout: unknown key 'layout' (known: title, explanation, scene, technique, "
            "params, camera, light, compare)");
  EXPECT_EQ(loadError("k4.json", R"({"technique": "da-rtw", "params": {"pca.min_anisotropy": 0},
    "cases": [{"title": "a", "explanation": "b"},
              {"title": "c", "explanation": "d", "technique": "uniform"}]})"),
            "cases[1]: a case that names its own \"technique\" gives its own \"params\" (the "
            "preset's are for 'da-rtw')");
  EXPECT_EQ(loadError("k5.json", R"({"technique": "uniform", "cases": [
    {"title": "a", "explanation": "b"},
    {"title": "c", "explanation": "d", "params": {"pca.threshold": 1}}]})"),
            "cases[1].params.pca.threshold: technique 'uniform' has no parameter 'pca.threshold'");
  EXPECT_EQ(loadError("k6.json", R"({"cases": "two"})"),
            "cases: expected an array [...], got \"two\"");
}

}  // namespace
}  // namespace sl
