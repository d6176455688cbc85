// The output-policy GUI test (see GuiTests.h): every file the window writes goes through
// algo/OutputFile.h's policy (ui/launch/GrabRun.h, writeWindowOutput); tests/gui/grab_outputs.sh
// starts it on a scene whose buffer is named like a grab's output and checks --grab itself.
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QTimer>

#include "launch/GrabRun.h"
#include "GuiTests.h"
#include "window/MainWindow.h"
#include "window/SessionFiles.h"

namespace sl::ui {

namespace {
QByteArray contents(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}
}  // namespace

bool GuiTests::outputPolicy(const QString& dirPath) {
  const QDir dir(dirPath);
  const QString scene = dir.filePath(QStringLiteral("scene.gltf"));
  const QString buffer = dir.filePath(QStringLiteral("viewport.png"));
  const QString link = dir.filePath(QStringLiteral("link.json"));
  const QString fifo = dir.filePath(QStringLiteral("fifo.png"));
  check(QFileInfo(auto_.sceneShown()).canonicalFilePath() == QFileInfo(scene).canonicalFilePath(),
        tr("the window shows %1").arg(scene));
  const QByteArray sceneBytes = contents(scene), bufferBytes = contents(buffer);
  check(!sceneBytes.isEmpty() && !bufferBytes.isEmpty(), tr("the scene's files are there"));

  // File > Save session onto the scene's glTF, its buffer, a link to the glTF: refused, the
  // error dialog read and closed as a user would.
  QString dialogText;
  QTimer driver;
  readAndCloseDialogs(driver, dialogText);
  for (const QString& path : {scene, buffer, link}) {
    dialogText.clear();
    const bool saved = auto_.saveSession(path);
    check(!saved && dialogText.contains(QStringLiteral("is the same file as")),
          tr("Save session %1 refused: \"%2\"").arg(path, dialogText.left(200)));
    check(contents(scene) == sceneBytes && contents(buffer) == bufferBytes,
          tr("after Save session %1 the scene's files are unchanged").arg(path));
  }
  // File > Export figure onto the buffer: refused, named.
  const std::optional<QString> figure = auto_.exportFigure(buffer);
  check(figure && figure->contains(QStringLiteral("the same file as the scene's file")),
        tr("Export figure onto the scene's buffer refused: %1").arg(figure.value_or(QString())));
  check(contents(buffer) == bufferBytes, tr("the buffer is unchanged"));
  // Save viewport / panel image (writeWindowOutput): a FIFO is refused at once, not waited on.
  QElapsedTimer clock;
  clock.start();
  const std::optional<QString> toFifo = writeWindowOutput(w_, fifo, pngBytes(w_.grab().toImage()));
  check(toFifo && toFifo->contains(QStringLiteral("FIFO")) && clock.elapsed() < 5000,
        tr("an image onto a FIFO refused in %1 ms: %2")
            .arg(clock.elapsed())
            .arg(toFifo.value_or(QString())));
  // A new session: written whole, nothing left beside it.
  const QString fresh = dir.filePath(QStringLiteral("fresh-session.json"));
  check(auto_.saveSession(fresh) && QFileInfo(fresh).size() > 0, tr("a new session saved"));
  const QStringList left = dir.entryList({QStringLiteral(".*tmp*")}, QDir::Hidden | QDir::Files);
  check(left.isEmpty(), tr("no temporary file left (%1)").arg(left.join(QStringLiteral(", "))));
  driver.stop();
  return true;
}

}  // namespace sl::ui
