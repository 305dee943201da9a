// parplot2d_wf's formulas on the GPU (gl/parplot_glsl.cpp): the GLSL the kernel generator compiles
// computes what muParser computes on the CPU (core/flame/parplot_formula.cpp), formula by formula
// and point by point, for the grammar's corners and for random formulas; and what it cannot
// translate it refuses with a reason, never a crash.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/flame/flame.h"
#include "core/flame/parplot_formula.h"
#include "core/flame/variations.h"
#include "core/random.h"
#include "core/scene.h"
#include "gl/flame_kernel.h"
#include "gl/headless_context.h"
#include "gl/parplot_glsl.h"
#include "gl/shader_program.h"
#include "gl_test_support.h"

namespace voxflame {
namespace {

constexpr int kPoints = 64;

struct Evaluated {
  std::vector<float> gpu;  // formula k at point j: [k * kPoints + j]
  std::vector<double> cpu;
  std::vector<std::array<float, 2>> uv;
};

// Each formula at kPoints points (u, v) in [−3, 3]², with param_a … param_f fixed, on the GPU
// (through gpuParplotSurfaces, three formulas a surface) and with muParser.
Evaluated evaluate(const std::vector<std::string>& formulas) {
  Evaluated e;
  core::SplitMix64 rng(11);
  e.uv.resize(kPoints);
  for (auto& p : e.uv) p = {static_cast<float>(3.0 * rng.symmetric()), static_cast<float>(3.0 * rng.symmetric())};
  const std::array<double, 6> params = {0.7, -1.3, 0.25, 2.0, -0.5, 1.5};
  std::vector<std::array<std::string, 3>> surfaces;
  for (std::size_t k = 0; k < formulas.size(); k += 3)
    surfaces.push_back({formulas[k], k + 1 < formulas.size() ? formulas[k + 1] : "0",
                        k + 2 < formulas.size() ? formulas[k + 2] : "0"});

  const std::string text = "#version 430 core\n" + gl::gpuVariationSource({}) + gl::gpuParplotSurfaces(surfaces) +
                           "layout(local_size_x = 64) in;\n"
                           "layout(std430, binding = 0) buffer Points { vec2 uv[]; };\n"
                           "layout(std430, binding = 1) buffer Results { vec4 results[]; };\n"
                           "void main() {\n"
                           "  uint i = gl_GlobalInvocationID.x;\n"
                           "  vec2 p = uv[i % " +
                           std::to_string(kPoints) +
                           "u];\n"
                           "  results[i] = vec4(parplotSurface(int(i / " +
                           std::to_string(kPoints) + "u), p.x, p.y, 0), 0.0);\n}\n";
  const gl::ShaderProgram program(gl::ShaderSource{"parplot formulas", text});
  std::vector<float> data(params.begin(), params.end());
  std::vector<float> uv;
  for (const auto& p : e.uv) uv.insert(uv.end(), p.begin(), p.end());
  std::vector<float> results(surfaces.size() * kPoints * 4);
  std::array<GLuint, 3> buffers{};
  glGenBuffers(3, buffers.data());
  test::uploadStorage(buffers[0], 0, uv.size() * sizeof(float), uv.data());
  test::uploadStorage(buffers[1], 1, results.size() * sizeof(float), results.data());
  test::uploadStorage(buffers[2], 8, data.size() * sizeof(float), data.data());  // flameData
  glUseProgram(program.id());
  glDispatchCompute(static_cast<GLuint>(surfaces.size()), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffers[1]);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(results.size() * sizeof(float)),
                     results.data());
  glDeleteBuffers(3, buffers.data());

