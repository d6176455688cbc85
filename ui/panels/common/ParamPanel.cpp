// The Parameters panel (see ParamPanel.h). Editors accept any typed number and leave the
// range check to ParamSet::set, so an out-of-range entry is refused with the declaration's
// own message instead of being silently clamped by the widget.
#include "ParamPanel.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QScrollArea>
#include <QScrollBar>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include "window/Theme.h"

namespace sl::ui {

namespace {

constexpr int kMaxSliderSteps = 1000;
constexpr double kWideRange = 1e12;  ///< editors take anything; ParamSet judges

// Spin boxes that accept any typed value (ParamSet judges the range and names it when it
// refuses) but whose arrows stop at the declared range.
template <typename Base, typename T>
class DeclRangeSpinBox : public Base {
 public:
  DeclRangeSpinBox(T lo, T hi, T wideRange) : lo_(lo), hi_(hi) {
    this->setRange(-wideRange, wideRange);
  }
  void stepBy(int steps) override {
    const double v = double(this->value()) + double(steps) * double(this->singleStep());
    this->setValue(static_cast<T>(std::clamp<double>(v, double(lo_), double(hi_))));
  }

 protected:
  typename Base::StepEnabled stepEnabled() const override {
    typename Base::StepEnabled e = Base::StepNone;
    if (this->value() < hi_) e |= Base::StepUpEnabled;
    if (this->value() > lo_) e |= Base::StepDownEnabled;
    return e;
  }

 private:
  T lo_, hi_;
};
using DeclSpinBox = DeclRangeSpinBox<QSpinBox, int>;

/// A number with as many decimals as its value needs: at least `shown` (the step's), at most
/// 9, so that a value finer than the step (a vibration threshold of 0.999999, set on the
/// Covariance panel's log scale or typed) is kept and shown whole, not rounded to the step.
class DeclDoubleSpinBox : public DeclRangeSpinBox<QDoubleSpinBox, double> {
 public:
  static constexpr int kMaxDecimals = 9;
  DeclDoubleSpinBox(double lo, double hi, double wideRange, int shown)
      : DeclRangeSpinBox(lo, hi, wideRange), shown_(std::clamp(shown, 0, kMaxDecimals)) {
    setDecimals(kMaxDecimals);
  }
  QString textFromValue(double value) const override {
    QString text = QDoubleSpinBox::textFromValue(value);
    const int dot = text.indexOf(locale().decimalPoint());
    if (dot < 0) return text;
    const qsizetype keep = dot + 1 + shown_;
    while (text.size() > keep && text.endsWith(QLatin1Char('0'))) text.chop(1);
    if (text.size() == dot + 1) text.chop(1);  // "5." -> "5"
    return text;
  }

 private:
  int shown_;
};

/// Stops the wheel from changing unfocused editors while the panel is scrolled.
class WheelGuard : public QObject {
 public:
  WheelGuard(QScrollArea* scroll, QObject* parent) : QObject(parent), scroll_(scroll) {}

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override {
    auto* w = qobject_cast<QWidget*>(watched);
    if (event->type() == QEvent::Wheel && w && !w->hasFocus()) {
      QApplication::sendEvent(scroll_->verticalScrollBar(), event);
      return true;
    }
    return false;
  }

