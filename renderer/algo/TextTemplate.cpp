#include "algo/TextTemplate.h"

#include <cmath>
#include <cstdio>

namespace sl {
namespace {

bool keyChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '.' || c == '-';
}

/// A placeholder as quoted in a message: one line (control characters as spaces), at most 40
/// bytes (cut on a UTF-8 character boundary, marked "...").
std::string quoted(std::string_view spelling) {
  constexpr std::size_t kMax = 40;
  std::string out;
  for (char c : spelling.substr(0, kMax + 1))
    out += (static_cast<unsigned char>(c) < 0x20) ? ' ' : c;
  if (out.size() > kMax) {
    std::size_t end = kMax;
    while (end > 0 && (static_cast<unsigned char>(out[end]) & 0xC0) == 0x80) --end;
    out = out.substr(0, end) + "...";
  }
  return out;
}

bool fail(std::string* error, std::size_t at, const std::string& what) {
  if (error) *error = "placeholder at byte " + std::to_string(at) + ": " + what;
  return false;
}

/// Parses "[compare.]key[[i]][:d]" (the text between the braces).
bool parsePlaceholder(std::string_view body, std::size_t at, TextPlaceholder& out,
                      std::string* error) {
  out.spelling = std::string(body);
  const std::string shown = quoted(body);
  std::string_view rest = body;
  if (const auto colon = rest.rfind(':'); colon != std::string_view::npos) {
    const std::string_view d = rest.substr(colon + 1);
    if (d.size() != 1 || d[0] < '0' || d[0] > '6')
      return fail(error, at, "decimals after ':' must be one digit 0..6 in {" + shown + "}");
    out.decimals = d[0] - '0';
    rest = rest.substr(0, colon);
  }
  if (!rest.empty() && rest.back() == ']') {
    const auto open = rest.rfind('[');
    if (open == std::string_view::npos)
      return fail(error, at, "']' without '[' in {" + shown + "}");
    const std::string_view digits = rest.substr(open + 1, rest.size() - open - 2);
    if (digits.empty() || digits.size() > 4)
      return fail(error, at, "the index in {" + shown + "} must be 0..9999");
    int index = 0;
    for (char c : digits) {
      if (c < '0' || c > '9')
        return fail(error, at, "the index in {" + shown + "} must be 0..9999");
      index = index * 10 + (c - '0');
    }
    out.index = index;
    rest = rest.substr(0, open);
  }
  constexpr std::string_view kCompare = "compare.";
  if (rest.substr(0, kCompare.size()) == kCompare) {
    out.compare = true;
    rest.remove_prefix(kCompare.size());
  }
  if (rest.empty()) return fail(error, at, "empty key in {" + shown + "}");
  for (char c : rest)
    if (!keyChar(c))
      return fail(error, at,
                  "key characters are letters, digits, '_', '.', '-' in {" + shown + "}");
  out.key = std::string(rest);
  return true;
}

}  // namespace

std::optional<TextTemplate> TextTemplate::parse(std::string_view text, std::string* error) {
  TextTemplate t;
  std::string literal;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '{' && i + 1 < text.size() && text[i + 1] == '{') {
      literal += '{';
      ++i;
    } else if (c == '}' && i + 1 < text.size() && text[i + 1] == '}') {
      literal += '}';
      ++i;
    } else if (c == '}') {
      fail(error, i, "'}' without '{' (write '}}' for a brace)");
      return std::nullopt;
    } else if (c == '{') {
      const auto close = text.find_first_of("{}", i + 1);
      if (close == std::string_view::npos || text[close] != '}') {
        fail(error, i, "'{' without '}' (write '{{' for a brace)");
        return std::nullopt;
      }
      TextPlaceholder p;
      if (!parsePlaceholder(text.substr(i + 1, close - i - 1), i, p, error)) return std::nullopt;
      if (!literal.empty()) t.parts_.push_back({std::move(literal), -1});
      literal.clear();
      t.parts_.push_back({{}, static_cast<int>(t.placeholders_.size())});
      t.placeholders_.push_back(std::move(p));
      i = close;
    } else {
      literal += c;
    }
  }
  if (!literal.empty()) t.parts_.push_back({std::move(literal), -1});
  return t;
}

std::string TextTemplate::fill(const Lookup& lookup) const {
  std::string out;
  for (const Part& part : parts_) {
    if (part.placeholder < 0) {
      out += part.literal;
      continue;
    }
    const TextPlaceholder& p = placeholders_[static_cast<std::size_t>(part.placeholder)];
    const std::optional<double> v = lookup ? lookup(p) : std::nullopt;
    out += v ? formatTextValue(*v, p.decimals) : std::string("n/a");
  }
  return out;
}

std::string formatTextValue(double value, int decimals) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (decimals < 0) {
    // Three significant digits, never an exponent: 0.000746, 0.746, 12.3, 1049000.
    const double a = std::fabs(value);
    if (a == 0.0) {
      decimals = 0;
    } else {
      const int magnitude = static_cast<int>(std::floor(std::log10(a)));
      decimals = magnitude >= 2 ? 0 : 2 - magnitude;
      if (decimals > 12) decimals = 12;
    }
    if (decimals == 0) value = std::round(value);
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  std::string s = buf;
  if (s == "-0" || s.find_first_not_of("-0.") == std::string::npos) {
    if (s[0] == '-') s.erase(0, 1);  // "-0.00" reads "0.00"
  }
  return s;
}

}  // namespace sl
