#include "core/flame/xml.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include <glm/common.hpp>
#include <glm/mat3x3.hpp>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include "core/chaos_game.h"
#include "core/error.h"
#include "core/keyframes.h"
#include "core/flame/parplot_formula.h"
#include "core/flame/obj_mesh_primitives.h"
#include "core/flame/subflame.h"
#include "core/flame/svg_raster.h"
#include "core/flame/text_raster.h"
#include "core/flame/variations.h"
#include "core/flame/variations_colormap.h"
#include "core/random.h"

namespace voxflame::core {

namespace {

// The longest "_<parameter>" a variation's parameter attribute ends with that the importer looks
// for, JWildfire's motion-curve suffixes included ("_power_view_xmin").
constexpr std::size_t kMaxParameterSuffix = 64;
// Motion (flam3's <motion>, JWildfire's curves) as keyframes: bounds that keep a hostile file's
// tracks small. flam3's motion runs over a loop; voxflame plays one loop in kFlam3LoopFrames
// frames at kFlam3LoopFps (Electric Sheep's loop length; flam3 itself leaves it to the caller).
constexpr std::size_t kMaxMotionsPerXform = 64;
constexpr int kMaxMotionFrequency = 64;
constexpr std::size_t kMaxCurvePoints = 4096;
// Keys between two points of JWildfire's pixels-per-unit and zoom curves when both move the scale.
constexpr std::size_t kFlameScaleSamplesBetween = 8;
constexpr double kFlam3LoopFrames = 128.0, kFlam3LoopFps = 30.0;
constexpr int kMaxKeysPerPeriod = 32;
constexpr std::size_t kMaxWaveKeys = 256;
// Every track is checked as a preset's would be (checkKeyframeTracks), which costs a flame
// validation per key and point between keys: a flame's motion keeps to these.
constexpr std::size_t kMaxMotionTracks = 512;
constexpr std::size_t kMaxMotionKeys = 20'000;
// Flame files are a few kilobytes; the largest real ones (animations with hundreds of keyframe
// genomes) stay well below this. A larger file is almost certainly something else.
constexpr std::uintmax_t kMaxFlameFileBytes = 64u << 20;

// Attributes of <xform> that are not variations: flam3's, Apophysis', Fractorium's and JWildfire's
// own keys. Anything else that is not a catalogue variation or one of its parameters is reported
// as an unknown variation.
const std::set<std::string, std::less<>>& knownXformAttributes() {
  static const std::set<std::string, std::less<>> names = {"weight",
                                                           "color",
                                                           "color_speed",
                                                           "symmetry",
                                                           "opacity",
                                                           "coefs",
                                                           "post",
                                                           "animate",
                                                           "chaos",
                                                           "name",
                                                           "plotmode",
                                                           "var_color",
                                                           "visible",
                                                           "motion_frequency",
                                                           "motion_function",
                                                           "motion_offset",
                                                           "mod_gamma",
                                                           "mod_gamma_speed",
                                                           "mod_contrast",
                                                           "mod_contrast_speed",
                                                           "mod_saturation",
                                                           "mod_saturation_speed",
                                                           "mod_hue",
                                                           "mod_hue_speed",
                                                           "material",
                                                           "material_speed",
                                                           "color_type",
                                                           "draw_mode",
                                                           "enabled",
                                                           "var",
                                                           "var1",
                                                           "opacity_speed",
                                                           "yzCoefs",
                                                           "zxCoefs",
                                                           "yzPost",
                                                           "zxPost"};
  return names;
}

std::string lowered(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// flam3's variations in the order of its list (variations.c), which flam3 2.x's var= and var1=
// attributes index.
constexpr std::array<std::string_view, 99> kFlam3VariationOrder = {
    "linear",        "sinusoidal",  "spherical",   "swirl",      "horseshoe",   "polar",      "handkerchief",
    "heart",         "disc",        "spiral",      "hyperbolic", "diamond",     "ex",         "julia",
    "bent",          "waves",       "fisheye",     "popcorn",    "exponential", "power",      "cosine",
    "rings",         "fan",         "blob",        "pdj",        "fan2",        "rings2",     "eyefish",
    "bubble",        "cylinder",    "perspective", "noise",      "julian",      "juliascope", "blur",
    "gaussian_blur", "radial_blur", "pie",         "ngon",       "curl",        "rectangles", "arch",
    "tangent",       "square",      "rays",        "blade",      "secant2",     "twintrian",  "cross",
    "disc2",         "super_shape", "flower",      "conic",      "parabola",    "bent2",      "bipolar",
    "boarders",      "butterfly",   "cell",        "cpow",       "curve",       "edisc",      "elliptic",
    "escher",        "foci",        "lazysusan",   "loonie",     "pre_blur",    "modulus",    "oscilloscope",
    "polar2",        "popcorn2",    "scry",        "separation", "split",       "splits",     "stripes",
    "wedge",         "wedge_julia", "wedge_sph",   "whorl",      "waves2",      "exp",        "log",
    "sin",           "cos",         "tan",         "sec",        "csc",         "cot",        "sinh",
    "cosh",          "tanh",        "sech",        "csch",       "coth",        "auger",      "flux",
    "mobius"};

// The catalogue entry a flame file's variation name means (pre_ and post_ forms included).
// Apophysis and JWildfire write "linear3D" for the linear map that carries z along, which is
// exactly voxflame's "linear"; the alias stands only while the catalogue has no entry of that name
// itself. Some editors capitalise names ("Spherical3D", "Mobius"): a name found only when case is
// ignored means that entry.
const VariationInfo* variationNamed(std::string_view name) {
  if (const VariationInfo* info = findVariation(name)) return info;
  if (name == "linear3D") return findVariation("linear");
  const std::string wanted = lowered(name);
  for (const VariationInfo& info : variationCatalogue())
    if (lowered(info.name) == wanted) return &info;
  // ...and capitalised after a pre_ or post_ (Apophysis' post_Mobius, post_Spherical3D).
  for (const std::string_view stage : {std::string_view("pre_"), std::string_view("post_")}) {
    if (!wanted.starts_with(stage)) continue;
    const std::string_view rest = std::string_view(wanted).substr(stage.size());
    for (const VariationInfo& info : variationCatalogue())
      if (lowered(info.name) == rest) return &info;
  }
  return nullptr;
}

// Where a flame file keeps a variation's parameter when not at `<variation>_<parameter>`: flam3's
// auger_weight is the catalogue's auger `strength` (a preset writes parameters beside "weight"),
// and Apophysis' Mobius plugin (and FLAM3H after it) writes mobius' parameters bare and
// capitalised (Re_A … Im_D). FracFx's octagon plugin for Apophysis names its offsets octa_x,
// octa_y and octa_z (JWildfire's octagon_x ...); bezo97's pixel_flow plugin writes its parameters
// bare (angle, len, ...). JWildfire's crop_trapezoid names two parameters "Base Sup." and
// "Base Inf." (not XML names; tolerantXml keeps them), the catalogue's base_sup and base_inf, and
// its sunflower names one "F. filling", the catalogue's fill.
// Fractorium's q_ode names its parameters q_ode01 … q_ode12, without the "_". JWildfire's rational3
// names Fractorium's t3, t2, t1, tc, b3, b2, b1, bc as a … h.
std::vector<std::string> fileParamNames(const std::string& termAttribute, const VariationInfo& info,
                                        const std::string& param) {
  std::vector<std::string> names = {termAttribute + "_" + param};
  if (info.name == "auger" && param == "strength") names.push_back(termAttribute + "_weight");
  if (info.name == "d_spherical" && param == "spherical_weight") names.push_back(termAttribute + "_weight");
  if (info.name == "octagon" && param.size() == 1) names.push_back("octa_" + param);
  if (info.name == "pixel_flow") names.push_back(param);
  if (info.name == "q_ode") names.push_back(termAttribute + param);
  if (info.name == "minkowskope") names.push_back("mskope_" + param);  // the Apophysis plugin's names
  if (info.name == "oscilloscope")
    names.push_back("oscope_" + param);  // flam3's own names (Fractorium writes oscilloscope_)
  if (info.name == "rational3") {
    static const std::array<std::string_view, 8> fractorium = {"t3", "t2", "t1", "tc", "b3", "b2", "b1", "bc"};
    const auto at = std::find(fractorium.begin(), fractorium.end(), param);
    if (at != fractorium.end()) names.push_back(termAttribute + "_" + char('a' + (at - fractorium.begin())));
  }
  if (info.name == "crop_trapezoid" && param == "base_sup") names.push_back(termAttribute + "_Base Sup.");
  if (info.name == "crop_trapezoid" && param == "base_inf") names.push_back(termAttribute + "_Base Inf.");
  if (info.name == "sunflower" && param == "fill") names.push_back(termAttribute + "_F. filling");
  // JWildfire's hamid_js names two parameters "number_lines/circles" and "filled circles", and
  // dc_booleans before 2021 its type "^/&/|"; its DC_BaseFunc variations (dc_booleans, dc_menger, ...)
  // named scale_z and offset_z z_scale and z_offset before July 2021.
  if (info.name == "hamid_js" && param == "number_lines_circles")
    names.push_back(termAttribute + "_number_lines/circles");
  if (info.name == "hamid_js" && param == "filled_circles") names.push_back(termAttribute + "_filled circles");
  if (info.name == "dc_booleans" && param == "type") names.push_back(termAttribute + "_^/&/|");
  // glynns3subfl's chance of the inversion is its "weight" (a term's own key here) and its show its
  // "show/hide(1/0)".
  if (info.name == "glynns3subfl" && param == "probability") names.push_back(termAttribute + "_weight");
  if (info.name == "glynns3subfl" && param == "show") names.push_back(termAttribute + "_show/hide(1/0)");
  if (info.name.starts_with("dc_") && param == "scale_z") names.push_back(termAttribute + "_z_scale");
  if (info.name.starts_with("dc_") && param == "offset_z") names.push_back(termAttribute + "_z_offset");
  if (info.name == "mobius" && param.size() == 4) {
    std::string bare = param;
    bare[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(bare[0])));
    bare[3] = static_cast<char>(std::toupper(static_cast<unsigned char>(bare[3])));
    names.push_back(bare);
  }
  // Fractorium's MobiusN writes its coefficients without the separating "_" (MobiusNRe_A, pre_MobiusNIm_B).
  if (info.name == "MobiusN" && param.size() == 4) names.push_back(termAttribute + param);
  return names;
}

// The name a term keeps: the catalogue's spelling, with the file's pre_/post_ prefix.
std::string termName(std::string_view fileName, const VariationInfo& info) {
  const std::string name = lowered(fileName);
  if (name == lowered(info.name)) return info.name;  // the catalogue's own pre_blur among them
  if (name.starts_with("pre_")) return "pre_" + info.name;
  if (name.starts_with("post_")) return "post_" + info.name;
  return info.name;
}

std::string trimmed(std::string_view text) {
  const auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
  while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
  return std::string(text);
}

// One number, in the C locale whatever the process's locale is; nullopt when the text is not
// exactly a number. "nan" and "inf" parse (and are then refused by the range checks).
std::optional<double> parseNumber(std::string_view text) {
  std::string token = trimmed(text);
  std::string_view view = token;
  if (!view.empty() && view.front() == '+') view.remove_prefix(1);
  if (view.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(view.data(), view.data() + view.size(), value);
  if (error == std::errc::result_out_of_range) return std::numeric_limits<double>::infinity();
  if (error != std::errc() || end != view.data() + view.size()) return std::nullopt;
  return value;
}

// Whitespace-separated numbers; nullopt when a token is not a number.
std::optional<std::vector<double>> parseNumbers(std::string_view text) {
  std::vector<double> values;
  std::istringstream in{std::string(text)};
  std::string token;
  while (in >> token) {
    const auto value = parseNumber(token);
    if (!value) return std::nullopt;
    values.push_back(*value);
  }
  return values;
}

// The length of the UTF-8 sequence at `at` (1–4), or 0 where the bytes there are not UTF-8 as
// JSON requires it: no overlong forms, no surrogates, nothing beyond U+10FFFF.
std::size_t utf8SequenceAt(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(at);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  std::uint32_t code = 0;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
    code = lead & 0x1Fu;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    code = lead & 0x0Fu;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    code = lead & 0x07u;
  } else {
    return 0;
  }
  if (at + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(at + k) & 0xC0u) != 0x80u) return 0;
    code = (code << 6) | (byte(at + k) & 0x3Fu);
  }
  if (length == 3 && (code < 0x800 || (code >= 0xD800 && code <= 0xDFFF))) return 0;
  if (length == 4 && (code < 0x10000 || code > 0x10FFFF)) return 0;
  return length;
}

// A flame's name goes into the preset, and JSON holds only UTF-8: saving an imported flame whose
// name was not UTF-8 threw (flame_xml_fuzzer checks that it does not). pugixml converts files
// that declare their encoding; old Windows editors wrote Latin-1 names without saying so, so a
// byte that is not part of a UTF-8 sequence is read as the Latin-1 character it is there.
// `changed` says whether any was.
std::string asUtf8(std::string_view text, bool& changed) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    if (const std::size_t length = utf8SequenceAt(text, i)) {
      out.append(text.substr(i, length));
      i += length;
      continue;
    }
    const auto latin1 = static_cast<unsigned char>(text[i++]);
    out += static_cast<char>(0xC0u | (latin1 >> 6));
    out += static_cast<char>(0x80u | (latin1 & 0x3Fu));
    changed = true;
  }
  return out;
}

bool finiteWithin(double v, double limit) {
  return std::isfinite(v) && std::abs(v) <= limit;
}