 private:
  QScrollArea* scroll_;
};

/// Decimals needed to show `v` exactly (up to 6).
int decimalsFor(double v) {
  for (int d = 0; d < 6; ++d) {
    const double scaled = std::abs(v) * std::pow(10.0, d);
    if (std::abs(scaled - std::round(scaled)) < 1e-6 * std::max(1.0, scaled)) return d;
  }
  return 6;
}

double stepOf(const sl::ParamDecl& d) {
  if (d.step > 0) return d.step;
  if (d.type == sl::ParamType::Float) {
    // A "round" step of about 1/100 of the range: 1, 2 or 5 times a power of ten.
    const double raw = (d.maxValue - d.minValue) / 100.0;
    if (!(raw > 0)) return 0.01;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
      if (raw <= m * p) return m * p;
    return 10 * p;
  }
  return 1.0;
}

/// Slider positions 0..n map linearly onto minValue..maxValue.
int sliderStepsOf(const sl::ParamDecl& d) {
  const double span = d.maxValue - d.minValue;
  if (!(span > 0)) return 1;
  const double steps = span / stepOf(d);
  return std::clamp(static_cast<int>(std::lround(steps)), 1, kMaxSliderSteps);
}

QString tooltipOf(const sl::ParamDecl& d) {
  sl::ParamSet defaults({d});
  return QStringLiteral(
             "<b>%1</b> <code>%2</code><br>%3<br><i>Range</i> %4 &nbsp; <i>default</i> %5")
      .arg(QString::fromStdString(d.label).toHtmlEscaped(), QString::fromStdString(d.key),
           QString::fromStdString(d.help).toHtmlEscaped(),
           QString::fromStdString(sl::describeRange(d)).toHtmlEscaped(),
           QString::fromStdString(defaults.format(d.key)).toHtmlEscaped());
}

}  // namespace

ParamPanel::ParamPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  scroll_ = new QScrollArea(this);
  scroll_->setWidgetResizable(true);
  scroll_->setFrameShape(QFrame::NoFrame);
  scroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  layout->addWidget(scroll_);
  clear();
}

void ParamPanel::clear() {
  refreshers_.clear();
  sets_.clear();
  auto* placeholder = new QLabel(tr("No renderer yet."), this);
  placeholder->setAlignment(Qt::AlignCenter);
  placeholder->setEnabled(false);
  scroll_->setWidget(placeholder);  // deletes the previous content
  scroll_->setMinimumHeight(0);
  Q_EMIT rebuilt();
}

void ParamPanel::setSections(std::vector<Section> sections) {
  refreshers_.clear();
  sets_.clear();
  for (const Section& section : sections)
    if (section.params) sets_.push_back(section.params);
  auto* content = new QWidget;
  auto* layout = new QVBoxLayout(content);
  layout->setContentsMargins(8, 6, 8, 8);
  layout->setSpacing(10);
  for (const Section& section : sections)
    if (section.params) layout->addWidget(buildSection(section));
  layout->addStretch(1);
  scroll_->setWidget(content);
  scroll_->setMinimumHeight(0);
  refreshValues();
  Q_EMIT rebuilt();
}

int ParamPanel::setStrip(const std::vector<StripRow>& rows) {
  refreshers_.clear();
  sets_.clear();
  for (const StripRow& r : rows)
    if (r.params) sets_.push_back(r.params);
  auto* content = new QWidget;
  auto* grid = new QGridLayout(content);
  grid->setContentsMargins(8, 4, 6, 4);
  grid->setHorizontalSpacing(6);
  grid->setVerticalSpacing(4);
  grid->setColumnStretch(1, 1);
  int row = 0;
  for (const StripRow& r : rows)
    if (r.params)
      if (const sl::ParamDecl* decl = r.params->find(r.key))
        buildRow(*r.params, *decl, grid, row++);
  scroll_->setWidget(content);
  // As tall as its rows: a strip is never scrolled (a cut row would hide a control).
  scroll_->setMinimumHeight(content->sizeHint().height());
  refreshValues();
  return row;
}

void ParamPanel::refreshValues() {
  for (const auto& refresh : refreshers_) refresh();
}

