// Lesson texts with live numbers: parsing, refusal of malformed placeholders, filling.
#include <gtest/gtest.h>

#include <map>

#include "algo/TextTemplate.h"

namespace sl {
namespace {

std::string fillWith(const TextTemplate& t, const std::map<std::string, double>& values) {
  return t.fill([&](const TextPlaceholder& p) -> std::optional<double> {
    std::string key = (p.compare ? "compare." : "") + p.key;
    if (p.index >= 0) key += "[" + std::to_string(p.index) + "]";
    const auto it = values.find(key);
    if (it == values.end()) return std::nullopt;
    return it->second;
  });
}

TEST(TextTemplate, FillsEachPlaceholderFromTheFrame) {
  std::string error;
  const auto t = TextTemplate::parse(
      "left {error_pct} %, right {compare.error_pct:2} %, m p95 {partition.m_p95[1]:1}", &error);
  ASSERT_TRUE(t) << error;
  ASSERT_EQ(t->placeholders().size(), 3u);
  EXPECT_EQ(t->placeholders()[0].key, "error_pct");
  EXPECT_FALSE(t->placeholders()[0].compare);
  EXPECT_TRUE(t->placeholders()[1].compare);
  EXPECT_EQ(t->placeholders()[1].decimals, 2);
  EXPECT_EQ(t->placeholders()[2].key, "partition.m_p95");
  EXPECT_EQ(t->placeholders()[2].index, 1);
  EXPECT_EQ(fillWith(*t, {{"error_pct", 0.7462},
                          {"compare.error_pct", 2.0671},
                          {"partition.m_p95[1]", 139.64}}),
            "left 0.746 %, right 2.07 %, m p95 139.6");
}

TEST(TextTemplate, AValueTheFrameDoesNotHaveReadsNotAvailableNeverZero) {
  const auto t = TextTemplate::parse("error {error_pct} %", nullptr);
  ASSERT_TRUE(t);
  EXPECT_EQ(fillWith(*t, {}), "error n/a %");
  EXPECT_EQ(t->fill(nullptr), "error n/a %");
}

TEST(TextTemplate, DoubledBracesAreLiteralAndPlainTextIsUnchanged) {
  const auto t = TextTemplate::parse("a {{set}} of {n} and }} alone", nullptr);
  ASSERT_TRUE(t);
  EXPECT_EQ(fillWith(*t, {{"n", 3}}), "a {set} of 3.00 and } alone");
  const auto plain = TextTemplate::parse("R settles at 45°, ± 2°.", nullptr);
  ASSERT_TRUE(plain);
  EXPECT_FALSE(plain->hasPlaceholders());
  EXPECT_EQ(plain->fill(nullptr), "R settles at 45°, ± 2°.");
}

TEST(TextTemplate, MalformedPlaceholdersAreRefusedNamingWhereAndWhat) {
  struct Case {
    const char* text;
    const char* says;
  };
  for (const Case c :
       {Case{"an {open brace", "'{' without '}'"}, Case{"close} brace", "'}' without '{'"},
        Case{"{}", "empty key"}, Case{"{compare.}", "empty key"}, Case{"{a b}", "key characters"},
        Case{"{x:7}", "decimals"}, Case{"{x:}", "decimals"}, Case{"{x[-1]}", "index"},
        Case{"{x[]}", "index"}, Case{"{x]}", "']' without '['"},
        Case{"{a{b}", "'{' without '}'"}}) {
    std::string error;
    EXPECT_FALSE(TextTemplate::parse(c.text, &error)) << c.text;
    EXPECT_NE(error.find(c.says), std::string::npos) << c.text << " -> " << error;
    EXPECT_NE(error.find("placeholder at byte "), std::string::npos) << error;
  }
  std::string error;
  EXPECT_FALSE(TextTemplate::parse("0123456789 {x:9}", &error));
  EXPECT_NE(error.find("byte 11"), std::string::npos) << error;
}

TEST(TextTemplate, AMessageQuotesAPlaceholderOnOneShortLine) {
  // A brace left open across paragraphs (a fuzzer's finding): the message stays one line.
  std::string error;
  const std::string text = "{error" + std::string(300, 'x') + "\n\nmore text:9}";
  EXPECT_FALSE(TextTemplate::parse(text, &error));
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  EXPECT_LT(error.size(), 160u) << error;
  EXPECT_NE(error.find("..."), std::string::npos) << error;
}

TEST(TextTemplate, ValuesReadAsThreeSignificantDigitsWithoutExponents) {
  EXPECT_EQ(formatTextValue(0.7462, -1), "0.746");
  EXPECT_EQ(formatTextValue(0.000746, -1), "0.000746");
  EXPECT_EQ(formatTextValue(12.345, -1), "12.3");
  EXPECT_EQ(formatTextValue(1049000.0, -1), "1049000");
  EXPECT_EQ(formatTextValue(-43.51, -1), "-43.5");
  EXPECT_EQ(formatTextValue(0.0, -1), "0");
  EXPECT_EQ(formatTextValue(-0.0001, 2), "0.00");
  EXPECT_EQ(formatTextValue(44.66, 0), "45");
  EXPECT_EQ(formatTextValue(1.0 / 0.0, -1), "inf");
  EXPECT_EQ(formatTextValue(-1.0 / 0.0, 1), "-inf");
  EXPECT_EQ(formatTextValue(0.0 / 0.0, 1), "nan");
}

}  // namespace
}  // namespace sl
