// The Help window (see ShortcutsDialog.h).
#include "window/ShortcutsDialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QTextBrowser>
#include <QVBoxLayout>

#include "window/WindowShortcuts.h"

namespace sl::ui {

namespace {
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
  html += heading(tr("Viewport (its keys work wherever the focus is, but in a text field)"));
  for (const WindowShortcuts::Control& c : WindowShortcuts::viewControls())
    html += row(QString::fromUtf8(c.input), tr(c.what));
  html += heading(tr("Panels"));
  for (const WindowShortcuts::Control& c : WindowShortcuts::panelControls())
    html += row(QString::fromUtf8(c.input), tr(c.what));
  html += heading(tr("Commands"));
  for (const WindowShortcuts::Row& r :
       WindowShortcuts::commandRows(parent ? parent->window() : nullptr, actions))
    html += row(r.keys, r.what);
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
