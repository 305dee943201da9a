// JWildfire's parplot2d_wf draws a surface given by three formulas of u, v and param_a … param_f,
// which the CPU evaluates with muParser (core/flame/parplot_formula.cpp). The GPU's kernel generator
// compiles them into the kernel instead: this translates muParser's text into a GLSL float
// expression that computes what muParser's double evaluation does, operator for operator: its
// precedence (the power right to left, signs below it, `?:` lowest), comparisons and logic giving
// 1 or 0, Java's % and Math.round, C's pow of a negative base.
#pragma once

#include <string>
#include <string_view>

namespace voxflame::gl {

struct ParplotGlsl {
  std::string glsl;   // a float expression of u, v and param_a … param_f; empty when it failed
  std::string error;  // why it cannot be translated (a name or form the GPU lacks), or empty
};

// `muParserText`: a formula as core::parplotMuParserText gives it, which muParser reads. The GLSL
// calls the functions of shaders/parplot_functions.glsl.
ParplotGlsl parplotFormulaGlsl(std::string_view muParserText);

}  // namespace voxflame::gl