  e.gpu.resize(formulas.size() * kPoints);
  e.cpu.resize(formulas.size() * kPoints);
  for (std::size_t s = 0; s < surfaces.size(); ++s) {
    core::ParplotEvaluator evaluator(surfaces[s][0], surfaces[s][1], surfaces[s][2]);
    EXPECT_TRUE(evaluator.ok()) << surfaces[s][0] << " | " << surfaces[s][1] << " | " << surfaces[s][2];
    evaluator.setParams(params.data());
    for (int j = 0; j < kPoints; ++j) {
      const std::array<double, 3> cpu =
          evaluator(e.uv[static_cast<std::size_t>(j)][0], e.uv[static_cast<std::size_t>(j)][1]);
      for (std::size_t axis = 0; axis < 3 && 3 * s + axis < formulas.size(); ++axis) {
        const std::size_t k = 3 * s + axis;
        e.cpu[k * kPoints + static_cast<std::size_t>(j)] = cpu[axis];
        e.gpu[k * kPoints + static_cast<std::size_t>(j)] =
            results[(s * kPoints + static_cast<std::size_t>(j)) * 4 + axis];
      }
    }
  }
  return e;
}

// Float against double: both not finite (the chaos game drops the point either way), both far
// (float overflows sooner), or within float's rounding of nested operations.
bool agrees(float gpu, double cpu) {
  if (!std::isfinite(cpu) || std::abs(cpu) > 1e30) return !std::isfinite(gpu) || std::abs(gpu) > 1e29f;
  return std::abs(static_cast<double>(gpu) - cpu) <= 2e-3 * std::max(1.0, std::abs(cpu));
}

TEST(ParplotGlsl, ComputesWhatMuParserComputesAtTheGrammarsCorners) {
  if (!test::glAvailable()) GTEST_SKIP() << "no headless OpenGL context here";
  gl::HeadlessContext context;
  const std::vector<std::string> formulas = {
      // Precedence and associativity, as muParser reads them.
      "2^3^2 - u", "-u^2", "2^-u^2", "u--v", "-u*v+v/-2", "1?2:3?4:5", "0?2:0?4:5", "3>2>1", "u<v?u:v",
      "u+v<1&&v>0||u==v", "0.5&&1", "u||0", "-1.5&&u", "sign(0/0)+signum(u)", "!(u>0)+1", "u-v-1-param_a", "8/u/2",
      "u*v%1.5", "-7%4+u", "u>0 ? v>0 ? 1 : 2 : 3",
      // Functions of both libraries, and Java's spellings.
      "min(u,v,param_a)", "max(u,v)*2", "sum(u,v,1)", "avg(u,v,param_b)", "round(u*2.5)", "rint(u*2.5)",
      "sign(u)*abs(v)", "signum(v)", "fabs(u)+sqr(v)", "floor(u)+ceil(v)", "trunc(u*1.7)+frac(v*2.3)", "lgamma(u+4)",
      "lgamma(v*0.3+0.2)", "erf(v/2)", "cbrt(u*5)", "hypot(u,v)", "log1p(u*u)", "expm1(v/4)",
      "toDegrees(u)+toRadians(v*60)", "pow(u,2)+pow(-2,3)", "(-2)^3+u", "pow(u,1/3)", "0^0+u", "1/(u-u)", "fmod(u*3,v)",
      "fmod(u,v-v)", "u%(v-v)+1", "atan2(u,v)", "atan2(u,sqrt(-1))", "atan2(0,0)+u",
      "log(abs(u))+ln(abs(v)+1)+log10(abs(u)+1)+log2(abs(v)+1)", "exp(u)-sqrt(abs(v))", "sin(u)+cos(v)+tan(u/3)",
      "asin(u/3)+acos(v/3)+atan(u)", "sinh(u)+cosh(v)+tanh(u)", "asinh(u)+acosh(abs(v)+1)+atanh(u/4)",
      "_pi*_e+pi-PI+E-M_E", "M_PI+M_PI_2+M_PI_4+M_1_PI+M_2_PI+M_2PI+M_1_2PI+M_SQRT2+M_LOG2E",
      "EPSILON*1e8+SMALL_EPSILON+C_255", "TRUE && FALSE || TRUE", "1e-3*u+.5*v+5.e-1*param_c+2E1",
      "param_a+param_b*param_c-param_d/param_e^param_f", "Math.sin(u)*(1.0+0.3f*Math.cos(v))",
      "MathLib.sqr(Math.cos(u))*2d", "(double)v/M_PI - (float) u", ""};
  std::vector<std::string> texts;
  for (const std::string& f : formulas) {
    const gl::ParplotGlsl glsl = gl::parplotFormulaGlsl(core::parplotMuParserText(f));
    EXPECT_TRUE(glsl.error.empty()) << f << ": " << glsl.error;
    texts.push_back(f);
  }
  const Evaluated e = evaluate(texts);
  for (std::size_t k = 0; k < texts.size(); ++k)
    for (int j = 0; j < kPoints; ++j) {
      const std::size_t at = k * kPoints + static_cast<std::size_t>(j);
      EXPECT_TRUE(agrees(e.gpu[at], e.cpu[at]))
          << "'" << texts[k] << "' at u = " << e.uv[static_cast<std::size_t>(j)][0]
          << ", v = " << e.uv[static_cast<std::size_t>(j)][1] << ": GPU " << e.gpu[at] << ", muParser " << e.cpu[at];
    }
}

// A random formula of the grammar, often without parentheses so that precedence decides.
std::string randomFormula(core::SplitMix64& rng, int depth) {
  const auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng.uniform() * static_cast<double>(n)); };
  if (depth == 0 || rng.uniform() < 0.25) {
    static const char* kLeaves[] = {"u", "v", "param_a", "param_d", "2", "0.5", ".25", "3e-1", "pi", "M_PI_2", "1.5"};
    return kLeaves[pick(std::size(kLeaves))];
  }
  const std::string a = randomFormula(rng, depth - 1);
  const double kind = rng.uniform();
  if (kind < 0.1) return "-" + a;
  if (kind < 0.15) return "(" + a + ")";
  if (kind < 0.6) {
    static const char* kOperators[] = {"+", "-", "*", "/", "^", "%", "<", ">=", "==", "!=", "&&", "||", "+", "*"};
    const std::string b = randomFormula(rng, depth - 1);
    const std::string op = kOperators[pick(std::size(kOperators))];
    return rng.uniform() < 0.5 ? a + op + b : "(" + a + op + b + ")";
  }
  if (kind < 0.7) return "(" + a + " ? " + randomFormula(rng, depth - 1) + " : " + randomFormula(rng, depth - 1) + ")";
  static const char* kOne[] = {"sin", "cos", "atan", "tanh", "exp",  "sqrt",  "abs",    "floor", "round", "frac",
                               "sqr", "log", "erf",  "cbrt", "sign", "asinh", "lgamma", "trunc", "rint",  "log1p"};
  static const char* kTwo[] = {"pow", "atan2", "fmod", "hypot", "min", "max", "avg", "sum"};
  if (kind < 0.9) return std::string(kOne[pick(std::size(kOne))]) + "(" + a + ")";
  return std::string(kTwo[pick(std::size(kTwo))]) + "(" + a + ", " + randomFormula(rng, depth - 1) + ")";
}

