// Every quote of scenes/claims/*.json is its seed's own words: found in the seed's text
// (../shared/seeds/NNN_*.txt beside the checkout), its "[...]" pieces in order. Whitespace is
// ignored (the text extractions join lines without a space), typographic quotes read as
// straight ones, and a word hyphenated at a line break matches joined or hyphenated. A seed
// claim without a quote, or a translation mixed into one, fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void replaceAll(std::string& s, const std::string& from, const std::string& to) {
  for (std::size_t i = s.find(from); i != std::string::npos; i = s.find(from, i + to.size()))
    s.replace(i, from.size(), to);
}

/// Straight quotes for typographic ones, no whitespace at all.
std::string normalised(std::string s) {
  for (const char* q : {"\u201c", "\u201d", "\u201e"}) replaceAll(s, q, "\"");
  for (const char* q : {"\u2018", "\u2019"}) replaceAll(s, q, "'");
  replaceAll(s, "\u00a0", " ");
  std::erase_if(s, [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; });
  return s;
}

/// The seed's text as it reads, and with every word hyphenated at a line break joined.
std::vector<std::string> seedReadings(const std::string& text) {
  std::string joined;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '-') {
      std::size_t j = i + 1;
      while (j < text.size() && (text[j] == ' ' || text[j] == '\t' || text[j] == '\r')) ++j;
      if (j < text.size() && text[j] == '\n') {
        i = j;
        continue;
      }
    }
    joined += text[i];
  }
  return {normalised(text), normalised(joined)};
}

/// The quote's pieces ("[...]" marks a gap) appear in the seed, in order.
bool quoted(const std::string& quote, const std::vector<std::string>& readings) {
  std::vector<std::string> pieces;
  std::size_t start = 0;
  for (std::size_t gap; (gap = quote.find("[...]", start)) != std::string::npos; start = gap + 5)
    pieces.push_back(normalised(quote.substr(start, gap - start)));
  pieces.push_back(normalised(quote.substr(start)));
  std::erase_if(pieces, [](const std::string& p) { return p.empty(); });
  if (pieces.empty()) return false;
  return std::any_of(readings.begin(), readings.end(), [&](const std::string& text) {
    std::size_t at = 0;
    for (const std::string& p : pieces) {
      at = text.find(p, at);
      if (at == std::string::npos) return false;
      at += p.size();
    }
    return true;
  });
}

fs::path seedFile(const std::string& seed) {
  for (const auto& e : fs::directory_iterator(SHADOWLAB_SEEDS_DIR))
    if (e.path().filename().string().rfind(seed + "_", 0) == 0 && e.path().extension() == ".txt")
      return e.path();
  return {};
}

TEST(ClaimQuotes, TheMatcherFindsGapsInOrderAndNothingElse) {
  const std::vector<std::string> text =
      seedReadings("the total shadow map-\nping time is \u201c2.06 ms\u201d, and\nthe rest");
  EXPECT_TRUE(quoted("shadow mapping time is \"2.06 ms\"", text));  // hyphenation, quotes
  EXPECT_TRUE(quoted("shadow map-ping time", text));
  EXPECT_TRUE(quoted("the total [...] the rest", text));
  EXPECT_FALSE(quoted("the rest [...] the total", text));        // out of order
  EXPECT_FALSE(quoted("shadow mapping time is 2.06 ms", text));  // the quotes dropped
  EXPECT_FALSE(quoted("the total shadow mapping time is 2.05 ms", text));
  EXPECT_FALSE(quoted("[...]", text));
}

TEST(ClaimQuotes, EveryQuoteIsInItsSeed) {
  // The seeds are not part of the repository: a checkout without them beside it (configure
  // with -DSHADOWLAB_SEEDS_DIR=...) skips, and says which folder it looked for.
  if (!fs::is_directory(SHADOWLAB_SEEDS_DIR))
    GTEST_SKIP() << SHADOWLAB_SEEDS_DIR
                 << ": no seeds folder (../shared/seeds beside the checkout); quotes not checked";
  int quotes = 0;
  for (const auto& e : fs::directory_iterator(SHADOWLAB_CLAIMS_DIR)) {
    if (e.path().extension() != ".json") continue;
    const nlohmann::json doc = nlohmann::json::parse(readFile(e.path()));
    const std::string seed = doc.at("seed").get<std::string>();
    const fs::path file = seedFile(seed);
    ASSERT_FALSE(file.empty()) << e.path() << ": no seed file " << seed << "_*.txt";
    const std::vector<std::string> readings = seedReadings(readFile(file));
    for (const nlohmann::json& c : doc.at("claims")) {
      const std::string id = c.at("id").get<std::string>();
      if (c.at("kind").get<std::string>() == "seed") {
        EXPECT_TRUE(c.contains("quote")) << id << ": a seed claim without a quote";
      }
      if (!c.contains("quote")) continue;
      ++quotes;
      EXPECT_TRUE(quoted(c.at("quote").get<std::string>(), readings))
          << e.path().filename().string() << ": " << id << ": the quote is not in "
          << file.filename().string() << ": " << c.at("quote").get<std::string>();
    }
  }
  EXPECT_GE(quotes, 25);
}

}  // namespace
