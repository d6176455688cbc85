// The window's images: File > Save viewport image, Export figure (renderer/figures/FigureKit.h),
// Save panel image and Save window and all panels, and the full-size grabs of the view and of
// the window that ui/Automation.h takes. Every image is drawn at full size: adaptive
// resolution is held off for the frame it needs.
#pragma once

#include <optional>

#include <QImage>
#include <QObject>
#include <QString>

class QDockWidget;

namespace sl::ui {

class GrabRun;
class MainWindow;

class WindowImages : public QObject {
  Q_OBJECT

 public:
  WindowImages(MainWindow& window, GrabRun& grab);

  /// The view as shown (ViewportWidget::grabView), rendered for it at full size.
  QImage grabViewFullSize();
  /// The whole window likewise (its view at full size).
  QImage grabWindowFullSize();
  /// Writes the figure (ViewportWidget::figureCells) to `path`; the problem, or nothing.
  std::optional<QString> exportFigure(const QString& path);
  /// Writes the view as shown at full size (grabViewFullSize) to `path`; the problem, or nothing.
  std::optional<QString> writeViewImage(const QString& path);

  // The File menu's commands: each asks for a file (or folder) and reports the outcome.
  void saveViewImage();
  void exportFigureDialog();
  void savePanelImage(QDockWidget* dock);
  void saveAllImages();

 private:
  MainWindow& w_;
  GrabRun& grab_;
};

}  // namespace sl::ui
