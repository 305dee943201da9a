#include "flame_kernel.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <utility>

#include "core/chaos_game.h"
#include "core/error.h"
#include "core/flame/flame.h"
#include "core/flame/noise.h"
#include "core/flame/parplot_formula.h"
#include "core/flame/subflame.h"
#include "core/flame/variations.h"
#include "core/scene.h"
#include "parplot_glsl.h"
#include "shader_program.h"

namespace voxflame::gl {

namespace {

// The files of the GPU's variations, in the order they are put together: flame_variations.glsl
// first, as it declares the data buffers and the helpers (psi, atan2c, ...) the others call. A
// family's file is the CPU catalogue's family (core/flame/variations_*.cpp) in float.
// weight_field.glsl last: the weighting fields' noise, which calls simplexNoise3D.
constexpr std::array<std::string_view, 8> kVariationFiles = {
    "flame_variations.glsl",         "flame_variations_2d.glsl",
    "flame_variations_2d_more.glsl", "flame_variations_3d.glsl",
    "flame_variations_blurs.glsl",   "flame_variations_jwildfire.glsl",
    "flame_variations_wild.glsl",    "weight_field.glsl"};

// The variation files split for the kernels: every top-level function apart (the V_<name>
// variations and the helpers they call), and the rest (buffers, constants, globals, macros) kept
// in place between them. A kernel compiles the rest and only the functions its variations reach:
// the driver parses and translates every function it is given, and a thousand unused ones made a
// llvmpipe compile take over a second.
struct SplitVariations {
  struct Piece {
    std::string text;        // with a #line, so the driver's log points into the file
    std::string function;    // empty: always put in
    std::vector<int> calls;  // the pieces of the functions it names
  };
  std::vector<Piece> pieces;  // in the files' order, which is an order GLSL accepts
  std::map<std::string, int, std::less<>> functionPiece;
  std::vector<std::string> names;  // the variations (V_<name>), in the files' order
};

bool identifierChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

// The name a line at depth 0 starts to define (`type name(`), or empty; a prototype (`...);`) defines none.
std::string definedFunction(std::string_view line) {
  std::size_t at = 0;
  while (at < line.size() && identifierChar(line[at])) ++at;  // the return type
  if (at == 0 || at >= line.size() || line[at] != ' ') return {};
  const std::size_t nameStart = ++at;
  while (at < line.size() && identifierChar(line[at])) ++at;
  if (at == nameStart || at >= line.size() || line[at] != '(') return {};
  const std::string_view code = line.substr(0, line.find("//"));
  if (code.find(';') != std::string_view::npos && code.find('{') == std::string_view::npos) return {};
  return std::string(line.substr(nameStart, at - nameStart));
}

SplitVariations splitVariationFiles() {
  static constexpr std::string_view kSignature = "(vec3 p, float w, int P, int A)";
  SplitVariations split;
  for (std::size_t k = 0; k < kVariationFiles.size(); ++k) {
    // Each file is source string k + 1, its place in kVariationFiles (the program's own file is 0).
    const std::string file = std::to_string(k + 1);
    const std::string text = embeddedShader(kVariationFiles[k]).text;
    SplitVariations::Piece* piece = nullptr;
    bool inFunction = false, opened = false;
    int depth = 0;
    std::size_t lineNumber = 0;
    for (std::size_t at = 0; at < text.size();) {
      std::size_t end = text.find('\n', at);
      if (end == std::string::npos) end = text.size();
      const std::string_view line(text.data() + at, end - at);
      ++lineNumber;
      at = end + 1;
      const std::string function = depth == 0 && !inFunction ? definedFunction(line) : std::string();
      if (!function.empty() || !piece) {
        split.pieces.emplace_back();
        piece = &split.pieces.back();
        piece->text = "#line " + std::to_string(lineNumber) + " " + file + "\n";
        piece->function = function;
        inFunction = !function.empty();
        opened = false;
        if (inFunction) {
          split.functionPiece[function] = static_cast<int>(split.pieces.size()) - 1;
          if (function.starts_with("V_") && line.substr(line.find('(')).starts_with(kSignature))
            split.names.push_back(function.substr(2));
        }
      }
      piece->text.append(line);
      piece->text.push_back('\n');
      // Braces outside comments (GLSL has no strings); a function ends where its depth returns to 0.
      const std::string_view code = line.substr(0, line.find("//"));
      for (const char c : code) {
        if (c == '{') opened = true;
        depth += c == '{' ? 1 : c == '}' ? -1 : 0;
      }
      if (inFunction && opened && depth == 0) {
        inFunction = false;
        piece = nullptr;  // what follows starts a piece of its own
      }
    }
  }
  // What each piece calls: the identifiers in it that name a function.
  for (SplitVariations::Piece& piece : split.pieces) {
    const std::string& t = piece.text;
    for (std::size_t at = 0; at < t.size();) {
      if (!identifierChar(t[at])) {
        ++at;
        continue;
      }
      const std::size_t start = at;
      while (at < t.size() && identifierChar(t[at])) ++at;
      const auto found = split.functionPiece.find(std::string_view(t).substr(start, at - start));
      if (found != split.functionPiece.end() &&
          split.pieces[static_cast<std::size_t>(found->second)].function != piece.function)
        piece.calls.push_back(found->second);
    }
  }
  return split;
}

const SplitVariations& splitVariations() {
  static const SplitVariations split = splitVariationFiles();
  return split;
}

bool gpuHasVariation(std::string_view name) {
  const std::vector<std::string>& names = gpuFlameVariations();
  return std::find(names.begin(), names.end(), name) != names.end();
}

// parplot2d_wf, polarplot3d_wf and isosfplot3d_wf, whose formulas the kernel compiles (parplotSurface).
bool drawsFormulas(const core::VariationInfo& info) {
  return info.name == "parplot2d_wf" || info.name == "polarplot3d_wf" || info.name == "isosfplot3d_wf";
}

// A parplot2d_wf term's three formulas, or polarplot3d_wf's formula as a surface (r(t, u), 0, 0)
// (core::polarplotSurfaceFormulas), or isosfplot3d_wf's (F(x, y, z), 0, 0), or nullopt where muParser cannot read one,
// or polarplot3d_wf's formula is empty: the CPU's own test (its evaluator, compiled once per thread and kept), where
// the term then adds nothing, as the GPU's does.
std::optional<std::array<std::string, 3>> termFormulas(const core::VariationInfo& info,
                                                       const core::VariationTerm& term) {
  const std::vector<std::string> texts = info.textsFor(term.texts);
  std::array<std::string, 3> surface;
  if (info.name == "polarplot3d_wf") {
    if (texts[0].empty()) return std::nullopt;
    surface = core::polarplotSurfaceFormulas(texts[0]);
  } else if (info.name == "isosfplot3d_wf") {
    surface = core::isosfplotSurfaceFormulas(texts[0]);
  } else {
    surface = {texts[0], texts[1], texts[2]};
  }
  if (!core::parplotEvaluator(surface[0], surface[1], surface[2]).ok()) return std::nullopt;
  return surface;
}

// Whether the GPU's variation reads numbers the generator derives from its parameters (a table
// built from them, crackle's slice in double, the parameters in double, parplot2d_wf's surface),
// which a weighting field that moves its parameters per point would leave as they were.
bool derivesFromParameters(const core::VariationInfo& info) {
  return info.table || gpuVariationReadsNoise(info.name) || gpuVariationReadsDoubles(info.name) || drawsFormulas(info);
}

// Why one transform cannot run on the GPU, or empty.
std::string xformUnsupported(const core::FlameXform& xform) {
  for (const core::VariationTerm& term : xform.variations) {
    if (term.weight == 0.0) continue;
    const core::VariationInfo* info = core::findVariation(term.name);
    if (!info) return "variation '" + term.name + "'";
    if (!gpuHasVariation(info->name)) return "variation '" + term.name + "'";
    if (derivesFromParameters(*info) && !core::weightFieldTerm(xform, term, *info).params.empty())
      return "a weighting field on " + term.name + "'s parameters";
    if (drawsFormulas(*info)) {
      if (const auto formulas = termFormulas(*info, term))
        for (const std::string& formula : *formulas)
          if (const ParplotGlsl glsl = parplotFormulaGlsl(core::parplotMuParserText(formula)); !glsl.error.empty())
            return "what a " + info->name + " formula asks: " + glsl.error;
      continue;
    }
    // Other text parameters reach a GLSL port only through the table its kernel builds from them.
    if (!info->textParams.empty() && !info->table) return "variation '" + term.name + "'";
  }
  return {};
}

// Whether a term of `xform` (of weight other than 0, as core::ChaosGame compiles them) has `flag`.
bool anyTerm(const core::FlameXform& xform, bool core::VariationInfo::*flag) {
  for (const core::VariationTerm& term : xform.variations)
    if (const core::VariationInfo* info = core::findVariation(term.name); info && term.weight != 0.0 && info->*flag)
      return true;
  return false;
}

// Doubles of memory per orbit the flame's terms keep (VariationInfo::laneState), each term its own.
std::size_t laneMemory(const std::vector<core::FlameXform>& xforms, const core::FlameGenome& genome) {
  std::size_t doubles = 0;
  const auto add = [&](const core::FlameXform& xform) {
    for (const core::VariationTerm& term : xform.variations)
      if (const core::VariationInfo* info = core::findVariation(term.name); info && term.weight != 0.0)
        doubles += info->laneState;
  };
  for (const core::FlameXform& xform : xforms) add(xform);
  if (genome.hasFinal) {
    add(genome.finalXform);
    for (const core::FlameXform& chained : genome.chainedFinals) add(chained);
  }
  return doubles;
}

class Generator {
 public:
  explicit Generator(FlameKernel& kernel, bool paintsRgb = false, const std::array<std::uint32_t, 256>& palette = {})
      : k_(kernel), paintsRgb_(paintsRgb), variationPalette_(palette) {}