QWidget* ParamPanel::buildSection(const Section& section) {
  sl::ParamSet& params = *section.params;
  auto* box = new QWidget;
  auto* layout = new QVBoxLayout(box);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(6);

  auto* header = new QHBoxLayout;
  auto* title = new QLabel(section.title);
  followBodyFont(title, 1.15, true);
  header->addWidget(title, 1);
  auto* resetAll = new QToolButton;
  resetAll->setText(tr("Reset all"));
  resetAll->setToolTip(tr("Reset every parameter of \"%1\" to its default").arg(section.title));
  resetAll->setAutoRaise(true);
  resetAll->setEnabled(!params.decls().empty());
  connect(resetAll, &QToolButton::clicked, this, [this, &params] {
    params.resetToDefaults();
    refreshValues();
    Q_EMIT paramChanged(QString());
  });
  header->addWidget(resetAll);
  layout->addLayout(header);

  if (!section.description.isEmpty()) {
    auto* description = new QLabel(section.description);
    description->setWordWrap(true);
    description->setTextFormat(Qt::PlainText);
    description->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(description);
  }
  if (params.decls().empty()) {
    auto* none = new QLabel(tr("No parameters."));
    none->setEnabled(false);
    layout->addWidget(none);
    return box;
  }

  // Group boxes in order of first appearance of each group.
  std::vector<QString> order;
  std::map<QString, std::vector<const sl::ParamDecl*>> groups;
  for (const sl::ParamDecl& d : params.decls()) {
    QString g = d.group.empty() ? tr("General") : QString::fromStdString(d.group);
    if (!groups.count(g)) order.push_back(g);
    groups[g].push_back(&d);
  }
  auto* guard = new WheelGuard(scroll_, box);
  for (const QString& g : order) {
    auto* group = new QGroupBox(g);
    auto* grid = new QGridLayout(group);
    grid->setContentsMargins(8, 6, 6, 6);
    grid->setHorizontalSpacing(6);
    grid->setVerticalSpacing(4);
    grid->setColumnStretch(1, 1);
    int row = 0;
    for (const sl::ParamDecl* d : groups[g]) buildRow(params, *d, grid, row++);
    for (QWidget* w : group->findChildren<QWidget*>()) {
      if (qobject_cast<QSlider*>(w) || qobject_cast<QAbstractSpinBox*>(w) ||
          qobject_cast<QComboBox*>(w)) {
        w->setFocusPolicy(Qt::StrongFocus);
        w->installEventFilter(guard);
      }
    }
    layout->addWidget(group);
  }
  return box;
}

