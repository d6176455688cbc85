// The Help window (see ShortcutsDialog.h).
#include "ShortcutsDialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace sl::ui {

namespace {
struct Binding {
  const char* keys;
  const char* what;
};

// The viewport's own controls (ViewportWidget::mouse*/key* events).
constexpr Binding kViewportBindings[] = {
    {"Left drag", "Orbit around the target"},
    {"Right drag / middle drag / Shift+left drag", "Pan"},
    {"Ctrl+left drag", "Look around (turn the camera in place)"},
    {"Wheel", "Dolly towards / away from the target"},
    {"W / S", "Fly forward / back"},
    {"A / D", "Fly left / right"},
    {"Q / E", "Fly down / up"},
    {"Shift (held)", "Fly four times faster"},
    {"Left drag / wheel in the outside view (V)",
     "Orbit / move the third camera; the main camera stays"},
    {"Drop a .gltf / .glb file", "Open it"},
};

// The image views and plots of the debug panels (PanelKit.h: ImageView, PlotWidget).
constexpr Binding kPanelBindings[] = {
    {"Wheel over an image", "Zoom around the cursor"},
    {"Drag an image", "Pan"},
    {"Double-click an image", "Fit it to the panel"},
    {"Hover an image / a plot", "Value under the cursor / every curve at that x"},
    {"Right-click a panel", "Save it as a PNG"},
};

QString row(const QString& keys, const QString& what) {
  return QStringLiteral(
             "<tr><td width='45%' style='padding:3px 16px 3px 0'><b>%1</b></td>"
             "<td style='padding:3px 0'>%2</td></tr>")
      .arg(keys.toHtmlEscaped(), what.toHtmlEscaped());
}

QString heading(const QString& text) {
  return QStringLiteral(
             "<tr><td colspan='2' style='padding:12px 0 4px 0'><big><b>%1</b></big></td></tr>")
      .arg(text.toHtmlEscaped());
}
}  // namespace

ShortcutsDialog::ShortcutsDialog(const QList<QAction*>& actions, QWidget* parent)
    : QDialog(parent) {
  setWindowTitle(tr("ShadowLab — Keyboard and mouse"));
  QString html = QStringLiteral("<table width='100%' cellspacing='0'>");
  html += heading(tr("Viewport (click into the view first)"));
  for (const Binding& b : kViewportBindings) html += row(QString::fromUtf8(b.keys), tr(b.what));
  html += heading(tr("Panels"));
  for (const Binding& b : kPanelBindings) html += row(QString::fromUtf8(b.keys), tr(b.what));
  html += heading(tr("Commands"));
  for (const QAction* action : actions) {
    if (action->shortcut().isEmpty()) continue;
    html += row(action->shortcut().toString(QKeySequence::NativeText),
                action->text().remove(QLatin1Char('&')).remove(QStringLiteral("…")));
  }
  html += QStringLiteral("</table>");

  auto* text = new QTextBrowser;
  text->setHtml(html);
  text->setOpenLinks(false);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(text);
  layout->addWidget(buttons);
  resize(560, 620);
}

}  // namespace sl::ui
