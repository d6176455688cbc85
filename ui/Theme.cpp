// Fusion + dark palette (see Theme.h).
#include "Theme.h"

#include <QApplication>
#include <QPalette>
#include <QStyleFactory>

namespace sl::ui {

void applyTheme(QApplication& app) {
  app.setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
  const QColor window(45, 47, 51), base(33, 35, 38), alternate(52, 55, 60), text(222, 224, 227),
      disabledText(128, 131, 136), highlight(66, 133, 214), button(55, 58, 63);
  QPalette p;
  p.setColor(QPalette::Window, window);
  p.setColor(QPalette::WindowText, text);
  p.setColor(QPalette::Base, base);
  p.setColor(QPalette::AlternateBase, alternate);
  p.setColor(QPalette::ToolTipBase, QColor(250, 250, 245));
  p.setColor(QPalette::ToolTipText, QColor(30, 30, 30));
  p.setColor(QPalette::PlaceholderText, QColor(150, 154, 160));
  p.setColor(QPalette::Text, text);
  p.setColor(QPalette::Button, button);
  p.setColor(QPalette::ButtonText, text);
  p.setColor(QPalette::BrightText, QColor(255, 90, 90));
  p.setColor(QPalette::Link, highlight.lighter(130));
  p.setColor(QPalette::Highlight, highlight);
  p.setColor(QPalette::HighlightedText, Qt::white);
  p.setColor(QPalette::Light, QColor(75, 78, 84));
  p.setColor(QPalette::Midlight, QColor(62, 65, 70));
  p.setColor(QPalette::Mid, QColor(40, 42, 45));
  p.setColor(QPalette::Dark, QColor(25, 26, 28));
  p.setColor(QPalette::Shadow, QColor(15, 15, 16));
  for (auto role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
    p.setColor(QPalette::Disabled, role, disabledText);
  p.setColor(QPalette::Disabled, QPalette::Highlight, QColor(80, 84, 90));
  app.setPalette(p);
}

}  // namespace sl::ui
