// The variation catalogue as a whole: the families' tables in one list, looked up by name (with the
// pre_/post_ forms), and written out as presets/VARIATIONS.md.
#include "core/flame/variations.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/flame/subflame.h"
#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

std::vector<VariationInfo> buildCatalogue() {
  std::vector<VariationInfo> c;
  variation_kernels::addFlam3ClassicVariations(c);
  variation_kernels::add3DVariations(c);
  variation_kernels::addFlam3Variations(c);
  variation_kernels::addApophysisVariations(c);
  variation_kernels::addPluginVariations(c);
  variation_kernels::addFractoriumVariations(c);
  variation_kernels::addJwildfireVariations(c);
  variation_kernels::addFractorium2dMVariations(c);
  variation_kernels::addFractorium2dSVariations(c);
  variation_kernels::addFractoriumTruchetVariations(c);
  variation_kernels::addQuaternionVariations(c);
  variation_kernels::addFractorium3DShapeVariations(c);
  variation_kernels::addFractorium3DMoreVariations(c);
  variation_kernels::addFractoriumRandom2DVariations(c);
  variation_kernels::addDirectColourVariations(c);
  variation_kernels::addBlurVariations(c);
  variation_kernels::addFractorium2DVariationsA(c);
  variation_kernels::addFractorium2DVariationsB(c);
  variation_kernels::addFractorium2DVariationsC(c);
  variation_kernels::addFractorium2DVariationsD(c);
  variation_kernels::addJwildfireShapeVariations(c);
  variation_kernels::addJwildfireMoreVariations(c);
  variation_kernels::addJwildfireTailVariations(c);
  variation_kernels::addFractoriumBlursMoreVariations(c);
  variation_kernels::addFractorium3DSumVariations(c);
  variation_kernels::addJwildfireCorpusVariations(c);
  variation_kernels::addJwildfireHoldoutVariations(c);
  variation_kernels::addSvgVariations(c);
  variation_kernels::addColormapVariations(c);
  variation_kernels::addSubflameVariations(c);
  variation_kernels::addParplotVariations(c);
  variation_kernels::addJwildfireMeshVariations(c);
  variation_kernels::addTextVariations(c);
  variation_kernels::addJwildfireGlslVariations(c);
  variation_kernels::addJwildfireWildVariations(c);
  variation_kernels::addJwildfireRareVariations(c);
  variation_kernels::addPluginsRareVariations(c);
  for (VariationInfo& info : c)
    if (info.name == "zblur" || info.name == "zscale" || info.name == "ztranslate" || info.name == "zcone" ||
        info.name == "flatten" || info.name == "inflateZ_3" || info.name == "zscale_wf")
      info.mapsXY = false;
  return c;
}

}  // namespace

int VariationInfo::paramIndex(std::string_view paramName) const {
  for (std::size_t i = 0; i < params.size(); ++i)
    if (params[i].name == paramName) return static_cast<int>(i);
  return -1;
}

std::vector<double> VariationInfo::defaultParams() const {
  std::vector<double> values;
  values.reserve(params.size());
  for (const auto& p : params) values.push_back(p.defaultValue);
  return values;
}

int VariationInfo::textParamIndex(std::string_view paramName) const {
  for (std::size_t i = 0; i < textParams.size(); ++i)
    if (textParams[i].name == paramName) return static_cast<int>(i);
  return -1;
}

std::vector<std::string> VariationInfo::defaultTexts() const {
  std::vector<std::string> values;
  values.reserve(textParams.size());
  for (const auto& p : textParams) values.push_back(p.defaultValue);
  return values;
}

std::vector<std::string> VariationInfo::textsFor(const std::vector<std::string>& texts) const {
  return texts.size() == textParams.size() ? texts : defaultTexts();
}