  // Adds `values` to the data block; returns where they start.
  int put(const double* values, std::size_t count) {
    const int at = static_cast<int>(k_.data.size());
    for (std::size_t i = 0; i < count; ++i) k_.data.push_back(static_cast<float>(values[i]));
    return at;
  }
  int put(double value) { return put(&value, 1); }

  // A GLSL function `vec3 <name>(vec3 p, inout float c, inout bool visible)` that runs one
  // transform as core::ChaosGame::applyGroup does, then its colour blend and opacity draw (`final`:
  // the final transform's, which always draws for its opacity).
  void xformFunction(const std::string& name, const core::FlameXform& xform, bool final) {
    std::string& s = k_.source;
    const int affine = put(xform.affine.m.data(), 12);
    s += "vec3 " + name + "(vec3 p, inout float c, inout bool visible) {\n";
    s += "  int A = " + std::to_string(affine) + ";\n";
    const bool paints = anyTerm(xform, &core::VariationInfo::paintsRgb);
    if (paints) s += "  gRgb = 0u;\n";  // JWildfire clears rgbColor as each transform starts
    // A direct-colour variation starts from the colour the transform's blend gives and may set it;
    // the transform then blends that in by its direct_color (core::ChaosGame::startDirectColour).
    const bool direct = anyTerm(xform, &core::VariationInfo::directColour);
    const int blend = put(1.0 - xform.colorSpeed);
    put(xform.colorSpeed * xform.color);
    if (direct)
      s += "  float saved = flameData[" + std::to_string(blend) + "] * c + flameData[" + std::to_string(blend + 1) +
           "];\n  gColour = saved;\n";
    s += "  vec3 t = vec3(dot(vec3(flameData[A], flameData[A + 1], flameData[A + 2]), p) + flameData[A + 3],\n"
         "                dot(vec3(flameData[A + 4], flameData[A + 5], flameData[A + 6]), p) + flameData[A + 7],\n"
         "                dot(vec3(flameData[A + 8], flameData[A + 9], flameData[A + 10]), p) + flameData[A + 11]);\n";
    // The weighting field (core::ChaosGame::fillField): its noise n at the transform's input or at
    // the affine point, and every term's factor 1 + amount · n.
    const bool field = xform.hasWeightField();
    int fieldAt = -1;
    if (field) {
      fieldAt = fieldBlock(xform);
      const int amount = put(xform.fieldAmount);
      s += "  float fieldN = weightFieldNoise(" + std::to_string(fieldAt) + ", " +
           (xform.fieldInput == core::WeightFieldInput::Position ? "p" : "t") + ");\n";
      s += "  float field = 1.0 + flameData[" + std::to_string(amount) + "] * fieldN;\n";
    }
    struct Term {
      const core::VariationInfo* info;
      const core::VariationTerm* term;
      core::WeightFieldTerm field;  // what the transform's weighting field does to it (none without one)
    };
    std::array<std::vector<Term>, 3> stages;
    for (const core::VariationStage stage :
         {core::VariationStage::Pre, core::VariationStage::Normal, core::VariationStage::Post})
      for (const core::VariationTerm& term : xform.variations) {
        if (term.weight == 0.0 || core::variationStage(term.name) != stage) continue;
        const core::VariationInfo* info = core::findVariation(term.name);
        stages[static_cast<int>(stage)].push_back(
            {info, &term, field ? core::weightFieldTerm(xform, term, *info) : core::WeightFieldTerm{}});
      }
    // Code a term's call needs before the statement that calls it: the copy of its numbers that the
    // field's noise moves (core::ChaosGame::applyGroup's lane-by-lane parameters).
    std::string setup;
    const auto call = [&](const Term& t, const char* point) {
      // Shared blocks (crackle's noise tables, the palette) go in before the term's numbers, which
      // must follow one another.
      const bool noise = gpuVariationReadsNoise(t.info->name);
      const int tables = noise ? noiseTables() : -1;
      const int paletteAt = t.info->paintsRgb ? palette() : -1;
      const int weight = put(t.term->weight);
      const int params = static_cast<int>(k_.data.size());
      put(t.term->params.data(), t.term->params.size());
      // What follows the parameters, in this order where it applies (flame_variations.glsl): the
      // parameters in full (defaults for any missing), crackle's extras; where its memory per orbit
      // starts in gLane, where the palette lies; where its table starts, its size, and the table;
      // the parameters in double.
      std::vector<double> full = t.term->params;
      for (std::size_t i = full.size(); i < t.info->params.size(); ++i) full.push_back(t.info->params[i].defaultValue);
      const bool formulas = drawsFormulas(*t.info);
      if (noise || t.info->laneState > 0 || t.info->paintsRgb || t.info->table || formulas ||
          gpuVariationReadsDoubles(t.info->name))
        put(full.data() + t.term->params.size(), full.size() - t.term->params.size());
      if (formulas) put(static_cast<double>(surface(*t.info, *t.term)));
      if (noise) {
        const std::vector<float> extras = gpuNoiseExtras(full, tables);
        k_.data.insert(k_.data.end(), extras.begin(), extras.end());
      }
      if (t.info->laneState > 0 || t.info->paintsRgb) {
        put(static_cast<double>(laneSlots_));
        laneSlots_ += t.info->laneState;
        if (t.info->paintsRgb) put(static_cast<double>(paletteAt));
      }
      if (t.info->table) {
        const std::vector<std::string> texts = t.info->textsFor(t.term->texts);
        const std::vector<double> table = t.info->table(full.data(), texts.empty() ? nullptr : texts.data());
        // A table already in the data (a symmetry's copies of a transform, one embedded flame drawn
        // by several terms: 4 M numbers each) is pointed at, not put in again.
        const auto same = std::find_if(tables_.begin(), tables_.end(), [&](const std::pair<int, std::size_t>& placed) {
          return placed.second == table.size() &&
                 std::equal(table.begin(), table.end(), k_.data.begin() + placed.first,
                            [](double v, float f) { return static_cast<float>(v) == f; });
        });
        put(static_cast<double>(same != tables_.end() ? same->first : static_cast<int>(k_.data.size()) + 2));
        put(static_cast<double>(table.size()));
        if (same == tables_.end()) {
          tables_.emplace_back(static_cast<int>(k_.data.size()), table.size());
          put(table.data(), table.size());
        }
      }
      if (gpuVariationReadsDoubles(t.info->name)) {
        const std::vector<float> words = gpuDoubleParams(full);
        k_.data.insert(k_.data.end(), words.begin(), words.end());
      }
      k_.variations.push_back(t.info->name);
      const core::WeightFieldTerm& moved = t.field;
      std::string at = std::to_string(params);
      setup.clear();
      if (!moved.params.empty()) {
        // Everything the variation reads relative to P (xformUnsupported refused those whose numbers
        // are derived from the parameters), into gFieldBlock, each moved parameter scaled there.
        const std::size_t block = k_.data.size() - static_cast<std::size_t>(params);
        k_.fieldBlock = std::max(k_.fieldBlock, block);
        setup +=
            "  for (int i = 0; i < " + std::to_string(block) + "; ++i) gFieldBlock[i] = flameData[" + at + " + i];\n";
        for (const core::WeightFieldTerm::Param& moving : moved.params) {
          const std::string slot = "gFieldBlock[" + std::to_string(moving.index) + "]";
          const std::string scaled =
              slot + " * (1.0 + fieldN * flameData[" + std::to_string(put(moving.intensity)) + "])";
          // An integer parameter rounds half away from 0, as std::round (JWildfire's FTOI).
          setup += "  " + slot + " = " +
                   (moving.integer ? "sign(" + scaled + ") * floor(abs(" + scaled + ") + 0.5)" : scaled) + ";\n";
        }
        at = "kFieldBlock";
      }
      return "V_" + t.info->name + "(" + point + ", flameData[" + std::to_string(weight) + "], " + at + ", A)";
    };
    // A term's factor under the field: the field's, times its own weight's (WeightFieldTerm::weight).
    const auto factor = [&](const Term& t) -> std::string {
      const double weight = t.field.weight;
      if (weight == 0.0) return "field";
      return "field * (1.0 + fieldN * flameData[" + std::to_string(put(weight)) + "])";
    };
    // A pre_ or post_ term replaces the coordinates its variation maps (or adds to them, for an
    // additive one) and keeps the others: core's combineStage.
    const auto combine = [&](const Term& t, const char* point) {
      // One that reads the sum finds none here: its result is all it adds (core clears the output).
      std::string code = t.info->readsSum ? "  gSum = vec3(0.0);\n" : "";
      const std::string called = call(t, point);
      code += setup + "  { vec3 r = " + called + ";\n";
      if (field) code += "    r *= " + factor(t) + ";\n";
      const std::string op = t.info->additive ? " += " : " = ";
      if (t.info->mapsXY) code += std::string("    ") + point + ".xy" + op + "r.xy;\n";
      if (t.info->threeD) code += std::string("    ") + point + ".z" + op + "r.z;\n";
      if (t.info->name == "flatten") code += std::string("    ") + point + ".z = 0.0;\n";
      return code + "  }\n";
    };
    // The transform's point (gVariationT, core's VariationInput::tx), which depth and smartcrop read:
    // for a pre_ term the point it maps, for the others the point after the pre_ terms. The driver
    // drops the stores where no variation reads it. And the stage (gStage), for those that read it.
    if (!stages[0].empty()) s += "  gStage = 0;\n";
    for (const Term& t : stages[0]) s += "  gVariationT = t;\n" + combine(t, "t");
    s += "  gVariationT = t;\n  gStage = 1;\n";
    s += stages[1].empty() ? "  vec3 o = t;\n" : "  vec3 o = vec3(0.0);\n";
    bool flatten = false;
    for (const Term& t : stages[1]) {
      // A term that assigns where the others add (shredlin, mirror_x) discards the sum so far.
      using Replaces = core::VariationInfo::Replaces;
      if (t.info->replaces == Replaces::XY || t.info->replaces == Replaces::XYZ) s += "  o.xy = vec2(0.0);\n";
      if (t.info->replaces == Replaces::Z || t.info->replaces == Replaces::XYZ) s += "  o.z = 0.0;\n";
      const std::string called = call(t, "t");
      s += setup;
      if (t.info->readsSum && field)  // its change to the sum, scaled
        s += "  gSum = o;\n  o += " + factor(t) + " * (" + called + " - o);\n";
      else if (t.info->readsSum)
        s += "  gSum = o;\n  o = " + called + ";\n";  // it returns the new sum
      else if (field)
        s += "  o += " + factor(t) + " * " + called + ";\n";
      else
        s += "  o += " + called + ";\n";
      // An ordinary term may move the transform's point for the terms after it (crob, core's
      // movableX/Y); where none does, the driver folds this away.
      s += "  t = gVariationT;\n";
      flatten = flatten || t.info->name == "flatten";
    }
    if (flatten) s += "  o.z = 0.0;\n";  // as core's applyGroup: the sum's z, after every ordinary term
    if (!stages[2].empty()) s += "  gStage = 2;\n";
    for (const Term& t : stages[2]) s += combine(t, "o");
    if (xform.hasPost && !xform.post.isIdentity()) {
      const int post = put(xform.post.m.data(), 12);
      s += "  int Q = " + std::to_string(post) + ";\n";
      s += "  o = vec3(dot(vec3(flameData[Q], flameData[Q + 1], flameData[Q + 2]), o) + flameData[Q + 3],\n"
           "           dot(vec3(flameData[Q + 4], flameData[Q + 5], flameData[Q + 6]), o) + flameData[Q + 7],\n"
           "           dot(vec3(flameData[Q + 8], flameData[Q + 9], flameData[Q + 10]), o) + flameData[Q + 11]);\n";
    }
    if (field && xform.fieldJitter != 0.0) {
      // core::ChaosGame::jitterByField: each coordinate in turn, read at the point as moved so far.
      const std::string jitter = "flameData[" + std::to_string(put(0.1 * xform.fieldJitter)) + "]";
      const std::string noise = "weightFieldNoise(" + std::to_string(fieldAt) + ", ";
      s += "  o.x += " + jitter + " * " + noise + "vec3(o.x, o.y, o.z));\n";
      s += "  o.y += " + jitter + " * " + noise + "vec3(o.y, o.x, o.z));\n";
      s += "  o.z += " + jitter + " * " + noise + "vec3(o.z, o.x, o.y));\n";
    }
    const int opacity = put(xform.opacity);
    if (direct) {
      // Fractorium's Xform::Apply: saved + direct_color · (set − saved), NaN as 0.
      const int directColor = put(xform.directColor);
      s += "  c = saved + flameData[" + std::to_string(directColor) + "] * (gColour - saved);\n";
      s += "  c = isnan(c) ? 0.0 : c;\n";
    } else {
      s += "  c = flameData[" + std::to_string(blend) + "] * c + flameData[" + std::to_string(blend + 1) + "];\n";
    }
    if (field && xform.fieldColor != 0.0)  // core::ChaosGame::colourByField, after the blend
      s += "  c *= 1.0 + flameData[" + std::to_string(put(0.1 * xform.fieldColor)) + "] * fieldN;\n";
    // The point's true colour (core::ChaosGame::keepPaintedRgb): a transform's replaces it (none
    // painted: the colour index's), a final transform's only where it paints one.
    if (paintsRgb_ && !final) s += paints ? "  gPointRgb = gRgb;\n" : "  gPointRgb = 0u;\n";
    if (paintsRgb_ && final && paints) s += "  if (gRgb != 0u) gPointRgb = gRgb;\n";
    if (final)
      s += "  visible = visible && psi() < flameData[" + std::to_string(opacity) + "];\n";
    else if (xform.opacity < 1.0)
      s += "  visible = psi() < flameData[" + std::to_string(opacity) + "];\n";
    else
      s += "  visible = true;\n";
    s += "  return o;\n}\n";
  }

