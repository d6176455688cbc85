// Fusion + dark palette, and presenter mode's high-contrast one (see Theme.h).
#include "window/Theme.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <QApplication>
#include <QEvent>
#include <QFontInfo>
#include <QWidget>
#include <QtCharts/QAbstractAxis>
#include <QtCharts/QChart>
#include <QtCharts/QLegend>
#include <QFont>
#include <QSize>
#include <QPalette>
#include <QStyleFactory>
#include <QStyleOption>
#include <QProxyStyle>
#include <QPainter>

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

int presenterBodyPixelSize(const QSize& screenLogicalSize, double logicalDpi) {
  constexpr double kPxAt1080p = 24.0;  // >= 22 px readable from the back of a lecture room
  const double scale =
      std::min(screenLogicalSize.width() / 1920.0, screenLogicalSize.height() / 1080.0);
  const double floorPx = 11.0 * std::max(logicalDpi, 72.0) / 72.0;  // 11 pt
  return int(std::lround(std::max(kPxAt1080p * scale, floorPx)));
}

namespace {
/// Fusion with check box and radio indicators drawn for a dark, high-contrast palette: a light
/// frame always, the highlight inside when checked, a bar when partly checked.
class PresenterStyle : public QProxyStyle {
 public:
  explicit PresenterStyle(QStyle* base) : QProxyStyle(base) {}
  void drawPrimitive(PrimitiveElement element, const QStyleOption* option, QPainter* painter,
                     const QWidget* widget) const override {
    const bool check = element == PE_IndicatorCheckBox || element == PE_IndicatorItemViewItemCheck;
    if (!check && element != PE_IndicatorRadioButton) {
      QProxyStyle::drawPrimitive(element, option, painter, widget);
      return;
    }
    const QPalette& pal = option->palette;
    const bool enabled = option->state & State_Enabled;
    const QRectF r = QRectF(option->rect).adjusted(1.5, 1.5, -1.5, -1.5);
    painter->save();
    painter->setRenderHint(QPainter::Antialiasing);
    painter->setPen(QPen(enabled ? pal.color(QPalette::Light) : pal.color(QPalette::Dark), 2.0));
    painter->setBrush(pal.color(QPalette::Base));
    if (check)
      painter->drawRect(r);
    else
      painter->drawEllipse(r);
    painter->setPen(Qt::NoPen);
    painter->setBrush(pal.color(QPalette::Highlight));
    const QRectF inner = r.adjusted(3, 3, -3, -3);
    if (option->state & State_On) {
      if (check)
        painter->drawRect(inner);
      else
        painter->drawEllipse(inner);
    } else if (option->state & State_NoChange) {
      painter->drawRect(QRectF(inner.left(), inner.center().y() - 1.5, inner.width(), 3.0));
    }
    painter->restore();
  }
};
}  // namespace

void applyPresenterTheme(QApplication& app, int bodyPixelSize, double logicalDpi) {
  // Fusion draws a check box's frame a shade off the window colour: on black it is invisible.
  // The presenter's style draws every indicator with a light frame (checked: filled with the
  // highlight). A style, not a style sheet: an application style sheet would take over the
  // widgets' fonts (the status line fell back to 12 px).
  app.setStyle(new PresenterStyle(QStyleFactory::create(QStringLiteral("Fusion"))));
  const QColor black(0, 0, 0), panel(12, 12, 12), text(255, 255, 255), yellow(255, 221, 0),
      frame(200, 200, 200);
  QPalette p;
  p.setColor(QPalette::Window, panel);
  p.setColor(QPalette::WindowText, text);
  p.setColor(QPalette::Base, black);
  p.setColor(QPalette::AlternateBase, QColor(30, 30, 30));
  p.setColor(QPalette::ToolTipBase, QColor(255, 255, 210));
  p.setColor(QPalette::ToolTipText, black);
  p.setColor(QPalette::PlaceholderText, QColor(235, 235, 235));
  p.setColor(QPalette::Text, text);
  p.setColor(QPalette::Button, QColor(25, 25, 25));
  p.setColor(QPalette::ButtonText, text);
  p.setColor(QPalette::BrightText, yellow);
  p.setColor(QPalette::Link, QColor(120, 200, 255));
  p.setColor(QPalette::Highlight, yellow);
  p.setColor(QPalette::HighlightedText, black);
  p.setColor(QPalette::Light, frame);
  p.setColor(QPalette::Midlight, QColor(150, 150, 150));
  p.setColor(QPalette::Mid, frame);
  p.setColor(QPalette::Dark, QColor(90, 90, 90));
  p.setColor(QPalette::Shadow, black);
  for (auto role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
    p.setColor(QPalette::Disabled, role, QColor(170, 170, 170));
  app.setPalette(p);
  QFont font = app.font();
  font.setPointSizeF(bodyPixelSize * 72.0 / std::max(logicalDpi, 1.0));
  app.setFont(font);
}

namespace {
/// The functions followBodyFont registered, run when the application font changes: one filter
/// on the application sees the ApplicationFontChange Qt sends to the top-level widgets (a
/// child with a font of its own set gets no event of its own), once per new font.
class BodyFontFollowers : public QObject {
 public:
  static BodyFontFollowers& instance() {
    static auto* self = [] {
      auto* f = new BodyFontFollowers(QCoreApplication::instance());
      QCoreApplication::instance()->installEventFilter(f);
      return f;
    }();
    return *self;
  }
  void add(QObject* owner, std::function<void()> apply) {
    apply();
    followers_.push_back({owner, std::move(apply)});
    connect(owner, &QObject::destroyed, this, [this](QObject* gone) {
      std::erase_if(followers_, [gone](const Follower& f) { return f.owner == gone; });
    });
  }
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() == QEvent::ApplicationFontChange && QApplication::font() != applied_) {
      applied_ = QApplication::font();
      const std::vector<Follower> now = followers_;  // an apply may add or remove one
      for (const Follower& f : now) f.apply();
    }
    return QObject::eventFilter(watched, event);
  }

 private:
  using QObject::QObject;
  struct Follower {
    QObject* owner;
    std::function<void()> apply;
  };
  std::vector<Follower> followers_;
  QFont applied_ = QApplication::font();
};
}  // namespace

int bodyPixelSize() {
  return QFontInfo(QApplication::font()).pixelSize();
}

QFont bodyRelativeFont(double relative, const QFont& base) {
  QFont font = base;
  font.setPixelSize(std::max(1, int(std::lround(bodyPixelSize() * relative))));
  return font;
}

QFont bodyRelativeFont(double relative) {
  return bodyRelativeFont(relative, QApplication::font());
}

void setChartFonts(QChart& chart) {
  chart.setTitleFont(bodyRelativeFont(1.0));
  const QFont small = bodyRelativeFont(kSmallText);
  for (QAbstractAxis* a : chart.axes()) {
    a->setTitleFont(small);
    a->setLabelsFont(small);
  }
  chart.legend()->setFont(small);
}

void followBodyFont(QWidget* owner, std::function<void()> apply) {
  BodyFontFollowers::instance().add(owner, std::move(apply));
}

void followBodyFont(QWidget* widget, double relative, bool bold) {
  followBodyFont(widget, [widget, relative, bold] {
    QFont font = bodyRelativeFont(relative);
    font.setBold(bold);
    widget->setFont(font);
  });
}

}  // namespace sl::ui
