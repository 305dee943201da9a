// Importing flame files (issue 12): Debian's flam3 samples, hand-written files with every element
// and attribute the reader supports, every bad-input case with a message naming the file, the
// depth given to flat flames, and mutated files that must neither crash nor hang.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "core/chaos_game.h"
#include "core/error.h"
#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "core/random.h"
#include "core/scene.h"
#include "core/scene_io.h"
#include "test_support.h"

using namespace voxflame::core;
using voxflame::test::TemporaryFolder;

namespace {

const std::filesystem::path kFlam3Samples = "/usr/share/flam3";

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// A flame file around these transforms; `extra` goes inside <flame> after them.
std::string flameFile(const std::string& xforms, const std::string& extra = "", const std::string& attributes = "") {
  return "<flames><flame name=\"hand\" " + attributes + ">\n" + xforms + extra + "</flame></flames>\n";
}

const std::string kTwoXforms =
    "<xform weight=\"0.5\" color=\"0\" spherical=\"1\" coefs=\"0.5 0 0 0.5 0.25 0\"/>\n"
    "<xform weight=\"0.5\" color=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 -0.25 0\"/>\n";

std::string errorOf(const std::string& text, const std::string& source = "bad.flame") {
  try {
    readFlameXml(text, source);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

bool hasWarningContaining(const ImportedFlame& flame, const std::string& text) {
  return std::any_of(flame.warnings.begin(), flame.warnings.end(),
                     [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

// 256 colours as Apophysis writes them: RRGGBB, 32 per line; colour i is (i, 255 − i, 128).
std::string hexPaletteBlock() {
  std::string out = "<palette count=\"256\" format=\"RGB\">\n";
  char hex[8];
  for (int i = 0; i < 256; ++i) {
    std::snprintf(hex, sizeof hex, "%02X%02X%02X", i, 255 - i, 128);
    out += hex;
    if (i % 32 == 31) out += "\n";
  }
  return out + "</palette>\n";
}

// The palette's sRGB colour i (0–255 per channel).
glm::vec3 srgb255(const ImportedFlame& flame, std::size_t i) {
  return linearToSrgb(flame.palette.at(i).color) * 255.0f;
}

void expectColorNear(glm::vec3 actual, glm::vec3 expected, float tolerance = 0.6f) {
  EXPECT_NEAR(actual.r, expected.r, tolerance);
  EXPECT_NEAR(actual.g, expected.g, tolerance);
  EXPECT_NEAR(actual.b, expected.b, tolerance);
}

std::vector<std::filesystem::path> debianSamples() {
  std::vector<std::filesystem::path> samples;
  if (!std::filesystem::is_directory(kFlam3Samples)) return samples;
  for (const auto& entry : std::filesystem::directory_iterator(kFlam3Samples))
    if (entry.path().extension() == ".flam3") samples.push_back(entry.path());
  std::sort(samples.begin(), samples.end());
  return samples;
}

// The z extent (5–95%) of points the chaos game draws for this genome.
double zSpread(const FlameGenome& genome) {
  PatternLayer layer;
  layer.kind = PatternKind::Flame;
  layer.attractor.clear();
  layer.flame = genome;
  const ChaosGame game(layer, "test");
  constexpr std::size_t kLanes = 256;
  ChaosLanes lanes;
  lanes.resize(kLanes);
  SplitMix64 rng(7);
  for (std::size_t i = 0; i < kLanes; ++i) game.seedLane(lanes, i, rng);
  std::vector<double> x(kLanes), y(kLanes), z(kLanes), c(kLanes), zs;
  for (int step = 0; step < 200; ++step) {
    game.step(lanes, x.data(), y.data(), z.data(), c.data(), kLanes);
    if (step >= 40)
      for (double v : z)
        if (std::isfinite(v)) zs.push_back(v);
  }
  std::sort(zs.begin(), zs.end());
  if (zs.empty()) return 0.0;
  return zs[zs.size() * 95 / 100] - zs[zs.size() * 5 / 100];
}

}  // namespace

TEST(FlameXml, DebianSampleGenomesImportWithTheirTransformsAndPalettes) {
  const auto samples = debianSamples();
  if (samples.empty()) GTEST_SKIP() << "flam3-utils is not installed (no " << kFlam3Samples << ")";
  // test.flam3: two flames of four spherical transforms, flam3 palettes 15 and 29.
  const std::filesystem::path test = kFlam3Samples / "test.flam3";
  ASSERT_TRUE(std::filesystem::exists(test));
  for (std::size_t index : {0u, 1u}) {
    FlameImportOptions options;
    options.index = index;
    const FlameFileContents contents = loadFlameFile(test, options);
    EXPECT_EQ(contents.names.size(), 2u);
    EXPECT_EQ(contents.index, index);
    EXPECT_EQ(contents.flame.name, "test " + std::to_string(index + 1));
    ASSERT_EQ(contents.flame.genome.xforms.size(), 4u);
    EXPECT_FALSE(contents.flame.genome.hasFinal);
    EXPECT_EQ(contents.flame.palette.size(), 256u);
    EXPECT_TRUE(contents.flame.warnings.empty()) << contents.flame.warnings.front();
    EXPECT_DOUBLE_EQ(contents.flame.tone.gamma, 4.0);
    EXPECT_DOUBLE_EQ(contents.flame.tone.brightness, 4.0);
    for (const FlameXform& x : contents.flame.genome.xforms) {
      ASSERT_EQ(x.variations.size(), 1u);
      EXPECT_EQ(x.variations[0].name, "spherical");
      EXPECT_DOUBLE_EQ(x.weight, 0.25);
    }
  }
  // coefs="a d b e c f" of the first transform of the first flame.
  const Affine3 a = loadFlameFile(test).flame.genome.xforms[0].affine;
  EXPECT_DOUBLE_EQ(a.m[0], -0.681206);   // a
  EXPECT_DOUBLE_EQ(a.m[4], -0.0779465);  // d
  EXPECT_DOUBLE_EQ(a.m[1], 0.20769);     // b
  EXPECT_DOUBLE_EQ(a.m[5], 0.755065);    // e
  EXPECT_DOUBLE_EQ(a.m[3], -0.0416126);  // c
  EXPECT_DOUBLE_EQ(a.m[7], -0.262334);   // f
  EXPECT_EQ(a.m[2], 0.0);
  EXPECT_EQ(a.m[6], 0.0);
  // Every sample either imports (a palette of 256) or, having no transforms, is refused by name.
  for (const auto& sample : samples) {
    try {
      const FlameFileContents contents = loadFlameFile(sample);
      EXPECT_EQ(contents.flame.palette.size(), 256u) << sample;
      EXPECT_FALSE(contents.flame.genome.xforms.empty()) << sample;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(sample.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("no transforms"), std::string::npos) << e.what();
    }
  }
}

// Ten random genomes that flam3-genome (Debian's flam3-utils) made, with the variations and
// parameter attributes flam3 really writes: each imports with all its transforms; a variation the
// catalogue knows is used (never reported unknown), and its parameters are named as flam3 names
// them (no "does not have" warning: this catches a catalogue parameter named differently).
TEST(FlameXml, Flam3GenomesImportAndTheirParameterNamesMatchTheCatalogue) {
  const std::filesystem::path file = voxflame::test::sourcePath("tests/data/flam3_random_genomes.flam3");
  const std::string text = readText(file);
  std::vector<std::size_t> starts;
  for (std::size_t at = text.find("<flame "); at != std::string::npos; at = text.find("<flame ", at + 1))
    starts.push_back(at);
  ASSERT_EQ(starts.size(), 10u);
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const std::string flameText =
        text.substr(starts[i], (i + 1 < starts.size() ? starts[i + 1] : text.size()) - starts[i]);
    FlameImportOptions options;
    options.index = i;
    const FlameFileContents contents = loadFlameFile(file, options);
    const ImportedFlame& flame = contents.flame;
    std::size_t xforms = 0;
    for (std::size_t at = flameText.find("<xform "); at != std::string::npos; at = flameText.find("<xform ", at + 1))
      ++xforms;
    EXPECT_EQ(flame.genome.xforms.size(), xforms) << "flame " << i;
    EXPECT_EQ(flame.genome.hasFinal, flameText.find("<finalxform") != std::string::npos) << "flame " << i;
    EXPECT_EQ(flame.palette.size(), 256u);
    EXPECT_FALSE(hasWarningContaining(flame, "does not have")) << "flame " << i << ": " << flame.warnings.front();
    // The transforms' tags only: the flame's own attributes (rotate, scale, gamma) are no variations.
    std::string xformTags;
    for (std::size_t at = flameText.find("xform "); at != std::string::npos; at = flameText.find("xform ", at + 1))
      xformTags += flameText.substr(at, flameText.find('>', at) - at);
    for (const VariationInfo& info : variationCatalogue()) {
      if (xformTags.find(" " + info.name + "=\"") == std::string::npos) continue;
      bool used = false;
      for (const FlameXform& x : flame.genome.xforms)
        for (const VariationTerm& term : x.variations) used |= term.name == info.name;
      if (flame.genome.hasFinal)
        for (const VariationTerm& term : flame.genome.finalXform.variations) used |= term.name == info.name;
      EXPECT_TRUE(used) << "flame " << i << " names " << info.name;
    }
  }
}

TEST(FlameXml, BuiltInPaletteNumberComesFromFlam3sTableTurnedByHue) {
  if (!std::filesystem::exists(kFlam3PaletteTable)) GTEST_SKIP() << "no " << kFlam3PaletteTable;
  // The table's own first colour of palette 15 ("00RRGGBB"), read here independently.
  const std::string table = readText(kFlam3PaletteTable);
  const std::size_t entry = table.find("number=\"15\"");
  ASSERT_NE(entry, std::string::npos);
  const std::size_t data = table.find("data=\"", entry) + 6;
  const glm::vec3 first(static_cast<float>(std::stoi(table.substr(data + 2, 2), nullptr, 16)),
                        static_cast<float>(std::stoi(table.substr(data + 4, 2), nullptr, 16)),
                        static_cast<float>(std::stoi(table.substr(data + 6, 2), nullptr, 16)));
  const ImportedFlame plain = readFlameXml(flameFile(kTwoXforms, "", "palette=\"15\""), "p.flame").flame;
  EXPECT_TRUE(plain.warnings.empty());
  expectColorNear(srgb255(plain, 0), first);
  // A whole turn of hue is no turn; half a turn changes the colours.
  const ImportedFlame whole = readFlameXml(flameFile(kTwoXforms, "", "palette=\"15\" hue=\"1\""), "p.flame").flame;
  expectColorNear(srgb255(whole, 0), first, 1.0f);
  const ImportedFlame half = readFlameXml(flameFile(kTwoXforms, "", "palette=\"15\" hue=\"0.5\""), "p.flame").flame;
  const glm::vec3 turned = srgb255(half, 0);
  EXPECT_GT(std::abs(turned.r - first.r) + std::abs(turned.g - first.g) + std::abs(turned.b - first.b), 20.0f);
}

TEST(FlameXml, MissingPaletteTableIsAWarningNotAFailure) {
  FlameImportOptions options;
  options.paletteTable = "/nonexistent/flam3-palettes.xml";
  const ImportedFlame flame = readFlameXml(flameFile(kTwoXforms, "", "palette=\"3\""), "p.flame", options).flame;
  EXPECT_EQ(flame.palette.size(), 256u);
  EXPECT_TRUE(hasWarningContaining(flame, "/nonexistent/flam3-palettes.xml")) << flame.warnings.size();
  EXPECT_TRUE(hasWarningContaining(flame, "missing"));
}

TEST(FlameXml, HandWrittenFileWithEveryElement) {
  const std::string xforms =
      // color_speed given directly; post map; opacity.
      "<xform weight=\"0.6\" color=\"0.25\" color_speed=\"0.3\" opacity=\"0.75\" spherical=\"0.8\" linear=\"0.2\" "
      "coefs=\"1 2 3 4 5 6\" post=\"0.9 0.1 -0.1 0.9 0.05 -0.05\" chaos=\"1 0\"/>\n"
      // The old symmetry attribute: color_speed = (1 − symmetry) / 2; an unknown variation and its parameter.
      "<xform weight=\"0.4\" color=\"0.75\" symmetry=\"0.5\" julia=\"1\" zzplot_wf=\"0.3\" zzplot_wf_font_size=\"2\" "
      "coefs=\"0.5 0 0 0.5 0 0\" plotmode=\"off\"/>\n"
      "<finalxform color=\"0.5\" color_speed=\"0.2\" swirl=\"0.7\" coefs=\"1 0 0 1 0.1 0.2\"/>\n";
  const std::string extra = "<symmetry kind=\"-3\"/>\n" + hexPaletteBlock();
  const std::string attributes =
      "brightness=\"7\" gamma=\"3.5\" gamma_threshold=\"0.02\" vibrancy=\"0.6\" highlight_power=\"0.5\" "
      "estimator_radius=\"7\" estimator_minimum=\"1\" estimator_curve=\"0.6\" background=\"1 0 0\"";
  FlameImportOptions options;
  options.depth = 0.0;
  const FlameFileContents contents = readFlameXml(flameFile(xforms, extra, attributes), "hand.flame", options);
  const ImportedFlame& flame = contents.flame;
  EXPECT_EQ(flame.name, "hand");
  ASSERT_EQ(flame.genome.xforms.size(), 2u);
  const FlameXform& first = flame.genome.xforms[0];
  EXPECT_DOUBLE_EQ(first.weight, 0.6);
  EXPECT_DOUBLE_EQ(first.color, 0.25);
  EXPECT_DOUBLE_EQ(first.colorSpeed, 0.3);
  EXPECT_DOUBLE_EQ(first.opacity, 0.75);
  // "1 2 3 4 5 6" is a d b e c f.
  EXPECT_EQ(first.affine.m[0], 1.0);
  EXPECT_EQ(first.affine.m[4], 2.0);
  EXPECT_EQ(first.affine.m[1], 3.0);
  EXPECT_EQ(first.affine.m[5], 4.0);
  EXPECT_EQ(first.affine.m[3], 5.0);
  EXPECT_EQ(first.affine.m[7], 6.0);
  ASSERT_TRUE(first.hasPost);
  EXPECT_DOUBLE_EQ(first.post.m[1], -0.1);  // post's b
  EXPECT_DOUBLE_EQ(first.post.m[4], 0.1);   // post's d
  EXPECT_DOUBLE_EQ(first.post.m[7], -0.05);
  ASSERT_EQ(first.variations.size(), 2u);
  EXPECT_EQ(first.variations[0].name, "spherical");
  EXPECT_DOUBLE_EQ(first.variations[0].weight, 0.8);
  EXPECT_EQ(first.variations[1].name, "linear");
  const FlameXform& second = flame.genome.xforms[1];
  EXPECT_DOUBLE_EQ(second.colorSpeed, 0.25);
  EXPECT_EQ(second.opacity, 0.0);           // plotmode="off"
  ASSERT_EQ(second.variations.size(), 1u);  // zzplot_wf left out
  EXPECT_EQ(second.variations[0].name, "julia");
  ASSERT_TRUE(flame.genome.hasFinal);
  EXPECT_DOUBLE_EQ(flame.genome.finalXform.colorSpeed, 0.2);
  EXPECT_DOUBLE_EQ(flame.genome.finalXform.affine.m[7], 0.2);
  EXPECT_EQ(flame.genome.finalXform.variations.at(0).name, "swirl");
  EXPECT_EQ(flame.genome.symmetry.rotational, 3);
  EXPECT_TRUE(flame.genome.symmetry.mirror);
  ASSERT_EQ(flame.palette.size(), 256u);
  expectColorNear(srgb255(flame, 0), {0, 255, 128});
  expectColorNear(srgb255(flame, 200), {200, 55, 128});
  EXPECT_FLOAT_EQ(flame.palette[255].position, 1.0f);
  EXPECT_DOUBLE_EQ(flame.tone.brightness, 7.0);
  EXPECT_DOUBLE_EQ(flame.tone.gamma, 3.5);
  EXPECT_DOUBLE_EQ(flame.tone.gammaThreshold, 0.02);
  EXPECT_DOUBLE_EQ(flame.tone.vibrancy, 0.6);
  EXPECT_DOUBLE_EQ(flame.tone.highlightPower, 0.5);
  EXPECT_DOUBLE_EQ(flame.tone.estimatorRadius, 7.0);
  EXPECT_DOUBLE_EQ(flame.tone.estimatorMinimum, 1.0);
  EXPECT_DOUBLE_EQ(flame.tone.estimatorCurve, 0.6);
  expectColorNear(linearToSrgb(flame.tone.background) * 255.0f, {255, 0, 0});
  // Xaos: transform 0 may not be followed by transform 1; transform 1 has none.
  EXPECT_EQ(first.xaos, (std::vector<double>{1.0, 0.0}));
  EXPECT_TRUE(flame.genome.xforms[1].xaos.empty());
  // The unknown variation by name (not its parameter); it is the one thing left out.
  EXPECT_TRUE(hasWarningContaining(flame, "zzplot_wf"));
  EXPECT_FALSE(hasWarningContaining(flame, "font_size"));
  EXPECT_FALSE(hasWarningContaining(flame, "xaos"));
  EXPECT_EQ(flame.leftOut, (std::vector<std::string>{"variation zzplot_wf"}));
  // zzplot_wf (0.3) is less than julia (1): no warning that transform 1 lost most of its weight.
  EXPECT_FALSE(hasWarningContaining(flame, "look different"));
  const std::string mostlyUnknown =
      "<xform weight=\"1\" julia=\"0.1\" zzunknownvariation=\"0.9\" coefs=\"0.5 0 0 0.5 0 0\"/>";
  const ImportedFlame shrunk = readFlameXml(flameFile(mostlyUnknown, hexPaletteBlock()), "u.flame").flame;
  EXPECT_TRUE(hasWarningContaining(shrunk, "transform 0 keeps 0.1 of its variation weight 1"));
}

TEST(FlameXml, HexPaletteLayoutsRgbaAndFlam3sPaddedColours) {
  std::string rgba = "<palette count=\"256\" format=\"RGBA\">", padded = "<colors count=\"256\" data=\"";
  char hex[16];
  for (int i = 0; i < 256; ++i) {
    std::snprintf(hex, sizeof hex, "%02x%02x%02xff", 255 - i, i, 7);
    rgba += hex;
    std::snprintf(hex, sizeof hex, "00%02x%02x%02x", 9, i, 255 - i);
    padded += hex;
  }
  const ImportedFlame fromRgba = readFlameXml(flameFile(kTwoXforms, rgba + "</palette>"), "a.flame").flame;
  expectColorNear(srgb255(fromRgba, 10), {245, 10, 7});
  const ImportedFlame fromPadded = readFlameXml(flameFile(kTwoXforms, padded + "\"/>"), "p.flame").flame;
  expectColorNear(srgb255(fromPadded, 10), {9, 10, 245});
  EXPECT_NE(errorOf(flameFile(kTwoXforms, "<palette format=\"HSV\">00</palette>")).find("HSV"), std::string::npos);
}

TEST(FlameXml, InlineColoursFillTheirGapsAndTrivialXaosIsSilent) {
  const std::string colours = "<color index=\"0\" rgb=\"255 0 0\"/><color index=\"100\" rgb=\"0 0 255\"/>";
  const std::string xforms =
      "<xform weight=\"1\" color=\"0\" linear=\"1\" chaos=\"1 1\" coefs=\"0.5 0 0 0.5 0 0\"/>"
      "<xform weight=\"1\" color=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0.5 0\"/>";
  const ImportedFlame flame = readFlameXml(flameFile(xforms, colours), "c.flame").flame;
  ASSERT_EQ(flame.palette.size(), 256u);
  expectColorNear(srgb255(flame, 0), {255, 0, 0});
  expectColorNear(srgb255(flame, 99), {255, 0, 0});
  expectColorNear(srgb255(flame, 255), {0, 0, 255});
  EXPECT_TRUE(flame.warnings.empty());
}

TEST(FlameXml, Linear3DOfApophysisIsTheCataloguesLinear3D) {
  const std::string xform = "<xform weight=\"1\" linear3D=\"0.8\" coefs=\"0.5 0 0 0.5 0 0\"/>";
  const ImportedFlame flame = readFlameXml(flameFile(xform, hexPaletteBlock()), "l.flame").flame;
  ASSERT_EQ(flame.genome.xforms.at(0).variations.size(), 1u);
  EXPECT_EQ(flame.genome.xforms[0].variations[0].name, "linear3D");
  EXPECT_DOUBLE_EQ(flame.genome.xforms[0].variations[0].weight, 0.8);
  EXPECT_TRUE(flame.warnings.empty());
}

TEST(FlameXml, SeveralFlamesArePickedByIndexOrName) {
  const std::string text = "<Flames>" + flameFile(kTwoXforms) + "<flame name=\"second\">" + kTwoXforms +
                           "<xform weight=\"1\" coefs=\"1 0 0 1 0 0\"/></flame>"
                           "</Flames>";
  FlameImportOptions options;
  options.name = "second";
  const FlameFileContents byName = readFlameXml(text, "many.flame", options);
  EXPECT_EQ(byName.names.size(), 2u);  // one inside a nested <flames>, one directly under <Flames>
  EXPECT_EQ(byName.index, 1u);
  EXPECT_EQ(byName.flame.genome.xforms.size(), 3u);
  options.name.clear();
  options.index = 5;
  try {
    readFlameXml(text, "many.flame", options);
    ADD_FAILURE() << "index 5 of 3 flames was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("many.flame"), std::string::npos);
  }
}

TEST(FlameXml, EveryCatalogueVariationAndItsParametersAreRead) {
  std::size_t withParameters = 0;
  for (const VariationInfo& info : variationCatalogue()) {
    std::string attributes = info.name + "=\"0.7\"";
    std::vector<double> expected;
    for (const VariationParam& param : info.params) {
      // A value inside the slider range that is not the default.
      const double value = param.defaultValue == param.sliderMin ? param.sliderMax : param.sliderMin;
      expected.push_back(value);
      std::ostringstream number;
      number.precision(17);
      number << value;
      attributes += " " + info.name + "_" + param.name + "=\"" + number.str() + "\"";
    }
    withParameters += !info.params.empty();
    const std::string xform = "<xform weight=\"1\" " + attributes + " coefs=\"0.5 0 0 0.5 0 0\"/>";
    FlameImportOptions flat;
    flat.depth = 0.0;  // depth would drop flatten (it would undo the depth)
    const ImportedFlame flame = readFlameXml(flameFile(xform, hexPaletteBlock()), "v.flame", flat).flame;
    // JWildfire's prepost_ variations come in as two terms: the inverse map before, the map after.
    const bool prepost = info.name.starts_with("prepost_");
    ASSERT_EQ(flame.genome.xforms.at(0).variations.size(), prepost ? 2u : 1u) << info.name;
    const VariationTerm& term = flame.genome.xforms[0].variations.back();
    EXPECT_EQ(term.name, prepost ? "post_" + info.name : info.name);
    if (prepost) {
      EXPECT_EQ(flame.genome.xforms[0].variations[0].name, "pre_" + info.name);
      EXPECT_EQ(flame.genome.xforms[0].variations[0].params, term.params);
    }
    EXPECT_DOUBLE_EQ(term.weight, 0.7);
    ASSERT_EQ(term.params.size(), expected.size()) << info.name;
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_DOUBLE_EQ(term.params[i], expected[i]) << info.name;
    if (info.name == "inversion")
      EXPECT_EQ(flame.leftOut, (std::vector<std::string>{"direct colour of " + info.name}));
    else if (info.name == "obj_mesh_primitive_wf")  // receive_only_shadows 1: a setting of solid rendering
      EXPECT_EQ(flame.leftOut, (std::vector<std::string>{"receive_only_shadows of " + info.name}));
    else if (info.name == "svg_wf")  // JWildfire colours its points by the SVG's colours
      EXPECT_EQ(flame.leftOut, (std::vector<std::string>{"colour of svg_wf"}));
    else if (info.name == "subflame_wf" || info.name == "glynns3subfl")  // no flame embedded; colour mode −2
      EXPECT_EQ(flame.leftOut,                                           // and a flame sequence are not kept
                (std::vector<std::string>{"embedded flame of " + info.name, "flame sequence of " + info.name,
                                          "true colour of " + info.name}));
    else if (info.name == "dc_perlin")  // a color_seed, set here, is pyr3's: its dc_perlin is another variation
      EXPECT_EQ(flame.leftOut, (std::vector<std::string>{"pyr3's dc_perlin"}));
    else if (info.name == "text_wf")  // its default font, Arial, may not be installed: the stand-in is named
      EXPECT_TRUE(flame.leftOut.empty() &&
                  std::all_of(flame.warnings.begin(), flame.warnings.end(),
                              [](const std::string& w) { return w.find("draws its text") != std::string::npos; }))
          << flame.warnings.front();
    else if (info.name == "parplot2d_wf")  // its formulas, text parameters, are not given here
      EXPECT_EQ(flame.leftOut, (std::vector<std::string>{"xformula of parplot2d_wf", "yformula of parplot2d_wf",
                                                         "zformula of parplot2d_wf"}));
    else if (info.name == "polarplot3d_wf" || info.name == "isosfplot3d_wf")  // nor their formula
      EXPECT_EQ(flame.leftOut, (std::vector<std::string>{"formula of " + info.name}));
    else if (info.name == "glsl_apollonian" || info.name == "glsl_circlesblue" || info.name == "glsl_grid3D" ||
             info.name == "glsl_mandala" || info.name == "glsl_acrilic") {
      // JWildfire's "Density Pixels" (and glsl_acrilic's "Red Fac." …) has a space, which XML does not allow
      ASSERT_EQ(flame.warnings.size(), 1u) << flame.warnings.front();
      EXPECT_NE(flame.warnings.front().find("not well-formed"), std::string::npos) << flame.warnings.front();
    } else
      EXPECT_TRUE(flame.warnings.empty()) << info.name << ": " << flame.warnings.front();
  }
  EXPECT_GT(withParameters, 0u) << "no catalogue variation has parameters: only their names were checked";
}

// flam3 takes any whole symmetry order; Electric Sheep's genomes have ones such as 57.
TEST(FlameXml, LargeSymmetryOrdersAreRead) {
  const ImportedFlame flame = readFlameXml(flameFile(kTwoXforms, "<symmetry kind=\"-57\"/>"), "s.flam3").flame;
  EXPECT_EQ(flame.genome.symmetry.rotational, 57);
  EXPECT_TRUE(flame.genome.symmetry.mirror);
  EXPECT_EQ(expandSymmetry(flame.genome).size(), 2u + 56u + 1u);  // the turns and the mirror
}

// flam3 3.x writes its palette rows with printf's "%2x": a byte under 16 is a space and a digit,
// and the spaces are part of the row (Mossop's fractal-flame renders, electricsheep.247's).
TEST(FlameXml, Flam3PalettesWhoseBytesArePaddedWithSpacesAreRead) {
  std::string block = "<palette count=\"256\" format=\"RGB\">\n";
  std::string zeroPadded;
  char hex[8];
  for (int i = 0; i < 256; ++i) {
    if (i % 8 == 0) block += "      ";
    const int r = i % 16, g = (7 * i) % 256, b = 255 - i;  // every row has bytes under 16
    std::snprintf(hex, sizeof hex, "%2x%2x%2x", r, g, b);
    block += hex;
    std::snprintf(hex, sizeof hex, "%02x%02x%02x", r, g, b);
    zeroPadded += hex;
    if (i % 8 == 7) block += "\n";
  }
  block += "   </palette>\n";
  ASSERT_NE(block.find("       "), std::string::npos) << "a row should start with a padded byte";
  const ImportedFlame padded = readFlameXml(flameFile(kTwoXforms, block), "padded.flam3").flame;
  const ImportedFlame plain =
      readFlameXml(flameFile(kTwoXforms, "<palette count=\"256\" format=\"RGB\">" + zeroPadded + "</palette>"),
                   "plain.flam3")
          .flame;
  ASSERT_EQ(padded.palette.size(), 256u);
  for (std::size_t i = 0; i < 256; ++i) EXPECT_EQ(padded.palette.at(i).color, plain.palette.at(i).color) << i;
  EXPECT_TRUE(padded.warnings.empty()) << padded.warnings.front();
  // A space inside a byte's low digit is no padding.
  EXPECT_NE(errorOf(flameFile(kTwoXforms, "<palette count=\"256\" format=\"RGB\">\n      0c 5e2d" +
                                              std::string(40, 'a') + "\n</palette>")),
            "");
}

// flam3 names oscilloscope's parameters oscope_* (Fractorium oscilloscope_*): both are read.
TEST(FlameXml, Flam3sOscopeParametersAreOscilloscopes) {
  const VariationInfo* oscilloscope = findVariation("oscilloscope");
  ASSERT_NE(oscilloscope, nullptr);
  const ImportedFlame flame =
      readFlameXml(flameFile("<xform weight=\"1\" oscilloscope=\"0.5\" oscope_frequency=\"3\" oscope_amplitude=\"2\" "
                             "oscope_damping=\"0.25\" oscope_separation=\"1.5\" coefs=\"0.5 0 0 0.5 0 0\"/>"),
                   "o.flam3")
          .flame;
  EXPECT_FALSE(hasWarningContaining(flame, "oscope")) << flame.warnings.front();
  ASSERT_EQ(flame.genome.xforms.at(0).variations.size(), 1u);
  const VariationTerm& term = flame.genome.xforms.at(0).variations.at(0);
  const auto param = [&](const char* name) {
    return term.params.at(static_cast<std::size_t>(oscilloscope->paramIndex(name)));
  };
  EXPECT_EQ(param("frequency"), 3.0);
  EXPECT_EQ(param("amplitude"), 2.0);
  EXPECT_EQ(param("damping"), 0.25);
  EXPECT_EQ(param("separation"), 1.5);
}

TEST(FlameXml, JulianPowerAndDistanceAreRead) {
  const VariationInfo* julian = findVariation("julian");
  ASSERT_NE(julian, nullptr) << "the variation catalogue has lost 'julian'";
  const std::string xform =
      "<xform weight=\"1\" julian=\"0.5\" julian_power=\"5\" julian_dist=\"-1\" "
      "coefs=\"0.5 0 0 0.5 0 0\"/>";
  const ImportedFlame flame = readFlameXml(flameFile(xform), "j.flame").flame;
  const VariationTerm& term = flame.genome.xforms.at(0).variations.at(0);
  EXPECT_EQ(term.params.at(static_cast<std::size_t>(julian->paramIndex("power"))), 5.0);
  EXPECT_EQ(term.params.at(static_cast<std::size_t>(julian->paramIndex("dist"))), -1.0);
}

TEST(FlameXml, BadFilesAreErrorsNamingTheFile) {
  const auto expectError = [](const std::string& text, const std::string& needle) {
    const std::string message = errorOf(text);
    EXPECT_NE(message.find("bad.flame"), std::string::npos) << "no file named for: " << text << "\n" << message;
    EXPECT_NE(message.find(needle), std::string::npos) << "expected '" << needle << "' in: " << message;
  };
  expectError("this is not XML at all <", "not flame XML");
  expectError("", "not flame XML");
  expectError("<svg><rect/></svg>", "no <flame>");
  expectError(flameFile(""), "no transforms");
  expectError(flameFile("<xform weight=\"0\" coefs=\"1 0 0 1 0 0\"/><xform weight=\"0\" coefs=\"1 0 0 1 0 0\"/>"),
              "weight 0");
  expectError(flameFile("<xform weight=\"1\" coefs=\"nan 0 0 1 0 0\"/>"), "transform 0");
  expectError(flameFile("<xform weight=\"1\" coefs=\"1e308 0 0 1 0 0\"/>"), "beyond");
  expectError(flameFile("<xform weight=\"1\" coefs=\"1 0 0 1 0 0\" post=\"1 0 0 1 0 inf\"/>"), "post");
  expectError(flameFile("<xform weight=\"1\" coefs=\"1 0 0 1 0\"/>"), "6 numbers");
  expectError(flameFile("<xform weight=\"1\"/>"), "coefs");
  expectError(flameFile("<xform weight=\"-1\" coefs=\"1 0 0 1 0 0\"/>"), "weight");
  expectError(flameFile("<xform weight=\"1\" linear=\"1e400\" coefs=\"1 0 0 1 0 0\"/>"), "linear");
  expectError(flameFile("<xform weight=\"1\" linear=\"x\" coefs=\"1 0 0 1 0 0\"/>"), "not a number");
  expectError(flameFile(kTwoXforms, "<symmetry kind=\"200\"/>"), "symmetry");
  expectError(flameFile(kTwoXforms, "<symmetry kind=\"-128\"/>"), "symmetry");
  expectError(flameFile(kTwoXforms, "<symmetry kind=\"2.5\"/>"), "symmetry");
  expectError(flameFile(kTwoXforms, "<palette count=\"256\" format=\"RGB\">00fg00</palette>"), "hex digits");
  expectError(flameFile(kTwoXforms, "<palette count=\"256\" format=\"RGB\">00ff0</palette>"), "hex digits");
  std::string many;
  for (int i = 0; i < 129; ++i) many += "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/>";
  expectError(flameFile(many), "128");
}

TEST(FlameXml, MissingFileIsNamed) {
  try {
    loadFlameFile("/nonexistent/x.flame");
    ADD_FAILURE() << "a missing file loaded";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/x.flame"), std::string::npos);
  }
}

TEST(FlameXml, FlatFlamesGainAdjustableDepth) {
  const std::string xforms =
      "<xform weight=\"1\" color=\"0\" spherical=\"2\" coefs=\"0.5 0 0 0.5 0.5 0\"/>"
      "<xform weight=\"1\" color=\"0.5\" linear=\"1\" coefs=\"0.5 0 0 0.5 0 0.5\"/>"
      "<xform weight=\"1\" color=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 -0.5 0\"/>";
  FlameImportOptions options;
  options.depth = 0.5;
  const ImportedFlame deep = readFlameXml(flameFile(xforms), "d.flame", options).flame;
  EXPECT_TRUE(deep.depthAdded);
  // z' = ½ z + depth · s after the variations: the spherical transform's weight 2 is divided out.
  EXPECT_DOUBLE_EQ(deep.genome.xforms[0].affine.m[10], 0.25);
  EXPECT_DOUBLE_EQ(deep.genome.xforms[0].affine.m[11], -0.25);
  EXPECT_DOUBLE_EQ(deep.genome.xforms[1].affine.m[11], 0.0);
  EXPECT_DOUBLE_EQ(deep.genome.xforms[2].affine.m[11], 0.5);
  options.depth = 0.0;
  const ImportedFlame flat = readFlameXml(flameFile(xforms), "d.flame", options).flame;
  // Depth fills a volume; depth 0 lies in one plane.
  EXPECT_GT(zSpread(deep.genome), 0.5);
  EXPECT_LT(zSpread(flat.genome), 1e-6);
  // A flame with a 3D variation keeps its own depth.
  FlameGenome threeD = deep.genome;
  threeD.xforms[0].variations = {{"spherical3D", 1.0, {}}};
  EXPECT_FALSE(isFlatFlame(threeD));
  EXPECT_FALSE(addFlameDepth(threeD, 0.5));
}

TEST(FlameXml, ImportedSceneIsACompletePresetThatLoadsBack) {
  const ImportedFlame flame = readFlameXml(flameFile(kTwoXforms, hexPaletteBlock(), "gamma=\"3\""), "s.flame").flame;
  ASSERT_EQ(defaultScene().render.method, RenderMethod::Volume);
  const Scene scene = sceneFromImportedFlame(flame, defaultScene());
  ASSERT_EQ(scene.layers.size(), 1u);
  EXPECT_EQ(scene.layers[0].kind, PatternKind::Flame);
  EXPECT_EQ(scene.layers[0].color.mode, ColorMode::Index);
  // Opened over an attractor's scene (the explorer's open), a flame still shows its filaments.
  EXPECT_EQ(scene.render.method, RenderMethod::Points);
  // Placed as framed: the frame's centre at the mesh's centre, its longer side across the grid.
  const LayerTransform& placed = scene.layers[0].transform;
  ASSERT_TRUE(placed.lockFit);
  EXPECT_DOUBLE_EQ(placed.lockedCenter.x, flame.flat.centerX);
  EXPECT_DOUBLE_EQ(placed.lockedCenter.y, flame.flat.centerY);
  const double frame = std::max(flame.flat.width, flame.flat.height) / (flame.flat.scale * std::exp2(flame.flat.zoom));
  EXPECT_NEAR(placed.lockedScale, defaultScene().gridResolution / frame, 1e-9);
  EXPECT_FALSE(placed.rotationDeg.x == 0.0 && placed.rotationDeg.y == 0.0) << "turned to face the camera";
  EXPECT_EQ(scene.layers[0].color.gradient.size(), 256u);
  EXPECT_EQ(scene.name, "hand");
  EXPECT_DOUBLE_EQ(scene.tone.gamma, 3.0);
  const Scene loaded = sceneFromJson(sceneToJson(scene), "s.json");
  ASSERT_EQ(loaded.layers.size(), 1u);
  EXPECT_EQ(loaded.layers[0].flame.xforms.size(), 2u);
  EXPECT_EQ(loaded.layers[0].color.gradient.size(), 256u);
  EXPECT_EQ(loaded.meshPath, scene.meshPath);
}

// Deterministic mutations of the Debian samples and the hand-written files: bytes flipped,
// deleted and inserted, and attribute values replaced by hostile numbers. Each case either
// imports (and then plays a few chaos-game steps and round-trips as a preset) or throws
// core::Error; never anything else, and the whole run takes seconds.
TEST(FlameXml, FuzzedFlameFilesNeverCrashOrHang) {
  std::vector<std::string> bases = {
      flameFile(kTwoXforms),
      flameFile(kTwoXforms, "<symmetry kind=\"-4\"/>" + hexPaletteBlock(), "gamma=\"3\" background=\"0 0 0.2\""),
      flameFile("<xform weight=\"0.5\" color=\"0\" swirl=\"1\" julia=\"0.5\" coefs=\"0.6 0.2 -0.2 0.6 0 0.1\" "
                "post=\"1 0 0 1 0.1 0\" symmetry=\"0.2\" opacity=\"0.5\"/>"
                "<xform weight=\"0.5\" color=\"1\" sinusoidal=\"1\" unknownvar=\"1\" coefs=\"0.5 0 0 0.5 0.3 0\"/>"
                "<finalxform spherical=\"1\" coefs=\"1 0 0 1 0 0\"/>"
                "<color index=\"0\" rgb=\"10 20 30\"/><color index=\"255\" rgb=\"200 100 50\"/>"),
  };
  for (const auto& sample : debianSamples()) bases.push_back(readText(sample));
  bases.push_back(readText(voxflame::test::sourcePath("tests/data/flam3_random_genomes.flam3")));
  const std::vector<std::string> hostile = {"nan", "inf",  "-inf", "1e308", "-1e308", "1e-320",      "0", "-0",
                                            "1e6", "-1e7", "abc",  "",      "1 2",    "99999999999", "-3"};
  const std::string alphabet = "<>/=\"' abcdefgxyz0123456789.-e\n&;!?[]";
  std::uint64_t state = 0x5eed;
  const auto next = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<std::size_t>(state >> 33);
  };
  FlameImportOptions options;
  options.paletteTable = kFlam3PaletteTable;
  const auto start = std::chrono::steady_clock::now();
  int imported = 0, refused = 0;
  // A deterministic sample of mutations, run on every build (sanitizers included); the open-ended
  // search is scripts/fuzz.sh's libFuzzer target on the same importer, so 5000 suffice here.
  constexpr int kCases = 5000;
  for (int round = 0; round < kCases; ++round) {
    std::string text = bases[static_cast<std::size_t>(round) % bases.size()];
    const int edits = 1 + static_cast<int>(next() % 4);
    for (int e = 0; e < edits; ++e) {
      if (text.empty()) text = "<";
      const std::size_t at = next() % text.size();
      switch (next() % 4) {
        case 0:
          text[at] = alphabet[next() % alphabet.size()];
          break;
        case 1:
          text.erase(at, 1 + next() % 12);
          break;
        case 2:
          text.insert(at, 1, alphabet[next() % alphabet.size()]);
          break;
        default: {
          // Replace the value of the attribute at or after `at`.
          const std::size_t open = text.find("=\"", at);
          if (open == std::string::npos) break;
          const std::size_t close = text.find('"', open + 2);
          if (close == std::string::npos) break;
          text.replace(open + 2, close - open - 2, hostile[next() % hostile.size()]);
        }
      }
    }
    options.index = next() % 3;
    try {
      const FlameFileContents contents = readFlameXml(text, "fuzz.flame", options);
      ++imported;
      const Scene scene = sceneFromImportedFlame(contents.flame, defaultScene());
      sceneFromJson(sceneToJson(scene), "fuzz.json");      // whatever imports is a valid preset
      if (round % 8 == 0) zSpread(contents.flame.genome);  // and iterates without trouble
    } catch (const Error&) {
      ++refused;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GT(imported, kCases / 20) << "the mutations should leave many files importable";
  EXPECT_GT(refused, kCases / 20);
  EXPECT_LT(seconds, 120.0);  // about 1 s in a Release build; sanitizer builds are slower
}

// Issue 25: what real files write that is not well-formed XML, read tolerantly.
TEST(FlameXml, JwildfireCopiesOfAVariationAreSeparateEntries) {
  const std::string xforms =
      "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0 0\" julian=\"0.5\" julian_power=\"3\" julian#1#=\"0.25\" "
      "julian#1#_power=\"5\" julian#1#_dist=\"2\" linear_fx_priority=\"0\"/>\n";
  const FlameFileContents contents = readFlameXml(flameFile(xforms, hexPaletteBlock()), "copies.flame");
  const std::vector<VariationTerm>& terms = contents.flame.genome.xforms.at(0).variations;
  ASSERT_EQ(terms.size(), 2u);
  EXPECT_EQ(terms[0].name, "julian");
  EXPECT_EQ(terms[0].weight, 0.5);
  EXPECT_EQ(terms[0].params, (std::vector<double>{3.0, 1.0}));
  EXPECT_EQ(terms[1].name, "julian");
  EXPECT_EQ(terms[1].weight, 0.25);
  EXPECT_EQ(terms[1].params, (std::vector<double>{5.0, 2.0}));
  EXPECT_TRUE(contents.flame.leftOut.empty()) << contents.flame.leftOut.front();
  EXPECT_TRUE(hasWarningContaining(contents.flame, "not well-formed"));
}

TEST(FlameXml, UnusualAttributeNamesAreSkippedAndNamed) {
  const std::string xforms =
      "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0 0\" linear=\"1\" odd name=\"2\" a^&amp;|b=\"3\" c&d=\"x<y\"/>\n"
      "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0.5 0\" spherical=\"1\"/>\n";
  const FlameFileContents contents = readFlameXml(flameFile(xforms, hexPaletteBlock()), "odd.flame");
  ASSERT_EQ(contents.flame.genome.xforms.size(), 2u);
  EXPECT_EQ(contents.flame.genome.xforms[0].variations.size(), 1u);
  EXPECT_TRUE(hasWarningContaining(contents.flame, "'odd name'"));
  EXPECT_TRUE(hasWarningContaining(contents.flame, "'c&d'"));
  EXPECT_NE(std::find(contents.flame.leftOut.begin(), contents.flame.leftOut.end(), "attribute 'odd name'"),
            contents.flame.leftOut.end());
}

TEST(FlameXml, SeveralTopLevelFlamesAndAStrayClosingTag) {
  const std::string one = "<flame name=\"one\">" + kTwoXforms + hexPaletteBlock() + "</flame>\n";
  const std::string two = "<flame name=\"two\">" + kTwoXforms + hexPaletteBlock() + "</flame>\n";
  // Electric Sheep: several <flame> elements without a root.
  FlameImportOptions second;
  second.index = 1;
  const FlameFileContents both = readFlameXml(one + two, "sheep.flam3", second);
  EXPECT_EQ(both.names, (std::vector<std::string>{"one", "two"}));
  EXPECT_EQ(both.flame.name, "two");
  // Old Apophysis: a closing tag that closes nothing, and a flame never closed.
  const FlameFileContents stray = readFlameXml(one + "</Flames>\r\n", "stray.flame");
  EXPECT_EQ(stray.flame.name, "one");
  EXPECT_TRUE(hasWarningContaining(stray.flame, "closing tag"));
  const FlameFileContents cut = readFlameXml("<flames><flame name=\"cut\">" + kTwoXforms, "cut.flame");
  EXPECT_EQ(cut.flame.genome.xforms.size(), 2u);
  EXPECT_TRUE(hasWarningContaining(cut.flame, "never closed"));
  // Truly broken text is still refused with the parser's message.
  EXPECT_NE(errorOf("<flame name=\"x\" <<<< \"\"\" ===>"), "");
  EXPECT_NE(errorOf("not xml at all").find("not flame XML"), std::string::npos);
}

TEST(FlameXml, JwildfireCurvesAndMotionAreNamedNotCalledVariations) {
  const std::string xforms =
      "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0 0\" linear=\"1\" colorCurve_enabled=\"false\" colorCurve_x0=\"0\" "
      "weightCurve_enabled=\"true\" weightCurve_points=\"2\" mirror_pre_post_translations=\"1\">"
      "<motion motion_frequency=\"1\" coefs=\"0 0 0 0 0.1 0\"/></xform>\n"
      "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0.5 0\" spherical=\"1\"/>\n";
  const FlameFileContents contents = readFlameXml(flameFile(xforms, hexPaletteBlock()), "curves.flame");
  const std::vector<std::string>& lost = contents.flame.leftOut;
  // The <motion> is kept, as keyframes (flame_import_test.cpp); the curve without its points is not.
  EXPECT_EQ(lost, (std::vector<std::string>{"JWildfire motion curve weightCurve", "mirror_pre_post_translations"}));
  EXPECT_EQ(contents.flame.keyframes.size(), 1u);
  EXPECT_FALSE(hasWarningContaining(contents.flame, "variations voxflame does not know"));
}

TEST(FlameXml, HexPalettesOfAnyCountAreResampled) {
  // Two colours: black to white, so colour i is i.
  const FlameFileContents two =
      readFlameXml(flameFile(kTwoXforms, "<palette count=\"2\" format=\"RGB\">000000FFFFFF</palette>"), "two.flame");
  expectColorNear(srgb255(two.flame, 0), {0, 0, 0});
  expectColorNear(srgb255(two.flame, 128), {128, 128, 128});
  expectColorNear(srgb255(two.flame, 255), {255, 255, 255});
  // One colour fills the gradient; 512 colours are sampled at every other one (and between).
  const FlameFileContents one =
      readFlameXml(flameFile(kTwoXforms, "<palette count=\"1\" format=\"RGB\">204060</palette>"), "one.flame");
  expectColorNear(srgb255(one.flame, 77), {32, 64, 96});
  std::string many = "<palette count=\"512\" format=\"RGB\">";
  char hex[16];
  for (int i = 0; i < 512; ++i) {
    std::snprintf(hex, sizeof hex, "%02X%02X%02X", i / 2, 0, 255 - i / 2);
    many += hex;
  }
  const FlameFileContents wide = readFlameXml(flameFile(kTwoXforms, many + "</palette>"), "wide.flame");
  expectColorNear(srgb255(wide.flame, 0), {0, 0, 255});
  expectColorNear(srgb255(wide.flame, 255), {255, 0, 0});
}

TEST(FlameXml, XaosIsReadTrimmedAndRoundTripsThroughThePreset) {
  // Fr0st's chaos lists: shorter than the transforms (the rest are 1), trailing spaces, longer.
  const std::string xforms =
      "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0 0\" linear=\"1\" chaos=\"0 \"/>\n"
      "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0.5 0\" linear=\"1\" chaos=\"1 1 0 1 0\"/>\n"
      "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0 0.5\" linear=\"1\" chaos=\"1 1 1\"/>\n";
  const FlameFileContents contents = readFlameXml(flameFile(xforms, hexPaletteBlock()), "xaos.flame");
  const FlameGenome& genome = contents.flame.genome;
  EXPECT_EQ(genome.xforms[0].xaos, (std::vector<double>{0.0}));
  EXPECT_EQ(genome.xforms[1].xaos, (std::vector<double>{1.0, 1.0, 0.0}));
  EXPECT_TRUE(genome.xforms[2].xaos.empty());
  EXPECT_TRUE(contents.flame.leftOut.empty());
  EXPECT_TRUE(hasWarningContaining(contents.flame, "more xaos factors"));
  Scene base;
  base.meshPath = "mesh.obj";
  const Scene scene = sceneFromImportedFlame(contents.flame, base);
  const Scene back = sceneFromJson(sceneToJson(scene), "xaos.json");
  EXPECT_EQ(back.layers.at(0).flame, genome);
  EXPECT_NE(sceneToJson(scene).find("\"xaos\""), std::string::npos);
}

TEST(FlameXml, PrePostFormsCapitalisedNamesAndBareParameters) {
  const std::string xforms =
      "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0 0\" pre_gaussian_blur=\"0.2\" linear=\"1\" post_curl=\"0.5\" "
      "post_curl_c1=\"0.3\" Spherical3D=\"0.1\" auger=\"0.4\" auger_weight=\"0.25\"/>\n"
      "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0.5 0\" Re_A=\"0.9\" Mobius=\"1\" Mobius_Im_D=\"0.3\" flatten=\"1\"/>\n";
  FlameImportOptions flat;
  flat.depth = 0.0;
  const FlameFileContents contents = readFlameXml(flameFile(xforms, hexPaletteBlock()), "forms.flame", flat);
  EXPECT_TRUE(contents.flame.leftOut.empty()) << contents.flame.leftOut.front();
  const std::vector<VariationTerm>& first = contents.flame.genome.xforms.at(0).variations;
  ASSERT_EQ(first.size(), 5u);
  EXPECT_EQ(first[0].name, "pre_gaussian_blur");
  EXPECT_EQ(first[2].name, "post_curl");
  EXPECT_EQ(first[2].params.at(0), 0.3);
  EXPECT_EQ(first[3].name, "spherical3D");
  EXPECT_EQ(first[4].name, "auger");
  EXPECT_EQ(first[4].params.at(1), 0.25);  // strength, which flame files call auger_weight
  const std::vector<VariationTerm>& second = contents.flame.genome.xforms.at(1).variations;
  ASSERT_EQ(second.size(), 2u);
  EXPECT_EQ(second[0].name, "mobius");
  EXPECT_EQ(second[0].params.at(0), 0.9);  // re_a
  EXPECT_EQ(second[0].params.at(7), 0.3);  // im_d
  EXPECT_EQ(second[1].name, "flatten");
  // A flat flame given depth (the default) loses flatten: it would set the depth back to 0.
  const std::string flatXforms =
      "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0 0\" linear=\"1\" flatten=\"1\"/>\n"
      "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0.5 0\" spherical=\"1\"/>\n";
  const FlameFileContents deep = readFlameXml(flameFile(flatXforms, hexPaletteBlock()), "flat.flame");
  EXPECT_TRUE(deep.flame.depthAdded);
  ASSERT_EQ(deep.flame.genome.xforms.at(0).variations.size(), 1u);
  EXPECT_EQ(deep.flame.genome.xforms[0].variations[0].name, "linear");
}

TEST(FlameXml, JwildfireLayersBecomeFlameLayersWithTheirOwnTransformsPalettesAndWeights) {
  // A second palette, every colour (10, 20, 30), tells the layers' palettes apart.
  std::string grey;
  for (std::size_t i = 0; i < kFlamePaletteSize; ++i) grey += "0A141E";
  const std::string greyPalette = "<palette count=\"256\" format=\"RGB\">" + grey + "</palette>";
  const std::string text =
      "<jwf-flame name=\"layered\" brightness=\"3\">\n"
      "<layer weight=\"1\" visible=\"1\">" +
      kTwoXforms + hexPaletteBlock() +
      "</layer>\n"
      "<layer weight=\"0.4\" density=\"0.5\"><xform weight=\"1\" color=\"0.25\" coefs=\"1 0 0 1 0.5 0\" "
      "linear=\"1\"/><finalxform color=\"0\" coefs=\"2 0 0 2 0 0\" spherical=\"1\"/>" +
      greyPalette +
      "</layer>\n"
      "<layer weight=\"3\" visible=\"0\"><xform weight=\"1\" coefs=\"1 0 0 1 0 0\" julia=\"1\"/>" +
      hexPaletteBlock() + "</layer></jwf-flame>\n";
  const FlameFileContents contents = readFlameXml(text, "layers.flame");
  const ImportedFlame& flame = contents.flame;
  EXPECT_EQ(contents.names, (std::vector<std::string>{"layered"}));
  EXPECT_TRUE(flame.leftOut.empty());
  EXPECT_DOUBLE_EQ(flame.tone.brightness, 3.0);
  // The first layer: its two transforms, its palette, weight 1.
  EXPECT_EQ(flame.genome.xforms.size(), 2u);
  EXPECT_FALSE(flame.genome.hasFinal);
  expectColorNear(srgb255(flame, 200), {200, 55, 128});
  EXPECT_DOUBLE_EQ(flame.weight, 1.0);
  // The second: one transform and its final, its own palette, weight 0.4 × density 0.5².
  ASSERT_EQ(flame.otherLayers.size(), 1u);
  const ImportedFlameLayer& second = flame.otherLayers[0];
  ASSERT_EQ(second.genome.xforms.size(), 1u);
  EXPECT_DOUBLE_EQ(second.genome.xforms[0].color, 0.25);
  EXPECT_DOUBLE_EQ(second.genome.xforms[0].affine.m[3], 0.5);
  ASSERT_TRUE(second.genome.hasFinal);
  EXPECT_EQ(second.genome.finalXform.variations.at(0).name, "spherical");
  ASSERT_EQ(second.palette.size(), kFlamePaletteSize);
  const glm::vec3 secondColour = linearToSrgb(second.palette[200].color) * 255.0f;
  expectColorNear(secondColour, {10, 20, 30});
  EXPECT_DOUBLE_EQ(second.weight, 0.4 * 0.25);
  // The hidden third layer is named in a warning, not imported (JWildfire does not draw it).
  EXPECT_TRUE(hasWarningContaining(flame, "layer 3 is hidden"));

  // The scene: two flame layers, the second placed with the first, and back through a preset.
  Scene base;
  base.meshPath = "mesh.obj";
  const Scene scene = sceneFromImportedFlame(flame, base);
  ASSERT_EQ(scene.layers.size(), 2u);
  EXPECT_EQ(scene.layers[0].kind, PatternKind::Flame);
  EXPECT_EQ(scene.layers[0].flame, flame.genome);
  EXPECT_DOUBLE_EQ(scene.layers[0].weight, 1.0);
  EXPECT_EQ(scene.layers[0].transform.fit, FitMode::Contain);
  EXPECT_EQ(scene.layers[1].flame, second.genome);
  EXPECT_EQ(scene.layers[1].color.mode, ColorMode::Index);
  EXPECT_EQ(scene.layers[1].color.gradient.size(), kFlamePaletteSize);
  EXPECT_DOUBLE_EQ(scene.layers[1].weight, 0.1);
  EXPECT_EQ(scene.layers[1].transform.fit, FitMode::Previous);
  const Scene again = sceneFromJson(sceneToJson(scene), "layers.json");
  ASSERT_EQ(again.layers.size(), 2u);
  EXPECT_EQ(again.layers[1].transform.fit, FitMode::Previous);
  EXPECT_DOUBLE_EQ(again.layers[1].weight, 0.1);
  EXPECT_EQ(again.layers[1].flame.xforms.size(), 1u);
  EXPECT_TRUE(again.layers[1].flame.hasFinal);
  EXPECT_EQ(again.layers[0].flame.xforms.size(), 2u);

  // Nothing visible to draw is an error, as before.
  EXPECT_NE(errorOf("<jwf-flame name=\"empty\"></jwf-flame>").find("<layer>"), std::string::npos);
  EXPECT_NE(
      errorOf("<jwf-flame name=\"hidden\"><layer visible=\"0\">" + kTwoXforms + "</layer></jwf-flame>").find("<layer>"),
      std::string::npos);
}

// Regressions found while fuzzing the importer (scripts/fuzz.sh); each input is the smallest that shows it.

TEST(FlameXml, NamesThatAreNotUtf8AreReadAsLatin1AndSaveAsAPreset) {
  // A Latin-1 name without an encoding declaration ("été"): the import kept the raw bytes, and
  // saving the imported scene threw nlohmann's type_error 316 (JSON is UTF-8 only).
  const std::string text = "<flame name=\"\xe9t\xe9\"><xform weight=\"1\" coefs=\"1 0 0 1 0 0\"/></flame>\n";
  const FlameFileContents contents = readFlameXml(text, "latin1.flame");
  EXPECT_EQ(contents.flame.name, "\xc3\xa9t\xc3\xa9");
  EXPECT_EQ(contents.names, std::vector<std::string>{"\xc3\xa9t\xc3\xa9"});
  ASSERT_FALSE(contents.flame.warnings.empty());
  EXPECT_NE(contents.flame.warnings.front().find("Latin-1"), std::string::npos);
  const Scene scene = sceneFromImportedFlame(contents.flame, defaultScene());
  EXPECT_EQ(sceneFromJson(sceneToJson(scene), "latin1.json").name, "\xc3\xa9t\xc3\xa9");
  // UTF-8 that is valid stays as it is, and a flame is found by its name as the user types it.
  FlameImportOptions byName;
  byName.name = "\xc3\xa9t\xc3\xa9";
  EXPECT_EQ(readFlameXml(text, "latin1.flame", byName).flame.name, "\xc3\xa9t\xc3\xa9");
  const std::string utf8 = "<flame name=\"\xc3\xa9t\xc3\xa9\"><xform weight=\"1\" coefs=\"1 0 0 1 0 0\"/></flame>";
  EXPECT_EQ(readFlameXml(utf8, "utf8.flame").flame.name, "\xc3\xa9t\xc3\xa9");
}

// Found while fuzzing, by reading what the fuzzer's 16 kB inputs could not reach: two loops of the
// importer were quadratic in the file's size, so a flame file of a few hundred kilobytes (the
// importer takes up to 64 MiB) hung it for hours. Both inputs below take milliseconds now.

TEST(FlameXml, ManyUnclosedElementsAndStrayClosingTagsReadInLinearTime) {
  // Every stray closing tag searched the stack of open elements: 200 000 of each took hours.
  constexpr std::size_t kCount = 200'000;
  std::string text = "<flame><xform weight=\"1\" coefs=\"1 0 0 1 0 0\"/>";
  for (std::size_t i = 0; i < kCount; ++i) text += "<a>";
  for (std::size_t i = 0; i < kCount; ++i) text += "</b>";
  const FlameFileContents contents = readFlameXml(text, "unclosed.flame");
  ASSERT_FALSE(contents.flame.warnings.empty());
  const std::string& fixes = contents.flame.warnings.front();
  EXPECT_NE(fixes.find("200000 closing tags without an opening one"), std::string::npos) << fixes;
  EXPECT_NE(fixes.find("200001 elements were never closed"), std::string::npos) << fixes;
  // An outer closing tag still closes the elements left open inside it.
  const FlameFileContents nested =
      readFlameXml("<flames><flame><xform weight=\"1\" coefs=\"1 0 0 1 0 0\"/><a><b></flames>", "nested.flame");
  EXPECT_NE(nested.flame.warnings.front().find("3 elements were never closed"), std::string::npos)
      << nested.flame.warnings.front();
}

TEST(FlameXml, LongAttributeNamesOfManyUnderscoresReadInLinearTime) {
  // Every "_" of an attribute name was tried as the end of a variation's name, copying and looking
  // up the whole prefix each time: a 40 kB name took 20 s, a 400 kB one hours.
  std::string name;
  for (int i = 0; i < 200'000; ++i) name += "a_";
  name += "b";
  const std::string text = "<flame><xform weight=\"1\" coefs=\"1 0 0 1 0 0\" linear=\"1\" " + name + "=\"1\"/></flame>";
  const FlameFileContents contents = readFlameXml(text, "underscores.flame");
  EXPECT_EQ(contents.flame.leftOut, std::vector<std::string>{"variation " + name});
  // Parameters are still found at the end of a name, JWildfire's curve suffixes included.
  const FlameFileContents params = readFlameXml(
      "<flame><xform weight=\"1\" coefs=\"1 0 0 1 0 0\" julian=\"1\" julian_power=\"3\" "
      "julian_power_view_xmin=\"0\"/></flame>",
      "params.flame");
  EXPECT_TRUE(params.flame.leftOut.empty());
  ASSERT_EQ(params.flame.genome.xforms.front().variations.size(), 1u);
  EXPECT_EQ(params.flame.genome.xforms.front().variations.front().params.front(), 3.0);
}

namespace {

// JWildfire chains several final transforms: the first is the final transform, the others follow
// it in order, and they round-trip through a preset.
TEST(FlameXml, ChainedFinalTransformsAreKeptInOrder) {
  const std::string finals =
      "<finalxform color=\"0\" spherical=\"1\" coefs=\"1 0 0 1 0 0\"/>\n"
      "<finalxform color=\"0\" linear=\"1\" coefs=\"2 0 0 2 0 0\"/>\n"
      "<finalxform color=\"0\" swirl=\"1\" coefs=\"1 0 0 1 0 0\"/>\n";
  const ImportedFlame flame = readFlameXml(flameFile(kTwoXforms, finals), "p.flame").flame;
  ASSERT_TRUE(flame.genome.hasFinal);
  EXPECT_EQ(flame.genome.finalXform.variations.front().name, "spherical");
  ASSERT_EQ(flame.genome.chainedFinals.size(), 2u);
  EXPECT_EQ(flame.genome.chainedFinals[0].variations.front().name, "linear");
  EXPECT_EQ(flame.genome.chainedFinals[1].variations.front().name, "swirl");
  EXPECT_TRUE(flame.leftOut.empty());
  Scene base;
  base.meshPath = "mesh.obj";
  const Scene scene = sceneFromImportedFlame(flame, base);
  const Scene again = sceneFromJson(sceneToJson(scene), "again.json");
  EXPECT_EQ(again.layers.front().flame.chainedFinals, flame.genome.chainedFinals);
}

}  // namespace

namespace {

// flam3 2.x's variation lists: var1="k" is flam3's k-th variation alone, var="w0 w1 ..." weighs
// them by index; an index past flam3's 99 is refused by var1 and named as lost by var.
TEST(FlameXml, Flam3sOldVariationListsAreRead) {
  const ImportedFlame one =
      readFlameXml(flameFile("<xform weight=\"1\" color=\"0\" var1=\"2\" coefs=\"0.5 0 0 0.5 0 0\"/>\n"), "old.flame")
          .flame;
  ASSERT_EQ(one.genome.xforms[0].variations.size(), 1u);
  EXPECT_EQ(one.genome.xforms[0].variations[0].name, "spherical");
  EXPECT_DOUBLE_EQ(one.genome.xforms[0].variations[0].weight, 1.0);
  EXPECT_TRUE(one.leftOut.empty());
  const ImportedFlame list =
      readFlameXml(
          flameFile(
              "<xform weight=\"1\" color=\"0\" var=\"0.5 0 0 0 0 0 0 0 0 0 0 0 0 0.25\" coefs=\"0.5 0 0 0.5 0 0\"/>\n"),
          "old.flame")
          .flame;
  ASSERT_EQ(list.genome.xforms[0].variations.size(), 2u);
  EXPECT_EQ(list.genome.xforms[0].variations[0].name, "linear");
  EXPECT_EQ(list.genome.xforms[0].variations[1].name, "julia");
  EXPECT_DOUBLE_EQ(list.genome.xforms[0].variations[1].weight, 0.25);
  EXPECT_NE(errorOf(flameFile("<xform weight=\"1\" var1=\"99\" coefs=\"1 0 0 1 0 0\"/>\n")).find("var1"),
            std::string::npos);
  EXPECT_NE(errorOf(flameFile("<xform weight=\"1\" var=\"1 x\" coefs=\"1 0 0 1 0 0\"/>\n")).find("var="),
            std::string::npos);
}

}  // namespace

namespace {

// What a flame turns on at its own level that voxflame does not keep is named, never passed over.
TEST(FlameXml, FlameLevelFeaturesVoxflameDoesNotKeepAreNamed) {
  // JWildfire's 3D camera is kept (its own model) but for the depth of field blur shapes that need
  // more than numbers (snowflake, brush stroke, sub-flame) and depth dimming; its solid rendering
  // but for the depth of field JWildfire draws after shading.
  const std::string attributes =
      "version=\"JWildfire V7.50\" post_symmetry_type=\"POINT\" post_symmetry_order=\"3\" cam_pitch=\"0.5\" "
      "cam_yaw=\"0\" cam_dof=\"0.2\" new_dof=\"1\" cam_dof_shape=\"SNOWFLAKE\" cam_zdimish=\"0.5\" "
      "sld_render_enabled=\"true\" contrastCurve_enabled=\"true\"";
  const ImportedFlame flame = readFlameXml(flameFile(kTwoXforms, "", attributes), "p.flame").flame;
  for (const char* lost :
       {"JWildfire solid rendering's depth of field", "3D camera", "JWildfire flame motion curve contrastCurve"})
    EXPECT_NE(std::find(flame.leftOut.begin(), flame.leftOut.end(), lost), flame.leftOut.end()) << lost;
  EXPECT_EQ(flame.genome.postSymmetry.kind, PostSymmetryKind::Point);
  for (const char* part : {"SNOWFLAKE", "cam_zdimish"}) EXPECT_TRUE(hasWarningContaining(flame, part)) << part;
  EXPECT_FALSE(hasWarningContaining(flame, "new_dof"));
  EXPECT_TRUE(flame.flat.hasCamera());
  EXPECT_EQ(flame.flat.cameraModel, FlatCameraModel::Jwildfire);
  EXPECT_NEAR(flame.flat.cameraPitchDeg, 0.5 * 180.0 / std::numbers::pi, 1e-9);
  // Its turn, perspective, position, zoom and plain (bubble) depth of field are kept whole.
  const ImportedFlame jwildfire =
      readFlameXml(flameFile(kTwoXforms, "",
                             "version=\"JWildfire V8.00\" scale=\"40\" cam_zoom=\"2.5\" cam_pitch=\"0.5\" "
                             "cam_yaw=\"-7\" cam_roll=\"0.25\" cam_persp=\"0.3\" cam_pos_x=\"0.1\" "
                             "cam_pos_y=\"0.2\" cam_pos_z=\"0.3\" cam_zpos=\"0.4\" cam_dof=\"-0.2\" "
                             "cam_dof_shape=\"BUBBLE\" cam_dof_scale=\"1.5\" cam_dof_fade=\"0.5\" new_dof=\"0\""),
                   "p.flame")
          .flame;
  EXPECT_TRUE(jwildfire.leftOut.empty());
  EXPECT_DOUBLE_EQ(jwildfire.flat.scale, 100.0);
  EXPECT_NEAR(jwildfire.flat.cameraYawDeg, (2.0 * std::numbers::pi - 7.0) * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(jwildfire.flat.cameraBankDeg, 0.25 * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_DOUBLE_EQ(jwildfire.flat.cameraPerspective, 0.3);
  EXPECT_EQ(jwildfire.flat.cameraPosition, glm::dvec3(0.1, 0.2, 0.3));
  EXPECT_DOUBLE_EQ(jwildfire.flat.cameraZ, 0.4);
  EXPECT_DOUBLE_EQ(jwildfire.flat.cameraDof, 0.2);
  EXPECT_DOUBLE_EQ(jwildfire.flat.cameraDofScale, 1.5);
  EXPECT_DOUBLE_EQ(jwildfire.flat.cameraDofFade, 0.5);
  // Without a turn, perspective, position or depth of field JWildfire draws the flame flat.
  EXPECT_EQ(readFlameXml(flameFile(kTwoXforms, "", "version=\"JWildfire V8.00\" cam_zpos=\"1\" cam_dof_scale=\"2\""),
                         "p.flame")
                .flame.flat,
            FlatViewSettings{});
  const ImportedFlame fractorium =
      readFlameXml(flameFile(kTwoXforms, "", "version=\"EMBER-WIN-1.0.0.19\" cam_pitch=\"0.5\" cam_persp=\"0.25\""),
                   "p.flame")
          .flame;
  EXPECT_TRUE(fractorium.leftOut.empty());
  EXPECT_NEAR(fractorium.flat.cameraPitchDeg, 0.5 * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_DOUBLE_EQ(fractorium.flat.cameraPerspective, 0.25);
  // Switched off, none of them is a loss.
  const ImportedFlame plain =
      readFlameXml(
          flameFile(kTwoXforms, "", "post_symmetry_type=\"NONE\" cam_pitch=\"0.0\" sld_render_enabled=\"false\""),
          "p.flame")
          .flame;
  EXPECT_TRUE(plain.leftOut.empty());
}

}  // namespace

namespace {

// JWildfire's post symmetry is kept whole, for every layer of a layered flame; an unknown kind is none
// (as JWildfire reads it) and an order beyond 64 is 64.
TEST(FlameXml, JwildfiresPostSymmetryIsKept) {
  const ImportedFlame axis =
      readFlameXml(flameFile(kTwoXforms, "",
                             "version=\"JWildfire V8.00\" post_symmetry_type=\"Y_AXIS\" post_symmetry_order=\"5\" "
                             "post_symmetry_centre_x=\"0.25\" post_symmetry_centre_y=\"-0.5\" "
                             "post_symmetry_distance=\"2\" post_symmetry_rotation=\"-30\""),
                   "p.flame")
          .flame;
  EXPECT_TRUE(axis.leftOut.empty());
  EXPECT_EQ(axis.genome.postSymmetry, (FlamePostSymmetry{PostSymmetryKind::YAxis, 5, 0.25, -0.5, 2.0, -30.0}));
  const ImportedFlame big =
      readFlameXml(flameFile(kTwoXforms, "", "post_symmetry_type=\"POINT\" post_symmetry_order=\"100\""), "p.flame")
          .flame;
  EXPECT_EQ(big.genome.postSymmetry.kind, PostSymmetryKind::Point);
  EXPECT_EQ(big.genome.postSymmetry.order, kMaxPostSymmetryOrder);
  EXPECT_DOUBLE_EQ(big.genome.postSymmetry.distance, 1.25);  // JWildfire's defaults
  EXPECT_DOUBLE_EQ(big.genome.postSymmetry.rotationDeg, 6.0);
  const ImportedFlame odd = readFlameXml(flameFile(kTwoXforms, "", "post_symmetry_type=\"SPIRAL\""), "p.flame").flame;
  EXPECT_EQ(odd.genome.postSymmetry.kind, PostSymmetryKind::None);
  EXPECT_TRUE(hasWarningContaining(odd, "SPIRAL"));
  const std::string layer = "<layer>" + kTwoXforms + "<palette count=\"1\" format=\"RGB\">FF0000</palette></layer>";
  const ImportedFlame layered =
      readFlameXml("<jwf-flames><jwf-flame version=\"JWildfire V8.00\" post_symmetry_type=\"X_AXIS\">" + layer + layer +
                       "</jwf-flame></jwf-flames>",
                   "p.flame")
          .flame;
  EXPECT_EQ(layered.genome.postSymmetry.kind, PostSymmetryKind::XAxis);
  ASSERT_EQ(layered.otherLayers.size(), 1u);
  EXPECT_EQ(layered.otherLayers[0].genome.postSymmetry.kind, PostSymmetryKind::XAxis);
}

// JWildfire's `<variation>_fx_priority` moves a variation to the pre_ (negative) or post_ (positive) stage.
TEST(FlameXml, JwildfiresPriorityMovesAVariationToItsStage) {
  const ImportedFlame flame =
      readFlameXml(flameFile("<xform weight=\"1\" color=\"0\" linear=\"1\" splits=\"0.5\" splits_fx_priority=\"1\" "
                             "julia=\"0.25\" julia_fx_priority=\"-1\" swirl=\"0.1\" swirl_fx_priority=\"0\" "
                             "coefs=\"1 0 0 1 0 0\"/>\n"),
                   "p.flame")
          .flame;
  std::vector<std::string> names;
  for (const VariationTerm& term : flame.genome.xforms[0].variations) names.push_back(term.name);
  EXPECT_NE(std::find(names.begin(), names.end(), "post_splits"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "pre_julia"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "swirl"), names.end());
  EXPECT_TRUE(flame.leftOut.empty());
}

}  // namespace
