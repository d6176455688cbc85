// Lessons and the Lesson dock (see LessonPanel.h).
#include "LessonPanel.h"

#include "core/Renderer.h"

#include <algorithm>

#include <QDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollBar>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

#include "window/MessageText.h"
#include "window/Theme.h"
#include "scene/GltfLoader.h"

namespace sl::ui {

QString lessonDirectory() {
  return QDir(QString::fromStdString(sl::builtinSceneDir().string()))
      .filePath(QStringLiteral("lessons"));
}

QString courseFilePath() {
  return QString::fromStdString(sl::courseFile(sl::builtinSceneDir()).string());
}

std::optional<std::vector<sl::Course>> loadCourseFile(QString* error) {
  const QString path = courseFilePath();
  if (!QFileInfo::exists(path)) return std::vector<sl::Course>{};
  std::string message;
  auto courses = sl::loadCourses(path.toStdString(), lessonDirectory().toStdString(), &message);
  if (!courses && error) *error = QString::fromStdString(message);
  return courses;
}

std::vector<Lesson> loadLessons(QStringList* errors) {
  std::vector<Lesson> out;
  const QDir dir(lessonDirectory());
  QStringList files = dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
  for (const QString& file : files) {
    const QString path = dir.filePath(file);
    std::string error;
    std::optional<sl::Preset> preset = sl::loadPreset(path.toStdString(), &error);
    if (!preset) {
      if (errors) *errors << QString::fromStdString(error);
      continue;
    }
    if (preset->title.empty()) preset->title = QFileInfo(file).baseName().toStdString();
    out.push_back({path, std::move(*preset)});
  }
  return out;
}

int findLesson(const std::vector<Lesson>& lessons, const QString& spec) {
  bool isNumber = false;
  const int number = spec.toInt(&isNumber);
  if (isNumber) return number >= 1 && number <= static_cast<int>(lessons.size()) ? number - 1 : -1;
  for (std::size_t i = 0; i < lessons.size(); ++i) {
    const QFileInfo info(lessons[i].path);
    if (info.completeBaseName() == spec || info.fileName() == spec ||
        QFileInfo(spec).absoluteFilePath() == info.absoluteFilePath())
      return static_cast<int>(i);
  }
  return -1;
}

std::optional<Lesson> resolveLesson(const QString& spec, QString* error) {
  const std::vector<Lesson> lessons = loadLessons(nullptr);
  const int index = findLesson(lessons, spec);
  if (index >= 0) return lessons[static_cast<std::size_t>(index)];
  if (QFileInfo::exists(spec) && QFileInfo(spec).isFile()) {
    std::string message;
    std::optional<sl::Preset> preset = sl::loadPreset(spec.toStdString(), &message);
    if (preset) return Lesson{spec, std::move(*preset)};
    if (error) *error = QString::fromStdString(message);
    return std::nullopt;
  }
  QStringList known;
  for (const Lesson& l : lessons) known << QFileInfo(l.path).completeBaseName();
  if (error)
    *error =
        QStringLiteral("unknown lesson '%1' (known: %2)")
            .arg(spec, known.isEmpty() ? QStringLiteral("none") : known.join(QStringLiteral(", ")));
  return std::nullopt;
}

LessonPanel::LessonPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(8, 6, 8, 8);
  course_ = new QLabel;
  course_->setObjectName(QStringLiteral("lessonCourse"));
  followBodyFont(course_, 1.0, true);
  course_->setWordWrap(true);
  course_->setTextFormat(Qt::PlainText);  // the course file's words, never markup
  course_->hide();
  layout->addWidget(course_);
  thread_ = new QLabel;
  thread_->setObjectName(QStringLiteral("lessonCourseThread"));
  thread_->setWordWrap(true);
  thread_->setTextFormat(Qt::PlainText);  // the course file's words: no rich text (images)
  thread_->setForegroundRole(QPalette::PlaceholderText);
  thread_->hide();
  layout->addWidget(thread_);
  title_ = new QLabel;
  title_->setObjectName(QStringLiteral("lessonTitle"));
  followBodyFont(title_, 1.2, true);
  title_->setWordWrap(true);
  layout->addWidget(title_);
  cases_ = new QWidget;
  cases_->setObjectName(QStringLiteral("lessonCases"));
  auto* caseRow = new QHBoxLayout(cases_);
  caseRow->setContentsMargins(0, 0, 0, 0);
  cases_->hide();
  layout->addWidget(cases_);
  text_ = new QTextBrowser;
  text_->setObjectName(QStringLiteral("lessonText"));
  text_->setOpenLinks(false);
  text_->setFrameShape(QFrame::NoFrame);
  connect(text_, &QTextBrowser::anchorClicked, this, [this](const QUrl& url) {
    bool ok = false;
    const int index = url.fragment().toInt(&ok);
    if (ok) Q_EMIT lessonChosen(index);
  });
  layout->addWidget(text_, 1);
  note_ = new QLabel;
  note_->setWordWrap(true);
  note_->setForegroundRole(QPalette::BrightText);
  note_->hide();
  layout->addWidget(note_);
  auto* buttons = new QHBoxLayout;
  previous_ = new QPushButton(tr("◀ Previous"));
  restart_ = new QPushButton(tr("Restart"));
  restart_->setToolTip(tr("Apply the lesson's scene, camera, light and parameters again"));
  next_ = new QPushButton(tr("Next ▶"));
  previous_->setObjectName(QStringLiteral("lessonPrevious"));
  next_->setObjectName(QStringLiteral("lessonNext"));
  connect(previous_, &QPushButton::clicked, this, &LessonPanel::previousRequested);
  connect(next_, &QPushButton::clicked, this, &LessonPanel::nextRequested);
  connect(restart_, &QPushButton::clicked, this, &LessonPanel::restartRequested);
  buttons->addWidget(previous_);
  buttons->addStretch(1);
  buttons->addWidget(restart_);
  buttons->addWidget(next_);
  layout->addLayout(buttons);
  showLesson(nullptr, -1, 0);
}