std::string formatted(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

// A name as XML spells one (ASCII letters, digits, "_", ":", ".", "-"; not starting with a digit,
// "." or "-"), which is what pugixml accepts. Non-ASCII bytes are accepted as pugixml does.
bool isXmlName(std::string_view name) {
  if (name.empty()) return false;
  const auto start = [](unsigned char c) { return std::isalpha(c) || c == '_' || c == ':' || c >= 0x80; };
  const auto inner = [&](unsigned char c) { return start(c) || std::isdigit(c) || c == '.' || c == '-'; };
  if (!start(static_cast<unsigned char>(name.front()))) return false;
  return std::all_of(name.begin(), name.end(), [&](char c) { return inner(static_cast<unsigned char>(c)); });
}

// JWildfire's mark of a variation's second copy on one transform: "julian2#1#" → "julian2".
std::string withoutCopyMark(std::string_view name) {
  if (name.size() >= 3 && name.back() == '#') {
    const std::size_t open = name.rfind('#', name.size() - 2);
    if (open != std::string_view::npos && open > 0 && open + 1 < name.size() - 1 &&
        std::all_of(name.begin() + static_cast<std::ptrdiff_t>(open) + 1, name.end() - 1,
                    [](char c) { return c >= '0' && c <= '9'; }))
      return std::string(name.substr(0, open));
  }
  return std::string(name);
}

// Values an editor works out from a variation's parameters and writes beside them: Fractorium
// writes auger's half_scale (scale / 2). And parameters an editor wrote that never changed what the
// variation draws: JWildfire's dc_tesla had `thicknes` and `shift` until 2020, which it did not read.
// They carry nothing of their own.
bool isDerivedParam(const VariationInfo& info, std::string_view param) {
  return (info.name == "auger" && param == "half_scale") ||
         (info.name == "dc_tesla" && (param == "thicknes" || param == "shift"));
}

// dc_warping's shifts from its seed as JWildfire's setParameter makes them: Java's (int) of the seed,
// then 2 · nextDouble() − 1 of a new java.util.Random(seed) (its 48-bit linear congruence), x first.
std::pair<double, double> dcWarpingShifts(double seedValue) {
  const std::int64_t seed =
      std::isnan(seedValue) ? 0 : static_cast<std::int64_t>(std::clamp(seedValue, -2147483648.0, 2147483647.0));
  constexpr std::uint64_t kMultiplier = 0x5DEECE66DULL, kMask = (std::uint64_t{1} << 48) - 1;
  std::uint64_t state = (static_cast<std::uint64_t>(seed) ^ kMultiplier) & kMask;
  const auto next = [&state](int bits) {
    state = (state * kMultiplier + 0xBULL) & kMask;
    return state >> (48 - bits);
  };
  const auto nextDouble = [&next] {
    const std::uint64_t high = next(26), low = next(27);
    return static_cast<double>((high << 27) + low) * 0x1.0p-53;
  };
  const double x = 2.0 * nextDouble() - 1.0;
  return {x, 2.0 * nextDouble() - 1.0};
}

// JWildfire writes a variation's resources (file names, references) beside its parameters: plane_wf's
// and obj_mesh_primitive_wf's colour and displacement images, recurrenceplot's and
// obj_mesh_primitive_wf's reference documents. voxflame reads no images: an empty name (no image)
// loses nothing, a named image is left out (the image file does not travel with the flame).
bool isJwildfireResource(const VariationInfo& info, std::string_view param) {
  const bool imageMaps = info.name == "plane_wf" || info.name == "parplot2d_wf" || info.name == "polarplot3d_wf" ||
                         info.name == "isosfplot3d_wf" || info.name == "obj_mesh_primitive_wf";
  return (imageMaps && (param == "colormap_filename" || param == "displ_map_filename")) ||
         (info.name == "recurrenceplot" && param == "func_id_reference") ||
         ((info.name == "parplot2d_wf" || info.name == "isosfplot3d_wf") && param == "preset_id_reference") ||
         (info.name == "obj_mesh_primitive_wf" && param == "primitive_reference") ||
         (embedsFlame(info) && param == "flame_filename");
}
bool jwildfireResourceMatters(const VariationInfo& info, std::string_view param, std::string_view value) {
  return (info.name == "plane_wf" || info.name == "parplot2d_wf" || info.name == "polarplot3d_wf" ||
          info.name == "isosfplot3d_wf" || info.name == "obj_mesh_primitive_wf") &&
         param.ends_with("_filename") && !value.empty();
}

// JWildfire stores a motion curve beside any variation parameter (`<variation>_<parameter>_enabled`,
// `_view_xmin`, `_x0`, ...) and a variation's stage as `<variation>_fx_priority` (read where the
// variation is); pugixml sees these as parameters of the variation.
bool isJwildfireParamCurve(std::string_view param) {
  if (param == "fx_priority") return true;
  static const std::array<std::string_view, 10> suffixes = {
      "_enabled",   "_interpolation", "_selected_idx", "_locked",    "_point_count",
      "_view_xmin", "_view_xmax",     "_view_ymin",    "_view_ymax", "_selected_pt"};
  if (std::any_of(suffixes.begin(), suffixes.end(), [&](std::string_view s) { return param.ends_with(s); }))
    return true;
  // Curve points: _x0, _y0, _x1, ...
  std::size_t digits = 0;
  while (digits < param.size() && std::isdigit(static_cast<unsigned char>(param[param.size() - 1 - digits]))) ++digits;
  if (digits == 0 || param.size() < digits + 2) return false;
  const char axis = param[param.size() - 1 - digits], underscore = param[param.size() - 2 - digits];
  return underscore == '_' && (axis == 'x' || axis == 'y');
}

// Real flame files are not always well-formed XML: JWildfire writes attribute names such as
// `julian2#1#` or `crop_trapezoid_Base Sup.` (with a space) or `dc_booleans_^/&/|`, and old
// Apophysis files end with a stray `</Flames>`. tolerantXml rewrites such text into XML that
// pugixml reads: every attribute name that is not an XML name gets a stand-in
// (`voxflame-attribute-N`, never used by a flame editor) that `renamed` maps back to the file's
// own name; a raw `<` or `&` in a value is escaped; a closing tag that closes nothing is dropped,
// one that closes an outer element first closes the ones left open inside it, and elements still
// open at the end are closed. `fixes` says what was done, for the warnings.
struct TolerantXml {
  std::string text;
  std::map<std::string, std::string> renamed;
  std::vector<std::string> fixes;
};

TolerantXml tolerantXml(std::string_view in) {
  TolerantXml result;
  std::string& out = result.text;
  out.reserve(in.size() + in.size() / 8);
  std::vector<std::string> open;
  // How many elements of each name are open: whether a closing tag closes anything is looked up
  // here, not by searching `open`, which made a file of many unclosed elements and stray closing
  // tags quadratic (a 700 kB one took hours).
  std::map<std::string, std::size_t, std::less<>> openCount;
  std::size_t strayClosings = 0, unclosed = 0;
  const auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  const auto isNameChar = [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return std::isalnum(u) || c == '_' || c == ':' || c == '.' || c == '-' || u >= 0x80;
  };
  // Copies `in` from i through the end of `terminator` (or to the end of the text).
  const auto copyThrough = [&](std::size_t& i, std::string_view terminator) {
    const std::size_t end = in.find(terminator, i);
    const std::size_t stop = end == std::string_view::npos ? in.size() : end + terminator.size();
    out.append(in.substr(i, stop - i));
    i = stop;
  };
  const auto appendEscaped = [&](std::string_view value) {
    for (std::size_t k = 0; k < value.size(); ++k) {
      const char c = value[k];
      if (c == '<') {
        out += "&lt;";
      } else if (c == '&') {
        // An entity (&amp; &#38; &#x26;) stays; a bare & is escaped.
        std::size_t e = k + 1;
        if (e < value.size() && value[e] == '#') ++e;
        while (e < value.size() && std::isalnum(static_cast<unsigned char>(value[e]))) ++e;
        out += e < value.size() && value[e] == ';' && e > k + 1 ? "&" : "&amp;";
      } else {
        out += c;
      }
    }
  };
  std::size_t i = 0;
  while (i < in.size()) {
    const char c = in[i];
    if (c != '<') {
      out += c;
      ++i;
      continue;
    }
    const std::string_view rest = in.substr(i);
    if (rest.starts_with("<!--")) {
      copyThrough(i, "-->");
    } else if (rest.starts_with("<![CDATA[")) {
      copyThrough(i, "]]>");
    } else if (rest.starts_with("<?")) {
      copyThrough(i, "?>");
    } else if (rest.starts_with("<!")) {
      copyThrough(i, ">");
    } else if (rest.starts_with("</")) {
      const std::size_t end = in.find('>', i);
      const std::size_t stop = end == std::string_view::npos ? in.size() : end;
      const std::string name = trimmed(in.substr(i + 2, stop - i - 2));
      i = end == std::string_view::npos ? in.size() : end + 1;
      const auto found = openCount.find(name);
      if (found == openCount.end() || found->second == 0) {
        ++strayClosings;
        continue;
      }
      while (open.back() != name) {
        out += "</" + open.back() + ">";
        --openCount[open.back()];
        open.pop_back();
        ++unclosed;
      }
      out += "</" + name + ">";
      --found->second;
      open.pop_back();
    } else if (i + 1 < in.size() && (std::isalpha(static_cast<unsigned char>(in[i + 1])) || in[i + 1] == '_')) {
      std::size_t k = i + 1;
      while (k < in.size() && isNameChar(in[k])) ++k;
      const std::string element(in.substr(i + 1, k - i - 1));
      out += "<" + element;
      bool closed = false;
      while (k < in.size()) {
        while (k < in.size() && isSpace(in[k])) ++k;
        if (k >= in.size()) break;
        if (in[k] == '>') {
          out += '>';
          ++k;
          open.push_back(element);
          ++openCount[element];
          closed = true;
          break;
        }
        if (in.substr(k).starts_with("/>")) {
          out += "/>";
          k += 2;
          closed = true;
          break;
        }
        // An attribute: its name runs to the "=" (it may hold spaces), then a quoted value.
        const std::size_t equals = in.find_first_of("=>", k);
        if (equals == std::string_view::npos || in[equals] == '>') {
          k = equals == std::string_view::npos ? in.size() : equals;  // junk without a value: dropped
          continue;
        }
        std::string name = trimmed(in.substr(k, equals - k));
        std::size_t v = equals + 1;
        while (v < in.size() && isSpace(in[v])) ++v;
        std::string_view value;
        if (v < in.size() && (in[v] == '"' || in[v] == '\'')) {
          const std::size_t close = in.find(in[v], v + 1);
          const std::size_t stop = close == std::string_view::npos ? in.size() : close;
          value = in.substr(v + 1, stop - v - 1);
          k = close == std::string_view::npos ? in.size() : close + 1;
        } else {
          std::size_t stop = v;
          while (stop < in.size() && !isSpace(in[stop]) && in[stop] != '>' && !in.substr(stop).starts_with("/>"))
            ++stop;
          value = in.substr(v, stop - v);
          k = stop;
        }
        if (name.empty()) continue;
        if (!isXmlName(name)) {
          const std::string standIn = "voxflame-attribute-" + std::to_string(result.renamed.size());
          result.renamed.emplace(standIn, name);
          name = standIn;
        }
        out += " " + name + "=\"";
        std::string quoted;
        for (const char ch : value) {
          if (ch == '"')
            quoted += "&quot;";
          else
            quoted += ch;
        }
        appendEscaped(quoted);
        out += '"';
      }
      if (!closed) {
        out += "/>";  // a tag cut off by the end of the file
      }
      i = k;
    } else {
      out += "&lt;";
      ++i;
    }
  }
  unclosed += open.size();
  while (!open.empty()) {
    out += "</" + open.back() + ">";
    open.pop_back();
  }
  if (!result.renamed.empty())
    result.fixes.push_back(std::to_string(result.renamed.size()) + " attribute name" +
                           (result.renamed.size() == 1 ? " is" : "s are") + " not XML names");
  if (strayClosings > 0)
    result.fixes.push_back(std::to_string(strayClosings) + " closing tag" + (strayClosings == 1 ? "" : "s") +
                           " without an opening one");
  if (unclosed > 0)
    result.fixes.push_back(std::to_string(unclosed) + " element" + (unclosed == 1 ? " was" : "s were") +
                           " never closed");
  return result;
}

// Builds the messages of one flame: "FILE, flame 'NAME'".
class FlameReader {
 public:
  FlameReader(std::string where, const FlameImportOptions& options) : where_(std::move(where)), options_(options) {}

  [[noreturn]] void fail(const std::string& context, const std::string& reason) const {
    throw Error(where_ + (context.empty() ? "" : " " + context) + ": " + reason);
  }

  // `clampFinite`: a finite value out of range is clamped instead (Fractorium writes hexcrop's dropoff as 1e10, a
  // point sent out of the picture, which the limit sends as far).
  double number(const pugi::xml_attribute& attribute, const std::string& context, double low, double high,
                bool clampFinite = false) const {
    const auto value = parseNumber(attribute.value());
    if (!value)
      fail(context, std::string("attribute ") + attribute.name() + "=\"" + attribute.value() + "\" is not a number");
    if (clampFinite && std::isfinite(*value)) return std::clamp(*value, low, high);
    if (!std::isfinite(*value) || *value < low || *value > high)
      fail(context, std::string("attribute ") + attribute.name() + "=\"" + attribute.value() +
                        "\" must be a number from " + formatted(low) + " to " + formatted(high));
    return *value;
  }

  // A number that the file may write slightly out of range (colour 1.0000001): clamped once finite.
  double clampedNumber(const pugi::xml_attribute& attribute, const std::string& context, double low,
                       double high) const {
    return std::clamp(number(attribute, context, -kFlameCoefficientLimit, kFlameCoefficientLimit), low, high);
  }

  // flam3's "a d b e c f" into Affine3's rows (x' = a x + b y + c, y' = d x + e y + f; z kept).
  Affine3 affine(const pugi::xml_attribute& attribute, const std::string& context) const {
    const auto values = parseNumbers(attribute.value());
    if (!values || values->size() != 6)
      fail(context, std::string("attribute ") + attribute.name() +
                        " must be 6 numbers \"a d b e c f\" (flam3's order), not \"" +
                        std::string(attribute.value()).substr(0, 80) + "\"");
    for (const double v : *values)
      if (!finiteWithin(v, kFlameCoefficientLimit))
        fail(context, std::string("attribute ") + attribute.name() +
                          " has a coefficient that is not finite or beyond ±1e6 (" + formatted(v) + ")");
    const auto& c = *values;
    Affine3 a;
    a.m[0] = c[0];  // a
    a.m[4] = c[1];  // d
    a.m[1] = c[2];  // b
    a.m[5] = c[3];  // e
    a.m[3] = c[4];  // c
    a.m[7] = c[5];  // f
    return a;
  }

  // JWildfire's 3D affine maps: after the x–y map of coefs (or post), a 2D map of the y–z plane
  // (yzCoefs, yzPost) and then one of the z–x plane (zxCoefs, zxPost), each written like coefs
  // ("00 01 10 11 20 21", u' = 00 u + 10 v, v' = 01 u + 11 v for the plane's (u, v)), whose
  // translations JWildfire adds only at the end. All of it is one affine map of 3D space.
  void addJwildfirePlanes(Affine3& a, const pugi::xml_attribute& yzAttribute, const pugi::xml_attribute& zxAttribute,
                          const std::string& context) const {
    if (!yzAttribute && !zxAttribute) return;
    const Affine3 yz = yzAttribute ? affine(yzAttribute, context) : Affine3{};
    const Affine3 zx = zxAttribute ? affine(zxAttribute, context) : Affine3{};
    // The linear parts as 3×3 matrices (row-major), applied x–y first.
    const std::array<double, 9> xyLinear = {a.m[0], a.m[1], a.m[2], a.m[4], a.m[5], a.m[6], a.m[8], a.m[9], a.m[10]};
    const std::array<double, 9> yzLinear = {1.0, 0.0, 0.0, 0.0, yz.m[0], yz.m[1], 0.0, yz.m[4], yz.m[5]};
    const std::array<double, 9> zxLinear = {zx.m[0], 0.0, zx.m[1], 0.0, 1.0, 0.0, zx.m[4], 0.0, zx.m[5]};
    const auto times = [](const std::array<double, 9>& l, const std::array<double, 9>& r) {
      std::array<double, 9> out{};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          for (int k = 0; k < 3; ++k) out[3 * i + j] += l[3 * i + k] * r[3 * k + j];
      return out;
    };
    const std::array<double, 9> linear = times(zxLinear, times(yzLinear, xyLinear));
    const std::array<double, 3> translation = {a.m[3] + zx.m[3], a.m[7] + yz.m[3], a.m[11] + yz.m[7] + zx.m[7]};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) a.m[4 * i + j] = linear[3 * i + j];
      a.m[4 * i + 3] = translation[i];
    }
  }

  FlameXform xform(const pugi::xml_node& node, const std::string& context, bool isFinal) {
    FlameXform x;
    x.variations.clear();
    if (isFinal) x.colorSpeed = 0.0;  // flam3's final transform leaves colour alone unless told
    bool haveColorSpeed = false;
    if (!isFinal) {
      const pugi::xml_attribute weight = node.attribute("weight");
      x.weight = weight ? number(weight, context, 0.0, kFlameCoefficientLimit) : 0.0;
      if (!weight) warn(context + " has no weight attribute; it is never chosen");
    }
    const pugi::xml_attribute coefs = node.attribute("coefs");
    if (!coefs) fail(context, "has no coefs attribute (its affine map \"a d b e c f\")");
    x.affine = affine(coefs, context);
    addJwildfirePlanes(x.affine, node.attribute("yzCoefs"), node.attribute("zxCoefs"), context);
    if (const pugi::xml_attribute post = node.attribute("post")) x.post = affine(post, context);
    addJwildfirePlanes(x.post, node.attribute("yzPost"), node.attribute("zxPost"), context);
    x.hasPost = !x.post.isIdentity();
    if (const pugi::xml_attribute color = node.attribute("color")) {
      // Apophysis writes "color" as one number; flam3's old files as two ("c1 c2"): the first counts.
      const auto values = parseNumbers(color.value());
      if (!values || values->empty() || !finiteWithin(values->front(), kFlameCoefficientLimit))
        fail(context, std::string("attribute color=\"") + color.value() + "\" is not a number");
      x.color = std::clamp(values->front(), 0.0, 1.0);
    }
    if (const pugi::xml_attribute speed = node.attribute("color_speed")) {
      x.colorSpeed = clampedNumber(speed, context, 0.0, 1.0);
      haveColorSpeed = true;
    }
    // flam3 before 3.0 wrote symmetry = 1 − 2 · color_speed.
    if (const pugi::xml_attribute symmetry = node.attribute("symmetry"); symmetry && !haveColorSpeed)
      x.colorSpeed = std::clamp(
          (1.0 - number(symmetry, context, -kFlameCoefficientLimit, kFlameCoefficientLimit)) / 2.0, 0.0, 1.0);
    if (const pugi::xml_attribute opacity = node.attribute("opacity"))
      x.opacity = clampedNumber(opacity, context, 0.0, 1.0);
    // JWildfire's solid rendering: the material index the transform pulls points towards.
    if (const pugi::xml_attribute material = node.attribute("material"))
      x.material = clampedNumber(material, context, 0.0, 1000.0);
    if (const pugi::xml_attribute speed = node.attribute("material_speed"))
      x.materialSpeed = clampedNumber(speed, context, -1.0, 1.0);
    // Fractorium's and Apophysis 7X's direct colour: how much of what dc_ variations set is kept.
    if (const pugi::xml_attribute direct = node.attribute("var_color"))
      x.directColor = clampedNumber(direct, context, 0.0, 1.0);
    if (const pugi::xml_attribute plotmode = node.attribute("plotmode");
        plotmode && std::string_view(plotmode.value()) == "off")
      x.opacity = 0.0;  // Apophysis' invisible transform
    // flam3's and Apophysis' xaos: factors for the transforms that may follow this one, in order;
    // readFlame trims the list to the transform count once it is known.
    if (const pugi::xml_attribute chaos = node.attribute("chaos"); chaos && !isFinal) {
      const auto values = parseNumbers(chaos.value());
      if (!values)
        fail(context, std::string("attribute chaos=\"") + std::string(chaos.value()).substr(0, 80) +
                          "\" must be numbers (xaos factors)");
      for (double v : *values) {
        if (!std::isfinite(v) || v < 0.0 || v > kFlameCoefficientLimit) {
          warn(context + " has a xaos factor " + formatted(v) + " outside 0–1e6; " + (v > 0.0 ? "1e6" : "0") +
               " is used");
          v = v > 0.0 ? kFlameCoefficientLimit : 0.0;  // NaN and negatives forbid the step
        }
        x.xaos.push_back(v);
      }
    }
    // flam3 2.x's variation lists: var="w0 w1 ..." weighs the variations by their index in flam3's
    // list, var1="k" is variation k alone at weight 1.
    std::vector<VariationTerm> oldList;
    if (const pugi::xml_attribute list = node.attribute("var")) {
      const auto weights = parseNumbers(list.value());
      if (!weights) fail(context, "attribute var=\"" + std::string(list.value()).substr(0, 80) + "\" must be numbers");
      for (std::size_t i = 0; i < weights->size(); ++i) {
        const double weight = (*weights)[i];
        if (weight == 0.0) continue;
        if (!std::isfinite(weight) || std::abs(weight) > kFlameCoefficientLimit)
          fail(context, "has a var= weight that is not a finite number within ±1e6");
        if (i >= kFlam3VariationOrder.size()) {
          lose("var= entry " + std::to_string(i));
          warn(context + " weighs variation " + std::to_string(i) + " of flam3's list in var=, which has only " +
               std::to_string(kFlam3VariationOrder.size()) + "; it was left out");
          continue;
        }
        const VariationInfo& info = variationOrThrow(kFlam3VariationOrder[i]);
        oldList.push_back({info.name, weight, info.defaultParams()});
      }
    } else if (const pugi::xml_attribute one = node.attribute("var1")) {
      const auto index = parseNumber(one.value());
      if (!index || *index < 0.0 || *index >= static_cast<double>(kFlam3VariationOrder.size()) ||
          *index != std::floor(*index))
        fail(context, "attribute var1=\"" + std::string(one.value()).substr(0, 40) +
                          "\" must be the index of one of flam3's " + std::to_string(kFlam3VariationOrder.size()) +
                          " variations");
      const VariationInfo& info = variationOrThrow(kFlam3VariationOrder[static_cast<std::size_t>(*index)]);
      oldList.push_back({info.name, 1.0, info.defaultParams()});
    }

    // Variations: attributes naming a catalogue entry. Their parameters follow as
    // `<variation>_<parameter>`; an unknown variation's parameters are dropped with it. JWildfire
    // writes a second copy of a variation on one transform as `<variation>#N#` (parameters
    // `<variation>#N#_<parameter>`): each copy is its own entry.
    std::map<std::string, pugi::xml_attribute, std::less<>> byName;
    std::map<std::string, std::pair<std::string, pugi::xml_attribute>> byLowerName;  // lower-case → name, attribute
    for (const pugi::xml_attribute& attribute : node.attributes()) {
      byName.emplace(nameOf(attribute), attribute);
      byLowerName.emplace(lowered(nameOf(attribute)), std::make_pair(nameOf(attribute), attribute));
    }
    double droppedWeight = 0.0;
    std::string dropped;
    std::set<std::string> consumed;                  // attributes read as some term's parameters
    std::map<std::string, std::size_t> termIndex;    // a variation attribute → its term in x.variations
    std::map<std::string, VariationTerm> zeroTerms;  // variations of weight 0, by attribute
    // First the variations (so parameters are known before anything is called unknown)...
    for (const pugi::xml_attribute& attribute : node.attributes()) {
      const std::string name = nameOf(attribute);
      if (knownXformAttributes().contains(name)) continue;
      const VariationInfo* info = variationNamed(withoutCopyMark(name));
      if (!info) continue;
      consumed.insert(name);
      VariationTerm term;
      term.name = termName(withoutCopyMark(name), *info);
      // JWildfire moves a variation to the pre_ stage (a negative `<variation>_fx_priority`) or the
      // post_ stage (a positive one) without renaming it.
      if (term.name == info->name && !info->name.starts_with("prepost_")) {
        if (const auto it = byName.find(name + "_fx_priority"); it != byName.end()) {
          const auto priority = parseNumber(it->second.value());
          if (priority && *priority < 0.0) term.name = "pre_" + info->name;
          if (priority && *priority > 0.0) term.name = "post_" + info->name;
        }
      }
      term.weight = number(attribute, context, -kFlameCoefficientLimit, kFlameCoefficientLimit);
      // JWildfire runs a variation whatever its weight, and pre_stabilize does not use its weight:
      // files leave it at 0. voxflame drops terms of weight 0, so it is kept at weight 1.
      if (term.weight == 0.0 && info->name == "stabilize" && term.name == "pre_stabilize") term.weight = 1.0;
      term.params = info->defaultParams();
      // JWildfire's rational3 names its coefficients a … h (rational3_a = Fractorium's t3, …) and has
      // defaults of its own, which a file naming them that way gets for the ones it leaves out.
      if (info->name == "rational3" && byLowerName.contains(lowered(name + "_a")))
        term.params = {0.5, 0.0, 0.25, 1.0, 0.0, 0.9, 0.0, 1.0};
      for (std::size_t i = 0; i < info->params.size(); ++i)
        for (const std::string& key : fileParamNames(name, *info, info->params[i].name)) {
          // Editors that capitalise a variation capitalise its parameters too (Mobius_Re_A). An
          // attribute that is itself a variation's name is that variation, never a parameter of
          // another whose name it extends (blur_square is not blur's parameter "square").
          const auto param = byLowerName.find(lowered(key));
          if (param == byLowerName.end() || variationNamed(withoutCopyMark(param->second.first))) continue;
          term.params[i] = number(param->second.second, context, -kFlameCoefficientLimit, kFlameCoefficientLimit,
                                  info->name == "hexcrop" && info->params[i].name == "dropoff");
          consumed.insert(param->second.first);
          break;
        }
      // JWildfire's dc_warping shifts its pattern by (x0, x0) since x0 became a parameter (2020), which
      // its seed `randomize` sets and a file's x0 then overrides; before, by (x0, y0), both from the
      // seed (dcWarpingShifts). The catalogue's y0 is that second shift.
      if (info->name == "dc_warping") {
        const auto at = [&](const char* param) { return static_cast<std::size_t>(info->paramIndex(param)); };
        if (byLowerName.contains(lowered(name + "_x0"))) {
          if (!byLowerName.contains(lowered(name + "_y0"))) term.params.at(at("y0")) = term.params.at(at("x0"));
        } else {
          const auto [x0, y0] = dcWarpingShifts(term.params.at(at("randomize")));
          term.params.at(at("x0")) = x0;
          term.params.at(at("y0")) = y0;
        }
      }
      // Text parameters (JWildfire's resources, which it writes as the hex of their bytes).
      if (!info->textParams.empty()) term.texts = info->defaultTexts();
      // An embedded flame is read, checked and said of at once (readTermText).
      if (embedsFlame(*info)) readTermText(name, *info, byLowerName, context, term, consumed);
      for (std::size_t i = 0; i < info->textParams.size() && !embedsFlame(*info); ++i) {
        const auto param = byLowerName.find(lowered(name + "_" + info->textParams[i].name));
        if (param == byLowerName.end()) continue;
        consumed.insert(param->second.first);
        // colormap_wf's inlined picture is a file's bytes, which JSON's UTF-8 text cannot hold: its hex is kept.
        if (info->name == "colormap_wf" && info->textParams[i].name == "inlined_image" &&
            decodeJwildfireResource(param->second.second.value())) {
          term.texts[i] = param->second.second.value();
        } else if (std::optional<std::string> text = decodeJwildfireResource(param->second.second.value())) {
          // Scenes are JSON, which holds UTF-8 only: other bytes are read as Latin-1 (as elsewhere here).
          bool changed = false;
          term.texts[i] = asUtf8(*text, changed);
          if (changed)
            warn(context + " gives " + param->second.first + " text that is not UTF-8; it was read as Latin-1");
        } else {
          lose(withoutCopyMark(name) + "_" + info->textParams[i].name);
          warn(context + " gives " + param->second.first +
               " a value that is not JWildfire's hex of a text; the default was used");
        }
      }
      // svg_wf's drawing: say what of it cannot be drawn, and whether anything is left.
      if (info->name == "svg_wf" && term.weight != 0.0) {
        const SvgRaster raster =
            rasteriseSvg(term.texts.at(0), term.params.at(1), std::round(term.params.at(3)) != 0.0);
        for (const std::string& problem : raster.problems)
          warn(context + " has " + name + " whose SVG voxflame cannot draw in full: " + problem);
        if (raster.column.size() < 2) {
          lose("picture of " + withoutCopyMark(name));
          warn(context + " has " + name +
               " whose SVG paints nothing; it draws a unit square's random points, as "
               "JWildfire does");
        }
        // JWildfire colours each point by the palette's entry nearest to its pixel's colour (or the
        // pixel's own colour with true_color), which voxflame does not.
        lose("colour of " + withoutCopyMark(name));
        warn(context + " has " + name + ", which JWildfire colours by the SVG's colours; voxflame does not");
      }
      // Only pyr3 writes dc_perlin's color_seed, and pyr3's dc_perlin is a variation of its own: it
      // leaves the point where it is and paints it an RGB colour from noise there, where voxflame's
      // (Fractorium's) moves the point into a noisy square and sets the colour index.
      if (info->name == "dc_perlin" && term.weight != 0.0 && byLowerName.contains(lowered(name + "_color_seed"))) {
        lose("pyr3's " + withoutCopyMark(name));
        warn(context + " has " + name +
             " with a color_seed, which only pyr3 writes: pyr3's dc_perlin leaves the point where it is and paints "
             "it an RGB colour from noise, which voxflame's (Fractorium's) does not; it was read as Fractorium's");
      }
      // colormap_wf draws an inlined PNG; a picture file the flame only names is not in it, and an inlined
      // picture of another format is not read: JWildfire's default picture (its four-corner gradient) stands in.
      if (info->name == "colormap_wf" && term.weight != 0.0) {
        if (!term.texts.at(1).empty()) {
          if (const std::string problem = colormapPictureProblem(term.texts.at(1)); !problem.empty()) {
            lose("picture of " + withoutCopyMark(name));
            warn(context + " has " + name + " whose inlined picture voxflame cannot read (" + problem +
                 "); JWildfire's default picture (its four-corner gradient) stands in");
          }
        } else if (!term.texts.at(0).empty()) {
          lose("picture of " + withoutCopyMark(name));
          warn(context + " has " + name + " with the picture file '" + term.texts.at(0).substr(0, 120) +
               "', which the flame does not hold; JWildfire's default picture (its four-corner gradient) stands in");
        }
      }
      // text_wf's font: one that is not installed here is drawn in the family fontconfig offers
      // instead (Java2D falls back the same way), which the importer names; the text itself is kept.
      if (info->name == "text_wf" && term.weight != 0.0) {
        const std::string& font = term.texts.at(1);
        if (const std::string standIn = substituteFontFamily(font); !standIn.empty())
          warn(context + " has " + name + " in the font '" + font.substr(0, 80) + "', which is not installed here; '" +
               standIn + "' draws its text");
        if (const TextRaster raster = rasteriseText(term.texts.at(0), font, static_cast<int>(term.params.at(0)),
                                                    static_cast<int>(term.params.at(6)));
            raster.column.size() < 2) {
          lose("text of " + withoutCopyMark(name));
          warn(context + " has " + name + " whose text paints nothing" +
               (raster.problem.empty() ? std::string() : " (" + raster.problem + ")") +
               "; it draws a unit square's random points, as JWildfire does");
        }
      }
      // parplot2d_wf's formulas: a file normally gives all three (JWildfire writes a preset's formulas
      // beside its preset_id too, so presets need not be looked up). One muParser cannot read makes
      // the term add nothing.
      if (info->name == "parplot2d_wf" && term.weight != 0.0) {
        for (std::size_t i = 0; i < info->textParams.size(); ++i) {
          const std::string& key = info->textParams[i].name;
          if (!byLowerName.contains(lowered(name + "_" + key))) {
            lose(key + " of " + withoutCopyMark(name));
            warn(context + " has " + name + " without its " + key + "; voxflame's default (a torus's) stands in");
          } else if (const std::optional<std::string> error = parplotFormulaError(term.texts[i])) {
            const std::string& formula = term.texts[i];
            lose(key + " of " + withoutCopyMark(name));
            warn(context + " has " + name + " whose " + key + " \"" +
                 (formula.size() > 120 ? formula.substr(0, 120) + "..." : formula) +
                 "\" cannot be evaluated (muParser: " + *error + "); the variation adds nothing");
          }
        }
      }
      // polarplot3d_wf's and isosfplot3d_wf's formula, evaluated as a parplot surface
      // (polarplotSurfaceFormulas, isosfplotSurfaceFormulas): one muParser cannot read makes the term add
      // nothing, as JWildfire's does, and so does polarplot3d_wf's empty one.
      if ((info->name == "polarplot3d_wf" || info->name == "isosfplot3d_wf") && term.weight != 0.0) {
        const std::string& formula = term.texts.at(0);
        const bool polar = info->name == "polarplot3d_wf";
        if (!byLowerName.contains(lowered(name + "_formula"))) {
          lose("formula of " + withoutCopyMark(name));
          warn(context + " has " + name + " without its formula; voxflame's default (" +
               (polar ? "JWildfire's preset 0" : "an octahedron") + ") stands in");
        } else if (polar && formula.empty()) {
          lose("formula of " + withoutCopyMark(name));
          warn(context + " has " + name + " with an empty formula; the variation adds nothing");
        } else if (const std::optional<std::string> error = parplotFormulaError(
                       (polar ? polarplotSurfaceFormulas(formula) : isosfplotSurfaceFormulas(formula))[0])) {
          lose("formula of " + withoutCopyMark(name));
          warn(context + " has " + name + " whose formula \"" +
               (formula.size() > 120 ? formula.substr(0, 120) + "..." : formula) +
               "\" cannot be evaluated (muParser: " + *error + "); the variation adds nothing");
        }
      }
      if (info->name == "obj_mesh_primitive_wf" && term.weight != 0.0) checkObjMeshPrimitive(name, context, term);
      // A variation of weight 0 draws nothing, unless a motion gives it weight (motion below).
      if (term.weight == 0.0) {
        zeroTerms.emplace(name, std::move(term));
        continue;
      }
      // inversion's direct colour is not applied either. (dc_quadtree's, dc_ducks', dc_booleans' and
      // glsl_apollonian's RGB colours are: VariationInfo::paintsRgb.)
      if (info->name == "inversion" && std::trunc(term.params.at(21)) >= 1.0 && std::trunc(term.params.at(21)) <= 4.0) {
        lose("direct colour of " + withoutCopyMark(name));
        warn(context + " has " + name + " with direct colour, which voxflame does not apply");
      }
      // JWildfire runs a prepost_ variation as a pre_ term (its inverse map) and as a post_ term (the map
      // itself): the catalogue has the two halves as pre_prepost_X and prepost_X.
      if (info->name.starts_with("prepost_") && term.name == info->name) {
        VariationTerm pre = term;
        pre.name = "pre_" + info->name;
        term.name = "post_" + info->name;
        x.variations.push_back(std::move(pre));
      }
      // (A motion curve of the attribute animates the post_ half.)
      termIndex.emplace(name, x.variations.size());
      x.variations.push_back(std::move(term));
    }
    // ...then everything else: parameters, JWildfire's own keys, and what voxflame does not know.
    for (const pugi::xml_attribute& attribute : node.attributes()) {
      const std::string name = nameOf(attribute);
      if (knownXformAttributes().contains(name) || consumed.contains(name)) continue;
      if (isJwildfireExtra(name, attribute.value(), context)) continue;
      // A parameter or an unknown variation. The name is cut at its last "_"s, longest prefix
      // first: the first prefix that is a catalogue variation decides. If the rest is one of that
      // variation's parameters (or JWildfire's curve keys of one), the attribute is that
      // parameter; otherwise it is a variation voxflame does not know whose name extends a known
      // one (blur_square beside blur), reported with its weight like any unknown variation. A
      // prefix that is an unknown variation present on the transform owns the attribute: its
      // parameters go with it. Parameter names are short (the catalogue's, perhaps with a
      // JWildfire curve suffix), so the cut is looked for only among the last kMaxParameterSuffix
      // characters: each cut copies and looks up the prefix, and trying every "_" of a long name
      // was quadratic (a 40 kB name of "a_a_..." took 20 s).
      bool parameter = false;
      std::string extends;  // the known variation an unknown one's name extends
      for (std::size_t cut = name.rfind('_');
           cut != std::string::npos && cut > 0 && name.size() - cut <= kMaxParameterSuffix;
           cut = name.rfind('_', cut - 1)) {
        const std::string prefix = name.substr(0, cut);
        const std::string rest = name.substr(cut + 1);
        if (const VariationInfo* info = variationNamed(withoutCopyMark(prefix))) {
          // A known variation's own parameter counts even when the variation is absent (weight 0).
          if (info->paramIndex(rest) >= 0 || info->textParamIndex(rest) >= 0 || isJwildfireParamCurve(rest) ||
              isDerivedParam(*info, rest)) {
            parameter = true;
          } else if (isJwildfireResource(*info, rest)) {
            parameter = true;
            if (jwildfireResourceMatters(*info, rest, attribute.value())) {
              lose("image " + withoutCopyMark(prefix) + "_" + rest);
              warn(context + " gives '" + name + "' an image, which voxflame does not read; it was left out");
            }
          } else {
            extends = info->name;
          }
          break;
        }
        // (The transform's own attributes are no variation: post_brush_stroke_wf beside a post-affine
        // `post` is a variation of its own, not post's parameter.)
        if (byName.contains(prefix) && !knownXformAttributes().contains(prefix)) {
          parameter = true;  // of an unknown variation, left out with it
          break;
        }
      }
      if (parameter) continue;
      if (!isXmlName(withoutCopyMark(name))) {
        lose("attribute '" + name + "'");
        warn(context + " has an attribute named '" + name + "', which is not an XML name; it was skipped");
        continue;
      }
      unknownVariations_.insert(withoutCopyMark(name));
      if (!extends.empty()) extendedNames_.emplace(withoutCopyMark(name), extends);
      if (const auto weight = parseNumber(attribute.value()); weight && std::isfinite(*weight)) {
        droppedWeight += std::abs(*weight);
        dropped += (dropped.empty() ? "" : ", ") + name;
      }
    }
    for (VariationTerm& term : oldList) x.variations.push_back(std::move(term));
    // Without most of its variation weight a transform shrinks towards its affine map's origin
    // and the picture changes: say so, so an odd-looking import is not a mystery.
    double keptWeight = 0.0;
    for (const VariationTerm& term : x.variations) keptWeight += std::abs(term.weight);
    if (droppedWeight > keptWeight)
      warn(context + " keeps " + formatted(keptWeight) + " of its variation weight " +
           formatted(keptWeight + droppedWeight) + " without " + dropped + "; it will look different");
    if (x.variations.size() > kMaxXformVariations)
      fail(context, "has " + std::to_string(x.variations.size()) + " variations; voxflame takes at most " +
                        std::to_string(kMaxXformVariations));
    if (x.variations.empty()) {
      x.variations = {{"linear", 1.0, {}}};
      termIndex.emplace("linear", 0);
    }
    // A motion may animate a variation the transform holds at weight 0 (or not at all): it joins
    // the transform at weight 0, with the file's parameters.
    const auto termFor = [&](const std::string& attribute, const VariationInfo& info) -> std::optional<std::size_t> {
      if (const auto found = termIndex.find(attribute); found != termIndex.end()) return found->second;
      if (x.variations.size() >= kMaxXformVariations) return std::nullopt;
      VariationTerm term;
      if (auto zero = zeroTerms.find(attribute); zero != zeroTerms.end()) {
        term = std::move(zero->second);
      } else {
        term.name = termName(withoutCopyMark(attribute), info);
        term.weight = 0.0;
        term.params = info.defaultParams();
      }
      termIndex.emplace(attribute, x.variations.size());
      x.variations.push_back(std::move(term));
      return x.variations.size() - 1;
    };
    readWeightField(node, context, x);
    readFlam3Motion(node, context, x, isFinal, termFor);
    readJwildfireCurves(node, context, x, isFinal, termFor);
    return x;
  }

  // obj_mesh_primitive_wf: say which of JWildfire's built-in meshes voxflame does not build (the
  // term then draws nothing), and that the solid renderer's shadow setting is not followed.
  void checkObjMeshPrimitive(const std::string& attribute, const std::string& context, const VariationTerm& term) {
    const std::string variation = withoutCopyMark(attribute);
    const double value = term.params.at(0);
    const std::size_t index = objMeshPrimitiveIndex(value);
    if (index == kObjMeshPrimitiveCount) {
      warn(context + " has " + attribute + " with primitive " + formatted(value) +
           ", outside JWildfire's list (0–25): it draws JWildfire's stand-in, a cube from −1 to 1");
    } else if (!objMeshPrimitiveReproduced(index)) {
      lose(std::string("primitive ") + objMeshPrimitiveName(index) + " of " + variation);
      warn(context + " has " + attribute + " with primitive " + std::to_string(index) + " (JWildfire's " +
           objMeshPrimitiveName(index) + " mesh), which voxflame does not build; it draws nothing");
    }
    // receive_only_shadows (JWildfire's limitIntVal(FTOI(v), 0, 1)): the points take shadows in
    // JWildfire's solid rendering but cast none.
    if (const double shadows = term.params.at(14); std::isfinite(shadows) && std::round(shadows) >= 1.0) {
      lose("receive_only_shadows of " + variation);
      warn(context + " has " + attribute +
           " with receive_only_shadows, a setting of JWildfire's solid rendering (its points cast no shadow), which "
           "voxflame does not follow");
    }
  }

  // A variation's text parameter (subflame_wf's embedded flame, `<variation>_flame`), which JWildfire
  // writes as the hex digits of its bytes; checked here (imported and iterated: the cloud it makes is
  // kept for the render), so what becomes of it is said at import, not silently at render time.
  template <class ByLowerName>
  void readTermText(const std::string& attribute, const VariationInfo& info, const ByLowerName& byLowerName,
                    const std::string& context, VariationTerm& term, std::set<std::string>& consumed) {
    const std::string variation = withoutCopyMark(attribute);
    const auto found = byLowerName.find(lowered(attribute + "_" + info.textParams.at(0).name));
    if (found == byLowerName.end()) {
      lose("embedded flame of " + variation);
      warn(context + " has " + attribute +
           " without the flame it embeds (JWildfire then draws a default flame of its own); a Sierpinski gasket "
           "stands in");
    } else {
      consumed.insert(found->second.first);
      const std::string_view value = found->second.second.value();
      term.texts.at(0) = decodeJwildfireResource(value).value_or(std::string(value));
      const EmbeddedFlameCheck check = checkEmbeddedFlame(term.texts.at(0));
      if (!check.error.empty()) {
        lose("embedded flame of " + variation);
        warn(context + " has " + attribute + " whose embedded flame cannot be read (" + check.error.substr(0, 300) +
             "); it adds nothing");
      } else if (check.escapes) {
        lose("embedded flame of " + variation);
        warn(context + " has " + attribute + " whose embedded flame gives no finite point; it adds nothing");
      }
      if (check.nested) {
        lose("subflame inside the flame " + variation + " embeds");
        warn(context + " has " + attribute +
             " whose embedded flame embeds a flame itself; voxflame leaves the inner one out");
      }
      for (const std::string& item : check.leftOut) lose(item + " in the flame " + variation + " embeds");
      if (!check.leftOut.empty())
        warn(context + " has " + attribute + " whose embedded flame was imported without some of it (" +
             check.leftOut.front() + (check.leftOut.size() > 1 ? ", ..." : "") + ")");
    }
    // The flame file (a sequence of them, or the file the embedded flame came from), read where the
    // variation is: its name extends the text attribute's, which would otherwise claim it.
    if (const auto file = byLowerName.find(lowered(attribute + "_flame_filename")); file != byLowerName.end()) {
      consumed.insert(file->second.first);
      if (*file->second.second.value() != '\0') {
        lose("flame file of " + variation);
        warn(context + " gives '" + file->second.first +
             "' a flame file, which voxflame does not read; the flame it embeds is drawn instead");
      }
    }
    const int modeAt = info.paramIndex("color_mode");
    const double mode = modeAt >= 0 ? std::round(term.params.at(static_cast<std::size_t>(modeAt))) : -1.0;
    if (mode == -2.0 || (mode >= 1.0 && mode <= 4.0)) {
      lose("true colour of " + variation);
      warn(context + " has " + attribute + " with color_mode " + formatted(mode) +
           " (the embedded flame's true colour), which voxflame does not paint; its colour index stands in");
    }
    const int sequenceAt = info.paramIndex("flame_is_sequence");
    if (sequenceAt >= 0 && std::round(term.params.at(static_cast<std::size_t>(sequenceAt))) != 0.0) {
      lose("flame sequence of " + variation);
      warn(context + " has " + attribute +
           " drawing a sequence of flames over the frames, which voxflame does not; the embedded one is drawn");
    }
  }

  // JWildfire's weighting field of a transform, as JWildfire writes it (wfield_type="PERLIN_NOISE",
  // wfield_var_amount_intensity, wfield_noise_frequency, ...) or as its GPU renderer's export
  // does (wfield_type="6", the type's ordinal; wfield_var_amount, wfield_scale, ...). Every noise
  // family becomes voxflame's of the same family (flame.h: the same kind of field, not the same
  // values), with what it drives: variation weights, colour, jitter and named variation
  // parameters. Image-map fields and the GPU export's parameters by index are left out.
  void readWeightField(const pugi::xml_node& node, const std::string& context, FlameXform& x) {
    const pugi::xml_attribute typeAttribute = node.attribute("wfield_type");
    if (!typeAttribute) return;
    static constexpr std::array<std::string_view, 12> kTypes = {
        "NONE",         "CELLULAR_NOISE",       "CUBIC_NOISE",   "CUBIC_FRACTAL_NOISE",
        "PERLIN_NOISE", "PERLIN_FRACTAL_NOISE", "SIMPLEX_NOISE", "SIMPLEX_FRACTAL_NOISE",
        "VALUE_NOISE",  "VALUE_FRACTAL_NOISE",  "WHITE_NOISE",   "IMAGE_MAP"};
    std::string type = trimmed(typeAttribute.value());
    if (const auto ordinal = parseNumber(type);
        ordinal && *ordinal >= 0.0 && *ordinal < static_cast<double>(kTypes.size()) && *ordinal == std::floor(*ordinal))
      type = kTypes[static_cast<std::size_t>(*ordinal)];
    if (type == "NONE") return;
    const auto leaveOut = [&](const std::string& why) {
      lose("JWildfire weighting field");
      warn(context + " has a JWildfire weighting field (" + type.substr(0, 40) + ") " + why + "; it was left out");
    };
    if (std::find(kTypes.begin(), kTypes.end(), type) == kTypes.end())
      return leaveOut("of a type JWildfire does not have");
    if (type == "IMAGE_MAP") return leaveOut("of a kind voxflame does not draw (an image map)");
    // A number under either of its names; nullopt (after leaveOut) when it is not one.
    bool bad = false;
    const auto number = [&](std::initializer_list<const char*> names, double fallback, double low,
                            double high) -> double {
      for (const char* name : names) {
        const pugi::xml_attribute attribute = node.attribute(name);
        if (!attribute) continue;
        const auto value = parseNumber(attribute.value());
        if (!value || !std::isfinite(*value) || *value < low || *value > high) {
          if (!bad)
            leaveOut(std::string("whose ") + name + "=\"" + std::string(attribute.value()).substr(0, 40) +
                     "\" is not a number from " + formatted(low) + " to " + formatted(high));
          bad = true;
          return fallback;
        }
        return *value;
      }
      return fallback;
    };
    FlameXform field;
    field.fieldKind = type.find("FRACTAL") != std::string::npos ? WeightFieldKind::Fractal : WeightFieldKind::Noise;
    field.fieldNoise = type.starts_with("PERLIN")  ? WeightFieldNoise::Perlin
                       : type.starts_with("VALUE") ? WeightFieldNoise::Value
                       : type.starts_with("CUBIC") ? WeightFieldNoise::Cubic
                       : type == "CELLULAR_NOISE"  ? WeightFieldNoise::Cellular
                       : type == "WHITE_NOISE"     ? WeightFieldNoise::White
                                                   : WeightFieldNoise::Simplex;
    field.fieldColor =
        number({"wfield_color_intensity", "wfield_color_amount"}, 0.0, -kFlameCoefficientLimit, kFlameCoefficientLimit);
    field.fieldJitter = number({"wfield_jitter_intensity", "wfield_jitter_amount"}, 0.0, -kFlameCoefficientLimit,
                               kFlameCoefficientLimit);
    field.fieldAmount = number({"wfield_var_amount_intensity", "wfield_var_amount"}, 0.0, -kFlameCoefficientLimit,
                               kFlameCoefficientLimit);
    field.fieldFrequency = number({"wfield_noise_frequency", "wfield_scale"}, 1.0, 0.0, kFlameCoefficientLimit);
    field.fieldSeed =
        static_cast<int>(number({"wfield_noise_seed", "wfield_seed"}, 1337.0, -2147483648.0, 2147483647.0));
    field.fieldOctaves = static_cast<int>(
        std::lround(number({"wfield_fract_noise_octaves", "wfield_octaves"}, 3.0, 1.0, kMaxWeightFieldOctaves)));
    field.fieldGain =
        number({"wfield_fract_noise_gain", "wfield_gain"}, 0.5, -kFlameCoefficientLimit, kFlameCoefficientLimit);
    field.fieldLacunarity = number({"wfield_fract_noise_lacunarity", "wfield_lacunarity"}, 2.0, -kFlameCoefficientLimit,
                                   kFlameCoefficientLimit);
    const std::string input = node.attribute("wfield_input").value();
    field.fieldInput = input == "POSITION" || input == "1" ? WeightFieldInput::Position : WeightFieldInput::Affine;
    for (const char* name : {"wfield_fract_noise_fract_type", "wfield_fractal_type"}) {
      const std::string fractal = node.attribute(name).value();
      if (fractal == "BILLOW" || fractal == "1") field.fieldFractal = WeightFieldFractal::Billow;
      if (fractal == "RIGID_MULTI" || fractal == "2") field.fieldFractal = WeightFieldFractal::Rigid;
    }
    // Cellular noise: JWildfire's names (EUCLIDIAN is its spelling) or the GPU export's ordinals.
    static constexpr std::array<std::string_view, 3> kDistances = {"EUCLIDIAN", "MANHATTAN", "NATURAL"};
    static constexpr std::array<std::string_view, 7> kReturns = {
        "CELL_VALUE", "DISTANCE", "DISTANCE2", "DISTANCE_ADD", "DISTANCE_SUB", "DISTANCE_MUL", "DISTANCE_DIV"};
    const auto choice = [&](std::initializer_list<const char*> names, auto names_, auto set) {
      for (const char* name : names) {
        const pugi::xml_attribute attribute = node.attribute(name);
        if (!attribute) continue;
        const std::string value = trimmed(attribute.value());
        for (std::size_t i = 0; i < names_.size(); ++i)
          if (value == names_[i] || value == std::to_string(i)) return set(i);
        if (!bad) leaveOut(std::string("whose ") + name + "=\"" + value.substr(0, 40) + "\" is not one JWildfire has");
        bad = true;
        return;
      }
    };
    choice({"wfield_cell_noise_dist_function", "wfield_cell_noise_dist_func"}, kDistances,
           [&](std::size_t i) { field.fieldCellDistance = static_cast<CellDistance>(i); });
    choice({"wfield_cell_noise_return_type", "wfield_cell_noise_ret_val"}, kReturns,
           [&](std::size_t i) { field.fieldCellReturn = static_cast<CellReturn>(i); });
    if (bad) return;
    // The variation parameters it scales (JWildfire's own attributes; the GPU export names them by
    // index below): a variation of voxflame's catalogue and one of its parameters, or `amount`.
    std::vector<std::string> notKept;
    const std::array<std::string*, 3> variations = {&field.fieldParam1Variation, &field.fieldParam2Variation,
                                                    &field.fieldParam3Variation};
    const std::array<std::string*, 3> parameters = {&field.fieldParam1Name, &field.fieldParam2Name,
                                                    &field.fieldParam3Name};
    const std::array<double*, 3> intensities = {&field.fieldParam1Intensity, &field.fieldParam2Intensity,
                                                &field.fieldParam3Intensity};
    for (std::size_t i = 0; i < 3; ++i) {
      const std::string prefix = "wfield_var_param" + std::to_string(i + 1) + "_";
      const double intensity =
          number({(prefix + "intensity").c_str()}, 0.0, -kFlameCoefficientLimit, kFlameCoefficientLimit);
      const std::string variation = trimmed(node.attribute((prefix + "var_name").c_str()).value());
      const std::string parameter = trimmed(node.attribute((prefix + "param_name").c_str()).value());
      if (intensity == 0.0 || variation.empty()) continue;  // JWildfire scales nothing
      const VariationInfo* info = variationNamed(withoutCopyMark(variation));
      if (!info) {
        notKept.push_back("parameters of " + variation.substr(0, 40) + " (a variation voxflame does not know)");
        continue;
      }
      if (parameter != "amount" && info->paramIndex(parameter) < 0) {
        notKept.push_back("parameter " + parameter.substr(0, 40) + " of " + info->name + " (which voxflame's " +
                          info->name + " does not have)");
        continue;
      }
      *variations[i] = info->name;
      *parameters[i] = parameter;
      *intensities[i] = intensity;
    }
    if (bad) return;
    // What the field does besides scaling the variations' weights.
    // (A value that is not a number counts as one that is not 0.)
    const auto nonZero = [&](std::initializer_list<const char*> names) {
      return std::any_of(names.begin(), names.end(), [&](const char* name) {
        const pugi::xml_attribute attribute = node.attribute(name);
        return attribute && parseNumber(attribute.value()) != std::optional<double>(0.0);
      });
    };
    if (nonZero({"wfield_param1_amount", "wfield_param2_amount", "wfield_param3_amount"}))
      notKept.push_back("variation parameters (by index, as JWildfire's GPU export names them)");
    std::string also;
    for (const std::string& what : notKept) {
      lose("JWildfire weighting field " + what);
      also += (also.empty() ? "" : ", ") + what;
    }
    x.fieldKind = field.fieldKind;
    x.fieldInput = field.fieldInput;
    x.fieldFractal = field.fieldFractal;
    x.fieldAmount = field.fieldAmount;
    x.fieldFrequency = field.fieldFrequency;
    x.fieldSeed = field.fieldSeed;
    x.fieldOctaves = field.fieldOctaves;
    x.fieldGain = field.fieldGain;
    x.fieldLacunarity = field.fieldLacunarity;
    x.fieldNoise = field.fieldNoise;
    x.fieldCellDistance = field.fieldCellDistance;
    x.fieldCellReturn = field.fieldCellReturn;
    x.fieldColor = field.fieldColor;
    x.fieldJitter = field.fieldJitter;
    x.fieldParam1Variation = field.fieldParam1Variation;
    x.fieldParam1Name = field.fieldParam1Name;
    x.fieldParam1Intensity = field.fieldParam1Intensity;
    x.fieldParam2Variation = field.fieldParam2Variation;
    x.fieldParam2Name = field.fieldParam2Name;
    x.fieldParam2Intensity = field.fieldParam2Intensity;
    x.fieldParam3Variation = field.fieldParam3Variation;
    x.fieldParam3Name = field.fieldParam3Name;
    x.fieldParam3Intensity = field.fieldParam3Intensity;
    weightFields_.insert(type);
    if (!also.empty())
      warn(context + " has a JWildfire weighting field that also scales its " + also +
           ", which voxflame does not; the rest of the field is kept");
  }

  // --- motion: flam3's <motion> elements and JWildfire's motion curves, kept as keyframes ---

  using TermFor = std::function<std::optional<std::size_t>(const std::string&, const VariationInfo&)>;

  // One animated value of a transform: which (MotionChannel::field, the path below the
  // transform), its range, and either flam3's periodic offsets (waves, added to the value as it
  // stands) or a JWildfire curve (points: frame → value).
  struct MotionWave {
    double amplitude = 0.0;
    int frequency = 1;
    char function = 's';  // s(in), t(riangle), h(ill), w (saw)
  };
  struct MotionChannel {
    std::size_t xform = 0;
    bool isFinal = false;
    std::string field;       // "weight", "affine/3", "variations/2/power"
    std::string layerField;  // instead of field: a value of the layer itself ("weight")
    std::string scenePath;   // instead of both: a value of the scene's flat view or tone ("/flat/center_x")
    double low = -kFlameCoefficientLimit, high = kFlameCoefficientLimit;
    std::vector<MotionWave> waves;
    std::vector<std::pair<double, double>> points;  // (JWildfire frame, value)
    bool smooth = false;                            // the curve's interpolation (JWildfire)
  };

  // flam3's <motion> children of a transform: each adds amplitude · f(frequency · t) to the
  // values it names, t running 0 → 1 over a loop, f one of flam3's (and Fractorium's) motion
  // functions, 0 at whole t, peak 1.
  void readFlam3Motion(const pugi::xml_node& node, const std::string& context, FlameXform& x, bool isFinal,
                       const TermFor& termFor) {
    std::size_t number = 0;
    for (const pugi::xml_node& motion : node.children("motion")) {
      const std::string where = context + ", <motion> " + std::to_string(++number);
      if (number > kMaxMotionsPerXform) {
        lose("<motion>");
        warn(where + " and after: a transform takes at most " + std::to_string(kMaxMotionsPerXform) +
             " <motion> elements; the others were left out");
        break;
      }
      MotionWave wave;
      const pugi::xml_attribute frequency = motion.attribute("motion_frequency");
      const auto freq = parseNumber(frequency.value());
      if (!frequency || !freq || *freq != std::floor(*freq) || std::abs(*freq) > kMaxMotionFrequency) {
        lose("<motion>");
        warn(where + " needs motion_frequency, a whole number from −" + std::to_string(kMaxMotionFrequency) + " to " +
             std::to_string(kMaxMotionFrequency) + " (it has \"" + std::string(frequency.value()).substr(0, 40) +
             "\"); it was left out");
        continue;
      }
      wave.frequency = static_cast<int>(*freq);
      if (wave.frequency == 0) continue;  // flam3: no motion
      const std::string function = motion.attribute("motion_function").value();
      if (function == "triangle")
        wave.function = 't';
      else if (function == "hill")
        wave.function = 'h';
      else if (function == "saw")
        wave.function = 'w';
      else if (!function.empty() && function != "sin")
        warn(where + " has motion_function \"" + function.substr(0, 40) +
             "\", not sin, triangle, hill or saw; sin is used");
      for (const pugi::xml_attribute& attribute : motion.attributes()) {
        const std::string name = nameOf(attribute);
        if (name == "motion_frequency" || name == "motion_function") continue;
        const auto values = parseNumbers(attribute.value());
        const bool numbers = values && !values->empty() && std::all_of(values->begin(), values->end(), [](double v) {
                               return finiteWithin(v, kFlameCoefficientLimit);
                             });
        if (!numbers) {
          lose("<motion> " + name);
          warn(where + " has " + name + "=\"" + std::string(attribute.value()).substr(0, 40) +
               "\", which is not numbers within ±1e6; it was left out");
          continue;
        }
        const auto add = [&](const std::string& field, double amplitude, double low, double high) {
          if (amplitude == 0.0) return;
          MotionChannel& channel = channelFor(field, low, high);
          MotionWave w = wave;
          w.amplitude = amplitude;
          channel.waves.push_back(w);
        };
        if (name == "coefs" || name == "post") {
          if (values->size() != 6) {
            lose("<motion> " + name);
            warn(where + " has " + name + " of " + std::to_string(values->size()) + " numbers, not 6; it was left out");
            continue;
          }
          if (name == "post" && !x.hasPost &&
              std::any_of(values->begin(), values->end(), [](double v) { return v != 0.0; }))
            x.hasPost = true;                                                 // an identity post map that moves
          static constexpr std::array<int, 6> kElement = {0, 4, 1, 5, 3, 7};  // a d b e c f
          for (std::size_t i = 0; i < 6; ++i)
            add((name == "coefs" ? "affine/" : "post/") + std::to_string(kElement[i]), (*values)[i],
                -kFlameCoefficientLimit, kFlameCoefficientLimit);
          continue;
        }
        const double amplitude = values->front();
        if (name == "weight") {
          if (!isFinal) add("weight", amplitude, 0.0, kFlameCoefficientLimit);
        } else if (name == "color") {
          add("color", amplitude, 0.0, 1.0);
        } else if (name == "color_speed") {
          add("color_speed", amplitude, 0.0, 1.0);
        } else if (name == "opacity") {
          add("opacity", amplitude, 0.0, 1.0);
        } else if (const auto target = variationTarget(name, termFor)) {
          add(*target, amplitude, -kFlameCoefficientLimit, kFlameCoefficientLimit);
        } else {
          // animate (the loop's rotation flag), symmetry, and what voxflame does not know.
          lose("<motion> " + name);
          warn(where + " animates " + name + ", which voxflame cannot animate; it was left out");
        }
      }
    }
  }

  // JWildfire's motion curves of a transform and its variations: `<name>_enabled="true"`, then
  // `<name>_point_count`, `<name>_x<i>` (frames), `<name>_y<i>` (values), `<name>_interpolation`.
  // The curve's value replaces the property's at each frame.
  void readJwildfireCurves(const pugi::xml_node& node, const std::string& context, FlameXform& x, bool isFinal,
                           const TermFor& termFor) {
    std::map<std::string, pugi::xml_attribute, std::less<>> byName;
    for (const pugi::xml_attribute& attribute : node.attributes()) byName.emplace(nameOf(attribute), attribute);
    const bool planes =
        node.attribute("yzCoefs") || node.attribute("zxCoefs") || node.attribute("yzPost") || node.attribute("zxPost");
    for (const auto& [attributeName, attribute] : byName) {
      if (!attributeName.ends_with("_enabled") || std::string_view(attribute.value()) != "true") continue;
      const std::string curve = attributeName.substr(0, attributeName.size() - std::string_view("_enabled").size());
      const auto leaveOut = [&](const std::string& why) {
        lose("JWildfire motion curve " + curve);
        warn(context + " has a JWildfire motion curve of " + curve + ", " + why + "; the value as it stands is used");
      };
      // Which value it animates, and how its y becomes voxflame's value.
      std::optional<std::string> field;
      double low = -kFlameCoefficientLimit, high = kFlameCoefficientLimit, scale = 1.0, offset = 0.0;
      if (curve.ends_with("Curve")) {
        const std::string property = curve.substr(0, curve.size() - 5);
        static const std::array<std::string_view, 6> kCoefficient = {"00", "01", "10", "11", "20", "21"};
        static constexpr std::array<int, 6> kElement = {0, 4, 1, 5, 3, 7};
        if (property == "weight" && !isFinal) {
          field = "weight";
          low = 0.0;
        } else if (property == "color" || property == "opacity") {
          field = property;
          low = 0.0;
          high = 1.0;
        } else if (property == "colorSymmetry") {  // color_speed = (1 − symmetry) / 2
          field = "color_speed";
          low = 0.0;
          high = 1.0;
          scale = -0.5;
          offset = 0.5;
        } else if (const auto target = weightFieldTarget(property)) {
          // A weighting-field value (readWeightField): keyed on the transform's field, which changes
          // nothing while the transform has none, as in JWildfire.
          field = target->path;
          low = target->low;
          high = target->high;
        } else if (property.ends_with("_amount")) {
          const std::string variation = property.substr(0, property.size() - 7);
          if (const VariationInfo* info = variationNamed(withoutCopyMark(variation));
              info && byName.contains(variation))
            if (const auto term = termFor(variation, *info)) field = "variations/" + std::to_string(*term) + "/weight";
        } else {
          for (std::size_t i = 0; i < 6 && !field; ++i) {
            if (property == "xyCoeff" + std::string(kCoefficient[i]))
              field = "affine/" + std::to_string(kElement[i]);
            else if (property == "xyPostCoeff" + std::string(kCoefficient[i]))
              field = "post/" + std::to_string(kElement[i]);
          }
          if (field && planes) {
            leaveOut("which voxflame cannot key on a transform with JWildfire's yz or zx planes");
            continue;
          }
        }
      } else {
        field = variationTarget(curve, termFor);
      }
      if (!field) {
        leaveOut("which voxflame cannot animate");
        continue;
      }
      if (byName.contains(curve + "_parent_curve")) {
        leaveOut("which adds a parent curve voxflame does not read");
        continue;
      }
      std::optional<std::vector<std::pair<double, double>>> points =
          curvePoints(byName, curve, scale, offset, leaveOut);
      if (!points) continue;
      const std::string interpolation =
          byName.contains(curve + "_interpolation") ? byName.at(curve + "_interpolation").value() : "SPLINE";
      MotionChannel& channel = channelFor(*field, low, high);
      if (!channel.points.empty() || !channel.waves.empty()) {
        leaveOut("a second motion of that value");
        continue;
      }
      if (*field == "post/0" || field->starts_with("post/")) x.hasPost = true;
      channel.points = std::move(*points);
      channel.smooth = interpolation != "LINEAR";
      if (interpolation != "LINEAR") approximatedCurves_.insert(interpolation.substr(0, 20));
    }
  }

  // The preset value a JWildfire weighting-field property's curve keys, and its range.
  struct CurveTarget {
    std::string path;
    double low, high;
  };
  static std::optional<CurveTarget> weightFieldTarget(const std::string& property) {
    static const std::array<std::pair<std::string_view, std::string_view>, 11> kTargets = {{
        {"weightingFieldVarAmountIntensity", "field/amount"},
        {"weightingFieldColorIntensity", "field/color"},
        {"weightingFieldJitterIntensity", "field/jitter"},
        {"weightingFieldNoiseFrequency", "field/frequency"},
        {"weightingFieldNoiseSeed", "field/seed"},
        {"weightingFieldFractalNoiseOctaves", "field/octaves"},
        {"weightingFieldFractalNoiseGain", "field/gain"},
        {"weightingFieldFractalNoiseLacunarity", "field/lacunarity"},
        {"weightingFieldVarParam1Intensity", "field/param1_intensity"},
        {"weightingFieldVarParam2Intensity", "field/param2_intensity"},
        {"weightingFieldVarParam3Intensity", "field/param3_intensity"},
    }};
    for (const auto& [name, path] : kTargets) {
      if (property != name) continue;
      if (path == "field/frequency") return CurveTarget{std::string(path), 0.0, kFlameCoefficientLimit};
      if (path == "field/seed") return CurveTarget{std::string(path), -2147483648.0, 2147483647.0};
      if (path == "field/octaves") return CurveTarget{std::string(path), 1.0, kMaxWeightFieldOctaves};
      return CurveTarget{std::string(path), -kFlameCoefficientLimit, kFlameCoefficientLimit};
    }
    return std::nullopt;
  }

  // A JWildfire curve's points (frame, offset + scale · y); nullopt, after leaveOut(why), when
  // they are not whole.
  template <typename LeaveOut>
  std::optional<std::vector<std::pair<double, double>>> curvePoints(
      const std::map<std::string, pugi::xml_attribute, std::less<>>& byName, const std::string& curve, double scale,
      double offset, const LeaveOut& leaveOut) {
    const auto countAttribute = byName.find(curve + "_point_count");
    const auto count = parseNumber(countAttribute == byName.end() ? "" : countAttribute->second.value());
    if (!count || *count != std::floor(*count) || *count < 1.0 || *count > static_cast<double>(kMaxCurvePoints)) {
      leaveOut("whose point_count is not a whole number from 1 to " + std::to_string(kMaxCurvePoints));
      return std::nullopt;
    }
    std::vector<std::pair<double, double>> points;
    std::string bad;
    for (std::size_t i = 0; i < static_cast<std::size_t>(*count) && bad.empty(); ++i) {
      const auto coordinate = [&](const char* axis) -> std::optional<double> {
        const std::string key = curve + "_" + axis + std::to_string(i);
        const auto found = byName.find(key);
        const auto value = found == byName.end() ? std::optional<double>(0.0) : parseNumber(found->second.value());
        if (!value || !finiteWithin(*value, kFlameCoefficientLimit)) bad = key + " is not a number within ±1e6";
        return value;
      };
      const auto frame = coordinate("x"), value = coordinate("y");
      if (!bad.empty()) break;
      if (!points.empty() && *frame <= points.back().first)
        bad = curve + "_x" + std::to_string(i) + " does not come after the point before it";
      points.emplace_back(*frame, offset + scale * *value);
    }
    if (!bad.empty()) {
      leaveOut("whose point " + bad);
      return std::nullopt;
    }
    return points;
  }

  // A JWildfire layer's weight curve, as a curve of voxflame's layer weight (× `factor`, the
  // density's share); the density curve is not keyed.
  void readLayerCurves(const pugi::xml_node& layer, const std::string& context, double factor) {
    std::map<std::string, pugi::xml_attribute, std::less<>> byName;
    for (const pugi::xml_attribute& attribute : layer.attributes()) byName.emplace(nameOf(attribute), attribute);
    for (const std::string& curve : {std::string("weightCurve"), std::string("densityCurve")}) {
      const auto enabled = byName.find(curve + "_enabled");
      if (enabled == byName.end() || std::string_view(enabled->second.value()) != "true") continue;
      const auto leaveOut = [&](const std::string& why) {
        lose("JWildfire layer motion curve " + curve);
        warn("JWildfire " + context + " has a motion curve of its " + curve.substr(0, curve.size() - 5) + ", " + why +
             "; the value as it stands is used");
      };
      if (curve == "densityCurve") {
        leaveOut("which voxflame does not key");
        continue;
      }
      if (byName.contains(curve + "_parent_curve")) {
        leaveOut("which adds a parent curve voxflame does not read");
        continue;
      }
      auto points = curvePoints(byName, curve, factor, 0.0, leaveOut);
      if (!points) continue;
      MotionChannel channel;
      channel.layerField = "weight";
      channel.low = 0.0;
      channel.high = kMaxImportedLayerWeight;
      channel.points = std::move(*points);
      const auto interpolation = byName.find(curve + "_interpolation");
      const std::string kind = interpolation == byName.end() ? "SPLINE" : interpolation->second.value();
      channel.smooth = kind != "LINEAR";
      if (channel.smooth) approximatedCurves_.insert(kind.substr(0, 20));
      pendingChannels_.push_back(std::move(channel));
    }
  }

  // The path below a transform that a motion's `<variation>` or `<variation>_<parameter>` names:
  // its weight or parameter (the longest catalogue name that is a prefix decides, as for the
  // transform's own attributes). The variation joins the transform at weight 0 when absent.
  std::optional<std::string> variationTarget(const std::string& name, const TermFor& termFor) {
    if (const VariationInfo* info = variationNamed(withoutCopyMark(name))) {
      if (const auto term = termFor(name, *info)) return "variations/" + std::to_string(*term) + "/weight";
      return std::nullopt;
    }
    for (std::size_t cut = name.rfind('_');
         cut != std::string::npos && cut > 0 && name.size() - cut <= kMaxParameterSuffix;
         cut = name.rfind('_', cut - 1)) {
      const std::string prefix = name.substr(0, cut), rest = name.substr(cut + 1);
      const VariationInfo* info = variationNamed(withoutCopyMark(prefix));
      if (!info) continue;
      if (info->paramIndex(rest) < 0) return std::nullopt;
      if (const auto term = termFor(prefix, *info)) return "variations/" + std::to_string(*term) + "/" + rest;
      return std::nullopt;
    }
    return std::nullopt;
  }

  MotionChannel& channelFor(const std::string& field, double low, double high) {
    for (MotionChannel& channel : pendingChannels_)
      if (channel.field == field) return channel;
    MotionChannel channel;
    channel.field = field;
    channel.low = low;
    channel.high = high;
    pendingChannels_.push_back(std::move(channel));
    return pendingChannels_.back();
  }

  // The channels the last xform() call found, for readGenome to give their transform.
  std::vector<MotionChannel> takePendingChannels() { return std::exchange(pendingChannels_, {}); }
  const std::set<std::string>& approximatedCurves() const { return approximatedCurves_; }
  // A JWildfire interpolation other than LINEAR, played as Catmull-Rom (named in the motion's warning).
  void noteApproximatedCurve(const std::string& kind) { approximatedCurves_.insert(kind.substr(0, 20)); }
  // Other ways the curves are played that the motion's warning names.
  void noteCurves(std::string note) { curveNotes_.push_back(std::move(note)); }
  const std::vector<std::string>& curveNotes() const { return curveNotes_; }

  void warn(std::string text) { warnings_.push_back(std::move(text)); }

  // The file's own name of an attribute: tolerantXml may have put a stand-in in its place.
  std::string nameOf(const pugi::xml_attribute& attribute) const {
    const auto found = renamed_.find(attribute.name());
    return found == renamed_.end() ? std::string(attribute.name()) : found->second;
  }
  void setRenamed(const std::map<std::string, std::string>* renamed) {
    renamed_ = renamed ? *renamed : decltype(renamed_){};
  }

  // JWildfire's keys that are not variations: motion curves of a transform's values
  // (`colorCurve_*`, `weightCurve_*`, `xyCoeff01Curve_*`, ...) and mirrored translations. Disabled
  // curves change nothing and pass silently; enabled ones and the mirror are named as unsupported.
  bool isJwildfireExtra(const std::string& name, std::string_view value, const std::string& context) {
    if (name == "mirror_pre_post_translations") {
      if (value != "0" && value != "false") {
        lose(name);
        warn(context + " has JWildfire's mirror_pre_post_translations, which voxflame does not support");
      }
      return true;
    }
    // JWildfire's weighting fields: readWeightField reads them.
    if (name.starts_with("wfield_")) return true;
    // Motion curves: readJwildfireCurves reads the enabled ones.
    const std::size_t curve = name.find("Curve_");
    return curve != std::string::npos && curve != 0;
  }
  // Records something of the file that the import does not keep (ImportedFlame::leftOut).
  void lose(std::string what) { lost_.insert(std::move(what)); }

  std::vector<std::string> finishLeftOut() const {
    std::set<std::string> all = lost_;
    for (const std::string& name : unknownVariations_) all.insert("variation " + name);
    return {all.begin(), all.end()};
  }

  std::vector<std::string> finishWarnings() {
    std::vector<std::string> out;
    // Every variation left out, in this one warning. A name that extends a known variation's
    // whose parameters do not include the rest could also be such a parameter of a newer
    // version of that variation: the warning says so.
    if (!unknownVariations_.empty()) {
      std::string list;
      for (const std::string& name : unknownVariations_) {
        list += (list.empty() ? "" : ", ") + name;
        const auto extended = extendedNames_.find(name);
        const VariationInfo* info = extended == extendedNames_.end() ? nullptr : findVariation(extended->second);
        if (info && !info->params.empty()) list += " (or a parameter that voxflame's " + info->name + " does not have)";
      }
      out.push_back("variations voxflame does not know were left out: " + list);
    }
    out.insert(out.end(), warnings_.begin(), warnings_.end());
    if (!weightFields_.empty()) {
      std::string types;
      for (const std::string& type : weightFields_) types += (types.empty() ? "" : ", ") + type;
      out.push_back("JWildfire's weighting fields (" + types +
                    ") scale the variation weights per point (and the colour, jitter and parameters they name) as "
                    "JWildfire's do, with voxflame's noise of the same family standing in for JWildfire's "
                    "FastNoise: the same kind of field at the same frequency, not the same values");
    }
    return out;
  }

  const std::string& where() const { return where_; }
  const FlameImportOptions& options() const { return options_; }

 private:
  std::string where_;
  const FlameImportOptions& options_;
  std::set<std::string> unknownVariations_;
  std::map<std::string, std::string> extendedNames_;  // unknown variation → the known one its name extends
  std::set<std::string> lost_;
  std::map<std::string, std::string> renamed_;
  std::vector<std::string> warnings_;
  std::vector<MotionChannel> pendingChannels_;
  std::set<std::string> approximatedCurves_;  // JWildfire interpolations played as Catmull-Rom
  std::vector<std::string> curveNotes_;
  std::set<std::string> weightFields_;  // JWildfire weighting field types read
};