  // `vec3 <name>(vec3 p)`: p through one of `maps` drawn at random (core's throughOneOf).
  void oneOfFunction(const std::string& name, const std::vector<std::array<double, 12>>& maps) {
    std::string& s = k_.source;
    const int first = static_cast<int>(k_.data.size());
    for (const auto& m : maps) put(m.data(), 12);
    s += "vec3 " + name + "(vec3 p) {\n";
    s += "  uint high, low;\n";
    s += "  psi();\n";  // advances the stream; the draw is its whole word, as the CPU takes it
    s += "  umulExtended(gChaosRandom, " + std::to_string(maps.size()) + "u, high, low);\n";
    s += "  int M = " + std::to_string(first) + " + 12 * int(high);\n";
    s += "  return vec3(dot(vec3(flameData[M], flameData[M + 1], flameData[M + 2]), p) + flameData[M + 3],\n"
         "              dot(vec3(flameData[M + 4], flameData[M + 5], flameData[M + 6]), p) + flameData[M + 7],\n"
         "              dot(vec3(flameData[M + 8], flameData[M + 9], flameData[M + 10]), p) + flameData[M + 11]);\n";
    s += "}\n";
  }

  // Where the variations' palette lies in the data block (3 floats a colour), put there the first
  // time a term asks.
  int palette() {
    if (palette_ < 0) {
      palette_ = static_cast<int>(k_.data.size());
      for (const std::uint32_t c : variationPalette_)
        for (int channel = 0; channel < 3; ++channel)
          k_.data.push_back(static_cast<float>((c >> (8 * channel)) & 255u));
    }
    return palette_;
  }