void ParamPanel::buildRow(sl::ParamSet& params, const sl::ParamDecl& decl, QGridLayout* grid,
                          int row) {
  const QString tip = tooltipOf(decl);
  auto* label = new QLabel(QString::fromStdString(decl.label));
  label->setToolTip(tip);
  grid->addWidget(label, row, 0);

  auto* reset = new QToolButton;
  reset->setObjectName(QStringLiteral("param:%1:reset").arg(QString::fromStdString(decl.key)));
  reset->setIcon(style()->standardIcon(QStyle::SP_BrowserReload));
  reset->setAutoRaise(true);
  reset->setToolTip(tr("Reset to default"));
  grid->addWidget(reset, row, 3);

  const std::string key = decl.key;
  const QString qkey = QString::fromStdString(key);
  std::function<void(double)> show;  // value -> editor widgets (signals blocked)

  switch (decl.type) {
    case sl::ParamType::Bool: {
      auto* check = new QCheckBox;
      check->setObjectName(QStringLiteral("param:") + qkey);
      check->setToolTip(tip);
      grid->addWidget(check, row, 1, 1, 2);
      connect(check, &QCheckBox::toggled, this, [this, &params, &decl, check](bool on) {
        if (!commit(params, decl, on ? 1.0 : 0.0)) {
          QSignalBlocker b(check);
          check->setChecked(params.getBool(decl.key));
        }
      });
      show = [check](double v) {
        QSignalBlocker b(check);
        check->setChecked(v != 0.0);
      };
      break;
    }
    case sl::ParamType::Enum: {
      auto* combo = new QComboBox;
      combo->setObjectName(QStringLiteral("param:") + qkey);
      combo->setToolTip(tip);
      for (const std::string& name : decl.enumNames) combo->addItem(QString::fromStdString(name));
      grid->addWidget(combo, row, 1, 1, 2);
      connect(combo, &QComboBox::currentIndexChanged, this,
              [this, &params, &decl, combo](int index) {
                if (index >= 0 && !commit(params, decl, index)) {
                  QSignalBlocker b(combo);
                  combo->setCurrentIndex(params.getInt(decl.key));
                }
              });
      show = [combo](double v) {
        QSignalBlocker b(combo);
        combo->setCurrentIndex(static_cast<int>(v));
      };
      break;
    }
    case sl::ParamType::Int:
    case sl::ParamType::Float: {
      const bool isInt = decl.type == sl::ParamType::Int;
      const double step = stepOf(decl);
      const int steps = sliderStepsOf(decl);
      const double lo = decl.minValue, hi = decl.maxValue;
      auto toSlider = [=](double v) {
        return hi > lo ? static_cast<int>(std::lround((v - lo) / (hi - lo) * steps)) : 0;
      };
      auto fromSlider = [=](int i) {
        double v = lo + (hi - lo) * i / steps;
        return isInt ? std::round(v) : v;
      };
      auto* slider = new QSlider(Qt::Horizontal);
      slider->setObjectName(QStringLiteral("param:%1:slider").arg(qkey));
      slider->setRange(0, steps);
      slider->setToolTip(tip);
      slider->setMinimumWidth(60);
      grid->addWidget(slider, row, 1);

      QAbstractSpinBox* spin = nullptr;
      std::function<void(double)> setSpin;
      if (isInt) {
        auto* s = new DeclSpinBox(static_cast<int>(lo), static_cast<int>(hi), INT_MAX / 2);
        s->setSingleStep(static_cast<int>(std::max(1.0, step)));
        connect(s, &QSpinBox::valueChanged, this, [this, &params, &decl](int v) {
          if (!commit(params, decl, v)) refreshValues();
        });
        setSpin = [s](double v) {
          QSignalBlocker b(s);
          s->setValue(static_cast<int>(v));
        };
        spin = s;
      } else {
        auto* s = new DeclDoubleSpinBox(
            lo, hi, kWideRange,
            std::max({decimalsFor(step), decimalsFor(lo), decimalsFor(decl.defaultValue)}));
        s->setSingleStep(step);
        connect(s, &QDoubleSpinBox::valueChanged, this, [this, &params, &decl](double v) {
          if (!commit(params, decl, v)) refreshValues();
        });
        setSpin = [s](double v) {
          QSignalBlocker b(s);
          s->setValue(v);
        };
        spin = s;
      }
      spin->setObjectName(QStringLiteral("param:") + qkey);
      spin->setKeyboardTracking(false);  // commit on Enter / focus out, not per keystroke
      spin->setAlignment(Qt::AlignRight);
      spin->setToolTip(tip);
      spin->setFixedWidth(spin->fontMetrics().horizontalAdvance(QStringLiteral("0000000.000")) +
                          24);
      grid->addWidget(spin, row, 2);

      connect(slider, &QSlider::valueChanged, this, [this, &params, &decl, fromSlider](int i) {
        if (!commit(params, decl, fromSlider(i))) refreshValues();
      });
      show = [slider, setSpin, toSlider](double v) {
        QSignalBlocker b(slider);
        slider->setValue(toSlider(v));
        setSpin(v);
      };
      break;
    }
  }

  auto refresh = [&params, key, show, reset, label, &decl] {
    const double v = params.get(key);
    show(v);
    const bool modified = v != decl.defaultValue;
    reset->setEnabled(modified);
    QFont f = label->font();
    f.setItalic(modified);
    label->setFont(f);
  };
  refreshers_.push_back(refresh);
  connect(reset, &QToolButton::clicked, this, [this, &params, key, qkey, refresh] {
    params.reset(key);
    refresh();
    Q_EMIT paramChanged(qkey);
  });
}

bool ParamPanel::edit(const std::string& key, double value) {
  for (sl::ParamSet* params : sets_)
    if (const sl::ParamDecl* decl = params ? params->find(key) : nullptr) {
      if (!commit(*params, *decl, value)) refreshValues();
      return true;
    }
  return false;
}

bool ParamPanel::commit(sl::ParamSet& params, const sl::ParamDecl& decl, double value) {
  if (auto error = params.set(decl.key, value)) {
    Q_EMIT editRefused(QString::fromStdString(*error));
    return false;
  }
  refreshValues();
  Q_EMIT paramChanged(QString::fromStdString(decl.key));
  return true;
}

}  // namespace sl::ui