// --- palettes -------------------------------------------------------------------------------

using Palette = std::array<glm::vec3, kFlamePaletteSize>;  // sRGB, 0–1

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// The layouts of a hex palette block: digits per colour and where red starts among them.
struct HexLayout {
  std::size_t digits;
  std::size_t redAt;
};
constexpr HexLayout kHexRgb{6, 0};     // RRGGBB (Apophysis, Fractorium, JWildfire: format="RGB")
constexpr HexLayout kHexRgba{8, 0};    // RRGGBBAA (format="RGBA"; the alpha is not used)
constexpr HexLayout kHexPadded{8, 2};  // 00RRGGBB (flam3's palette table and its <colors data=>)

// A hex block of colours in `layout`, whitespace anywhere, resampled to kFlamePaletteSize: a file may
// hold any number of colours (JWildfire and Fractorium write fewer or more than 256); colour i of
// the gradient is the block's colours interpolated at i/255 of the way through them. nullopt when
// the block is not whole colours of hex digits.
std::optional<Palette> parseHexPalette(std::string_view text, HexLayout layout) {
  const std::size_t digits = layout.digits;
  std::string hex;
  hex.reserve(text.size());
  for (const char c : text)
    if (c != ' ' && c != '\t' && c != '\n' && c != '\r') hex.push_back(c);
  if (hex.empty() || hex.size() % digits != 0) return std::nullopt;
  const std::size_t count = hex.size() / digits;
  std::vector<glm::vec3> colors(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t start = i * digits + layout.redAt;
    int rgb[3];
    for (int k = 0; k < 3; ++k) {
      const int high = hexDigit(hex[start + 2 * static_cast<std::size_t>(k)]);
      const int low = hexDigit(hex[start + 2 * static_cast<std::size_t>(k) + 1]);
      if (high < 0 || low < 0) return std::nullopt;
      rgb[k] = high * 16 + low;
    }
    colors[i] = glm::vec3(static_cast<float>(rgb[0]), static_cast<float>(rgb[1]), static_cast<float>(rgb[2])) / 255.0f;
  }
  Palette palette;
  for (std::size_t i = 0; i < kFlamePaletteSize; ++i) {
    if (count == kFlamePaletteSize) {
      palette[i] = colors[i];
      continue;
    }
    const double at =
        static_cast<double>(i) / static_cast<double>(kFlamePaletteSize - 1) * static_cast<double>(count - 1);
    const auto low = static_cast<std::size_t>(std::floor(at));
    const std::size_t high = std::min(low + 1, count - 1);
    const auto t = static_cast<float>(at - static_cast<double>(low));
    palette[i] = glm::mix(colors[low], colors[high], t);
  }
  return palette;
}

