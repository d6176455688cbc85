// Elision of the messages the GUI shows (see MessageText.h).
#include "window/MessageText.h"

#include <cstdio>

#include <algorithm>

namespace sl::ui {

QString shownMessage(const QString& message) {
  qsizetype end = std::min<qsizetype>(message.size(), kShownMessageChars);
  // Cut after the kShownMessageLines-th line as well.
  qsizetype lines = 0;
  for (qsizetype i = 0; i < end; ++i) {
    if (message[i] == QLatin1Char('\n') && ++lines == kShownMessageLines) {
      end = i;
      break;
    }
  }
  if (end == message.size()) return message;
  if (end > 0 && message[end - 1].isHighSurrogate()) --end;
  QString shown = message.left(end);
  while (!shown.isEmpty() && shown.back().isSpace()) shown.chop(1);
  return shown + QChar(0x2026);
}

QString shownSummary(const QString& text) {
  const QString shown = shownMessage(text);
  if (shown == text) return text;
  const QString kept = shown.left(shown.size() - 1);  // without the "…"
  // The last sentence end (". ", "! ", "? " or a line end after one) within what is shown.
  qsizetype end = -1;
  for (qsizetype i = 0; i + 1 < kept.size(); ++i)
    if ((kept[i] == QLatin1Char('.') || kept[i] == QLatin1Char('!') ||
         kept[i] == QLatin1Char('?')) &&
        kept[i + 1].isSpace())
      end = i + 1;
  if (end <= 0) {  // no sentence end: cut at the last space, never inside a word or number
    end = kept.lastIndexOf(QLatin1Char(' '));
    if (end <= 0) return shown;
  }
  return kept.left(end).trimmed() + QStringLiteral(" \u2026");
}

QString messageDetails(const QString& message) {
  if (message.size() > kMessageDetailsChars || shownMessage(message) == message) return {};
  return message;
}

void printErr(const QString& line) {
  std::fprintf(stderr, "shadowlab: %s\n", line.toLocal8Bit().constData());
  std::fflush(stderr);
}

}  // namespace sl::ui