  // Which of the kernel's parplot surfaces draws `term`'s formulas (one per set of formulas), −1
  // where muParser cannot read one.
  int surface(const core::VariationInfo& info, const core::VariationTerm& term) {
    const auto formulas = termFormulas(info, term);
    if (!formulas) return -1;
    const auto found = std::find(surfaces_.begin(), surfaces_.end(), *formulas);
    if (found != surfaces_.end()) return static_cast<int>(found - surfaces_.begin());
    surfaces_.push_back(*formulas);
    return static_cast<int>(surfaces_.size()) - 1;
  }
  const std::vector<std::array<std::string, 3>>& surfaces() const { return surfaces_; }

  // Where a transform's weighting field lies in the data block (weight_field.glsl's layout); puts
  // the noise tables first where its noise is simplex.
  int fieldBlock(const core::FlameXform& xform) {
    const int tables = xform.fieldNoise == core::WeightFieldNoise::Simplex ? noiseTables() : 0;
    k_.variations.emplace_back("weightFieldNoise");
    const int at = static_cast<int>(k_.data.size());
    const std::vector<float> block = gpuWeightFieldBlock(xform, tables);
    k_.data.insert(k_.data.end(), block.begin(), block.end());
    return at;
  }

  // Where the noise tables lie in the data block, put there the first time a term asks.
  int noiseTables() {
    if (noise_ < 0) {
      const std::vector<float> tables = gpuNoiseTables();
      noise_ = static_cast<int>(k_.data.size());
      k_.data.insert(k_.data.end(), tables.begin(), tables.end());
    }
    return noise_;
  }