// flam3 3.x writes its palette rows with printf's "%2x": a byte under 16 is a space and one digit
// (" b41c c 41c17..."), so the spaces are digits, not separators. Its rows are fixed: an indent, then
// 8 colours of 6 columns each. The hex of such a block, its padding read as zeros; nullopt where a
// line is not an indent and 48 columns of hex digits and spaces (the block is not of this kind).
std::optional<std::string> spacePaddedHexRows(std::string_view text) {
  constexpr std::size_t kRowColumns = 8 * 6;
  std::string hex;
  while (!text.empty()) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    std::string_view line = text.substr(0, end);
    text.remove_prefix(std::min(end + 1, text.size()));
    while (!line.empty() && (line.back() == ' ' || line.back() == '\t' || line.back() == '\r')) line.remove_suffix(1);
    const std::size_t indent = line.find_first_not_of(" \t");
    if (indent == std::string_view::npos) continue;  // a blank line
    if (line.size() < kRowColumns) return std::nullopt;
    const std::string_view row = line.substr(line.size() - kRowColumns);
    if (line.substr(0, line.size() - kRowColumns).find_first_not_of(" \t") != std::string_view::npos)
      return std::nullopt;
    for (std::size_t i = 0; i < kRowColumns; ++i) {
      if (row[i] == ' ' && i % 2 == 0) {
        hex.push_back('0');
      } else if (hexDigit(row[i]) >= 0) {
        hex.push_back(row[i]);
      } else {
        return std::nullopt;
      }
    }
  }
  if (hex.empty()) return std::nullopt;
  return hex;
}

