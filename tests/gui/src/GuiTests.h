// The GUI tests (`shadowlab-gui-tests --test NAME[=ARG] [shadowlab options]`, driven by
// tests/gui/*.sh under Xvfb; the names and their arguments: GuiTests::all()). They drive the
// real window through ui/Automation.h and its public parts as a user would and check what the
// renderer and the window did; each check prints "ok   ..." or "FAIL ...", then "PASS" or
// "FAIL"; exit 0 = pass. The tests of a family live in GuiTests<Family>.cpp.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <QObject>
#include <QRect>
#include <QSize>
#include <QString>

#include "Automation.h"
#include "core/Preset.h"
#include "core/Renderer.h"

class QAction;
class QTimer;

namespace sl::ui {

class MainWindow;
class PublicationPanel;

struct HeartbeatClock;  // GuiTestsHeartbeat.cpp

class GuiTests : public QObject {
  Q_OBJECT

 public:
  /// A test: its name, its argument's form ("" none, "=DIR", "[=DIR]", ...) and its body.
  struct Test {
    const char* name;
    const char* argument;
    bool (*run)(GuiTests& tests, const QString& argument);
  };
  /// Every GUI test, in one list (the command line checks names against it).
  static const std::vector<Test>& all();
  static const Test* find(const QString& name);
  /// "params, bad-gltf=FILE[,FILE...], ...": for usage messages.
  static QString usage();

  /// Drives `window` (an Automation of it, a child of the window).
  explicit GuiTests(MainWindow& window);

  /// Runs `test` once the renderer has drawn its first frames: exits 0 (pass) or 1.
  void start(const Test& test, const QString& argument);

