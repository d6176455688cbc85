// Sessions (see SessionFiles.h): the window's state written as a preset, opened as a lesson.
#include "window/SessionFiles.h"

#include <QAction>
#include <QDateTime>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

#include "launch/GrabRun.h"
#include "teaching/LessonController.h"
#include "window/MainWindow.h"
#include "teaching/PresenterMode.h"
#include "view/ViewportWidget.h"

namespace sl::ui {

namespace {
const QString kRecentKey = QStringLiteral("sessions/recent");
constexpr int kStateVersion = 1;  ///< QMainWindow::saveState's version in a session
const QString kFilter = QStringLiteral("ShadowLab sessions and lessons (*.json)");
constexpr int kLargeDockPercent = 45;  ///< a lesson's large dock: share of the window
}  // namespace

QFileDialog::Options SessionFiles::dialogOptions() const {
  // A script (ui/Automation.h) drives Qt's own dialog.
  return w_.scripted() ? QFileDialog::DontUseNativeDialog : QFileDialog::Options();
}

SessionFiles::SessionFiles(MainWindow& window) : QObject(&window), w_(window) {
  if (w_.interactive()) recent_ = QSettings().value(kRecentKey).toStringList().mid(0, kMaxRecent);
}

void SessionFiles::createMenu(QMenu* file) {
  QAction* open = file->addAction(tr("Open sess&ion…"), this, [this] {
    const QString path = QFileDialog::getOpenFileName(&w_, tr("Open session"), QString(), kFilter,
                                                      nullptr, dialogOptions());
    if (!path.isEmpty()) this->open(path);
  });
  open->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O));
  QAction* save = file->addAction(tr("Save sessi&on…"), this, [this] {
    QString path = QFileDialog::getSaveFileName(&w_, tr("Save session"), QString(), kFilter,
                                                nullptr, dialogOptions());
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".json");
    this->save(path);
  });
  save->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_S));
  recentMenu_ = file->addMenu(tr("&Recent sessions"));
  recentMenu_->setObjectName(QStringLiteral("recentSessionsMenu"));
  connect(recentMenu_, &QMenu::aboutToShow, this, &SessionFiles::fillRecentMenu);
  fillRecentMenu();
  w_.addCommandAction(open);
  w_.addCommandAction(save);
  openAction_ = open;
  saveAction_ = save;
}

sl::Preset SessionFiles::current(const QString& path) const {
  sl::Preset p;
  p.title = QFileInfo(path).completeBaseName().toStdString();
  const int lesson = w_.lessons()->index();
  if (lesson >= 0)
    p.explanation = w_.lessons()->lessons()[static_cast<std::size_t>(lesson)].preset.explanation;
  const QFileInfo sceneFile(w_.sceneSpec());
  p.scene = (sceneFile.isFile() ? sceneFile.absoluteFilePath() : w_.sceneSpec()).toStdString();
  p.technique = w_.viewport()->techniqueId();
  if (sl::ViewSide* r = w_.viewport()->mainSide()) {
    for (const sl::ParamSet* set : {&r->params(), &r->rendererParams()})
      for (const sl::ParamDecl& d : set->decls()) p.params[d.key] = set->format(d.key);
  }
  p.camera = w_.viewport()->camera()->camera();
  p.light = w_.viewport()->camera()->light();
  p.compare = sl::PresetCompare{w_.viewport()->frames()->splitTechnique(),
                                w_.viewport()->frames()->splitParams()};
  sl::PresetLayout layout;
  for (QDockWidget* dock : w_.findChildren<QDockWidget*>())
    if (dock->toggleViewAction()->isChecked())
      layout.docks.push_back(dock->objectName().toStdString());
  layout.state = w_.saveState(kStateVersion).toBase64().toStdString();
  p.layout = layout;
  return p;
}

bool SessionFiles::save(const QString& path) {
  const std::string text = sl::presetToJson(current(path)) + "\n";
  // The output policy (GrabRun.h): never over the scene's files, atomically.
  if (auto e = writeWindowOutput(w_, path, QByteArray::fromStdString(text), true)) {
    w_.report(*e, tr("Cannot save session"));
    return false;
  }
  remember(path);
  w_.info(tr("Session saved to %1").arg(path));
  return true;
}