// Whether a line of `text` has a space or tab between two of its other characters.
bool hasSpaceWithinARow(std::string_view text) {
  bool inRow = false, gap = false;
  for (const char c : text) {
    if (c == '\n' || c == '\r') {
      inRow = gap = false;
    } else if (c == ' ' || c == '\t') {
      gap = inRow;
    } else {
      if (gap) return true;
      inRow = true;
    }
  }
  return false;
}

// flam3's palette table, read once per path (1.5 MB of XML) and kept for the process.
struct PaletteTable {
  std::map<int, Palette> palettes;
  std::string error;  // why it could not be read, when it could not
};

const PaletteTable& paletteTable(const std::filesystem::path& path) {
  static std::mutex mutex;
  static std::map<std::filesystem::path, PaletteTable> tables;
  const std::lock_guard lock(mutex);
  if (const auto found = tables.find(path); found != tables.end()) return found->second;
  PaletteTable& table = tables[path];
  pugi::xml_document document;
  const pugi::xml_parse_result result = document.load_file(path.c_str());
  if (!result) {
    table.error =
        std::filesystem::exists(path)
            ? "flam3's palette table " + path.string() + " could not be read (" + result.description() + ")"
            : "flam3's palette table " + path.string() + " is missing (Debian's flam3-utils package installs it)";
    return table;
  }
  for (const pugi::xml_node& node : document.child("palettes").children("palette")) {
    const auto number = parseNumber(node.attribute("number").value());
    if (!number || !(*number >= 0.0 && *number < 1e6)) continue;
    if (const auto palette = parseHexPalette(node.attribute("data").value(), kHexPadded))
      table.palettes[static_cast<int>(*number)] = *palette;
  }
  if (table.palettes.empty()) table.error = "flam3's palette table " + path.string() + " holds no palettes";
  return table;
}

// flam3 turns a built-in palette's hues by `hue` of a full turn (the flame's hue attribute).
glm::vec3 rotateHue(glm::vec3 rgb, double turns) {
  const float maxC = std::max({rgb.r, rgb.g, rgb.b}), minC = std::min({rgb.r, rgb.g, rgb.b});
  const float chroma = maxC - minC;
  if (chroma <= 0.0f) return rgb;
  float hue;  // in sixths of a turn
  if (maxC == rgb.r)
    hue = (rgb.g - rgb.b) / chroma;
  else if (maxC == rgb.g)
    hue = 2.0f + (rgb.b - rgb.r) / chroma;
  else
    hue = 4.0f + (rgb.r - rgb.g) / chroma;
  hue = static_cast<float>(std::fmod(hue + 6.0 * turns, 6.0));
  if (hue < 0.0f) hue += 6.0f;
  const float x = chroma * (1.0f - std::abs(std::fmod(hue, 2.0f) - 1.0f));
  glm::vec3 out;
  switch (static_cast<int>(hue)) {
    case 0:
      out = {chroma, x, 0.0f};
      break;
    case 1:
      out = {x, chroma, 0.0f};
      break;
    case 2:
      out = {0.0f, chroma, x};
      break;
    case 3:
      out = {0.0f, x, chroma};
      break;
    case 4:
      out = {x, 0.0f, chroma};
      break;
    default:
      out = {chroma, 0.0f, x};
      break;
  }
  return out + glm::vec3(minC);
}

// A fallback when a flame names no usable palette: flam3's palette 0 is not always at hand, so a
// warm ramp from the named palettes stands in.
Palette fallbackPalette() {
  const Gradient gradient(paletteStops(namedPalettes().front().name));
  Palette palette;
  for (std::size_t i = 0; i < kFlamePaletteSize; ++i)
    palette[i] = linearToSrgb(gradient.at(static_cast<float>(i) / static_cast<float>(kFlamePaletteSize - 1)));
  return palette;
}

Palette readPalette(const pugi::xml_node& flame, FlameReader& reader) {
  // Inline colours: <color index="i" rgb="r g b"/> (0–255), gaps filled from the colour before.
  std::array<bool, kFlamePaletteSize> set{};
  Palette palette;
  palette.fill(glm::vec3(0.0f));
  bool any = false;
  for (const pugi::xml_node& color : flame.children("color")) {
    const auto index = parseNumber(color.attribute("index").value());
    const auto rgb = parseNumbers(color.attribute("rgb").value());
    if (!index || !std::isfinite(*index) || *index < 0.0 || *index > 255.0 || *index != std::floor(*index))
      reader.fail(
          "", std::string("<color index=\"") + color.attribute("index").value() + "\"> needs an index from 0 to 255");
    if (!rgb || rgb->size() != 3 || !std::all_of(rgb->begin(), rgb->end(), [](double v) { return std::isfinite(v); }))
      reader.fail("", "<color index=\"" + std::to_string(static_cast<int>(*index)) +
                          "\"> needs rgb=\"r g b\" with three numbers from 0 to 255");
    const auto i = static_cast<std::size_t>(*index);
    palette[i] = glm::clamp(
        glm::vec3(static_cast<float>((*rgb)[0]), static_cast<float>((*rgb)[1]), static_cast<float>((*rgb)[2])) / 255.0f,
        0.0f, 1.0f);
    set[i] = true;
    any = true;
  }
  if (any) {
    std::size_t first = 0;
    while (!set[first]) ++first;
    for (std::size_t i = 0; i < kFlamePaletteSize; ++i)
      if (!set[i]) palette[i] = palette[i < first ? first : i - 1];
    return palette;
  }
  // Apophysis/Fractorium: <palette count="256" format="RGB">hex</palette>; flam3: <colors data=>.
  for (const char* element : {"palette", "colors"}) {
    const pugi::xml_node block = flame.child(element);
    if (!block) continue;
    const std::string format = block.attribute("format").value();
    const std::string data = block.attribute("data") ? block.attribute("data").value() : block.text().get();
    // Without a format the length tells: 6 digits a colour, or flam3's padded 8.
    const HexLayout layout = format == "RGB"    ? kHexRgb
                             : format == "RGBA" ? kHexRgba
                             : format.empty()   ? (std::string_view(element) == "colors" ? kHexPadded : kHexRgb)
                                                : HexLayout{0, 0};
    if (layout.digits == 0)
      reader.fail("", std::string("<") + element + " format=\"" + format + "\"> is not RGB or RGBA");
    // Rows with spaces inside are flam3 3.x's padded bytes: read as such first (with the spaces
    // dropped, a block whose padding happens to be whole colours would read as shifted colours).
    std::optional<Palette> parsed;
    if (layout.digits == 6 && hasSpaceWithinARow(data))
      if (const std::optional<std::string> padded = spacePaddedHexRows(data)) parsed = parseHexPalette(*padded, layout);
    if (!parsed) parsed = parseHexPalette(data, layout);
    if (!parsed && format.empty()) parsed = parseHexPalette(data, layout.digits == 6 ? kHexPadded : kHexRgb);
    if (!parsed)
      reader.fail("", std::string("<") + element + "> must hold colours as hex digits (" +
                          std::to_string(layout.digits) + " each)");
    return *parsed;
  }
  // flam3's built-in palettes by number, turned by the flame's hue.
  if (const pugi::xml_attribute number = flame.attribute("palette")) {
    const double index = reader.number(number, "", -1.0, 100000.0);
    const PaletteTable& table = paletteTable(reader.options().paletteTable);
    const auto found = table.palettes.find(static_cast<int>(index));
    if (!table.error.empty()) {
      reader.lose("palette " + std::to_string(static_cast<int>(index)));
      reader.warn(table.error + "; palette " + std::to_string(static_cast<int>(index)) +
                  " was replaced by voxflame's '" + namedPalettes().front().name + "'");
    } else if (found == table.palettes.end()) {
      reader.lose("palette " + std::to_string(static_cast<int>(index)));
      reader.warn("flam3 has no palette " + std::to_string(static_cast<int>(index)) + "; voxflame's '" +
                  namedPalettes().front().name + "' stands in");
    } else {
      Palette turned = found->second;
      double hue = 0.0;
      if (const pugi::xml_attribute hueAttribute = flame.attribute("hue"))
        hue = reader.number(hueAttribute, "", -kFlameCoefficientLimit, kFlameCoefficientLimit);
      if (hue != 0.0)
        for (glm::vec3& c : turned) c = rotateHue(c, hue);
      return turned;
    }
    return fallbackPalette();
  }
  reader.warn("the flame has no palette; voxflame's '" + namedPalettes().front().name + "' stands in");
  return fallbackPalette();
}

// JWildfire writes its version as "JWildfire …" (flam3, Apophysis and Fractorium their own), on the
// <flame> or on the <jwf-flame> around it.
bool writtenByJwildfire(const pugi::xml_node& flame) {
  for (pugi::xml_node node = flame; node; node = node.parent()) {
    if (std::string_view(node.name()) == "jwf-flame") return true;
    if (std::string_view(node.attribute("version").as_string()).starts_with("JWildfire")) return true;
  }
  return false;
}

// JWildfire's flame-level features that neither the flat view nor the mesh keeps, named as lost
// when a file turns them on: solid rendering's depth of field and the parts of its 3D camera the flat view does not
// draw (readFlameCurves names the motion curves it leaves out).
bool solidRenderingOn(const pugi::xml_node& flame);  // JWildfire's sld_render_enabled (below)

// JWildfire's depth of field shapes that the flat view draws as bubbles: its snowflake grows a
// crystal (snowflake_wf, not in the catalogue), its brush stroke paints an image and its sub-flame
// renders a flame of its own.
bool unkeptDofShape(std::string_view shape) {
  return shape == "SNOWFLAKE" || shape == "BRUSH_STROKE" || shape == "SUB_FLAME";
}

void reportUnkeptFlameFeatures(const pugi::xml_node& flame, FlameReader& reader) {
  // Solid rendering is kept (readSolid) but for its depth of field, which JWildfire draws after
  // shading (a post blur with bokeh) and the flat view leaves sharp.
  if (solidRenderingOn(flame)) {
    const auto dof = parseNumber(flame.attribute("cam_dof").as_string("0"));
    if (dof && std::isfinite(*dof) && *dof != 0.0) {
      reader.lose("JWildfire solid rendering's depth of field");
      reader.warn("the solid rendering's depth of field (a blur with bokeh after shading) is not drawn; it is sharp");
    }
  }
  // The flat view keeps the 3D camera (readFlat) but for these parts of JWildfire's: three of its
  // depth of field's blur shapes, and its depth dimming.
  std::string camera;
  if (writtenByJwildfire(flame)) {
    const auto set = [&](const char* key) {
      const auto value = parseNumber(flame.attribute(key).as_string("0"));
      return value && *value != 0.0 && std::isfinite(*value);
    };
    const auto add = [&](const std::string& part) { camera += (camera.empty() ? "" : ", ") + part; };
    if (set("cam_dof")) {
      const std::string shape = flame.attribute("cam_dof_shape").as_string("BUBBLE");
      if (unkeptDofShape(shape))
        add("the depth of field's blur shape " + shape + " (drawn as BUBBLE; it needs " +
            (shape == "SNOWFLAKE"   ? "a grown snowflake"
             : shape == "SUB_FLAME" ? "a flame"
                                    : "a brush image") +
            ")");
    }
    if (set("cam_zdimish")) add("depth dimming (cam_zdimish)");
  }
  if (!camera.empty()) {
    reader.lose("3D camera");
    reader.warn(
        "the flame's JWildfire 3D camera has " + camera +
        ", which the flat view does not draw; the camera's turn, perspective and plain depth of field are kept");
  }
}

// --- JWildfire's motion curves of flame values -----------------------------------------------

// A flame value a JWildfire motion curve animates (Flame.java's `<property>Curve`) and where the
// import keeps that value: a path of the scene's flat view or tone, or below every layer (JWildfire's
// post symmetry, which every layer draws through), with the range there. The curves hold the values
// as JWildfire's Flame does: angles in degrees (its file writes cam_pitch, cam_yaw and cam_roll, which
// is camBank, in radians, and camRoll as `rotate`), the rest as the file writes them.
struct FlameCurveTarget {
  std::string_view curve;
  std::string_view path;
  double low, high;
  bool everyLayer = false;  // path is below /layers/N/
  bool magnitude = false;   // the value's size is kept (cam_dof, as readFlat reads it)
};

constexpr std::array<FlameCurveTarget, 24> kFlameCurveTargets = {{
    {"centreXCurve", "/flat/center_x", -1e6, 1e6},
    {"centreYCurve", "/flat/center_y", -1e6, 1e6},
    {"camRollCurve", "/flat/rotate", -3600.0, 3600.0},
    {"camPitchCurve", "/flat/camera_pitch", -360.0, 360.0},
    {"camYawCurve", "/flat/camera_yaw", -360.0, 360.0},
    {"camBankCurve", "/flat/camera_bank", -360.0, 360.0},
    {"camPerspectiveCurve", "/flat/camera_perspective", -1e6, 1e6},
    {"camZCurve", "/flat/camera_z", -1e6, 1e6},
    {"camPosXCurve", "/flat/camera_position/0", -1e6, 1e6},
    {"camPosYCurve", "/flat/camera_position/1", -1e6, 1e6},
    {"camPosZCurve", "/flat/camera_position/2", -1e6, 1e6},
    {"camDOFCurve", "/flat/camera_dof", 0.0, 1e6, false, true},
    {"camDOFScaleCurve", "/flat/camera_dof_scale", 0.0, 1e6},
    {"camDOFFadeCurve", "/flat/camera_dof_fade", 0.0, 1.0},
    {"brightnessCurve", "/tone/brightness", 0.0, 1000.0},
    {"gammaCurve", "/tone/gamma", 0.1, 10.0},
    {"gammaThresholdCurve", "/tone/gamma_threshold", 0.0, 1.0},
    {"vibrancyCurve", "/tone/vibrancy", 0.0, 1.0},
    {"postSymmetryOrderCurve", "flame/post_symmetry/order", 1.0, static_cast<double>(kMaxPostSymmetryOrder), true},
    {"postSymmetryCentreXCurve", "flame/post_symmetry/center_x", -kFlameCoefficientLimit, kFlameCoefficientLimit, true},
    {"postSymmetryCentreYCurve", "flame/post_symmetry/center_y", -kFlameCoefficientLimit, kFlameCoefficientLimit, true},
    {"postSymmetryDistanceCurve", "flame/post_symmetry/distance", -kFlameCoefficientLimit, kFlameCoefficientLimit,
     true},
    {"postSymmetryRotationCurve", "flame/post_symmetry/rotation", -kFlameCoefficientLimit, kFlameCoefficientLimit,
     true},
    // pixelsPerUnitCurve and camZoomCurve: the flat view's scale (readFlameCurves).
    {"pixelsPerUnitCurve", "/flat/scale", 1e-6, 1e6},
}};

// A curve's value at a JWildfire frame, interpolated as its keyframe track will be (times in frames:
// Catmull-Rom with uneven spacing and linear keys are the same curve under finishMotion's affine
// map of frames to seconds).
double curveValueAt(const FlameReader::MotionChannel& channel, double frame) {
  KeyframeTrack track;
  track.interpolation = channel.smooth ? Interpolation::Smooth : Interpolation::Linear;
  const double origin = channel.points.front().first;
  for (const auto& [at, value] : channel.points) track.keys.push_back({at - origin, {value}});
  return evaluateTrack(track, std::max(0.0, frame - origin), track.keys.back().time, false).get<double>();
}

// A number attribute of the flame as readFlat reads it, or `fallback`.
double flameNumber(const pugi::xml_node& flame, const char* key, double fallback) {
  const auto value = parseNumber(flame.attribute(key).as_string(""));
  return value && finiteWithin(*value, kFlameCoefficientLimit) ? *value : fallback;
}

