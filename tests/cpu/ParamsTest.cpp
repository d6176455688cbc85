// Parameter declarations: range checks and parsing, the contract every front end relies on.
#include <cmath>

#include <gtest/gtest.h>

#include "algo/Params.h"

namespace sl {
namespace {

ParamSet makeSet() {
  return ParamSet({
      {.key = "resolution",
       .label = "Resolution",
       .group = "Shadow map",
       .type = ParamType::Int,
       .defaultValue = 2048,
       .minValue = 64,
       .maxValue = 16384,
       .step = 1,
       .help = "SM size"},
      {.key = "bias.slope",
       .label = "Slope bias",
       .group = "Bias",
       .type = ParamType::Float,
       .defaultValue = 1.5,
       .minValue = 0,
       .maxValue = 10,
       .step = 0.1,
       .help = ""},
      {.key = "pcf",
       .label = "PCF",
       .group = "Filter",
       .type = ParamType::Bool,
       .defaultValue = 0,
       .minValue = 0,
       .maxValue = 1,
       .step = 1,
       .help = ""},
      {.key = "filter",
       .label = "Filter",
       .group = "Filter",
       .type = ParamType::Enum,
       .defaultValue = 1,
       .minValue = 0,
       .maxValue = 2,
       .step = 1,
       .enumNames = {"none", "pcf3", "pcf5"},
       .help = ""},
  });
}

TEST(Params, DefaultsAndSet) {
  ParamSet p = makeSet();
  EXPECT_EQ(p.getInt("resolution"), 2048);
  EXPECT_FALSE(p.set("resolution", 4096));
  EXPECT_EQ(p.getInt("resolution"), 4096);
  EXPECT_EQ(p.format("filter"), "pcf3");
}

TEST(Params, OutOfRangeNamesTheRangeAndKeepsValue) {
  ParamSet p = makeSet();
  auto err = p.set("resolution", 20000);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("64..16384"), std::string::npos) << *err;
  EXPECT_NE(err->find("resolution"), std::string::npos) << *err;
  EXPECT_EQ(p.getInt("resolution"), 2048);
  EXPECT_TRUE(p.set("resolution", 100.5));  // not an integer
  EXPECT_TRUE(p.set("bias.slope", std::nan("")));
}

TEST(Params, UnknownKeyListsKnownKeys) {
  ParamSet p = makeSet();
  auto err = p.assign("nope=3");
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("unknown parameter 'nope'"), std::string::npos) << *err;
  EXPECT_NE(err->find("bias.slope"), std::string::npos) << *err;
}

TEST(Params, ParsesBoolsEnumsAndNumbers) {
  ParamSet p = makeSet();
  EXPECT_FALSE(p.assign("pcf=on"));
  EXPECT_TRUE(p.getBool("pcf"));
  EXPECT_FALSE(p.assign("filter=pcf5"));
  EXPECT_EQ(p.getInt("filter"), 2);
  EXPECT_FALSE(p.assign("bias.slope=2.5"));
  EXPECT_DOUBLE_EQ(p.get("bias.slope"), 2.5);
  EXPECT_TRUE(p.assign("bias.slope=abc"));
  EXPECT_TRUE(p.assign("filter=bilinear"));
  EXPECT_TRUE(p.assign("novalue"));
  unsigned rev = p.revision();
  EXPECT_FALSE(p.assign("bias.slope=2.5"));  // unchanged value: no new revision
  EXPECT_EQ(p.revision(), rev);
  p.resetToDefaults();
  EXPECT_EQ(p.getInt("filter"), 1);
}

}  // namespace
}  // namespace sl
