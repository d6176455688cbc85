// Lesson texts that quote live numbers: "{error_pct}", "{pca.anisotropy:2}",
// "{partition.m_p95[0]}", "{compare.error_pct}". A text is parsed once (at load: a malformed
// placeholder is refused naming its offset) and filled every frame from whatever the frame
// measured and published, so the number a text quotes is the one on the screen, at any window
// size and after any interaction. A value the frame does not have reads "n/a".
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sl {

/// One "{...}" in a text.
struct TextPlaceholder {
  /// "compare." prefix: the split view's right half (the lesson's "compare" technique);
  /// otherwise the main view (the left half when split).
  bool compare = false;
  std::string key;       ///< "error_pct", "pca.anisotropy", "partition.m_p95"
  int index = -1;        ///< "[i]": element i of a published curve; -1: a number
  int decimals = -1;     ///< ":d" (0..6); -1: three significant digits
  std::string spelling;  ///< as written, without the braces ("compare.error_pct:2")
};

/// A parsed text: literal runs and placeholders, in order. "{{" and "}}" are literal braces.
class TextTemplate {
 public:
  /// Parses `text`; nullopt with `error` set ("placeholder at byte 41: ...") when a brace is
  /// unbalanced, a key is empty or has a character outside [A-Za-z0-9_.-], an index is not a
  /// non-negative integer or decimals are not 0..6.
  static std::optional<TextTemplate> parse(std::string_view text, std::string* error);

  /// A placeholder's value: nullopt when the frame has none (not measured, not published).
  using Lookup = std::function<std::optional<double>(const TextPlaceholder&)>;
  /// The text with every placeholder replaced by its formatted value or "n/a".
  std::string fill(const Lookup& lookup) const;

  const std::vector<TextPlaceholder>& placeholders() const { return placeholders_; }
  bool hasPlaceholders() const { return !placeholders_.empty(); }

 private:
  struct Part {
    std::string literal;  ///< used when placeholder < 0
    int placeholder = -1;
  };
  std::vector<Part> parts_;
  std::vector<TextPlaceholder> placeholders_;
};

/// How a placeholder's value is written: `decimals` digits after the point, or (decimals < 0)
/// three significant digits without an exponent (0.746, 12.3, 1049000); "inf", "-inf",
/// "nan" for non-finite values.
std::string formatTextValue(double value, int decimals);

}  // namespace sl
