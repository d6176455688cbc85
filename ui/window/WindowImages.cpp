// The window's images (see WindowImages.h).
#include "window/WindowImages.h"

#include <QDir>
#include <QDockWidget>
#include <QFileDialog>

#include "figures/FigureKit.h"
#include "launch/GrabRun.h"
#include "view/ViewportWidget.h"
#include "window/MainWindow.h"

namespace sl::ui {

namespace {
constexpr int kStatusMessageMs = 10000;

/// Runs `draw` with the view's adaptive resolution held off (its frames at full size).
template <typename Draw>
auto atFullSize(ViewportWidget& view, Draw draw) {
  const bool adaptive = view.frames()->adaptiveAllowed();
  view.frames()->setAdaptiveAllowed(false);
  auto result = draw();
  view.frames()->setAdaptiveAllowed(adaptive);
  return result;
}
}  // namespace

WindowImages::WindowImages(MainWindow& window, GrabRun& grab)
    : QObject(&window), w_(window), grab_(grab) {}

QImage WindowImages::grabViewFullSize() {
  ViewportWidget& view = *w_.viewport();
  return atFullSize(view, [&view] { return view.grabView(); });  // grabView renders a frame
}

QImage WindowImages::grabWindowFullSize() {
  return atFullSize(*w_.viewport(), [this] { return w_.grab().toImage(); });
}

void WindowImages::saveViewImage() {
  const QString path = QFileDialog::getSaveFileName(
      &w_, tr("Save viewport image"), QDir::home().filePath(QStringLiteral("shadowlab.png")),
      tr("PNG images (*.png)"));
  if (path.isEmpty()) return;
  if (auto e = writeViewImage(path))
    w_.report(*e, tr("Save viewport image"));
  else
    w_.showStatus(tr("Saved %1").arg(path));
}

std::optional<QString> WindowImages::writeViewImage(const QString& path) {
  return writeWindowOutput(w_, path, pngBytes(grabViewFullSize()));
}

void WindowImages::exportFigureDialog() {
  const QString path = QFileDialog::getSaveFileName(
      &w_, tr("Export figure"), QDir::home().filePath(QStringLiteral("shadowlab-figure.png")),
      tr("PNG images (*.png)"));
  if (path.isEmpty()) return;
  if (auto e = exportFigure(path))
    w_.report(*e, tr("Export figure"));
  else
    w_.showStatus(tr("Saved %1").arg(path));
}

std::optional<QString> WindowImages::exportFigure(const QString& path) {
  constexpr int kDilatePx = 1;  // single-pixel error lines survive printing
  const std::vector<FigureCell> cells = w_.viewport()->measure()->figureCells(kDilatePx);
  if (cells.empty()) return tr("export figure: no frame to export yet");
  const sl::Light& light = w_.viewport()->camera()->light();
  const QString kind = light.type == sl::LightType::Directional ? tr("directional")
                       : light.type == sl::LightType::Spot      ? tr("spot")
                                                                : tr("point");
  const QString title =
      tr("%1, %2x%3, %4 light; below each image its errors against the exact reference "
         "(magenta: wrongly lit, cyan: wrongly shadowed; drawn %5 px wider)")
          .arg(w_.sceneSpec())
          .arg(cells.front().shaded.width)
          .arg(cells.front().shaded.height)
          .arg(kind)
          .arg(kDilatePx);
  return writeWindowOutput(w_, path,
                           pngBytes(drawFigure(cells, title.toStdString(), 0, std::nullopt)));
}

void WindowImages::savePanelImage(QDockWidget* dock) {
  const QString name = QStringLiteral("shadowlab-%1.png").arg(dock->objectName());
  const QString path = QFileDialog::getSaveFileName(
      &w_, tr("Save panel image"), QDir::home().filePath(name), tr("PNG images (*.png)"));
  if (path.isEmpty()) return;
  if (auto e = writeWindowOutput(w_, path, pngBytes(dock->grab().toImage())))
    w_.report(*e, tr("Save panel image"));
  else
    w_.showStatus(tr("Saved %1").arg(path), kStatusMessageMs);
}

void WindowImages::saveAllImages() {
  const QString dir = QFileDialog::getExistingDirectory(&w_, tr("Save window and all panels into"),
                                                        QDir::homePath());
  if (dir.isEmpty()) return;
  // Every image at full size: adaptive resolution held off while they are drawn.
  const QStringList failures =
      atFullSize(*w_.viewport(), [this, &dir] { return grab_.writeImages(dir, false); });
  if (failures.isEmpty())
    w_.showStatus(tr("Saved the window and every panel in %1").arg(dir), kStatusMessageMs);
  else
    w_.report(failures.join(QLatin1Char('\n')), tr("Save images"));
}

}  // namespace sl::ui