void LessonPanel::setLessonTitles(const QStringList& titles) {
  titles_ = titles;
}

void LessonPanel::showLesson(const Lesson* lesson, int index, int count, int caseIndex) {
  note_->hide();
  // The case buttons: made again for each lesson (a few at most).
  for (QPushButton* b : cases_->findChildren<QPushButton*>(QString(), Qt::FindDirectChildrenOnly))
    delete b;
  const std::vector<sl::Preset>* cases = lesson ? &lesson->preset.cases : nullptr;
  if (cases && !cases->empty()) {
    auto* row = static_cast<QHBoxLayout*>(cases_->layout());
    for (std::size_t k = 0; k < cases->size(); ++k) {
      auto* b = new QPushButton(
          tr("%1 · %2").arg(k + 1).arg(shownMessage(QString::fromStdString((*cases)[k].title))));
      b->setObjectName(QStringLiteral("lessonCase%1").arg(k + 1));
      b->setCheckable(true);
      b->setChecked(int(k) == caseIndex);
      b->setToolTip(tr("Case %1 of this lesson: its scene, view, technique and comparison "
                       "(Ctrl+Shift+N: the next case)")
                        .arg(k + 1));
      connect(b, &QPushButton::clicked, this, [this, k] { Q_EMIT caseChosen(int(k)); });
      row->addWidget(b);
    }
  }
  cases_->setVisible(cases && !cases->empty());
  if (!lesson) {
    shownLesson_.reset();
    live_ = false;
    title_->setText(tr("Lessons"));
    QString html =
        tr("<p>Each lesson sets up a scene, camera, light, technique and parameters "
           "and says what to look at. Choose one (Lessons menu, Ctrl+1…):</p><ol>");
    for (int i = 0; i < titles_.size(); ++i)
      html +=
          QStringLiteral("<li><a href='#%1'>%2</a></li>").arg(i).arg(titles_[i].toHtmlEscaped());
    html += QStringLiteral("</ol>");
    if (titles_.isEmpty())
      html = tr("<p>No lessons found in %1.</p>").arg(lessonDirectory().toHtmlEscaped());
    text_->setHtml(html);
    previous_->setEnabled(false);
    next_->setEnabled(!titles_.isEmpty());
    restart_->setEnabled(false);
    return;
  }
  title_->setText(tr("Lesson %1 of %2: %3")
                      .arg(index + 1)
                      .arg(count)
                      .arg(shownMessage(QString::fromStdString(lesson->preset.title))));
  shownLesson_ = *lesson;
  shownIndex_ = index;
  shownCount_ = count;
  shownCase_ = caseIndex;
  shownHtml_.clear();
  showText();
  previous_->setEnabled(index > 0);
  next_->setEnabled(index + 1 < count);
  restart_->setEnabled(true);
}