 private:
  FlameKernel& k_;
  bool paintsRgb_ = false;
  std::array<std::uint32_t, 256> variationPalette_;
  std::size_t laneSlots_ = 0;                         // gLane's doubles given out so far
  std::vector<std::pair<int, std::size_t>> tables_;   // the variations' tables in the data: where, how long
  std::vector<std::array<std::string, 3>> surfaces_;  // parplot2d_wf's formulas, by surface
  int noise_ = -1, palette_ = -1;
};

void flameSource(const core::PatternLayer& layer, const core::ChaosGame& game, bool groupChoice, FlameKernel& kernel) {
  const std::vector<core::FlameXform> xforms = core::expandSymmetry(layer.flame);
  Generator g(kernel, game.paintsRgb(), game.variationPalette());
  std::string& s = kernel.source;
  s += "#define CHAOS_STATE vec4\n";
  if (game.paintsRgb()) s += "#define PAINTS_RGB\nuint gPointRgb;\n";  // the drawn point's (accumulate.comp.glsl)
  if (game.hidesPointsByTerm()) s += "#define HIDES_POINTS\n";
  kernel.laneMemory = laneMemory(xforms, layer.flame);
  for (std::size_t k = 0; k < xforms.size(); ++k) g.xformFunction("xform" + std::to_string(k), xforms[k], false);
  const core::FlameGenome& genome = layer.flame;
  if (genome.hasFinal) {
    g.xformFunction("finalXform", genome.finalXform, true);
    for (std::size_t k = 0; k < genome.chainedFinals.size(); ++k)
      g.xformFunction("chainedFinal" + std::to_string(k), genome.chainedFinals[k], true);
  }
  if (!game.symmetryGroupMaps().empty()) g.oneOfFunction("throughSymmetry", game.symmetryGroupMaps());
  if (!game.postSymmetryImages().empty()) g.oneOfFunction("throughPostSymmetry", game.postSymmetryImages());
  const std::vector<std::uint8_t>& pick = game.pickTable();
  kernel.pick.assign(pick.begin(), pick.end());

  const int shift = 32 - core::ChaosGame::pickBits();
  // Without xaos, a group of orbits may share each step's transform (GROUP_CHOICE in
  // accumulate.comp.glsl): the draw is then the group's, and chaosStepWith runs the one it names.
  // A flame with xaos picks per orbit, by the transform each took last.
  // Nor may orbits be dealt to other lanes when each lane keeps memory of its own orbit (gLane, gHidden).
  kernel.groupChoice =
      groupChoice && !game.usesXaos() && xforms.size() > 1 && kernel.laneMemory == 0 && !game.hidesPointsByTerm();
  if (kernel.groupChoice) s += "#define GROUP_CHOICE\n";
  s += "uint pickTransform(uint draw) { return flamePick[draw >> " + std::to_string(shift) + "]; }\n";
  s += "bool chaosStepWith(uint k, inout CHAOS_STATE state, inout float colour, out vec3 drawn,\n"
       "                   out float drawnColour);\n";
  s += "bool chaosStep(inout CHAOS_STATE state, inout float colour, inout uint previous, out vec3 drawn,\n"
       "               out float drawnColour) {\n";
  s += "  psi();\n";
  if (game.usesXaos()) {
    s += "  uint k = flamePick[(previous << " + std::to_string(core::ChaosGame::pickBits()) + ") | (gChaosRandom >> " +
         std::to_string(shift) + ")];\n";
    s += "  previous = k + 1u;\n";
  } else {
    s += "  uint k = pickTransform(gChaosRandom);\n";
  }
  s += "  return chaosStepWith(k, state, colour, drawn, drawnColour);\n}\n";
  s += "bool chaosStepWith(uint k, inout CHAOS_STATE state, inout float colour, out vec3 drawn,\n"
       "                   out float drawnColour) {\n";
  s += "  bool visible = true;\n  vec3 p = state.xyz;\n  switch (k) {\n";
  for (std::size_t k = 0; k < xforms.size(); ++k)
    s += "    case " + std::to_string(k) + "u: p = xform" + std::to_string(k) + "(p, colour, visible); break;\n";
  s += "  }\n  state.xyz = p;\n";
  // flam3's limit: a state beyond it has escaped (the caller reseeds what is not drawn finite).
  s += "  bool good = all(lessThan(abs(p), vec3(1e10)));\n";
  s += "  vec3 o = p;\n  float oc = colour;\n";
  if (genome.hasFinal) {
    s += "  o = finalXform(p, oc, visible);\n";
    for (std::size_t k = 0; k < genome.chainedFinals.size(); ++k)
      s += "  o = chainedFinal" + std::to_string(k) + "(o, oc, visible);\n";
  }
  if (!game.symmetryGroupMaps().empty()) s += "  o = throughSymmetry(o);\n";
  if (!game.postSymmetryImages().empty()) s += "  o = throughPostSymmetry(o);\n";
  s += "  drawn = good ? o : vec3(uintBitsToFloat(0x7fc00000u));\n";
  // A point a variation hid (JWildfire's doHide) is not drawn, though it goes on moving.
  s += game.hidesPointsByTerm() ? "  drawnColour = oc;\n  return visible && !gHidden;\n}\n"
                                : "  drawnColour = oc;\n  return visible;\n}\n";
  // A term whose formulas do not compile calls no surface (which −1), but its call is in the program,
  // so parplotSurface is defined wherever a term draws formulas.
  if (std::any_of(kernel.variations.begin(), kernel.variations.end(), [](const std::string& name) {
        return name == "parplot2d_wf" || name == "polarplot3d_wf" || name == "isosfplot3d_wf";
      }))
    s += gpuParplotSurfaces(g.surfaces());
}

// core::ChaosGame::stepJulia in double: the inverse iteration multiplies each coordinate by the
// root's scale at every step, and a coordinate that wanders small would underflow to 0 in float
// and stay there, collapsing old orbits onto a hyperplane the CPU's double orbits do not reach
// (qjulia-cage-orb drifted to 0.38 relative RMS from the CPU at 15 M points in float). The step is
// a square root and a few products, cheap even at a GPU's double rate.
void juliaSource(const core::PatternLayer& layer, FlameKernel& kernel) {
  Generator g(kernel);
  const core::QuaternionJuliaSettings& q = layer.julia;
  const double turn = q.turnDeg * 3.14159265358979323846 / 180.0;
  const std::array<double, 8> values{q.c.x, q.c.y, q.c.z, q.c.w, std::cos(turn), std::sin(turn), q.sliceW, q.thickness};
  g.put(values.data(), values.size());
  std::string& s = kernel.source;
  s += "#define CHAOS_STATE dvec4\n";
  s += "bool chaosStep(inout dvec4 state, inout float colour, inout uint previous, out vec3 drawn,\n"
       "               out float drawnColour) {\n"
       // The constant in double from its float halves would still be a float: the numbers it needs
       // in double are the state's, which the step keeps exact.
       "  dvec4 q = state - dvec4(flameData[0], flameData[1], flameData[2], flameData[3]);\n"
       "  double vectorPart = length(q.yzw);\n"
       "  double norm = sqrt(q.x * q.x + vectorPart * vectorPart);\n"
       "  double real = sqrt(max(0.0lf, 0.5lf * (norm + q.x)));\n"
       "  double imaginary = sqrt(max(0.0lf, 0.5lf * (norm - q.x)));\n"
       "  bool axis = vectorPart < 1e-300lf;\n"
       "  double scale = axis ? 0.0lf : imaginary / vectorPart;\n"
       "  psi();\n"
       "  bool negative = (gChaosRandom >> 31) != 0u;\n"
       "  double sgn = negative ? -1.0lf : 1.0lf;\n"
       "  state = sgn * dvec4(real, axis ? imaginary : q.y * scale, q.z * scale, q.w * scale);\n"
       "  colour = 0.5 * colour + (negative ? 0.5 : 0.0);\n"
       "  double turnedZ = double(flameData[4]) * state.z - double(flameData[5]) * state.w;\n"
       "  double turnedW = double(flameData[5]) * state.z + double(flameData[4]) * state.w;\n"
       "  drawn = vec3(state.x, state.y, turnedZ);\n"
       "  drawnColour = colour;\n";
  s += q.view == core::QuaternionView::Slice ? "  return abs(turnedW - double(flameData[6])) < double(flameData[7]);\n"
                                             : "  return true;\n";
  s += "}\n";
}

}  // namespace

bool gpuVariationReadsNoise(std::string_view name) {
  // crackle's and dc_crackle_wf's cells (the slice at the same place); dc_perlin's octaves, which
  // read only the tables' place of the extras.
  return name == "crackle" || name == "dc_crackle_wf" || name == "dc_perlin";
}

bool gpuVariationReadsDoubles(std::string_view name) {
  return name == "dc_inversion" || name == "dc_portal" || name == "dc_tesla" || name == "dc_warping" ||
         name == "fract_mandelbrot_wf" || name == "mandelbrot";
}

std::vector<float> gpuDoubleParams(const std::vector<double>& params) {
  // Carried in floats that are only copied, never computed with (as the noise's slice).
  std::vector<float> words;
  for (const double v : params) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    words.push_back(std::bit_cast<float>(static_cast<std::uint32_t>(bits)));
    words.push_back(std::bit_cast<float>(static_cast<std::uint32_t>(bits >> 32)));
  }
  return words;
}