// JWildfire's motion curves of flame values (the camera's, the view's, the tone's, the post
// symmetry's) as channels that finishMotion keys with the transforms' curves, on the paths where
// readFlat, readTone and readPostSymmetry keep the values: flame-wide ones in the first layer's
// channels (they name their scene path), the post symmetry's in every layer's. JWildfire draws with
// pixels per unit × cam_zoom (readFlat's scale): a curve of either keys the flat view's scale with
// the other's value, and curves of both their product, sampled between their points. Curves of
// values voxflame does not have are named and left out.
void readFlameCurves(const pugi::xml_node& flame, FlameReader& reader,
                     std::vector<std::vector<FlameReader::MotionChannel>>& channels) {
  std::map<std::string, pugi::xml_attribute, std::less<>> byName;
  for (const pugi::xml_attribute& attribute : flame.attributes()) byName.emplace(reader.nameOf(attribute), attribute);
  // A curve's parent is written beside it as `parent<hash>Curve_*`: not a value of the flame.
  std::set<std::string, std::less<>> parents;
  for (const auto& [name, attribute] : byName)
    if (name.ends_with("_parent_curve")) parents.insert(attribute.value());
  const bool jwildfire = writtenByJwildfire(flame);
  std::string unkept;
  std::optional<FlameReader::MotionChannel> pixelsPerUnit, zoom;
  for (const auto& [attributeName, attribute] : byName) {
    if (!attributeName.ends_with("Curve_enabled") || std::string_view(attribute.value()) != "true") continue;
    const std::string curve = attributeName.substr(0, attributeName.size() - std::string_view("_enabled").size());
    if (parents.contains(curve)) continue;
    const auto leaveOut = [&](const std::string& why) {
      reader.lose("JWildfire flame motion curve " + curve);
      reader.warn("the flame has a JWildfire motion curve of " + curve + ", " + why +
                  "; the value as it stands is used");
    };
    const auto target = std::find_if(kFlameCurveTargets.begin(), kFlameCurveTargets.end(),
                                     [&](const FlameCurveTarget& t) { return t.curve == curve; });
    if (!jwildfire || (target == kFlameCurveTargets.end() && curve != "camZoomCurve")) {
      reader.lose("JWildfire flame motion curve " + curve);
      unkept += (unkept.empty() ? "" : ", ") + curve;
      continue;
    }
    if (byName.contains(curve + "_parent_curve")) {
      leaveOut("which adds a parent curve voxflame does not read");
      continue;
    }
    auto points = reader.curvePoints(byName, curve, 1.0, 0.0, leaveOut);
    if (!points) continue;
    FlameReader::MotionChannel channel;
    const auto interpolation = byName.find(curve + "_interpolation");
    const std::string kind = interpolation == byName.end() ? "SPLINE" : interpolation->second.value();
    channel.smooth = kind != "LINEAR";
    if (channel.smooth) reader.noteApproximatedCurve(kind);
    channel.points = std::move(*points);
    if (curve == "camZoomCurve") {
      zoom = std::move(channel);
      continue;
    }
    if (curve == "pixelsPerUnitCurve") {
      pixelsPerUnit = std::move(channel);
      continue;
    }
    if (target->magnitude)
      for (auto& point : channel.points) point.second = std::abs(point.second);
    channel.low = target->low;
    channel.high = target->high;
    if (target->everyLayer) {
      channel.layerField = std::string(target->path);
      for (auto& layerChannels : channels) layerChannels.push_back(channel);
    } else {
      channel.scenePath = std::string(target->path);
      channels.front().push_back(std::move(channel));
    }
  }
  if (pixelsPerUnit || zoom) {
    // The flat view's scale: pixels per unit × cam_zoom, each the curve's value or the file's.
    FlameReader::MotionChannel scale;
    if (pixelsPerUnit && zoom) {
      std::set<double> frames;
      for (const auto* channel : {&*pixelsPerUnit, &*zoom})
        for (const auto& point : channel->points) frames.insert(point.first);
      // The product of two interpolated curves is not one through their points: it is sampled
      // between them, within the points a curve may have.
      const std::size_t between =
          std::clamp<std::size_t>(kMaxCurvePoints / frames.size(), 1, kFlameScaleSamplesBetween);
      const std::vector<double> at(frames.begin(), frames.end());
      for (std::size_t i = 0; i < at.size(); ++i)
        for (std::size_t k = 0; k < (i + 1 < at.size() ? between : 1); ++k) {
          const double frame =
              at[i] +
              (i + 1 < at.size() ? (at[i + 1] - at[i]) * static_cast<double>(k) / static_cast<double>(between) : 0.0);
          scale.points.emplace_back(frame, curveValueAt(*pixelsPerUnit, frame) * curveValueAt(*zoom, frame));
        }
      scale.smooth = pixelsPerUnit->smooth || zoom->smooth;
      reader.noteCurves("the flame's pixelsPerUnit and camZoom curves both move its scale: their product is keyed at " +
                        std::to_string(scale.points.size()) + " frames");
    } else if (pixelsPerUnit) {
      scale = std::move(*pixelsPerUnit);
      const double factor = flameNumber(flame, "cam_zoom", 1.0);
      for (auto& point : scale.points) point.second *= factor;
    } else {
      scale = std::move(*zoom);
      const double factor = flameNumber(flame, "scale", FlatViewSettings{}.scale);
      for (auto& point : scale.points) point.second *= factor;
    }
    scale.scenePath = "/flat/scale";
    scale.low = 1e-6;
    scale.high = 1e6;
    channels.front().push_back(std::move(scale));
  }
  if (!unkept.empty())
    reader.warn("the flame animates " + unkept.substr(0, 300) +
                " with JWildfire motion curves, which voxflame has no value for; the values as they stand are used");
}

// --- tone -----------------------------------------------------------------------------------

ToneMapSettings readTone(const pugi::xml_node& flame, FlameReader& reader) {
  // flam3's defaults where the file is silent (they differ from voxflame's: gamma 4).
  ToneMapSettings tone;
  tone.brightness = 4.0;
  tone.gamma = 4.0;
  tone.gammaThreshold = 0.01;
  tone.vibrancy = 1.0;
  tone.highlightPower = -1.0;
  tone.background = glm::vec3(0.0f);
  tone.estimatorRadius = 9.0;
  tone.estimatorMinimum = 0.0;
  tone.estimatorCurve = 0.4;
  // Out-of-range values are brought into voxflame's ranges (scene.cpp's), with a warning.
  const auto key = [&](const char* name, double& target, double low, double high) {
    const pugi::xml_attribute attribute = flame.attribute(name);
    if (!attribute) return;
    const double value = reader.number(attribute, "", -kFlameCoefficientLimit, kFlameCoefficientLimit);
    target = std::clamp(value, low, high);
    if (target != value)
      reader.warn(std::string(name) + " " + formatted(value) + " is outside voxflame's range; " + formatted(target) +
                  " is used");
  };
  key("brightness", tone.brightness, 0.0, 1000.0);
  key("gamma", tone.gamma, 0.1, 10.0);
  key("gamma_threshold", tone.gammaThreshold, 0.0, 1.0);
  key("vibrancy", tone.vibrancy, 0.0, 1.0);
  key("highlight_power", tone.highlightPower, -1.0, 10.0);
  key("estimator_radius", tone.estimatorRadius, 0.0, 50.0);
  key("estimator_minimum", tone.estimatorMinimum, 0.0, 50.0);
  key("estimator_curve", tone.estimatorCurve, 0.01, 5.0);
  // flam3's "estimator" is the radius.
  key("estimator", tone.estimatorRadius, 0.0, 50.0);
  if (tone.estimatorMinimum > tone.estimatorRadius) tone.estimatorMinimum = tone.estimatorRadius;
  if (const pugi::xml_attribute background = flame.attribute("background")) {
    const auto rgb = parseNumbers(background.value());
    if (!rgb || rgb->size() < 3 ||
        !std::all_of(rgb->begin(), rgb->begin() + 3, [](double v) { return finiteWithin(v, 1e6); }))
      reader.fail("", std::string("background=\"") + background.value() + "\" must be three numbers \"r g b\"");
    glm::vec3 srgb(static_cast<float>((*rgb)[0]), static_cast<float>((*rgb)[1]), static_cast<float>((*rgb)[2]));
    // flam3 writes 0–1; a few editors 0–255.
    if (std::max({srgb.r, srgb.g, srgb.b}) > 1.0f) srgb /= 255.0f;
    tone.background = srgbToLinear(glm::clamp(srgb, 0.0f, 1.0f));
  }
  return tone;
}

// --- JWildfire's solid rendering ---------------------------------------------------------------

// JWildfire's own defaults (SolidRenderSettings.setupDefaults), which a file's missing keys keep.
FlatSolidSettings jwildfireSolidDefaults() {
  FlatSolidSettings solid;
  solid.aoEnabled = true;
  solid.lights = {{55.0, -22.0, 0.8, glm::dvec3(1.0), true, 0.8}, {64.0, 55.0, 0.6, glm::dvec3(1.0), false, 0.7}};
  solid.materials = {{0.7, 0.5, 0.6, 24.0, glm::dvec3(1.0), SolidDiffuseResponse::Cosa}};
  return solid;
}

bool solidRenderingOn(const pugi::xml_node& flame) {
  const std::string_view value = flame.attribute("sld_render_enabled").as_string("0");
  return value == "1" || value == "true";
}

// The sld_render_* keys of a JWildfire flame with solid rendering on. A value that is not a number
// keeps JWildfire's default, one out of range is brought into it, each with a warning; a material's
// reflection map (an image file beside JWildfire, not in the flame) is named as lost.
FlatSolidSettings readSolid(const pugi::xml_node& flame, FlameReader& reader) {
  FlatSolidSettings solid = jwildfireSolidDefaults();
  solid.enabled = true;
  const auto number = [&](const std::string& name, double& target, double low, double high) {
    const pugi::xml_attribute attribute = flame.attribute(name.c_str());
    if (!attribute) return false;
    const auto value = parseNumber(attribute.value());
    if (!value || !std::isfinite(*value)) {
      reader.warn(name + "=\"" + std::string(attribute.value()).substr(0, 40) +
                  "\" is not a number; the solid rendering uses JWildfire's default " + formatted(target));
      return false;
    }
    const double kept = std::clamp(*value, low, high);
    if (kept != *value)
      reader.warn(name + " " + formatted(*value) + " is outside voxflame's range; " + formatted(kept) + " is used");
    target = kept;
    return true;
  };
  const auto whole = [&](const std::string& name, int& target, int low, int high) {
    double value = target;
    if (number(name, value, low, high)) target = static_cast<int>(std::lround(value));
  };
  const auto flag = [&](const std::string& name, bool& target) {
    if (const pugi::xml_attribute attribute = flame.attribute(name.c_str())) {
      const std::string_view value = attribute.value();
      target = value == "1" || value == "true";
    }
  };
  // A JWildfire enum by its Java name; an unknown one keeps the default, as JWildfire does.
  const auto named = [&](const std::string& name, std::span<const std::string_view> javaNames, auto& target) {
    const pugi::xml_attribute attribute = flame.attribute(name.c_str());
    if (!attribute) return;
    const std::string_view value = attribute.value();
    const auto found = std::find(javaNames.begin(), javaNames.end(), value);
    if (found == javaNames.end()) {
      reader.warn(name + "=\"" + std::string(value).substr(0, 40) +
                  "\" is not one JWildfire knows; its default is used");
      return;
    }
    target = static_cast<std::remove_reference_t<decltype(target)>>(found - javaNames.begin());
  };
  flag("sld_render_ao_enabled", solid.aoEnabled);
  number("sld_render_ao_intensity", solid.aoIntensity, 0.0, 4.0);
  number("sld_render_ao_search_radius", solid.aoSearchRadius, 0.25, 120.0);
  number("sld_render_ao_blur_radius", solid.aoBlurRadius, 0.25, 10.0);
  whole("sld_render_ao_radius_samples", solid.aoRadiusSamples, 1, 128);
  whole("sld_render_ao_azimuth_samples", solid.aoAzimuthSamples, 1, 128);
  number("sld_render_ao_falloff", solid.aoFalloff, 0.0, 10.0);
  number("sld_render_ao_affect_diffuse", solid.aoAffectDiffuse, 0.0, 1.0);
  static constexpr std::string_view kShadowTypes[] = {"OFF", "FAST", "SMOOTH"};
  named("sld_render_shadow_type", kShadowTypes, solid.shadowType);
  number("sld_render_shadow_smooth_radius", solid.shadowSmoothRadius, 0.0, 100.0);
  whole("sld_render_shadowmap_size", solid.shadowmapSize, 64, 8192);
  number("sld_render_shadowmap_bias", solid.shadowmapBias, 0.0, 100.0);

  constexpr int kMaxEntries = 64;
  int materials = -1, lights = -1;
  whole("sld_render_material_count", materials, 0, kMaxEntries);
  whole("sld_render_ligtht_count", lights, 0, kMaxEntries);  // sic: JWildfire's spelling
  std::vector<std::string> reflectionMaps;
  if (materials >= 0) {
    solid.materials.assign(static_cast<std::size_t>(materials), SolidMaterial{});
    for (int i = 0; i < materials; ++i) {
      SolidMaterial& m = solid.materials[static_cast<std::size_t>(i)];
      m.phongColor = glm::dvec3(0.0);  // JWildfire's MaterialSettings starts without a highlight colour
      const std::string n = std::to_string(i);
      number("sld_render_material_diffuse" + n, m.diffuse, 0.0, 100.0);
      number("sld_render_material_ambient" + n, m.ambient, 0.0, 100.0);
      number("sld_render_material_phong" + n, m.phong, 0.0, 100.0);
      number("sld_render_material_phong_size" + n, m.phongSize, 0.0, 10000.0);
      number("sld_render_material_phong_red" + n, m.phongColor.r, 0.0, 100.0);
      number("sld_render_material_phong_green" + n, m.phongColor.g, 0.0, 100.0);
      number("sld_render_material_phong_blue" + n, m.phongColor.b, 0.0, 100.0);
      static constexpr std::string_view kResponses[] = {"COSA", "COSA_SQUARE", "COSA_HALVE", "COSA_HALVE_SQUARE"};
      named("sld_render_material_light_diif_func" + n, kResponses, m.diffuseResponse);
      const std::string map = flame.attribute(("sld_render_material_refl_map_filename" + n).c_str()).as_string("");
      double mapIntensity = 0.5;
      number("sld_render_material_refl_map_intensity" + n, mapIntensity, 0.0, 100.0);
      if (!map.empty() && mapIntensity > 0.0) reflectionMaps.push_back(n);
    }
  }
  if (lights >= 0) {
    solid.lights.assign(static_cast<std::size_t>(lights), SolidLight{});
    for (int i = 0; i < lights; ++i) {
      SolidLight& l = solid.lights[static_cast<std::size_t>(i)];
      // JWildfire's DistantLight starts at altitude and azimuth 0, black, casting shadows.
      l = {0.0, 0.0, 0.5, glm::dvec3(0.0), true, 0.8};
      const std::string n = std::to_string(i);
      number("sld_render_light_altitude" + n, l.altitudeDeg, -3600.0, 3600.0);
      number("sld_render_light_azimuth" + n, l.azimuthDeg, -3600.0, 3600.0);
      number("sld_render_light_intensity" + n, l.intensity, 0.0, 100.0);
      number("sld_render_light_red" + n, l.color.r, 0.0, 100.0);
      number("sld_render_light_green" + n, l.color.g, 0.0, 100.0);
      number("sld_render_light_blue" + n, l.color.b, 0.0, 100.0);
      flag("sld_render_light_shadows" + n, l.castShadows);
      number("sld_render_light_shadow_intensity" + n, l.shadowIntensity, 0.0, 1.0);
    }
  }
  if (!reflectionMaps.empty()) {
    std::string which;
    for (const std::string& n : reflectionMaps) which += (which.empty() ? "" : ", ") + n;
    reader.lose("JWildfire solid rendering's reflection maps");
    reader.warn("the solid rendering's material" + std::string(reflectionMaps.size() == 1 ? " " : "s ") + which +
                " reflect" + (reflectionMaps.size() == 1 ? "s" : "") +
                " an image file that is not part of the flame; the reflection is left out");
  }
  return solid;
}

// --- the 2D framing -------------------------------------------------------------------------

