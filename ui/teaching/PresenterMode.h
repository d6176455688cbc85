// Presenter mode (F11, View > Presenter mode, --presenter): the window for a projector.
// Fonts scaled to the screen (Theme: presenterBodyPixelSize), the high-contrast theme, the
// window filling the screen, ONE big publication panel beside the view (the one the user
// picked in View > Presenter panel, else the first visible panel that shows the technique's
// data; the Lesson and Parameters tabbed behind it, the lesson's strip of parameters under
// it, every other dock hidden), a ring
// following the pointer over the view. Leaving it restores font, theme, docks and geometry.
// The big panel full screen (F12, View > Big panel full screen; presenter mode turns on with
// it): the view, the tool bars, the status line and the panels tabbed behind are hidden and
// the panel fills the window under the menu bar; F12 again brings the view back beside it.
// Explicit fonts follow the body size through Theme.h's bodyRelativeFont / followBodyFont.
#pragma once

#include <functional>

#include <QByteArray>
#include <QFont>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QString>

class QAction;
class QDockWidget;
class QMenu;
class QWidget;

namespace sl::ui {

class MainWindow;

class PresenterMode : public QObject {
  Q_OBJECT

 public:
  explicit PresenterMode(MainWindow& window);

  /// Adds "Presenter mode" (F11) and the "Presenter panel" choice to `view`.
  void createActions(QMenu* view);
  QAction* action() const { return action_; }
  QAction* fullPanelAction() const { return fullPanelAction_; }

  bool active() const { return active_; }
  void setActive(bool on);

  /// The big panel's dock while active (null otherwise or when no panel applies).
  QDockWidget* bigDock() const;
  /// The big panel full screen (the view hidden); turning it on turns presenter mode on,
  /// leaving presenter mode turns it off.
  void setFullPanel(bool on);
  bool fullPanel() const { return fullPanel_; }
  /// The user's choice of big panel (by dock object name; empty: automatic).
  void choosePanel(const QString& dockName);
  /// A lesson's or session's layout was applied: its large panel (dock object name; empty:
  /// none) is the big panel unless the user chose one, and, while active, the docks are
  /// arranged again and the window fitted to the screen.
  /// `others`: the layout's other docks; up to kMaxPanelsBelow of them (not the Lesson or
  /// Parameters, which stay tabbed behind the big panel) are shown under it, so a lesson's
  /// panels are in view together (e.g. Shadow map over Light, Pages over Timing).
  void setLessonPanel(const QString& dockName, const QStringList& others = {});
  static constexpr int kMaxPanelsBelow = 2;
  /// Panels under the big one only on screens at least this tall: on smaller ones (1280x800)
  /// two panels at the presenter's font do not fit (their content grows once data arrives).
  static constexpr int kMinScreenHeightForPanelsBelow = 1000;
  /// Share of the height the big panel keeps when panels stand under it (they and the lesson's
  /// strip share the rest): a panel the layout names is shown under it only while the panels
  /// there (at their minimum height) and the strip fit in that rest of the screen's height;
  /// else it is tabbed behind it.
  static constexpr double kMinBigPanelShare = 0.6;
  /// Share of the window's width the big panel takes.
  static constexpr double kPanelShare = 0.42;
  /// Where its plots and images do not read at that width (the window would be taller than
  /// the screen), the big panel is widened in steps of kPanelShareStep up to this share
  /// before it gives up its readable size: a panel that lays its content out by its width
  /// (Partitions' maps in one row, the Covariance panel's numbers in two columns) may then
  /// be short enough; the view keeps the rest.
  static constexpr double kMaxPanelShare = 0.6;
  static constexpr double kPanelShareStep = 0.03;

  /// After a frame: the first few frames after an arrangement give the big panel its share of
  /// the width again where its content, filled now, allows it (a panel still holding the last
  /// lesson's wider content kept its width, and the next lesson's view was narrower than
  /// when opened alone). When the panels make the window taller than its screen, the
  /// docks are arranged again (a panel that no longer fits under the big one goes behind it)
  /// and the window fits the screen. The arrangement measures the panels as they are; a panel
  /// shown before its first frame grows when the frame arrives.
  void keepOnScreen();
  /// A lesson settled: a big panel that gave up its readable size while the lesson was being
  /// arranged (the last lesson's content still in it) asks for it once more (once per
  /// arrangement), now that it shows this lesson's data (LessonController::reportFit measures
  /// after this).
  void askReadableSettled();

 private:
  void arrangeDocks();
  void sizeBigDock();
  /// Asks the big panel's plots and images for their readable sizes (setReadableMinimums), and
  /// gives that up where the window would then not fit its screen; true when they have them.
  bool askReadable();
  /// The big panel takes what there is on the screen: its content outgrew it.
  void giveUpReadable();
  bool eventFilter(QObject* watched, QEvent* event) override;
  /// Runs `change` (a re-arrangement or a new width of the big panel) and lays the window out;
  /// a lesson whose view changed size settles again.
  void resizeView(const std::function<void()>& change);
  void fitScreen();
  QDockWidget* pickBigDock() const;

  MainWindow& w_;
  QAction* action_ = nullptr;
  QAction* fullPanelAction_ = nullptr;
  bool fullPanel_ = false;
  QList<QWidget*> hiddenForPanel_;  ///< tool bars and status line the full panel hid
  QMenu* panelMenu_ = nullptr;
  bool active_ = false;
  double panelShare_ = kPanelShare;  ///< the big panel's share of the width (askReadable)
  QString chosen_;            ///< View > Presenter panel (dock object name), empty: automatic
  QString lessonPanel_;       ///< the applied layout's large panel (dock object name), or empty
  QStringList lessonOthers_;  ///< the layout's other docks (object names)
  QPointer<QDockWidget> big_;
  QByteArray savedState_, savedGeometry_;
  QFont savedFont_;
  bool savedMaximized_ = false;
  bool askedSettled_ = false;    ///< askReadableSettled asked since the last arrangement
  bool giveUpQueued_ = false;    ///< giveUpReadable is queued
  int rearrangedForGrowth_ = 0;  ///< times giveUpReadable arranged the docks again this lesson
  static constexpr int kMaxRearrangedForGrowth = 2;
  int keptOnScreen_ = 0;      ///< times keepOnScreen re-arranged since the last arrangement
  int fedSinceArranged_ = 0;  ///< frames fed to the panels since the last arrangement
  static constexpr int kMaxKeepOnScreen = 3;
  /// The frames after an arrangement that may give the big panel its share of the width again.
  static constexpr int kFeedsResized = 3;
};

}  // namespace sl::ui