std::string gpuParplotSurfaces(const std::vector<std::array<std::string, 3>>& surfaces) {
  std::string s = embeddedShader("parplot_functions.glsl").text;
  s += "vec3 parplotSurface(int which, float u, float v, int Q) {\n";
  s += "  float param_a = flameData[Q], param_b = flameData[Q + 1], param_c = flameData[Q + 2],\n"
       "        param_d = flameData[Q + 3], param_e = flameData[Q + 4], param_f = flameData[Q + 5];\n"
       "  switch (which) {\n";
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    std::array<std::string, 3> glsl;
    for (std::size_t axis = 0; axis < 3; ++axis) {
      ParplotGlsl translated = parplotFormulaGlsl(core::parplotMuParserText(surfaces[k][axis]));
      if (!translated.error.empty())
        throw core::Error("parplot formula '" + surfaces[k][axis] + "': " + translated.error);
      glsl[axis] = std::move(translated.glsl);
    }
    s += "    case " + std::to_string(k) + ":\n      return vec3(" + glsl[0] + ",\n                  " + glsl[1] +
         ",\n                  " + glsl[2] + ");\n";
  }
  return s + "  }\n  return vec3(0.0);\n}\n";
}

std::vector<float> gpuNoiseExtras(const std::vector<double>& params, int tables) {
  // The slice's bits, low word first (GLSL's packDouble2x32), carried in floats that are only
  // copied, never computed with.
  const auto bits = std::bit_cast<std::uint64_t>(params.at(4));
  return {std::bit_cast<float>(static_cast<std::uint32_t>(bits)),
          std::bit_cast<float>(static_cast<std::uint32_t>(bits >> 32)), static_cast<float>(tables)};
}