namespace {

// Whether a variation's result depends on the point: it is run at two points with the same random
// state and default parameters, and its mapped coordinates compared. It runs as a pre_ term, the
// form this decides for (extrude adds nothing to x and y as an ordinary term but keeps them as a
// pre_ one).
bool resultIgnoresThePoint(const VariationInfo& info) {
  constexpr double kAffine[12] = {0.9, 0.2, 0.0, 0.3, -0.1, 0.8, 0.0, -0.4, 0.0, 0.0, 1.0, 0.0};
  const std::vector<double> params = info.defaultParams();
  const auto at = [&](double x, double y, double z) {
    std::uint32_t random = 0x2545F491u;
    double ox = 0.0, oy = 0.0, oz = 0.0, colour = 0.5;
    VariationInput in;
    in.x = &x;
    in.y = &y;
    in.z = &z;
    in.random = &random;
    in.count = 1;
    in.params = params.data();
    in.affine = kAffine;
    in.tx = &x;
    in.ty = &y;
    in.tz = &z;
    in.colour = &colour;
    in.stage = VariationStage::Pre;
    info.apply(in, &ox, &oy, &oz);
    return std::array<double, 3>{info.mapsXY ? ox : 0.0, info.mapsXY ? oy : 0.0, info.threeD ? oz : 0.0};
  };
  return at(0.3, -0.7, 0.5) == at(-0.45, 0.2, -0.35);
}

}  // namespace

const std::vector<VariationInfo>& variationCatalogue() {
  static const std::vector<VariationInfo> catalogue = [] {
    std::vector<VariationInfo> c = buildCatalogue();
    for (VariationInfo& info : c)
      if (!embedsFlame(info)) info.additive = resultIgnoresThePoint(info);
    return c;
  }();
  return catalogue;
}

namespace {

const VariationInfo* catalogueEntry(std::string_view name) {
  for (const auto& info : variationCatalogue())
    if (info.name == name) return &info;
  return nullptr;
}

constexpr std::string_view kPrePrefix = "pre_", kPostPrefix = "post_";

}  // namespace

VariationStage variationStage(std::string_view name) {
  // flam3's pre_blur is an entry of its own that acts before the others.
  if (catalogueEntry(name)) return name.starts_with(kPrePrefix) ? VariationStage::Pre : VariationStage::Normal;
  if (name.starts_with(kPrePrefix) && catalogueEntry(name.substr(kPrePrefix.size()))) return VariationStage::Pre;
  if (name.starts_with(kPostPrefix) && catalogueEntry(name.substr(kPostPrefix.size()))) return VariationStage::Post;
  return VariationStage::Normal;
}

const VariationInfo* findVariation(std::string_view name) {
  if (const VariationInfo* info = catalogueEntry(name)) return info;
  if (name.starts_with(kPrePrefix)) return catalogueEntry(name.substr(kPrePrefix.size()));
  if (name.starts_with(kPostPrefix)) return catalogueEntry(name.substr(kPostPrefix.size()));
  return nullptr;
}

namespace {

std::string lowered(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char ch) { return std::tolower(ch); });
  return out;
}

// Levenshtein distance, for "did you mean": swapped or missing letters are the usual typos.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

const VariationInfo& variationOrThrow(std::string_view name) {
  if (const VariationInfo* info = findVariation(name)) return *info;
  // Close names: the same letters in another case, a shared three-letter start, or two edits away
  // (ignoring case and underscores, so "spherical_3d" finds "spherical3D").
  const std::string lower = lowered(name);
  std::string bare = lower;
  std::erase(bare, '_');
  std::string close;
  if (!lower.empty()) {
    for (const auto& info : variationCatalogue()) {
      const std::string candidate = lowered(info.name);
      std::string candidateBare = candidate;
      std::erase(candidateBare, '_');
      const bool near = candidate == lower || (lower.size() >= 3 && candidate.rfind(lower.substr(0, 3), 0) == 0) ||
                        editDistance(bare, candidateBare) <= 2;
      if (!near) continue;
      if (!close.empty()) close.append(", ");
      close.append(info.name);
    }
  }
  std::string message = "'";
  message.append(name);
  message.append("' is not a known variation");
  if (close.empty()) {
    message.append("; `voxflame list --variations` lists them");
  } else {
    message.append("; did you mean ");
    message.append(close);
    message.append("?");
  }
  throw Error(message);
}

namespace {

std::string formatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// A table cell: '|' would end the cell early.
std::string cell(const std::string& text) {
  std::string out;
  for (const char ch : text) {
    if (ch == '|') out += '\\';
    out += ch;
  }
  return out;
}

}  // namespace