// flam3's framing of the flame (FlatViewSettings' defaults are flam3's). Values outside the
// preset's ranges are brought into them with a warning, as the tone keys are.
FlatViewSettings readFlat(const pugi::xml_node& flame, FlameReader& reader, bool cameraAnimated) {
  FlatViewSettings flat;
  const auto clamped = [&](const char* name, double value, double low, double high) {
    const double kept = std::clamp(value, low, high);
    if (kept != value)
      reader.warn(std::string(name) + " " + formatted(value) + " is outside voxflame's range; " + formatted(kept) +
                  " is used");
    return kept;
  };
  // The framing only matters to the flat view: a value that is not a number (real files have
  // center="nan nan") keeps flam3's default with a warning instead of refusing the flame.
  const auto unusable = [&](const pugi::xml_attribute& attribute, const char* what) {
    reader.warn(std::string(attribute.name()) + "=\"" + attribute.value() + "\" is not " + what +
                "; the flat view uses flam3's default");
  };
  const auto key = [&](const char* name, double& target, double low, double high) {
    const pugi::xml_attribute attribute = flame.attribute(name);
    if (!attribute) return false;
    const auto value = parseNumbers(attribute.value());
    if (!value || value->size() != 1 || !finiteWithin(value->front(), kFlameCoefficientLimit)) {
      unusable(attribute, "a number");
      return false;
    }
    target = clamped(name, value->front(), low, high);
    return true;
  };
  const auto pair = [&](const char* name) -> std::optional<std::array<double, 2>> {
    const pugi::xml_attribute attribute = flame.attribute(name);
    if (!attribute) return std::nullopt;
    const auto values = parseNumbers(attribute.value());
    if (!values || values->size() < 2 || !finiteWithin((*values)[0], kFlameCoefficientLimit) ||
        !finiteWithin((*values)[1], kFlameCoefficientLimit)) {
      unusable(attribute, "two numbers");
      return std::nullopt;
    }
    return std::array<double, 2>{(*values)[0], (*values)[1]};
  };
  if (const auto size = pair("size")) {
    flat.width = static_cast<int>(std::lround(clamped("width", (*size)[0], 1.0, 65536.0)));
    flat.height = static_cast<int>(std::lround(clamped("height", (*size)[1], 1.0, 65536.0)));
  }
  if (const auto center = pair("center")) {
    flat.centerX = clamped("center x", (*center)[0], -1e6, 1e6);
    flat.centerY = clamped("center y", (*center)[1], -1e6, 1e6);
  }
  key("scale", flat.scale, 1e-6, 1e6);
  key("zoom", flat.zoom, -30.0, 30.0);
  key("rotate", flat.rotateDeg, -3600.0, 3600.0);
  double oversample = flat.oversample;
  // Old flam3 files say supersample; Apophysis writes oversample.
  if (key("supersample", oversample, 1.0, 4.0) || key("oversample", oversample, 1.0, 4.0))
    flat.oversample = static_cast<int>(std::lround(oversample));
  key("filter", flat.filterRadius, 0.0, 10.0);
  key("quality", flat.quality, 1e-3, 1e6);
  if (const pugi::xml_attribute mode = flame.attribute("palette_mode")) {
    const std::string_view value = mode.value();
    if (value == "linear")
      flat.paletteMode = PaletteMode::Linear;
    else if (value != "step")  // flam3 warns and steps
      reader.warn("palette_mode '" + std::string(value) +
                  "' is not step or linear; the flat view steps, as flam3 does");
  }
  // The 3D camera (angles in radians in the files): Apophysis 3D's and Fractorium's, or JWildfire's,
  // which has more (FlatCamera in flat_render.h).
  const auto angle = [&](const char* name, double& degrees) {
    double radians = 0.0;
    if (!key(name, radians, -kFlameCoefficientLimit, kFlameCoefficientLimit)) return;
    // A whole turn more or less is the same camera; the preset keeps −360° to 360°.
    degrees = std::remainder(radians, 2.0 * std::numbers::pi) * 180.0 / std::numbers::pi;
  };
  if (!writtenByJwildfire(flame)) {
    double pitch = 0.0, yaw = 0.0;
    if (key("cam_pitch", pitch, -2.0 * std::numbers::pi, 2.0 * std::numbers::pi))
      flat.cameraPitchDeg = pitch * 180.0 / std::numbers::pi;
    if (key("cam_yaw", yaw, -2.0 * std::numbers::pi, 2.0 * std::numbers::pi))
      flat.cameraYawDeg = yaw * 180.0 / std::numbers::pi;
    key("cam_persp", flat.cameraPerspective, -1e6, 1e6);
    key("cam_zpos", flat.cameraZ, -1e6, 1e6);
    key("cam_dof", flat.cameraDof, 0.0, 1e6);
  } else {
    // JWildfire's cam_zoom multiplies its pixels per unit (FlameRendererView.initView) and nothing
    // else: its sample count and log density scale with the image, as the flat view's do with scale.
    double zoom = 1.0;
    if (key("cam_zoom", zoom, 1e-6, 1e6)) flat.scale = std::clamp(flat.scale * zoom, 1e-6, 1e6);
    FlatViewSettings camera = flat;
    camera.cameraModel = FlatCameraModel::Jwildfire;
    angle("cam_pitch", camera.cameraPitchDeg);
    angle("cam_yaw", camera.cameraYawDeg);
    angle("cam_roll", camera.cameraBankDeg);  // JWildfire's bank; its roll is `rotate`
    // JWildfire reads cam_perspective (older files) after cam_persp.
    key("cam_persp", camera.cameraPerspective, -1e6, 1e6);
    key("cam_perspective", camera.cameraPerspective, -1e6, 1e6);
    key("cam_zpos", camera.cameraZ, -1e6, 1e6);
    key("cam_pos_x", camera.cameraPosition.x, -1e6, 1e6);
    key("cam_pos_y", camera.cameraPosition.y, -1e6, 1e6);
    key("cam_pos_z", camera.cameraPosition.z, -1e6, 1e6);
    // A negative cam_dof blurs as its size does (the blur's direction is drawn at random).
    if (double dof = 0.0; key("cam_dof", dof, -1e6, 1e6)) camera.cameraDof = std::abs(dof);
    key("cam_dof_scale", camera.cameraDofScale, 0.0, 1e6);
    key("cam_dof_fade", camera.cameraDofFade, 0.0, 1.0);
    // JWildfire's depth of field about a focus point (its reader takes new_dof="1" alone as on).
    camera.cameraDofNew = std::string_view(flame.attribute("new_dof").as_string()) == "1";
    key("cam_xfocus", camera.cameraDofFocus.x, -1e6, 1e6);
    key("cam_yfocus", camera.cameraDofFocus.y, -1e6, 1e6);
    key("cam_zfocus", camera.cameraDofFocus.z, -1e6, 1e6);
    key("cam_dof_area", camera.cameraDofArea, -1e6, 1e6);
    key("cam_dof_exponent", camera.cameraDofExponent, 1e-3, 1e3);
    // The blur's shape: JWildfire's names in capitals. Its reader takes an unknown name as BUBBLE;
    // the shapes the flat view does not draw (reportUnkeptFlameFeatures names them) are drawn as
    // bubbles too.
    if (const pugi::xml_attribute shape = flame.attribute("cam_dof_shape")) {
      std::string name = shape.value();
      std::transform(name.begin(), name.end(), name.begin(),
                     [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      const auto known = std::find(std::begin(kFlatDofShapeNames), std::end(kFlatDofShapeNames), name);
      if (known != std::end(kFlatDofShapeNames))
        camera.cameraDofShape = static_cast<FlatDofShape>(known - std::begin(kFlatDofShapeNames));
      else if (!unkeptDofShape(shape.value()))
        reader.warn("cam_dof_shape \"" + std::string(shape.value()).substr(0, 40) +
                    "\" is not one of JWildfire's; its depth of field is drawn as BUBBLE, as JWildfire does");
    }
    key("cam_dof_rotate", camera.cameraDofRotateDeg, -3600.0, 3600.0);
    key("cam_dof_param1", camera.cameraDofParam1, -1e6, 1e6);
    key("cam_dof_param2", camera.cameraDofParam2, -1e6, 1e6);
    key("cam_dof_param3", camera.cameraDofParam3, -1e6, 1e6);
    key("cam_dof_param4", camera.cameraDofParam4, -1e6, 1e6);
    key("cam_dof_param5", camera.cameraDofParam5, -1e6, 1e6);
    key("cam_dof_param6", camera.cameraDofParam6, -1e6, 1e6);
    // Without a 3D camera JWildfire draws the flame flat, turned about the centre as flam3 does:
    // nothing of the camera is kept then, unless a motion curve moves it.
    if (camera.hasCamera() || cameraAnimated) flat = camera;
  }
  if (solidRenderingOn(flame)) flat.solid = readSolid(flame, reader);
  if (const pugi::xml_attribute shape = flame.attribute("filter_shape");
      shape && std::string_view(shape.value()) != "gaussian") {
    reader.warn(std::string("the spatial filter '") + shape.value() + "' is drawn as flam3's gaussian");
  }
  return flat;
}

// --- the flame ------------------------------------------------------------------------------

FlameSymmetry symmetryOfKind(double kind, FlameReader& reader) {
  if (kind != std::floor(kind) || std::abs(kind) > kMaxFlameSymmetry)
    reader.fail("", "symmetry kind " + formatted(kind) + " must be a whole number from −" +
                        std::to_string(kMaxFlameSymmetry) + " to " + std::to_string(kMaxFlameSymmetry));
  FlameSymmetry symmetry;
  const int n = static_cast<int>(kind);
  symmetry.rotational = std::max(1, std::abs(n));
  symmetry.mirror = n < 0;  // flam3: negative kinds add a mirror
  return symmetry;
}

// The transforms and final transform of one genome: a <flame>, or one <layer> of a JWildfire
// <jwf-flame> (`context` then names the layer in messages: "layer 2, transform 0").
using MotionChannel = FlameReader::MotionChannel;

FlameGenome readGenome(const pugi::xml_node& body, const std::string& context, FlameReader& reader,
                       std::vector<MotionChannel>& channels) {
  FlameGenome genome;
  const auto tagChannels = [&](std::size_t xform, bool isFinal) {
    for (MotionChannel& channel : reader.takePendingChannels()) {
      channel.xform = xform;
      channel.isFinal = isFinal;
      channels.push_back(std::move(channel));
    }
  };
  const std::string prefix = context.empty() ? "" : context + ", ";
  std::size_t index = 0;
  for (const pugi::xml_node& child : body.children("xform")) {
    if (index >= kMaxFlameXforms)
      reader.fail(context, "has more than " + std::to_string(kMaxFlameXforms) + " transforms; voxflame takes at most " +
                               std::to_string(kMaxFlameXforms));
    genome.xforms.push_back(reader.xform(child, prefix + "transform " + std::to_string(index), false));
    tagChannels(index, false);
    ++index;
  }
  if (genome.xforms.empty()) reader.fail(context, "has no transforms (<xform> elements); there is nothing to draw");
  // Xaos lists longer than the transforms (Fr0st writes trailing ones) are trimmed; a list of 1s
  // is no xaos at all.
  for (std::size_t i = 0; i < genome.xforms.size(); ++i) {
    std::vector<double>& xaos = genome.xforms[i].xaos;
    if (xaos.size() > genome.xforms.size()) {
      if (std::any_of(xaos.begin() + static_cast<std::ptrdiff_t>(genome.xforms.size()), xaos.end(),
                      [](double v) { return v != 1.0; }))
        reader.warn(prefix + "transform " + std::to_string(i) +
                    " has more xaos factors than the flame has transforms; the extra ones were left out");
      xaos.resize(genome.xforms.size());
    }
    if (std::all_of(xaos.begin(), xaos.end(), [](double v) { return v == 1.0; })) xaos.clear();
  }
  double total = 0.0;
  for (const FlameXform& x : genome.xforms) total += x.weight;
  if (!(total > 0.0)) reader.fail(context, "has only transforms of weight 0; at least one needs a positive weight");
  if (const pugi::xml_node finalNode = body.child("finalxform")) {
    genome.hasFinal = true;
    genome.finalXform = reader.xform(finalNode, prefix + "final transform", true);
    tagChannels(0, true);
    // JWildfire applies several final transforms one after the other.
    std::size_t finalNumber = 1;
    for (pugi::xml_node node = finalNode.next_sibling("finalxform"); node; node = node.next_sibling("finalxform")) {
      if (genome.chainedFinals.size() == kMaxChainedFinals) {
        reader.lose("final transforms after the " + std::to_string(kMaxChainedFinals + 1) + "th");
        reader.warn(context + " chains more than " + std::to_string(kMaxChainedFinals + 1) +
                    " final transforms; the rest were left out");
        break;
      }
      const std::string where = prefix + "final transform " + std::to_string(++finalNumber);
      genome.chainedFinals.push_back(reader.xform(node, where, true));
      // Keyframes reach the final transform, not those chained after it.
      if (!reader.takePendingChannels().empty()) {
        reader.lose("motion of chained final transforms");
        reader.warn(where +
                    " is animated, which voxflame does not keyframe on a chained final transform; it "
                    "stands still");
      }
    }
  }
  return genome;
}

std::vector<GradientStop> gradientOf(const Palette& palette) {
  std::vector<GradientStop> gradient;
  gradient.reserve(kFlamePaletteSize);
  for (std::size_t i = 0; i < kFlamePaletteSize; ++i)
    gradient.push_back({static_cast<float>(i) / static_cast<float>(kFlamePaletteSize - 1), srgbToLinear(palette[i])});
  return gradient;
}

// JWildfire's layer weight and density as voxflame's layer weight. JWildfire iterates every
// visible layer equally often into one histogram, each point's colour scaled by its layer's
// weight, and skips a layer's iteration with probability 1 − density² when density < 1. voxflame's
// weight is a layer's share of the iterations, whose colours are summed per voxel: where layers
// overlap, both blend the colours in proportion to weight × hits, and a heavier layer is brighter.
double jwildfireLayerWeight(const pugi::xml_node& layer, const std::string& context, FlameReader& reader) {
  double weight = 1.0;
  if (const pugi::xml_attribute attribute = layer.attribute("weight"))
    weight = reader.number(attribute, context, 0.0, kFlameCoefficientLimit);
  if (const pugi::xml_attribute attribute = layer.attribute("density")) {
    const double density = reader.number(attribute, context, 0.0, kFlameCoefficientLimit);
    if (density < 1.0) weight *= density * density;
  }
  return weight;
}

// --- motion as keyframes ----------------------------------------------------------------------

// flam3's motion functions (interpolation.c's motion_funcs) and Fractorium's saw: periodic in t,
// 0 at whole t, peaks ±1 (hill: 0 to 1).
double motionFunction(char function, double t) {
  switch (function) {
    case 't': {
      const double fr = t - std::floor(t);
      return fr <= 0.25 ? 4.0 * fr : fr <= 0.75 ? 2.0 - 4.0 * fr : 4.0 * fr - 4.0;
    }
    case 'h':
      return (1.0 - std::cos(2.0 * std::numbers::pi * t)) * 0.5;
    case 'w':
      return 2.0 * (t - std::floor(t + 0.5));
    default:
      return std::sin(2.0 * std::numbers::pi * t);
  }
}

// The value a channel animates, as the transform holds it.
double channelBase(const FlameXform& x, const std::string& field) {
  if (field == "weight") return x.weight;
  if (field.starts_with("field/")) {
    const std::string key = field.substr(6);
    if (key == "amount") return x.fieldAmount;
    if (key == "color") return x.fieldColor;
    if (key == "jitter") return x.fieldJitter;
    if (key == "frequency") return x.fieldFrequency;
    if (key == "seed") return x.fieldSeed;
    if (key == "octaves") return x.fieldOctaves;
    if (key == "gain") return x.fieldGain;
    if (key == "lacunarity") return x.fieldLacunarity;
    if (key == "param1_intensity") return x.fieldParam1Intensity;
    if (key == "param2_intensity") return x.fieldParam2Intensity;
    return x.fieldParam3Intensity;
  }
  if (field == "color") return x.color;
  if (field == "color_speed") return x.colorSpeed;
  if (field == "opacity") return x.opacity;
  const std::size_t slash = field.find('/');
  const std::string head = field.substr(0, slash), rest = field.substr(slash + 1);
  if (head == "affine") return x.affine.m.at(std::stoul(rest));
  if (head == "post") return x.post.m.at(std::stoul(rest));
  // variations/K/weight or variations/K/PARAM
  const std::size_t second = rest.find('/');
  const VariationTerm& term = x.variations.at(std::stoul(rest.substr(0, second)));
  const std::string key = rest.substr(second + 1);
  if (key == "weight") return term.weight;
  const VariationInfo* info = findVariation(term.name);
  const int index = info ? info->paramIndex(key) : -1;
  return index >= 0 && static_cast<std::size_t>(index) < term.params.size()
             ? term.params[static_cast<std::size_t>(index)]
             : 0.0;
}

// How motion times map to seconds: flam3's loop, JWildfire's frames.
struct MotionTiming {
  double loopSeconds = kFlam3LoopFrames / kFlam3LoopFps;
  bool loop = true;          // only flam3 motion: the animation loops
  double fps = 30.0;         // JWildfire's frames per second
  double originFrame = 1.0;  // the JWildfire frame shown at 0 s
};

struct MotionNotes {
  std::size_t flam3 = 0, curves = 0;
  bool clamped = false, linearWaves = false, linearised = false;
};

// One channel as a keyframe track of layer `layer`.
KeyframeTrack motionTrack(const FlameGenome& genome, const MotionChannel& channel, std::size_t layer,
                          const MotionTiming& timing, MotionNotes& notes) {
  const FlameXform& x = channel.isFinal ? genome.finalXform : genome.xforms.at(channel.xform);
  KeyframeTrack track;
  track.path =
      !channel.scenePath.empty()
          ? channel.scenePath
          : "/layers/" + std::to_string(layer) + "/" +
                (!channel.layerField.empty()
                     ? channel.layerField
                     : "flame/" + (channel.isFinal ? std::string("final") : "xforms/" + std::to_string(channel.xform)) +
                           "/" + channel.field);
  track.kind = KeyKind::Number;
  const auto keep = [&](double v) {
    const double kept = std::clamp(v, channel.low, channel.high);
    notes.clamped |= kept != v;
    return kept;
  };
  if (!channel.points.empty()) {
    ++notes.curves;
    track.interpolation = channel.smooth ? Interpolation::Smooth : Interpolation::Linear;
    for (const auto& [frame, value] : channel.points)
      track.keys.push_back({std::max(0.0, (frame - timing.originFrame) / timing.fps), {keep(value)}});
    // Frames before the origin all land at 0 s: the latest of them stands there.
    while (track.keys.size() > 1 && track.keys[1].time <= track.keys[0].time) track.keys.erase(track.keys.begin());
    return track;
  }
  ++notes.flam3;
  int frequency = 1;
  bool smooth = true;
  for (const FlameReader::MotionWave& wave : channel.waves) {
    frequency = std::max(frequency, std::abs(wave.frequency));
    smooth &= wave.function == 's' || wave.function == 'h';
  }
  notes.linearWaves |= !smooth;
  track.interpolation = smooth ? Interpolation::Smooth : Interpolation::Linear;
  const std::size_t perLoop =
      std::min(kMaxWaveKeys,
               static_cast<std::size_t>(frequency) * static_cast<std::size_t>(kMaxKeysPerPeriod / (smooth ? 2 : 1)));
  const double base = channelBase(x, channel.field);
  for (std::size_t k = 0; k < perLoop + (timing.loop ? 0 : 1); ++k) {
    const double t = static_cast<double>(k) / static_cast<double>(perLoop);
    double value = base;
    for (const FlameReader::MotionWave& wave : channel.waves)
      value += wave.amplitude * motionFunction(wave.function, wave.frequency * t);
    track.keys.push_back({t * timing.loopSeconds, {keep(value)}});
  }
  return track;
}

PatternLayer importedFlameLayer(const FlameGenome& genome, const std::vector<GradientStop>& palette, double weight) {
  PatternLayer layer;
  layer.kind = PatternKind::Flame;
  layer.attractor.clear();
  layer.params.clear();
  layer.flame = genome;
  layer.weight = weight;
  layer.color.mode = ColorMode::Index;
  layer.color.palette.clear();
  layer.color.gradient = palette;
  return layer;
}

// The flame's motion as keyframes (ImportedFlame::keyframes): every track is checked as a preset's
// would be, and one that fails (a value its variation refuses somewhere in the motion) is left
// out with the reason.
void finishMotion(ImportedFlame& flame, const std::vector<std::vector<MotionChannel>>& channels,
                  const pugi::xml_node& node, FlameReader& reader) {
  bool anyCurve = false, anyWave = false;
  double firstFrame = 1.0;
  for (const auto& layerChannels : channels)
    for (const MotionChannel& channel : layerChannels) {
      anyCurve |= !channel.points.empty();
      anyWave |= channel.points.empty();
      if (!channel.points.empty()) firstFrame = std::min(firstFrame, channel.points.front().first);
    }
  if (!anyCurve && !anyWave) return;
  MotionTiming timing;
  timing.loop = !anyCurve;
  timing.originFrame = firstFrame;
  if (const pugi::xml_attribute fps = node.attribute("fps")) {
    const auto value = parseNumber(fps.value());
    if (value && *value >= 1.0 && *value <= 240.0)
      timing.fps = *value;
    else
      reader.warn(std::string("fps=\"") + std::string(fps.value()).substr(0, 40) +
                  "\" is not a frame rate from 1 to 240; the motion curves play at 30 fps");
  }
  MotionNotes notes;
  std::vector<KeyframeTrack> tracks;
  std::vector<FlameGenome*> genomes = {&flame.genome};
  for (ImportedFlameLayer& other : flame.otherLayers) genomes.push_back(&other.genome);
  for (std::size_t layer = 0; layer < channels.size() && layer < genomes.size(); ++layer)
    for (const MotionChannel& channel : channels[layer])
      tracks.push_back(motionTrack(*genomes[layer], channel, layer, timing, notes));

  AnimationSettings animation;
  animation.loop = timing.loop;
  animation.fps = timing.loop ? kFlam3LoopFps : timing.fps;
  double end = timing.loop ? timing.loopSeconds : 0.0;
  for (const KeyframeTrack& track : tracks) end = std::max(end, track.keys.back().time);
  if (const pugi::xml_attribute frames = node.attribute("frame_count"); frames && !timing.loop) {
    const auto count = parseNumber(frames.value());
    if (count && *count >= 1.0 && *count <= 1e6)
      end = std::max(end, std::min(kMaxAnimationSeconds, (*count - timing.originFrame) / timing.fps));
  }
  animation.duration = std::min(end, kMaxAnimationSeconds);
  if (const pugi::xml_attribute frame = node.attribute("frame"); frame && !timing.loop) {
    const auto value = parseNumber(frame.value());
    if (value && std::isfinite(*value))
      animation.time = std::clamp((*value - timing.originFrame) / timing.fps, 0.0, animation.duration);
  }

  // Each track alone in the scene the import makes.
  Scene check;
  check.tone = flame.tone;
  check.flat = flame.flat;
  check.layers = {importedFlameLayer(flame.genome, flame.palette, flame.weight)};
  for (const ImportedFlameLayer& other : flame.otherLayers)
    check.layers.push_back(importedFlameLayer(other.genome, other.palette, other.weight));
  check.animation = animation;
  std::size_t keys = 0;
  for (KeyframeTrack& track : tracks) {
    if (flame.keyframes.size() >= kMaxMotionTracks || keys + track.keys.size() > kMaxMotionKeys) {
      reader.lose("motion of " + track.path);
      reader.warn("the motion of " + track.path + " was left out: an imported flame's motion keeps to " +
                  std::to_string(kMaxMotionTracks) + " tracks and " + std::to_string(kMaxMotionKeys) + " keys");
      continue;
    }
    // A smooth track whose curve overshoots its value's range (a colour near 1) is keyed
    // linearly instead, through the same keys.
    std::string refused;
    for (int attempt = 0; attempt < 2; ++attempt) {
      check.keyframes = {track};
      try {
        checkKeyframeTracks(check, "the motion");
        refused.clear();
        break;
      } catch (const Error& e) {
        refused = e.what();
        if (track.interpolation == Interpolation::Linear) break;
        track.interpolation = Interpolation::Linear;
        notes.linearised = true;
      }
    }
    if (!refused.empty()) {
      reader.lose("motion of " + track.path);
      reader.warn(refused + "; the motion of " + track.path + " was left out");
      continue;
    }
    keys += track.keys.size();
    flame.keyframes.push_back(std::move(track));
  }
  if (flame.keyframes.empty()) return;
  flame.animation = animation;
  std::ostringstream say;
  say.precision(3);
  if (notes.flam3 > 0) {
    say << "flam3's <motion> became " << notes.flam3 << " keyframe track" << (notes.flam3 == 1 ? "" : "s")
        << (timing.loop ? ", a loop of " : " over ") << timing.loopSeconds << " s (" << kFlam3LoopFrames
        << " frames at " << kFlam3LoopFps
        << " fps, voxflame's choice) adding each motion's periodic offset to the value; flam3's turn of transforms "
           "marked animate=\"1\" over the loop is not keyed";
    if (notes.linearWaves)
      say << "; triangle and saw motions are keyed linearly at " << kMaxKeysPerPeriod
          << " keys a period (saw's jump becomes a steep ramp)";
  }
  if (notes.curves > 0) {
    say << (notes.flam3 > 0 ? "; " : "") << "JWildfire's motion curves became " << notes.curves << " keyframe track"
        << (notes.curves == 1 ? "" : "s") << " (frame f at (f − " << timing.originFrame << ") / " << timing.fps
        << " s)";
    if (!reader.approximatedCurves().empty()) {
      std::string kinds;
      for (const std::string& kind : reader.approximatedCurves()) kinds += (kinds.empty() ? "" : ", ") + kind;
      say << "; its " << kinds
          << " curves are played as Catmull-Rom curves through the same points, an approximation of JWildfire's";
    }
    for (const std::string& note : reader.curveNotes()) say << "; " << note;
  }
  if (notes.clamped) say << "; values beyond voxflame's ranges are held at their ends";
  if (notes.linearised) say << "; smooth tracks that would overshoot their value's range are keyed linearly";
  reader.warn(say.str());
}

// JWildfire's post symmetry (post_symmetry_*, flame.h's FlamePostSymmetry). As JWildfire reads it, an
// unknown kind is none and an order beyond 64 is 64; a value that is not a usable number keeps
// JWildfire's default, with a warning.
FlamePostSymmetry readPostSymmetry(const pugi::xml_node& flame, FlameReader& reader) {
  FlamePostSymmetry post;
  const pugi::xml_attribute kind = flame.attribute("post_symmetry_type");
  if (!kind) return post;
  const std::string_view name = kind.value();
  if (name == "POINT")
    post.kind = PostSymmetryKind::Point;
  else if (name == "X_AXIS")
    post.kind = PostSymmetryKind::XAxis;
  else if (name == "Y_AXIS")
    post.kind = PostSymmetryKind::YAxis;
  else if (name != "NONE")
    reader.warn("post_symmetry_type \"" + std::string(name.substr(0, 40)) +
                "\" is not one of JWildfire's (NONE, POINT, X_AXIS, Y_AXIS); as JWildfire does, the flame has none");
  const auto value = [&](const char* key, double& target) {
    const pugi::xml_attribute attribute = flame.attribute(key);
    if (!attribute) return;
    const auto number = parseNumber(attribute.value());
    if (number && std::isfinite(*number) && std::abs(*number) <= kFlameCoefficientLimit)
      target = *number;
    else
      reader.warn(std::string(key) + "=\"" + std::string(std::string_view(attribute.value()).substr(0, 40)) +
                  "\" is not a number within ±1e6; JWildfire's default " + formatted(target) + " is used");
  };
  double order = post.order;
  value("post_symmetry_order", order);
  post.order = static_cast<int>(std::clamp(std::trunc(order), 1.0, static_cast<double>(kMaxPostSymmetryOrder)));
  value("post_symmetry_centre_x", post.centerX);
  value("post_symmetry_centre_y", post.centerY);
  value("post_symmetry_distance", post.distance);
  value("post_symmetry_rotation", post.rotationDeg);
  return post;
}

ImportedFlame readFlame(const pugi::xml_node& node, const std::string& where, const std::string& name,
                        const FlameImportOptions& options, const std::map<std::string, std::string>& renamed) {
  FlameReader reader(where, options);
  reader.setRenamed(&renamed);
  ImportedFlame flame;
  flame.name = name;
  FlameSymmetry symmetry;
  if (const pugi::xml_attribute kind = node.attribute("symmetry"))
    symmetry = symmetryOfKind(reader.number(kind, "", -kFlameCoefficientLimit, kFlameCoefficientLimit), reader);
  if (const pugi::xml_node element = node.child("symmetry")) {
    if (!element.attribute("kind"))
      reader.fail("", "<symmetry> needs a kind attribute (flam3: N-fold, negative adds a mirror)");
    symmetry = symmetryOfKind(
        reader.number(element.attribute("kind"), "<symmetry>", -kFlameCoefficientLimit, kFlameCoefficientLimit),
        reader);
  }
  // JWildfire's post symmetry belongs to the whole flame: every layer draws through it.
  const FlamePostSymmetry postSymmetry = readPostSymmetry(node, reader);
  const auto finishGenome = [&](FlameGenome& genome, const std::string& context) {
    genome.symmetry = symmetry;
    genome.postSymmetry = postSymmetry;
    const bool depthAdded = addFlameDepth(genome, options.depth);
    validateFlame(genome, context.empty() ? where : where + ", " + context);
    return depthAdded;
  };
  std::vector<std::vector<MotionChannel>> channels;  // per imported layer
  if (std::string_view(node.name()) == "jwf-flame") {
    // JWildfire's layered flames keep their transforms and palette in <layer> children, drawn
    // together into one image: each visible layer becomes a voxflame flame layer, the first one
    // the flame's own genome and palette, the others in otherLayers, all placed with the first.
    std::size_t number = 0;
    bool first = true;
    // A single-layer flame names its transforms plainly, as a <flame> does.
    const bool layered = std::distance(node.children("layer").begin(), node.children("layer").end()) > 1;
    for (const pugi::xml_node& layer : node.children("layer")) {
      const std::string context = "layer " + std::to_string(++number);
      if (const pugi::xml_attribute visible = layer.attribute("visible"); visible && !visible.as_bool(true)) {
        reader.warn("JWildfire " + context +
                    " is hidden (visible=\"0\"); JWildfire does not draw it, so it was "
                    "left out");
        continue;
      }
      if (!layer.child("xform")) {
        // JWildfire skips a layer without transforms as well.
        reader.warn("JWildfire " + context + " has no transforms; it was left out");
        continue;
      }
      const std::string layerContext = layered ? context : "";
      std::vector<MotionChannel> layerChannels;
      FlameGenome genome = readGenome(layer, layerContext, reader, layerChannels);
      const double weight = jwildfireLayerWeight(layer, layerContext, reader);
      {
        double factor = 1.0;
        if (const auto density = parseNumber(layer.attribute("density").value()); density && *density < 1.0)
          factor = std::max(0.0, *density * *density);
        reader.readLayerCurves(layer, context, factor);
        for (MotionChannel& channel : reader.takePendingChannels()) layerChannels.push_back(std::move(channel));
      }
      // JWildfire's background transforms paint the picture's background (FlameGenome::backgroundXforms).
      // The flat view draws them; a 3D render has no such picture plane and shows the plain background.
      if (layer.child("bgxform")) {
        std::size_t bgNumber = 0;
        for (const pugi::xml_node bg : layer.children("bgxform")) {
          if (genome.backgroundXforms.size() == kMaxFlameXforms) {
            reader.lose("background transforms after the " + std::to_string(kMaxFlameXforms) + "th");
            reader.warn("JWildfire " + context + " has more than " + std::to_string(kMaxFlameXforms) +
                        " background transforms; the rest were left out");
            break;
          }
          const std::string bgWhere =
              (layerContext.empty() ? "" : layerContext + " ") + "background transform " + std::to_string(++bgNumber);
          genome.backgroundXforms.push_back(reader.xform(bg, bgWhere, false));
          if (!reader.takePendingChannels().empty()) {
            reader.lose("motion of background transforms");
            reader.warn(bgWhere + " is animated, which voxflame does not keyframe; it stands still");
          }
        }
        if (const auto zoom = parseNumber(node.attribute("cam_zoom").value()); zoom && *zoom > 0.0 && *zoom < 1e6)
          genome.backgroundZoom = *zoom;
        reader.lose("JWildfire background transforms in 3D renders");
        reader.warn("JWildfire " + context +
                    " has background transforms (<bgxform>), which paint JWildfire's background: the flat view "
                    "draws them, a 3D render shows the plain background colour");
      }
      const std::vector<GradientStop> palette = gradientOf(readPalette(layer, reader));
      const bool depthAdded = finishGenome(genome, layerContext);
      if (first) {
        flame.genome = std::move(genome);
        flame.palette = palette;
        flame.weight = weight;
        flame.depthAdded = depthAdded;
        first = false;
      } else {
        flame.otherLayers.push_back({std::move(genome), palette, weight, depthAdded});
      }
      channels.push_back(std::move(layerChannels));
    }
    if (first)
      reader.fail("",
                  "is a JWildfire <jwf-flame> without a visible <layer> with transforms; there is "
                  "nothing to draw");
    // voxflame's weights reach 1000; only the ratios matter, so larger ones are scaled down together.
    double heaviest = flame.weight;
    for (const ImportedFlameLayer& layer : flame.otherLayers) heaviest = std::max(heaviest, layer.weight);
    if (heaviest > kMaxImportedLayerWeight) {
      for (auto& layerChannels : channels)
        for (MotionChannel& channel : layerChannels)
          if (!channel.layerField.empty())
            for (auto& point : channel.points) point.second *= kMaxImportedLayerWeight / heaviest;
      flame.weight *= kMaxImportedLayerWeight / heaviest;
      for (ImportedFlameLayer& layer : flame.otherLayers) layer.weight *= kMaxImportedLayerWeight / heaviest;
    }
  } else {
    channels.emplace_back();
    flame.genome = readGenome(node, "", reader, channels.back());
    flame.palette = gradientOf(readPalette(node, reader));
    flame.depthAdded = finishGenome(flame.genome, "");
  }
  readFlameCurves(node, reader, channels);
  flame.tone = readTone(node, reader);
  // A curve of the 3D camera turns JWildfire's camera on even where the file's own values leave it off.
  const bool cameraAnimated = std::any_of(channels.front().begin(), channels.front().end(), [](const MotionChannel& c) {
    return c.scenePath.starts_with("/flat/camera_");
  });
  flame.flat = readFlat(node, reader, cameraAnimated);
  // After the tone and the flat view: their tracks are checked against them.
  finishMotion(flame, channels, node, reader);
  reportUnkeptFlameFeatures(node, reader);
  flame.warnings = reader.finishWarnings();
  flame.leftOut = reader.finishLeftOut();
  return flame;
}

// Every <flame> (or JWildfire <jwf-flame>) element, in document order, at any depth (explicit stack: a deeply nested
// file must not exhaust the call stack).
std::vector<pugi::xml_node> flameElements(const pugi::xml_document& document) {
  std::vector<pugi::xml_node> flames;
  std::vector<pugi::xml_node> stack;
  for (pugi::xml_node child = document.last_child(); child; child = child.previous_sibling()) stack.push_back(child);
  while (!stack.empty()) {
    const pugi::xml_node node = stack.back();
    stack.pop_back();
    if (node.type() != pugi::node_element) continue;
    if (std::string_view(node.name()) == "flame" || std::string_view(node.name()) == "jwf-flame") {
      flames.push_back(node);
      continue;  // flames do not nest
    }
    for (pugi::xml_node child = node.last_child(); child; child = child.previous_sibling()) stack.push_back(child);
  }
  return flames;
}

}  // namespace

bool isFlameFilePath(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".flame" || extension == ".flam3";
}

bool isFlatFlame(const FlameGenome& genome) {
  const auto flatAffine = [](const Affine3& a) {
    return a.m[2] == 0.0 && a.m[6] == 0.0 && a.m[8] == 0.0 && a.m[9] == 0.0 && a.m[10] == 1.0 && a.m[11] == 0.0;
  };
  const auto flatXform = [&](const FlameXform& x) {
    if (!flatAffine(x.affine) || (x.hasPost && !flatAffine(x.post))) return false;
    for (const VariationTerm& term : x.variations) {
      const VariationInfo* info = findVariation(term.name);
      // flatten keeps z at 0: flat.
      if (!info || (info->threeD && info->name != "flatten")) return false;
    }
    return true;
  };
  if (genome.hasFinal && !flatXform(genome.finalXform)) return false;
  return std::all_of(genome.xforms.begin(), genome.xforms.end(), flatXform);
}

bool addFlameDepth(FlameGenome& genome, double depth) {
  if (!isFlatFlame(genome)) return false;
  // flatten would set the depth back to 0 (Apophysis 3D flames use it to stay flat).
  const auto isFlatten = [](const VariationTerm& term) {
    const VariationInfo* info = findVariation(term.name);
    return info && info->name == "flatten";
  };
  if (depth > 0.0) {
    for (FlameXform& x : genome.xforms) std::erase_if(x.variations, isFlatten);
    if (genome.hasFinal) std::erase_if(genome.finalXform.variations, isFlatten);
  }
  // A transform's place in colour order (ties by position) sets its layer: s from −1 to +1.
  const std::size_t n = genome.xforms.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return genome.xforms[a].color < genome.xforms[b].color; });
  constexpr double kShrink = 0.5;  // each step halves the depth already recorded: a binary fraction
  for (std::size_t rank = 0; rank < n; ++rank) {
    FlameXform& x = genome.xforms[order[rank]];
    const double s = n > 1 ? 2.0 * static_cast<double>(rank) / static_cast<double>(n - 1) - 1.0 : 0.0;
    // 2D variations carry z as (sum of their weights) · z: divide it out, so z' is exactly
    // ½ z + depth · s after them. Near-zero sums are held at ±0.05 (z then shrinks further).
    double sum = 0.0;
    for (const VariationTerm& term : x.variations) sum += term.weight;
    if (x.variations.empty()) sum = 1.0;
    const double divisor = std::abs(sum) < 0.05 ? std::copysign(0.05, sum) : sum;
    x.affine.m[10] = kShrink / divisor;
    x.affine.m[11] = depth * s / divisor;
  }
  return true;
}