TEST(ParplotGlsl, RandomFormulasComputeWhatMuParserComputes) {
  if (!test::glAvailable()) GTEST_SKIP() << "no headless OpenGL context here";
  gl::HeadlessContext context;
  core::SplitMix64 rng(2024);
  std::vector<std::string> formulas;
  while (formulas.size() < 240) {
    const std::string f = randomFormula(rng, 4);
    if (core::parplotFormulaError(f)) continue;  // the generator writes only what muParser reads
    const gl::ParplotGlsl glsl = gl::parplotFormulaGlsl(core::parplotMuParserText(f));
    ASSERT_TRUE(glsl.error.empty()) << f << ": " << glsl.error;
    formulas.push_back(f);
  }
  // Five surfaces a program, as a kernel holds a few (with eighty in one, llvmpipe once computed the
  // last one wrong where the first held a remainder by 0).
  Evaluated e;
  for (std::size_t k = 0; k < formulas.size(); k += 15) {
    const Evaluated part = evaluate(std::vector<std::string>(formulas.begin() + static_cast<std::ptrdiff_t>(k),
                                                             formulas.begin() + static_cast<std::ptrdiff_t>(k + 15)));
    e.gpu.insert(e.gpu.end(), part.gpu.begin(), part.gpu.end());
    e.cpu.insert(e.cpu.end(), part.cpu.begin(), part.cpu.end());
  }
  std::size_t agreeing = 0, finite = 0;
  for (std::size_t k = 0; k < formulas.size(); ++k) {
    std::size_t here = 0;
    for (int j = 0; j < kPoints; ++j) {
      const std::size_t at = k * kPoints + static_cast<std::size_t>(j);
      here += agrees(e.gpu[at], e.cpu[at]) ? 1 : 0;
      finite += std::isfinite(e.cpu[at]) ? 1 : 0;
    }
    agreeing += here;
    // Float against double parts where a value lies within float's rounding of a step (floor,
    // a comparison) or a branch: a point or two, never most of them.
    EXPECT_GE(here, kPoints * 3 / 4) << k << " '" << formulas[k] << "' agrees at " << here << " of " << kPoints
                                     << " points; at the first, GPU " << e.gpu[k * kPoints] << ", muParser "
                                     << e.cpu[k * kPoints];
  }
  const std::size_t total = formulas.size() * kPoints;
  std::printf("random formulas: %zu of %zu values agree (%zu finite on the CPU)\n", agreeing, total, finite);
  EXPECT_GE(static_cast<double>(agreeing), 0.98 * static_cast<double>(total));
  EXPECT_GE(static_cast<double>(finite), 0.5 * static_cast<double>(total)) << "the formulas are mostly NaN: no test";
}

