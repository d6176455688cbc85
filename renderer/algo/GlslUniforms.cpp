#include "GlslUniforms.h"

#include <cctype>
#include <regex>

namespace sl {

namespace {

std::string stripComments(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '/' && i + 1 < s.size() && s[i + 1] == '/') {
      while (i < s.size() && s[i] != '\n') ++i;
      out += '\n';
    } else if (s[i] == '/' && i + 1 < s.size() && s[i + 1] == '*') {
      i += 2;
      while (i + 1 < s.size() && !(s[i] == '*' && s[i + 1] == '/')) ++i;
      ++i;
      out += ' ';
    } else {
      out += s[i];
    }
  }
  return out;
}

bool isIdent(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// Adds the declarator names of "type a, b[3], c = 1.0" (everything after the type).
void addDeclarators(std::string_view decl, std::set<std::string>& out) {
  // Drop array sizes and initialisers' nesting by tracking depth.
  std::string cleaned;
  int depth = 0;
  for (char c : decl) {
    if (c == '[' || c == '(' || c == '{') ++depth;
    if (depth == 0) cleaned += c;
    if ((c == ']' || c == ')' || c == '}') && depth > 0) --depth;
  }
  size_t start = 0;
  while (start <= cleaned.size()) {
    size_t comma = cleaned.find(',', start);
    std::string part =
        cleaned.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (size_t eq = part.find('='); eq != std::string::npos) part.resize(eq);
    // The declarator is the last identifier of the part.
    size_t e = part.size();
    while (e > 0 && !isIdent(part[e - 1])) --e;
    size_t b = e;
    while (b > 0 && isIdent(part[b - 1])) --b;
    if (b < e) out.insert(part.substr(b, e - b));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
}

}  // namespace

std::string_view uniformBaseName(std::string_view name) {
  size_t bracket = name.find('[');
  return bracket == std::string_view::npos ? name : name.substr(0, bracket);
}

std::set<std::string> declaredUniforms(std::string_view source) {
  const std::string text = stripComments(source);
  std::set<std::string> names;
  static const std::regex word(R"(\buniform\b)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), word); it != std::sregex_iterator();
       ++it) {
    const size_t from = size_t(it->position()) + 7;
    const size_t semi = text.find(';', from);
    const size_t brace = text.find('{', from);
    if (semi == std::string::npos) break;
    if (brace != std::string::npos && brace < semi) {  // uniform block: its members
      const size_t close = text.find('}', brace);
      if (close == std::string::npos) break;
      std::string body = text.substr(brace + 1, close - brace - 1);
      size_t s = 0;
      for (size_t m = body.find(';'); m != std::string::npos; s = m + 1, m = body.find(';', s)) {
        std::string member = body.substr(s, m - s);
        // "type name" or "type a, b": drop the first word (the type).
        size_t t = member.find_first_not_of(" \t\r\n");
        if (t == std::string::npos) continue;
        size_t afterType = member.find_first_of(" \t\r\n", t);
        if (afterType != std::string::npos) addDeclarators(member.substr(afterType), names);
      }
      continue;
    }
    // "uniform [qualifiers] type a, b;": drop the type (the first identifier after
    // precision/memory qualifiers is enough: declarators are the LAST identifier of each
    // comma-separated part, and the type precedes the first one).
    std::string decl = text.substr(from, semi - from);
    size_t t = decl.find_first_not_of(" \t\r\n");
    if (t == std::string::npos) continue;
    addDeclarators(decl.substr(t), names);
  }
  return names;
}

}  // namespace sl