void LessonPanel::refreshLiveNumbers() {
  if (shownLesson_ && live_ && liveFill_) showText();
}

QString LessonPanel::shownText() const {
  return text_->toPlainText();
}

void LessonPanel::showText() {
  const Lesson* lesson = &*shownLesson_;
  const std::vector<sl::Preset>* cases = &lesson->preset.cases;
  const int caseIndex = shownCase_;
  // Explanations are plain text; blank lines separate paragraphs. A lesson told in cases:
  // its own text, then the case's under the case's title.
  QString html;
  live_ = false;
  auto paragraphs = [this, &html](const std::string& text) {
    const bool live = text.find('{') != std::string::npos;
    live_ = live_ || live;
    const std::string shown = live && liveFill_ ? liveFill_(text) : text;
    for (const QString& para : QString::fromStdString(shown).split(QStringLiteral("\n\n")))
      html += QStringLiteral("<p>%1</p>")
                  .arg(para.toHtmlEscaped().replace(QLatin1Char('\n'), QStringLiteral("<br>")));
  };
  paragraphs(lesson->preset.explanation);
  const bool hasCase = cases && caseIndex >= 0 && caseIndex < int(cases->size());
  const sl::Preset& shown = hasCase ? (*cases)[std::size_t(caseIndex)] : lesson->preset;
  if (hasCase) {
    html += QStringLiteral("<h3>%1</h3>")
                .arg(tr("Case %1 of %2: %3")
                         .arg(caseIndex + 1)
                         .arg(cases->size())
                         .arg(QString::fromStdString(shown.title))
                         .toHtmlEscaped());
    paragraphs(shown.explanation);
  }
  html += QStringLiteral("<p style='color:gray'>%1</p>")
              .arg(tr("Scene %1 · technique %2")
                       .arg(QString::fromStdString(shown.scene),
                            QString::fromStdString(shown.technique))
                       .toHtmlEscaped());
  // The passes of the lesson's technique, from their declaration: what ] steps through.
  if (const sl::TechniqueInfo* t = sl::Renderer::findTechnique(shown.technique)) {
    QStringList titles;
    for (const sl::PassDecl& pass : sl::framePassDecls(*t))
      titles << QString::fromStdString(pass.title).toHtmlEscaped();
    html += QStringLiteral("<p style='color:gray'>%1</p>")
                .arg(tr("Its passes (] steps through them): %1")
                         .arg(titles.join(QStringLiteral(" → "))));
  }
  if (html == shownHtml_) return;  // the same numbers: nothing to lay out
  shownHtml_ = html;
  const int scroll = text_->verticalScrollBar()->value();
  text_->setHtml(html);
  text_->verticalScrollBar()->setValue(scroll);
}

void LessonPanel::setCourse(const QString& position, const QString& thread, bool hasPrevious,
                            bool hasNext) {
  course_->setText(position);
  course_->setVisible(!position.isEmpty());
  thread_->setText(thread);
  thread_->setVisible(!position.isEmpty() && !thread.isEmpty());
  if (position.isEmpty()) return;
  previous_->setEnabled(hasPrevious);
  next_->setEnabled(hasNext);
}

QString LessonPanel::courseLine() const {
  return course_->isHidden() ? QString() : course_->text();
}

void LessonPanel::setNote(const QString& note) {
  noteText_ = note;
  note_->setText(shownMessage(note));
  note_->setToolTip(messageDetails(note));
  note_->setVisible(!note.isEmpty());
}

}  // namespace sl::ui
