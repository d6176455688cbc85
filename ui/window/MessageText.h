// Every message the GUI shows (status bar, dialogs, panel notes, the viewport banner) goes
// through shownMessage(): a message can carry text echoed from a hostile file (a 40 MB buffer
// URI), and a label, status bar or message box laying out megabytes of text freezes the window.
// The full text always goes to stderr (printErr); the GUI keeps it as details only when short.
#pragma once

#include <QString>

namespace sl::ui {

/// At most this many characters of a message are shown.
inline constexpr int kShownMessageChars = 300;
/// At most this many lines of a message are shown.
inline constexpr int kShownMessageLines = 12;
/// A message up to this long is kept whole as details (tooltip, "Show Details…").
inline constexpr int kMessageDetailsChars = 20000;

/// `message` cut to kShownMessageChars characters and kShownMessageLines lines; a cut is
/// marked with "…". Never splits a surrogate pair.
QString shownMessage(const QString& message);

/// A summary of a long text for the viewport's banner: shownMessage(), but cut after the last
/// whole sentence that fits (a number is never cut in half); the Lesson dock has the rest.
QString shownSummary(const QString& text);

/// The full message, for a tooltip or details, when shownMessage() cut it and it is at most
/// kMessageDetailsChars long; otherwise empty.
QString messageDetails(const QString& message);

/// Writes "shadowlab: `line`" to stderr (the full text of what the GUI shows cut).
void printErr(const QString& line);

}  // namespace sl::ui