std::vector<float> gpuWeightFieldBlock(const core::FlameXform& xform, int tables) {
  std::vector<float> block;
  block.push_back(xform.fieldKind == core::WeightFieldKind::Noise ? 1.0f : 2.0f);
  for (const int code :
       {static_cast<int>(xform.fieldFractal), static_cast<int>(xform.fieldNoise),
        static_cast<int>(xform.fieldCellDistance), static_cast<int>(xform.fieldCellReturn), xform.fieldOctaves})
    block.push_back(static_cast<float>(code));
  block.push_back(static_cast<float>(xform.fieldFrequency));
  block.push_back(static_cast<float>(xform.fieldGain));
  block.push_back(static_cast<float>(xform.fieldLacunarity));
  block.push_back(std::bit_cast<float>(static_cast<std::int32_t>(xform.fieldSeed)));  // its bits, never computed with
  block.push_back(static_cast<float>(tables));
  if (xform.fieldNoise == core::WeightFieldNoise::Simplex) {
    const int octaves = xform.fieldKind == core::WeightFieldKind::Noise ? 1 : xform.fieldOctaves;
    for (int octave = 0; octave < octaves; ++octave) {
      const std::array<double, 3> offset = core::weightFieldSimplexOffset(
          static_cast<std::int32_t>(static_cast<std::uint32_t>(xform.fieldSeed) + static_cast<std::uint32_t>(octave)));
      const std::vector<float> words = gpuDoubleParams({offset.begin(), offset.end()});
      block.insert(block.end(), words.begin(), words.end());
    }
  }
  return block;
}