TEST(ParplotGlsl, RefusesWhatItCannotTranslateWithAReasonAndNeverCrashes) {
  const auto error = [](const std::string& text) { return gl::parplotFormulaGlsl(text).error; };
  EXPECT_NE(error("u=3").find("assignment"), std::string::npos);
  EXPECT_NE(error("gamma(u)").find("function 'gamma'"), std::string::npos);
  EXPECT_NE(error("w*2").find("name 'w'"), std::string::npos);
  EXPECT_NE(error("sin(u, v)").find("'sin' with 2 arguments"), std::string::npos);
  EXPECT_NE(error("(u+v").find("without its ')'"), std::string::npos);
  EXPECT_NE(error("u ? v").find("':'"), std::string::npos);
  EXPECT_NE(error(std::string(100000, '(') + "u").find("nesting deeper"), std::string::npos);
  EXPECT_NE(error(std::string(100000, '-') + "u").find("nesting deeper"), std::string::npos);
  // Names reach the GLSL only as the translator spells them: no text of the formula passes through.
  EXPECT_FALSE(error("u; discard").empty());
  EXPECT_FALSE(error("flameData[0]").empty());
  // Random bytes and random cuts of real formulas: a translation or a reason, nothing else.
  core::SplitMix64 rng(5);
  const std::string alphabet = "uv+-*/^%()?:<>=!&|,. 0123456789eEpiasncotxqrlgf_";
  for (int k = 0; k < 20000; ++k) {
    std::string text;
    const std::size_t length = static_cast<std::size_t>(rng.uniform() * 40.0);
    for (std::size_t i = 0; i < length; ++i)
      text += alphabet[static_cast<std::size_t>(rng.uniform() * static_cast<double>(alphabet.size()))];
    const gl::ParplotGlsl glsl = gl::parplotFormulaGlsl(text);
    EXPECT_NE(glsl.glsl.empty(), glsl.error.empty()) << text;
  }
}

// A parplot2d_wf whose formulas the GPU cannot translate keeps the flame on the CPU, named; one
// whose formulas muParser cannot read runs (it adds nothing on either backend).
TEST(ParplotGlsl, AFormulaTheGpuCannotReadKeepsTheFlameOnTheCpuSayingWhy) {
  core::PatternLayer layer;
  layer.kind = core::PatternKind::Flame;
  layer.flame = core::defaultFlame();
  core::VariationTerm term{"parplot2d_wf", 0.5, core::variationOrThrow("parplot2d_wf").defaultParams()};
  term.texts = {"u=3", "v", "0"};
  layer.flame.xforms.front().variations.push_back(term);
  EXPECT_NE(gl::flameKernelUnsupported(layer).find("what a parplot2d_wf formula asks: an assignment"),
            std::string::npos)
      << gl::flameKernelUnsupported(layer);
  layer.flame.xforms.front().variations.back().texts = {"sin(", "v", "0"};
  EXPECT_EQ(gl::flameKernelUnsupported(layer), "");
  layer.flame.xforms.front().variations.back().texts = {"sin(u)*param_a", "v^2", "u<v ? 1 : 0"};
  EXPECT_EQ(gl::flameKernelUnsupported(layer), "");
}

}  // namespace
}  // namespace voxflame