 private:
  void run(const Test& test);
  bool params();
  /// bad-gltf=FILE[,FILE…]: each broken file opened through File > Open, then dropped on
  /// the window; each time the error is shown (elided) and the scene stays.
  bool badGltf(const QString& paths);
  /// bad-session=FILE[,FILE…]: each broken session opened through File > Open session…, then
  /// dropped on the window; each time the error is shown (elided) and the scene, technique,
  /// parameters and split view stay.
  bool badSession(const QString& paths);
  /// badGltf and badSession: each file opened through `open` (the menu item called
  /// `menuName`, driving its file dialog), then dropped on the window.
  bool badFiles(const QString& paths, QAction* open, const QString& menuName);
  void badFileOpen(const QString& path, QAction* open, const QString& menuName, bool drop);
  /// What a refused file must leave unchanged: scene, technique, parameters, split view.
  struct ViewState {
    std::shared_ptr<const sl::Scene> scene;
    QString sceneSpec;
    std::string technique, splitTechnique;
    sl::ParamSet params, shared;
    std::map<std::string, std::string> splitParams;
    bool operator==(const ViewState&) const = default;
  };
  ViewState viewState() const;
  /// Pass stepping, overlays, split view and lessons; PNGs of each step into `dir`.
  bool teaching(const QString& dir);
  /// A tiny Charts sweep, its PNG into `dir`, and a click on a point switching the view.
  bool charts(const QString& dir);
  /// Part of charts(): x: memory and back through the combo box (axis, front).
  bool chartsAxis(const QString& dir);
  /// Part of charts(): a sweep of a sky-only view: its error n/a (no point, the status says so).
  bool chartsUnmeasured();
  /// split-resize[=TECHNIQUE]: the split view measures the same errors after the window
  /// was shrunk to 3x3 and restored.
  bool splitResize(const QString& splitTechnique);
  /// omni-probe[=DIR]: the mouse over the view (no button) puts the Omni map's marker on the
  /// face or hemisphere and uv algo/omni computes for that pixel's direction from the light;
  /// leaving the view removes it. PNG of the window into `dir`.
  bool omniProbe(const QString& dir);
  /// Part of omniProbe: the Omni map's texel-density view (one log2 texels/sr scale for both
  /// mappings) and its value under the cursor at a face's / disc's centre and its corner / rim,
  /// against algo/omni's density there; then back to depth.
  void omniMapReadout(PublicationPanel* panel, bool cube);
  /// session-save=FILE: a state far from the defaults (scene, technique, parameters, overlay,
  /// camera, light, a split technique with its own parameters, a hidden dock), its metrics
  /// printed ("metric ..." lines), saved to FILE through SessionFiles; Recent sessions lists
  /// it and drops a deleted one; a malformed session is refused and changes nothing.
  bool sessionSave(const QString& path);
  /// session-check: the same "metric ..." lines for the state the window started in
  /// (tests/gui/session_roundtrip.sh starts it with --open-session FILE and compares).
  bool sessionCheck();
  /// output-policy=DIR: the window's writers (Save session, Export figure, the image
  /// exports' writeWindowOutput) refuse the scene's own files in DIR (its glTF, and its
  /// buffer named viewport.png), a symbolic link to one, a FIFO (at once, not waiting for a
  /// reader); each leaves the file as it was; a new file is written whole, no temporary left.
  bool outputPolicy(const QString& dir);
  /// presenter[=DIR] (GuiTestsPresenter.cpp): presenter mode at the screen's size: the
  /// window fits, body text >= 22 px x min(w / 1920, h / 1080), one panel with an image >=
  /// 35 % of the screen's height, the changed overlay's vivid pixels = the renderer's count,
  /// pointer ring, zoom inset (nearest neighbour), ticks; every dock's fonts (widgets, dock
  /// titles, Qt Charts items) >= 80 % of the body size and the Timing panel's pass names
  /// drawn whole with it the big panel; the big panel full screen (F12) and back; PNGs into DIR.
  bool presenter(const QString& dir);
  void checkPresenterFonts(const QString& dir, const QSize& screen);
  /// The view's overlay with everything on (banner, pause badge, outside legend, split
  /// captions, each legend, note, zoom inset) at `view`'s size and two smaller: no box covers
  /// another or leaves the view; overlay-boxes.png into DIR.
  void checkOverlayBoxes(const QString& dir, const QSize& view);
  void checkFullPanel(const QString& dir, const QRect& screen);
  /// split-params[=DIR] (GuiTestsPresenter.cpp): the compare side's own parameter panel
  /// (a resolution edit changes its memory, not the main side's) and "equal memory".
  bool splitParams(const QString& dir);
  /// The view pinned to 640x400, a few frames, the error computed; prints the metrics.
  void printSessionMetrics();
  /// live-error[=DIR]: continuous rendering (F6) keeps the error live: a number and the reference's
  /// age within a time limit, equal to the error computed synchronously for the same frame;
  /// a camera move makes it stale, then fresh again; a scene change mid-trace drops the
  /// trace; the window then closes while a trace runs (GuiTestsLive.cpp).
  bool liveError(const QString& dir);
  /// adaptive-resolution[=DIR]: a slow technique's frame (over the 250 ms budget) drops the view's
  /// internal resolution with a note in the view; frames then render at the lower size; a
  /// large budget climbs back to full size; view.adaptive off renders at full size. PNGs of
  /// the window (live error) and the reduced view into DIR when given.
  bool adaptiveResolution(const QString& dir);
  /// no-freeze[=DIR]: continuous rendering of virtual-tiled at its defaults resolves its
  /// tiles progressively: a 20 ms heartbeat timer never waits 1 s or more, partial frames
  /// say "tile k of 256", a complete frame arrives, and it equals the one-call frame pixel
  /// for pixel with the same error (live vs synchronous). PNGs into DIR when given.
  bool noFreeze(const QString& dir);
  /// heartbeat[=DIR] (GuiTestsHeartbeat.cpp): the UI thread never stalls while fvsm,
  /// virtual-tiled and da-rtw render continuously, still and while the camera is dragged: a
  /// 10 ms heartbeat timer's longest stall (gap minus interval) stays under 100 ms; the figures
  /// are printed per technique and phase. PNGs of the busy view into DIR when given.
  bool heartbeat(const QString& dir);
  /// The heartbeat while O, Ctrl+E, F5, Export figure, Save viewport image and Equal memory
  /// run (the window waits for the render thread in each); the worst stall.
  qint64 heartbeatActions(const QString& dir, HeartbeatClock& hb);
  /// storage-click[=DIR] (GuiTestsStorage.cpp): a click on the Storage factor panel's
  /// hemisphere moves the light to the direction there (the paper's Fig. 7 frame of this
  /// camera, from algo/partition), the status bar says so, the panel re-analyses with the
  /// mark under the click; a click outside the disk keeps the light. PNGs into DIR.
  bool storageClick(const QString& dir);
  /// panels (GuiTestsPanels.cpp, started without --technique): the window opens on DA-RTW
  /// with its panels open and filled; a switch shows the new technique's panels and closes
  /// the ones it does not feed, except one opened by hand from View > Panels, which stays
  /// until it is closed; no panel in view shows its "publishes no ..." placeholder.
  bool panelsFollowTechnique();
  /// course[=DIR] (started with --course NAME): Next in the Lesson dock opens each of the
  /// course's lessons in its order, the dock shows "Course N min: K of M · ~T min" and the
  /// lesson's sentence; Next is off at the last, Previous goes back one, and a lesson outside
  /// the course ends it. The Lesson dock at each lesson is saved to DIR.
  bool course(const QString& dir);
  /// course-claims[=DIR] (started with --course NAME, as a lecturer: --presenter): Next from
  /// the course's first lesson to its last; after each Next, once the lesson has settled, the
  /// checks lesson-claims makes of a lesson opened alone (technique, layout, the window on its
  /// screen, live numbers, the claims). The window at each lesson is saved to DIR.
  bool courseClaims(const QString& dir);
  /// course-grabs=DIR (started with --course NAME --presenter; scripts/grab_lessons.sh with
  /// COURSE): Next from the course's first lesson to its last, each lesson's window saved as
  /// DIR/<lesson>.png once it has settled and its panels are filled (a lesson told in cases:
  /// each further case as DIR/<lesson>-case<K>.png), its fit note printed. No claims.
  bool courseGrabs(const QString& dir);
  /// Prints the big panel's size against its least size with every plot and image readable.
  void printReadableNeed();
  /// shortcuts (GuiTestsShortcuts.cpp): with a Parameters slider, then a dock's list or tree
  /// focused, V (outside view), F6 (continuous), Space (pause), O (overlay) and W held (fly)
  /// act and the focus stays; V and Space from one widget of every kind and from a floating
  /// dock; ".", "]" and Esc step a frame and the passes; typed into a spin box, V, Space and
  /// W do not, F6 does; a drag in the view orbits 180° per view height, a wheel notch moves
  /// 15 % of the distance; F1 lists every command and no two share a key.
  bool shortcuts();
  /// turn-prediction[=DIR]: the Covariance panel on band-diagonal draws the predicted score of
  /// every turn with its markers, its state says why the rotation turned, and "Measure the
  /// error at these turns" measures the fixed turns on the render thread while the window
  /// keeps answering; the truth and the prediction agree on the best turn. The panel's PNG
  /// into DIR.
  bool turnPrediction(const QString& dir);
  /// A malformed session opened through SessionFiles: refused, named, nothing changed.
  void badSessionOpen(const QString& path);
  /// lesson-claims[=DIR] (with --lesson NAME): the lesson the app started with, once settled;
  /// its layout (listed docks only, the large one large) and, for the lessons that state one,
  /// its claim measured with the numbers read from its own text (perspective aliasing: m bands
  /// and thin error lines; projective aliasing: the floor's m at a low and a high sun;
  /// tessellation: the error without it against with it; RTW: below uniform in the split view; PCA:
  /// the settled angle; vibration: changed pixels per frame, none once held). A PNG of the window
  /// into DIR.
  bool lessonClaims(const QString& dir);
  /// lesson-claims' checks of the lesson open now (index into the Lessons menu).
  void checkOpenLesson(int index, const QString& dir);
  void lessonReadable(const sl::PresetLayout& layout);
  void lessonLayout(const sl::PresetLayout& layout);
  /// A lesson's strip: in view and whole, an editor per key; none without one.
  void lessonStrip(const sl::PresetLayout& layout);
  /// The lesson's window fits its screen, its text's live numbers are filled, no label cuts
  /// its text and no table cell or header in view is elided.
  void lessonOnScreen(const QString& name);
  void claimPerspective(const QString& text);
  void claimProjective(const QString& text);
  void claimTessellation(const QString& text);
  void claimRtw();
  void claimPca(int lessonIndex);
  void claimPcaCase(const sl::Preset& lessonCase, int caseNumber);
  /// The Covariance panel's readouts against the renderer's publication of the same frame.
  void checkCovarianceReadouts(const QString& where);
  void claimVibration(const QString& text);
  // Lessons 5 and 8-12 (GuiTestsLessons.cpp): each changes one thing the lesson's text names
  // (technique, Warp eta, split scheme, tessellation, resolution) and measures the main view.
  struct LessonNumbers {
    double errorPct = 0.0;  ///< against the ray-traced reference
    double mP95 = 0.0;      ///< m's 95th percentile over the covered pixels (exact)
    std::uint64_t bytes = 0;
    double frameMs = 0.0;
  };
  LessonNumbers measureLesson();
  /// Sets the current technique's parameter `key` (a failure is a check), then renders
  /// `frames` frames.
  void lessonSet(const char* key, const QString& value, int frames = 2);
  /// Switches the technique as the Technique list does, sets `params` before its first frame
  /// renders, then renders `frames` frames (`timeoutMs` for slow techniques).
  void lessonSwitch(const QString& technique,
                    const std::vector<std::pair<const char*, QString>>& params, int frames = 3,
                    int timeoutMs = 30000);
  void claimForwardBackward(const QString& text);
  void claimPerspectiveWarp(const QString& text);
  void claimDuelingFrusta(const QString& text);
  void claimCascades(const QString& text);
  void claimOmni(const QString& text);
  void claimFvsm(const QString& text);
  void claimAsm(const QString& text);
  /// The main view's error against the reference, with its per-pixel readback.
  sl::Renderer::ErrorResult measureView();
  void check(bool ok, const QString& what);
  /// Automation::waitForFrames, a failed check when the frames did not come in `timeoutMs`.
  bool waitForFrames(int frames, int timeoutMs = 30000);
  /// Starts `driver` closing each message box as a user would, its text read into `text`
  /// first (the caller stops it).
  void readAndCloseDialogs(QTimer& driver, QString& text);

  MainWindow& w_;
  Automation& auto_;
  QString argument_;
  int failures_ = 0;
};

}  // namespace sl::ui