std::vector<float> gpuNoiseTables() {
  const core::SimplexNoiseTables& tables = core::simplexNoiseTables();
  std::vector<float> values(tables.hash.begin(), tables.hash.end());
  values.insert(values.end(), tables.gradients.begin(), tables.gradients.end());
  return values;
}

std::string gpuVariationSource(const std::vector<std::string>& variations) {
  const SplitVariations& split = splitVariations();
  // The pieces that are no function, the variations named, and every function those reach.
  std::vector<bool> wanted(split.pieces.size(), false);
  std::vector<int> pending;
  for (std::size_t i = 0; i < split.pieces.size(); ++i)
    if (split.pieces[i].function.empty()) pending.push_back(static_cast<int>(i));
  for (const std::string& name : variations) {
    auto found = split.functionPiece.find("V_" + name);
    if (found == split.functionPiece.end()) found = split.functionPiece.find(name);  // a helper the kernel calls
    if (found != split.functionPiece.end()) pending.push_back(found->second);
  }
  while (!pending.empty()) {
    const auto i = static_cast<std::size_t>(pending.back());
    pending.pop_back();
    if (wanted[i]) continue;
    wanted[i] = true;
    pending.insert(pending.end(), split.pieces[i].calls.begin(), split.pieces[i].calls.end());
  }
  std::string text;
  for (std::size_t i = 0; i < split.pieces.size(); ++i)
    if (wanted[i]) text += split.pieces[i].text;
  return text;
}

const std::vector<std::string>& gpuFlameVariations() {
  return splitVariations().names;
}

std::string flameKernelUnsupported(const core::PatternLayer& layer) {
  if (layer.kind == core::PatternKind::QuaternionJulia) return {};
  if (layer.kind != core::PatternKind::Flame) return "not a chaos-game layer";
  const core::FlameGenome& genome = layer.flame;
  std::vector<const core::FlameXform*> all;
  for (const core::FlameXform& xform : genome.xforms) all.push_back(&xform);
  if (genome.hasFinal) {
    all.push_back(&genome.finalXform);
    for (const core::FlameXform& xform : genome.chainedFinals) all.push_back(&xform);
  }
  std::set<std::string> embedded;  // the texts of the flames embedded by subflame terms
  for (const core::FlameXform* xform : all) {
    if (std::string why = xformUnsupported(*xform); !why.empty()) return why;
    for (const core::VariationTerm& term : xform->variations)
      if (const core::VariationInfo* info = core::findVariation(term.name);
          info && term.weight != 0.0 && core::embedsFlame(*info))
        embedded.insert(info->textsFor(term.texts).front());
  }
  // The kernel reads where a table starts as a float, exact up to 2²⁴; each embedded flame's cloud
  // is 4 × 2²⁰ numbers, so three fit beside everything else.
  if (embedded.size() > 3) return "more than three embedded flames";
  return {};
}

FlameKernel makeFlameKernel(const core::PatternLayer& layer, const core::ChaosGame& game, bool groupChoice) {
  FlameKernel kernel;
  kernel.source = "#define CHAOS_GAME\n";
  if (layer.kind == core::PatternKind::QuaternionJulia)
    juliaSource(layer, kernel);
  else
    flameSource(layer, game, groupChoice, kernel);
  if (kernel.pick.empty()) kernel.pick.push_back(0);  // a buffer is never empty
  return kernel;
}

}  // namespace voxflame::gl
