#include <gtest/gtest.h>

#include "core/color.h"
#include "core/error.h"

using namespace voxflame::core;

TEST(Color, HexRoundTrips) {
  for (const char* hex : {"#000000", "#ffffff", "#1e4dff", "#ffb13b", "#808080"})
    EXPECT_EQ(toHexColor(parseHexColor(hex)), hex);
}

TEST(Color, RejectsMalformedHex) {
  for (const char* bad : {"", "#12345", "123456", "#12345g", "#1234567"})
    EXPECT_THROW(parseHexColor(bad), Error) << bad;
}

TEST(Color, OklabRoundTrips) {
  const glm::vec3 colour(0.2f, 0.5f, 0.9f);
  const glm::vec3 back = oklabToLinear(linearToOklab(colour));
  EXPECT_NEAR(back.r, colour.r, 1e-4);
  EXPECT_NEAR(back.g, colour.g, 1e-4);
  EXPECT_NEAR(back.b, colour.b, 1e-4);
}

TEST(Color, GradientMidpointKeepsPerceivedLightness) {
  // Blue to yellow mixed naively on sRGB values gives a dull grey; the OKLab midpoint sits
  // halfway in perceived lightness between its ends.
  const glm::vec3 blue = parseHexColor("#0000ff"), yellow = parseHexColor("#ffff00");
  const Gradient gradient({{0.0f, blue}, {1.0f, yellow}});
  const float midLightness = linearToOklab(gradient.at(0.5f)).x;
  const float endsAverage = 0.5f * (linearToOklab(blue).x + linearToOklab(yellow).x);
  EXPECT_NEAR(midLightness, endsAverage, 1e-3);
  const glm::vec3 naive = srgbToLinear(0.5f * (linearToSrgb(blue) + linearToSrgb(yellow)));
  EXPECT_GT(midLightness, linearToOklab(naive).x + 0.05f);
  EXPECT_EQ(gradient.at(0.0f), blue);
  EXPECT_EQ(gradient.at(1.0f), yellow);
  EXPECT_EQ(gradient.at(-3.0f), blue);
}

TEST(Color, NamedPalettesParseAndUnknownNamesAreListed) {
  ASSERT_GE(namedPalettes().size(), 6u);
  for (const auto& palette : namedPalettes()) {
    const auto stops = paletteStops(palette.name);
    ASSERT_GE(stops.size(), 2u) << palette.name;
    EXPECT_FLOAT_EQ(stops.front().position, 0.0f);
    EXPECT_FLOAT_EQ(stops.back().position, 1.0f);
  }
  try {
    paletteStops("plaid");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("ember"), std::string::npos) << e.what();
  }
}