std::string variationsMarkdown() {
  std::ostringstream md;
  md << "# Flame variations\n\n"
     << "The variations a flame transform can use (`\"variations\": [{\"name\": ..., \"weight\": ..., "
        "PARAMETER: VALUE}]` in a preset;\nsee [SCHEMA.md](SCHEMA.md)). Parameters left out take the default "
        "shown; the range is the slider's,\nnot a limit. This file is generated from the catalogue: "
        "`voxflame list --variations --markdown > presets/VARIATIONS.md`.\n\n"
     << "Notation (flam3's): p = (x, y, z) is the point after the transform's affine map, r² = x² + y², "
        "θ = atan2(x, y),\nφ = atan2(y, x), ε = 10⁻¹⁰, Ψ a uniform random number in [0, 1) (a new one each "
        "time it appears), and\nb, c, e, f the pre-affine's coefficients as flam3 names them. Each formula "
        "is V(p); a transform adds\nweight · V(p). A 2D variation maps x and y and carries z through; a 3D one "
        "acts on z itself.\n\n"
     << "Every variation also has a `pre_` and a `post_` form (`pre_spherical`, `post_curl`), as in Apophysis "
        "7X,\nJWildfire and Fractorium: a transform applies its `pre_` terms one after the other to the point after "
        "its\naffine map, then sums its other variations, then applies its `post_` terms to the sum, before its "
        "post map.\nSuch a term replaces the coordinates its variation maps (x and y for a 2D one, z too for a 3D "
        "one, z alone\nfor zscale, zcone, zblur, ztranslate, inflateZ_3 and flatten) by weight · V(p) and keeps the "
        "others; a "
        "variation whose\nresult does not depend on the point (the blurs, ztranslate) adds weight · V(p) instead. "
        "`pre_blur` is\nflam3's own: a Gaussian blur added to the point first.\n\n"
     << "## Which variations real flames use\n\n"
     << "The catalogue holds every variation of Fractorium's list but two (each also as `pre_` and `post_`, "
        "the direct-colour\n`dc_*` ones setting the colour index from the position, as Fractorium does) and the "
        "JWildfire variations that real flame files use.\nThose were counted in 779 flames written by "
        "JWildfire and published in public repositories (thargor6/JWildfireSwan's\nand thargor6/JWildfire's "
        "examples, sidwellr/Variations' one flame per variation, and 102 flames of other repositories),\n"
        "one count per flame that uses the name. The most used overall: linear3D 196, pre_blur 78, julian 76, "
        "bubble 54,\njulia3D 41, curl 36, spherical3D 33, synth 33, text_wf 29, radial_blur 26, zscale 23, "
        "blur3D 22, waves2 22. The most used\nof those voxflame did not have before this catalogue was "
        "completed: synth 33, text_wf 29, bwraps7 12, blob3D 11,\ndc_linear 11, parplot2d_wf 11, spirograph "
        "10, yin_yang 10, waves2b 8, affine3D 7, boarders2 7, juliac 7, plane_wf 7,\npoint_symmetry_wf 7, "
        "cannabiscurve_wf 6, recurrenceplot 6, waves2_3D 6, barycentroid 5, blade3D 5, butterfly3D 5,\n"
        "cylinder_apo 5, waffle 5, xtrb 5. The formula texts of parplot2d_wf, polarplot3d_wf and isosfplot3d_wf\n"
        "are evaluated by muParser, obj_mesh_primitive_wf's meshes are built in code and text_wf's text is drawn by "
        "FreeType.\nNot here: obj_mesh_wf (a mesh file beside the flame), dla3d_wf "
        "(a grown cluster),\nbrush_stroke_wf (images), and Fractorium's hexaplay3D and hexnix3D "
        "(a walk over\nhexagons kept from one iteration to the next). `hopalong` keeps an orbit too, "
        "but one that does not depend on the\npoint: it draws a point of the orbit's first 2²⁰ instead.\n\n"
     << "| name | kind | parameters (default, slider range) | formula |\n"
     << "| --- | --- | --- | --- |\n";
  for (const VariationInfo& info : variationCatalogue()) {
    std::string params;
    for (const VariationParam& p : info.params) {
      params += (params.empty() ? "" : "<br>") +
                ("`" + p.name + "` = " + formatNumber(p.defaultValue) + " (" + formatNumber(p.sliderMin) + " … " +
                 formatNumber(p.sliderMax) + (p.integer ? ", whole" : "") + ")");
    }
    md << "| `" << info.name << "` | " << (info.threeD ? "3D" : "2D") << (info.random ? ", random" : "") << " | "
       << (params.empty() ? "—" : params) << " | " << cell(info.formula) << " |\n";
  }
  return md.str();
}

}  // namespace voxflame::core
