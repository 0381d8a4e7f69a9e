// Receiver positions against the standards that define them, and the [radiation] receivers key.
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "core/config_table.hpp"
#include "core/error.hpp"
#include "radiation/receivers.hpp"

namespace rollnoise {
namespace {

std::vector<Receiver> parse(const std::string& text, double width = 0.2) {
  static toml::table holder;
  holder = toml::parse(text);
  return read_receivers(ConfigTable(*holder["radiation"].as_table(), "case.toml", "radiation"), width);
}

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Receivers, StandardPositions) {
  // ISO 11819-2: 0.1 m high, 0.2 m from the sidewall, ±0.2 m along; ISO 11819-1: 7.5 m, 1.2 m.
  // A 0.2 m wide tyre: the CPX microphones 0.1 + 0.2 m from the centre plane.
  EXPECT_LE((standard_receiver("cpx_front", 0.2).position - Eigen::Vector3d(0.2, 0.3, 0.1)).norm(), 1e-15);
  EXPECT_LE((standard_receiver("cpx_rear", 0.2).position - Eigen::Vector3d(-0.2, 0.3, 0.1)).norm(), 1e-15);
  EXPECT_EQ(standard_receiver("spb", 0.2).position, Eigen::Vector3d(0.0, 7.5, 1.2));
}

TEST(Receivers, DefaultAndListed) {
  const auto defaults = parse("[radiation]\n");
  ASSERT_EQ(defaults.size(), 3u);
  EXPECT_EQ(defaults[2].name, "spb");
  const auto listed = parse("[radiation]\nreceivers = [\"spb\", {name = \"mic1\", x = 1.0, y = -0.5, z = 0.3}]\n");
  ASSERT_EQ(listed.size(), 2u);
  EXPECT_EQ(listed[1].name, "mic1");
  EXPECT_EQ(listed[1].position, Eigen::Vector3d(1.0, -0.5, 0.3));
}

TEST(Receivers, BadListsNameTheKey) {
  EXPECT_NE(error_of("[radiation]\nreceivers = [\"cpx\"]\n").find("[radiation] receivers"), std::string::npos);
  EXPECT_NE(error_of("[radiation]\nreceivers = [\"cpx\"]\n").find("allowed names"), std::string::npos);
  EXPECT_NE(error_of("[radiation]\nreceivers = []\n").find("non-empty"), std::string::npos);
  EXPECT_NE(error_of("[radiation]\nreceivers = [\"spb\", \"spb\"]\n").find("twice"), std::string::npos);
  EXPECT_NE(error_of("[radiation]\nreceivers = [{name = \"m\", x = 0, y = 1, z = -0.1}]\n").find("z"), std::string::npos);
  EXPECT_NE(error_of("[radiation]\nreceivers = [{name = \"m\", x = 0, y = 1, z = 1, w = 2}]\n").find("unknown key"),
            std::string::npos);
  EXPECT_NE(error_of("[radiation]\nreceivers = [{name = \"a/b\", x = 0, y = 1, z = 1}]\n").find("file name"), std::string::npos);
  EXPECT_NE(error_of("[radiation]\nreceivers = [3]\n").find("name or a table"), std::string::npos);
}

}  // namespace
}  // namespace rollnoise
