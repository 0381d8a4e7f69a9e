// The calibrated model file: fitted values in place in the original text (comments kept, TOML
// floats), or the whole file written anew when a key is not on a line of its own; either way
// it reads back as exactly the fitted model.
#include <gtest/gtest.h>

#include <string>

#include <toml++/toml.h>

#include "calibrate/calibrated_model_file.hpp"

namespace rollnoise {
namespace {

TEST(CalibratedModelFile, ValuesReplacedInPlaceWithCommentsKept) {
  const std::string original =
      "# a tyre\nmodel = \"sdof\"\nmass = 1                   # kg\ndamping = 50.0 # N*s/m\n"
      "stiffness=500.0\ncontact_stiffness = 1.0e5\n\n[extra]\nmass = 3.0\n";
  const std::string text =
      calibrated_model_text(original, "m.toml", {{"mass", 0.798}, {"stiffness", 788.0}, {"damping", 1e-300}},
                            {"Calibrated", ""});
  EXPECT_EQ(text,
            "# Calibrated\n#\n# a tyre\nmodel = \"sdof\"\nmass = 0.798               # kg\ndamping = 1e-300 # N*s/m\n"
            "stiffness=788.0\ncontact_stiffness = 1.0e5\n\n[extra]\nmass = 3.0\n");
  const toml::table t = toml::parse(text);
  EXPECT_EQ(t["mass"].value<double>(), 0.798);
  EXPECT_TRUE(t["stiffness"].is_floating_point()) << "788 is written as 788.0, a TOML float";
  EXPECT_EQ(t["extra"]["mass"].value<double>(), 3.0) << "only top-level keys are replaced";
}

TEST(CalibratedModelFile, KeysNotOnALineOfTheirOwnRewriteTheFile) {
  // A quoted key: not found on a line as `key = value`, so the file is written from its table.
  const std::string original = "model = \"sdof\"\n\"mass\" = 1.0\ndamping = 50.0\n[tread]\ntype = \"winkler\"\n";
  const std::string text = calibrated_model_text(original, "m.toml", {{"mass", 2.5}}, {"Calibrated"});
  const toml::table t = toml::parse(text);
  EXPECT_EQ(t["mass"].value<double>(), 2.5);
  EXPECT_EQ(t["damping"].value<double>(), 50.0);
  EXPECT_EQ(t["tread"]["type"].value<std::string>(), "winkler");
  EXPECT_EQ(text.substr(0, 13), "# Calibrated\n");
}

TEST(CalibratedModelFile, TomlFloatsReadBackExactly) {
  for (double v : {52000.0, 1e5, 0.08, 5.502984108770436, 2708775.017145848, 1e-7, 123456789012345678.0}) {
    const std::string text = toml_float(v);
    const toml::table t = toml::parse("x = " + text);
    ASSERT_TRUE(t["x"].is_floating_point()) << text;
    EXPECT_EQ(t["x"].value<double>(), v) << text;
  }
}

}  // namespace
}  // namespace rollnoise