bool SessionFiles::open(const QString& path) {
  if (!w_.lessons()->startFile(path, tr("Cannot open session"))) return false;
  remember(path);
  return true;
}

void SessionFiles::applyLayout(const sl::PresetLayout& layout, QStringList* problems) {
  applyLayoutDocks(layout, problems);
  // The layout's large panel is presenter mode's one big panel, and the window stays on the
  // screen (the docks just shown at the large font may want more). Told also while presenter
  // mode is off: it may come on later (F11, or --presenter after a lesson laid out its docks).
  QStringList others;
  for (const std::string& dock : layout.docks) others << QString::fromStdString(dock);
  w_.presenter()->setLessonPanel(QString::fromStdString(layout.large), others);
}

void SessionFiles::applyLayoutDocks(const sl::PresetLayout& layout, QStringList* problems) {
  if (!layout.state.empty() &&
      !w_.restoreState(QByteArray::fromBase64(QByteArray::fromStdString(layout.state)),
                       kStateVersion))
    *problems << tr("the window layout in the session could not be restored");
  if (layout.docks.empty() && !layout.state.empty()) return;  // the state alone decides
  // A lesson names its docks without a state: they go where the default layout puts them.
  if (layout.state.empty() && !layout.docks.empty()) w_.applyDefaultLayout();
  QStringList wanted;
  for (const std::string& name : layout.docks) wanted << QString::fromStdString(name);
  const QList<QDockWidget*> docks = w_.findChildren<QDockWidget*>();
  for (const QString& name : wanted) {
    bool known = false;
    for (const QDockWidget* dock : docks) known = known || dock->objectName() == name;
    if (!known)
      *problems << tr("the session shows a panel '%1' this build does not have").arg(name);
  }
  for (QDockWidget* dock : docks) {
    const bool on = wanted.contains(dock->objectName());
    if (dock->toggleViewAction()->isChecked() != on) dock->setVisible(on);
  }
  // Listed docks sharing a tab group: the first listed is in front.
  for (auto it = wanted.crbegin(); it != wanted.crend(); ++it)
    if (QDockWidget* dock = w_.findChild<QDockWidget*>(*it)) dock->raise();
  if (layout.large.empty()) return;
  QDockWidget* large = w_.findChild<QDockWidget*>(QString::fromStdString(layout.large));
  if (!large) return;  // reported above
  // The telling panel: most of its side of the window (the view keeps the rest).
  large->raise();
  const Qt::DockWidgetArea area = w_.dockWidgetArea(large);
  const bool vertical = area == Qt::TopDockWidgetArea || area == Qt::BottomDockWidgetArea;
  const int share =
      vertical ? w_.height() * kLargeDockPercent / 100 : w_.width() * kLargeDockPercent / 100;
  w_.resizeDocks({large}, {share}, vertical ? Qt::Vertical : Qt::Horizontal);
}

QStringList SessionFiles::recent() {
  QStringList kept;
  for (const QString& path : recent_) {
    if (QFileInfo(path).isFile())
      kept << path;
    else
      w_.report(tr("recent session %1 no longer exists: removed from the list").arg(path));
  }
  if (kept != recent_) {
    recent_ = kept;
    storeRecent();
  }
  return recent_;
}

void SessionFiles::remember(const QString& path) {
  const QString absolute = QFileInfo(path).absoluteFilePath();
  recent_.removeAll(absolute);
  recent_.prepend(absolute);
  recent_ = recent_.mid(0, kMaxRecent);
  storeRecent();
}

void SessionFiles::storeRecent() {
  if (w_.interactive()) QSettings().setValue(kRecentKey, recent_);
}

void SessionFiles::fillRecentMenu() {
  recentMenu_->clear();
  const QStringList paths = recent();
  for (int i = 0; i < paths.size(); ++i) {
    QAction* a = recentMenu_->addAction(tr("&%1 %2").arg(i + 1).arg(QFileInfo(paths[i]).fileName()),
                                        this, [this, path = paths[i]] {
                                          if (!QFileInfo(path).isFile()) {
                                            recent();  // drops it, with the message
                                            return;
                                          }
                                          open(path);
                                        });
    a->setToolTip(paths[i]);
  }
  if (paths.isEmpty()) recentMenu_->addAction(tr("(none yet)"))->setEnabled(false);
  recentMenu_->setToolTipsVisible(true);
}

}  // namespace sl::ui