FlameFileContents readFlameXml(std::string_view text, const std::string& sourceName,
                               const FlameImportOptions& options) {
  if (!std::isfinite(options.depth) || options.depth < 0.0 || options.depth > kMaxFlameDepth)
    throw Error("the flame depth must be from 0 to " + formatted(kMaxFlameDepth));
  pugi::xml_document document;
  const pugi::xml_parse_result result =
      document.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_auto);
  // Not well-formed: read again tolerantly (tolerantXml); a file that is still not XML is refused
  // with the first reading's error.
  TolerantXml tolerant;
  if (!result) {
    tolerant = tolerantXml(text);
    pugi::xml_document again;
    if (!again.load_buffer(tolerant.text.data(), tolerant.text.size(), pugi::parse_default, pugi::encoding_auto) ||
        flameElements(again).empty())
      throw Error(sourceName + " is not flame XML: " + result.description() + " at byte " +
                  std::to_string(result.offset));
    document.reset(again);
  }
  const std::vector<pugi::xml_node> flames = flameElements(document);
  if (flames.empty())
    throw Error(sourceName +
                " holds no <flame> element; it is XML but not a flame file (flam3, Apophysis, "
                "Fractorium or JWildfire)");
  FlameFileContents contents;
  bool latin1Names = false;
  for (std::size_t i = 0; i < flames.size(); ++i) {
    const std::string name = asUtf8(flames[i].attribute("name").value(), latin1Names);
    contents.names.push_back(name.empty() ? "flame " + std::to_string(i + 1) : name);
  }
  if (!options.name.empty()) {
    const auto found = std::find(contents.names.begin(), contents.names.end(), options.name);
    if (found == contents.names.end())
      throw Error(sourceName + " has no flame named '" + options.name + "'; it holds " + std::to_string(flames.size()) +
                  " flame" + (flames.size() == 1 ? "" : "s"));
    contents.index = static_cast<std::size_t>(found - contents.names.begin());
  } else {
    if (options.index >= flames.size())
      throw Error(sourceName + " holds " + std::to_string(flames.size()) + " flame" + (flames.size() == 1 ? "" : "s") +
                  "; there is no flame " + std::to_string(options.index + 1));
    contents.index = options.index;
  }
  const pugi::xml_node chosen = flames[contents.index];
  std::string title = chosen.attribute("name").value()[0] ? contents.names[contents.index] : "";
  if (title.empty()) {
    bool changed = false;
    title = asUtf8(std::filesystem::path(sourceName).stem().string(), changed);
    if (flames.size() > 1) title += " " + std::to_string(contents.index + 1);
  }
  const std::string where = sourceName + ", flame '" + contents.names[contents.index] + "'";
  contents.flame = readFlame(chosen, where, title, options, tolerant.renamed);
  if (latin1Names)
    contents.flame.warnings.insert(contents.flame.warnings.begin(),
                                   "flame names of the file are not UTF-8; they were read as Latin-1");
  if (!tolerant.fixes.empty()) {
    std::string fixes;
    for (const std::string& fix : tolerant.fixes) fixes += (fixes.empty() ? "" : "; ") + fix;
    contents.flame.warnings.insert(contents.flame.warnings.begin(),
                                   "the file is not well-formed XML (" + fixes + "); it was read tolerantly");
  }
  return contents;
}

FlameFileContents loadFlameFile(const std::filesystem::path& path, const FlameImportOptions& options) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error) throw Error(path.string() + ": cannot read it (" + error.message() + ")");
  if (size > kMaxFlameFileBytes)
    throw Error(path.string() + " is " + std::to_string(size >> 20) + " MiB; a flame file is far smaller");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string() + ": cannot open it");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return readFlameXml(bytes.str(), path.string(), options);
}

namespace {

// How much of the mesh the flat view's frame takes: its longer side spans the mesh's longest
// axis (grid.resolution voxels), and the depth of the points drawn inside it (5–95%) this share
// of that side, so the layers a flat flame gains fill the mesh's thickness about as its frame
// fills the mesh's width.
constexpr double kFrameDepthShare = 0.6;
constexpr std::size_t kDepthProbeLanes = 256;
constexpr int kDepthProbeTransient = 20, kDepthProbeSteps = 200;

// The z of points the flame draws inside the frame: where the flame's depth lies (its median) and
// how far it spreads. All drawn points when too few fall inside the frame. Empty when none stay finite.
std::vector<double> framedDepths(const PatternLayer& layer, const FlatViewSettings& flat, double frame) {
  std::vector<double> inside, all;
  try {
    const ChaosGame game(layer, "the imported flame");
    SplitMix64 rng(1);
    ChaosLanes lanes;
    lanes.resize(kDepthProbeLanes);
    for (std::size_t i = 0; i < kDepthProbeLanes; ++i) game.seedLane(lanes, i, rng);
    std::vector<double> x(kDepthProbeLanes), y(kDepthProbeLanes), z(kDepthProbeLanes), color(kDepthProbeLanes);
    for (int step = 0; step < kDepthProbeTransient + kDepthProbeSteps; ++step) {
      game.step(lanes, x.data(), y.data(), z.data(), color.data(), kDepthProbeLanes);
      for (std::size_t i = 0; i < kDepthProbeLanes; ++i) {
        if (!std::isfinite(x[i]) || !std::isfinite(y[i]) || !std::isfinite(z[i])) {
          game.seedLane(lanes, i, rng);
          continue;
        }
        if (step < kDepthProbeTransient || !lanes.visible[i]) continue;
        all.push_back(z[i]);
        if (std::abs(x[i] - flat.centerX) <= 0.5 * frame && std::abs(y[i] - flat.centerY) <= 0.5 * frame)
          inside.push_back(z[i]);
      }
    }
  } catch (const Error&) {
    return {};  // a genome the chaos game refuses keeps the automatic fit
  }
  return inside.size() >= 100 ? inside : all;
}

// Euler angles (degrees, about x, then y, then z: LayerTransform::rotationDeg) of a rotation
// matrix R = Rz · Ry · Rx.
glm::dvec3 eulerDegrees(const glm::dmat3& r) {
  // glm is column-major: r[column][row].
  const double x = std::atan2(r[1][2], r[2][2]);
  const double y = std::asin(std::clamp(-r[0][2], -1.0, 1.0));
  const double z = std::atan2(r[0][1], r[0][0]);
  return glm::dvec3(x, y, z) * (180.0 / std::numbers::pi);
}

glm::dmat3 turnAbout(int axis, double degrees) {
  const double a = degrees * std::numbers::pi / 180.0, c = std::cos(a), s = std::sin(a);
  glm::dmat3 m(1.0);
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  m[i][i] = c;
  m[i][j] = s;
  m[j][i] = -s;
  m[j][j] = c;
  return m;
}

// The layers' turn for a frame turned by `rotateDeg` (placeAsFramed).
glm::dmat3 frameTurn(const CameraSettings& camera, double rotateDeg) {
  return turnAbout(1, camera.azimuthDeg) * turnAbout(0, -camera.elevationDeg) * turnAbout(0, 180.0) *
         turnAbout(2, -rotateDeg);
}

// Places an imported flame in the mesh as its author framed it in 2D (the flat view), instead of
// fitting the box of all its points: flames often scatter a faint haze far beyond the part their
// author framed (Ethereal passage's frame is a twentieth of its robust box, which left the framed
// flame a faint speck in the bunny). A locked fit puts the frame's centre at the mesh's centre and
// its longer side across the mesh's longest axis. The rotation turns the frame as flam3 turns it,
// puts the flat view's top (its first rows, the smaller y) up on screen, and faces the frame to
// the scene's camera: the flame's depth then runs along the view instead of smearing its picture
// sideways (Ethereal passage's depth comes from 3D variations and has no order a viewer could
// read). Returns false, changing nothing, when there is no sensible frame or the flame draws
// nothing finite.
bool placeAsFramed(std::vector<PatternLayer>& layers, const FlatViewSettings& flat, const CameraSettings& camera,
                   int gridResolution) {
  const double pixelsPerUnit = flat.scale * std::exp2(flat.zoom);
  const double frame = static_cast<double>(std::max(flat.width, flat.height)) / pixelsPerUnit;  // flame units
  if (!std::isfinite(frame) || frame <= 0.0 || layers.empty()) return false;
  std::vector<double> depths = framedDepths(layers.front(), flat, frame);
  if (depths.empty()) return false;
  const auto at = [&](double fraction) {
    const auto nth = depths.begin() + static_cast<std::ptrdiff_t>(fraction * static_cast<double>(depths.size() - 1));
    std::nth_element(depths.begin(), nth, depths.end());
    return *nth;
  };
  const double low = at(0.05), middle = at(0.5), high = at(0.95);
  // A flame without depth (imported with --depth 0) keeps its z as it is: there is nothing to spread.
  const double depthScale = high - low > 1e-9 ? std::clamp(kFrameDepthShare * frame / (high - low), 1e-6, 1e6) : 1.0;
  LayerTransform& first = layers.front().transform;
  first.lockFit = true;
  first.lockedCenter = glm::dvec3(flat.centerX, flat.centerY, middle);
  first.lockedScale = std::clamp(static_cast<double>(gridResolution) / frame, 1e-9, 1e9);
  first.lockedAxisScale = glm::dvec3(1.0, 1.0, depthScale);
  // Read from the right: about z by −rotate and about x by 180° are flam3's turn seen the right way
  // up (x by 180° turns y, and z to stay a rotation, over); then the frame's normal (+z) turns to
  // the eye: down by the elevation, round by the azimuth (camera.cpp's orbit). The other layers
  // take the first one's fit (FitMode::Previous) and this turn.
  for (PatternLayer& layer : layers) layer.transform.rotationDeg = eulerDegrees(frameTurn(camera, flat.rotateDeg));
  return true;
}

// The flat view's motion (JWildfire's centre, scale and roll curves) moves the frame placeAsFramed
// puts in the mesh, so that an animation in the mesh pans, zooms and turns as the flat view does:
// the centre and the scale key the locked fit through the same keys (both are linear in them, so
// the tracks are the same curves), the roll keys the layers' turn, whose Euler angles are not
// linear in it: they are sampled every kTurnSampleDeg of roll or less, unwrapped, and keyed linearly.
constexpr double kTurnSampleDeg = 2.0;
constexpr std::size_t kMaxTurnKeys = 2048;

void keyFramedPlacement(Scene& scene, const CameraSettings& camera, int gridResolution) {
  const FlatViewSettings& flat = scene.flat;
  const double voxelsPerPixel = static_cast<double>(gridResolution) * std::exp2(flat.zoom) /
                                static_cast<double>(std::max(flat.width, flat.height));
  std::vector<KeyframeTrack> placement;
  for (const KeyframeTrack& track : scene.keyframes) {
    if (track.path == "/flat/center_x" || track.path == "/flat/center_y" || track.path == "/flat/scale") {
      KeyframeTrack fit = track;
      if (track.path == "/flat/scale") {
        fit.path = "/layers/0/transform/locked_fit/scale";
        for (Keyframe& key : fit.keys) key.values[0] = std::clamp(key.values[0] * voxelsPerPixel, 1e-9, 1e9);
      } else {
        fit.path = std::string("/layers/0/transform/locked_fit/center/") + (track.path.back() == 'x' ? "0" : "1");
      }
      placement.push_back(std::move(fit));
    } else if (track.path == "/flat/rotate" && !track.keys.empty()) {
      const double duration = animationDuration(scene);
      const double start = track.keys.front().time, end = track.keys.back().time;
      double travelled = 0.0;  // degrees of roll over the track, at its keys
      for (std::size_t i = 1; i < track.keys.size(); ++i)
        travelled += std::abs(track.keys[i].values[0] - track.keys[i - 1].values[0]);
      const std::size_t steps =
          end > start ? std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(travelled / kTurnSampleDeg)) *
                                                    (track.interpolation == Interpolation::Smooth ? 2 : 1),
                                                1, kMaxTurnKeys - 1)
                      : 0;
      KeyframeTrack turn;
      turn.path = "/layers/0/transform/rotation_deg";
      turn.kind = KeyKind::Array;
      turn.interpolation = Interpolation::Linear;
      for (std::size_t k = 0; k <= steps; ++k) {
        const double t =
            steps == 0 ? start : start + (end - start) * static_cast<double>(k) / static_cast<double>(steps);
        const double roll = evaluateTrack(track, t, duration, scene.animation.loop).get<double>();
        glm::dvec3 angles = eulerDegrees(frameTurn(camera, roll));
        // The nearest whole turn to the angles before: no spin back at ±180°.
        if (!turn.keys.empty())
          for (int axis = 0; axis < 3; ++axis)
            angles[axis] =
                std::clamp(angles[axis] - 360.0 * std::round((angles[axis] - turn.keys.back().values[axis]) / 360.0),
                           -3600.0, 3600.0);
        turn.keys.push_back({t, {angles.x, angles.y, angles.z}});
      }
      // Every layer turns with the first (placeAsFramed).
      for (std::size_t layer = 0; layer < scene.layers.size(); ++layer) {
        turn.path = "/layers/" + std::to_string(layer) + "/transform/rotation_deg";
        placement.push_back(turn);
      }
    }
  }
  for (KeyframeTrack& track : placement) scene.keyframes.push_back(std::move(track));
}

}  // namespace

Scene sceneFromImportedFlame(const ImportedFlame& flame, const Scene& base) {
  Scene scene = base;
  scene.name = flame.name;
  scene.layers = {importedFlameLayer(flame.genome, flame.palette, flame.weight)};
  for (const ImportedFlameLayer& other : flame.otherLayers) {
    // Drawn in the first layer's coordinates, as JWildfire draws them into one image.
    scene.layers.push_back(importedFlameLayer(other.genome, other.palette, other.weight));
    scene.layers.back().transform.fit = FitMode::Previous;
  }
  const bool framed = placeAsFramed(scene.layers, flame.flat, base.camera, base.gridResolution);
  scene.tone = flame.tone;
  scene.flat = flame.flat;
  // Whatever the scene it replaces had: a flame's filaments survive projecting every point (the
  // flam3 way), and ray-marching the grid blurs them to the voxel size.
  scene.render.method = defaultRenderMethod(scene.layers);
  scene.animation = flame.animation;
  scene.keyframes = flame.keyframes;
  if (framed) keyFramedPlacement(scene, base.camera, base.gridResolution);
  return scene;
}

}  // namespace voxflame::core
