// Elision of the messages the GUI shows (see MessageText.h).
#include "MessageText.h"

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

QString messageDetails(const QString& message) {
  if (message.size() > kMessageDetailsChars || shownMessage(message) == message) return {};
  return message;
}

}  // namespace sl::ui
