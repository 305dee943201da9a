// A flame layer's editor: its transforms, each one's affine maps, variations and colour, the xaos
// matrix, the final transform and symmetry. Changes the layer's flame genome.
#include "explorer_ui.h"

#include <imgui.h>

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <sstream>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <utility>

#include "core/attractor.h"
#include "core/flame/flame.h"
#include "core/flame/search.h"
#include "core/flame/variations.h"
#include "core/scene_schema.h"
#include "panels.h"
#include "widgets.h"

namespace voxflame::app::panels {

// ---------------------------------------------------------------------------------------------
// Chaos-game layers: the kind of a layer, a flame's transforms and variations, a Julia set.

// A layer's kind; a new kind starts from its defaults (the default flame, the classic Julia set,
// the attractor catalogue's first-layer default) and the colour mode that suits it.
void patternKindChoice(Ui& ui, PatternPanelState& pattern, std::size_t index, const std::string& scope,
                       core::PatternLayer& layer) {
  static constexpr const char* kKindLabels[] = {"attractor", "flame", "quaternion Julia"};
  const int current = static_cast<int>(layer.kind);
  if (ImGui::BeginCombo("pattern", kKindLabels[current])) {
    for (int k = 0; k < 3; ++k) {
      const bool chosen = ImGui::Selectable(kKindLabels[k], k == current);
      probe(ui, scope + "pattern/" + kKindLabels[k]);
      if (!chosen || k == current) continue;
      const core::PatternLayer defaults;
      layer.kind = static_cast<core::PatternKind>(k);
      if (layer.isChaosGame()) {
        layer.attractor.clear();
        layer.params.clear();
        layer.flame = layer.kind == core::PatternKind::Flame ? core::defaultFlame() : core::FlameGenome{};
        layer.julia = core::QuaternionJuliaSettings{};
        layer.color.mode = core::ColorMode::Index;
      } else {
        const core::AttractorInfo& info = core::attractorOrThrow(defaults.attractor);
        layer.attractor = info.id;
        layer.params = info.defaultParams();
        layer.step = info.defaultStep;
        layer.integrator = info.defaultIntegrator;
        layer.flame = {};
        layer.julia = {};
        if (layer.color.mode == core::ColorMode::Index) layer.color.mode = core::ColorMode::Speed;
      }
      pattern.selectedXform[index] = 0;
      // The still method follows the pattern's default: a flame shows its filaments as points.
      core::Scene& scene = ui.document.scene;
      const core::RenderMethod method = core::defaultRenderMethod(scene.layers);
      const bool methodChanged = scene.render.method != method;
      scene.render.method = method;
      ui.document.edited(methodChanged ? core::Affects::Pattern | core::Affects::Still : core::Affects::Pattern);
    }
    ImGui::EndCombo();
  }
  probe(ui, scope + "pattern");
}

// The length of column `col` of the 3×3 part: how much the map stretches its own axis `col`.
double columnLength(const std::array<double, 12>& m, int col) {
  const auto c = static_cast<std::size_t>(col);
  return std::sqrt(m[c] * m[c] + m[4 + c] * m[4 + c] + m[8 + c] * m[8 + c]);
}

// rotation about x, then y, then z (degrees), as a 3×3 row-major matrix.
std::array<double, 9> eulerRotation(const double degrees[3]) {
  const double a = glm::radians(degrees[0]), b = glm::radians(degrees[1]), c = glm::radians(degrees[2]);
  const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b), cc = std::cos(c),
               sc = std::sin(c);
  // Rz · Ry · Rx
  return {cc * cb,
          cc * sb * sa - sc * ca,
          cc * sb * ca + sc * sa,  //
          sc * cb,
          sc * sb * sa + cc * ca,
          sc * sb * ca - cc * sa,  //
          -sb,
          cb * sa,
          cb * ca};
}

// Translate, rotate and scale handles for one affine map, then its 12 numbers on request. The
// rotate handle turns the matrix about the transform's own frame (M ← M · R), so its scales and
// offset stay; the scale handles set the length of each column of the 3×3 part.
void affineEditor(Ui& ui, PatternPanelState& pattern, const std::string& scope, core::Affine3& affine) {
  std::array<double, 12>& m = affine.m;
  double translate[3] = {m[3], m[7], m[11]};
  const double minT = -3.0, maxT = 3.0;
  if (reportEdit(ui,
                 ImGui::SliderScalarN("translate", ImGuiDataType_Double, translate, 3, &minT, &maxT, "%.3f", kClamp),
                 core::Affects::Pattern))
    m[3] = translate[0], m[7] = translate[1], m[11] = translate[2];
  probe(ui, scope + "translate");

  const std::string rotateId = scope + "rotate";
  const bool rotatingThis = pattern.rotatingId == rotateId;
  double shown[3] = {0.0, 0.0, 0.0};
  if (rotatingThis) std::copy(std::begin(pattern.rotateAngles), std::end(pattern.rotateAngles), shown);
  const double minDeg = -180.0, maxDeg = 180.0;
  // Relative: each drag turns the map from where it is, so the handle reads +0° before and after one.
  const bool turned =
      ImGui::SliderScalarN("turn by", ImGuiDataType_Double, shown, 3, &minDeg, &maxDeg, "%+.0f°", kClamp);
  probe(ui, rotateId);
  if (ImGui::IsItemActivated()) {
    pattern.rotatingId = rotateId;
    pattern.rotateStart = m;
  }
  if (reportEdit(ui, turned && pattern.rotatingId == rotateId, core::Affects::Pattern)) {
    std::copy(std::begin(shown), std::end(shown), pattern.rotateAngles);
    const std::array<double, 9> r = eulerRotation(shown);
    for (int row = 0; row < 3; ++row)
      for (int col = 0; col < 3; ++col) {
        double sum = 0.0;
        for (int k = 0; k < 3; ++k)
          sum += pattern.rotateStart[static_cast<std::size_t>(row * 4 + k)] * r[static_cast<std::size_t>(k * 3 + col)];
        m[static_cast<std::size_t>(row * 4 + col)] = sum;
      }
  }
  if (ImGui::IsItemDeactivated() && pattern.rotatingId == rotateId) {
    pattern.rotatingId.clear();
    if (m != pattern.rotateStart) {
      pattern.turnedId = rotateId;
      std::copy(std::begin(pattern.rotateAngles), std::end(pattern.rotateAngles), pattern.turnedAngles.begin());
      pattern.turnedResult = m;
    }
    std::fill(std::begin(pattern.rotateAngles), std::end(pattern.rotateAngles), 0.0);
  }
  if (ImGui::IsItemHovered() && !ImGui::IsItemActive())
    ImGui::SetTooltip(
        "relative: drag to turn the map by so many degrees about its own x, y and z axes.\n"
        "Each drag starts at +0° and the turn stays when you let go (Ctrl+Z undoes it).");
  if (pattern.turnedId == rotateId && pattern.turnedResult == m && !rotatingThis) {
    dimText("turned by %+.0f°, %+.0f°, %+.0f° (Ctrl+Z undoes)", pattern.turnedAngles[0], pattern.turnedAngles[1],
            pattern.turnedAngles[2]);
    probe(ui, scope + "turned");
  }

  double scales[3] = {columnLength(m, 0), columnLength(m, 1), columnLength(m, 2)};
  const double minS = 0.01, maxS = 2.0;
  // Absolute, unlike the turn: each value is the length of one axis of the map, and stays as dragged.
  if (reportEdit(ui,
                 ImGui::SliderScalarN("axis lengths", ImGuiDataType_Double, scales, 3, &minS, &maxS, "%.3f", kClamp),
                 core::Affects::Pattern))
    for (int col = 0; col < 3; ++col) {
      const double length = columnLength(m, col);
      const auto c = static_cast<std::size_t>(col);
      if (length > 1e-12) {
        const double factor = scales[col] / length;
        m[c] *= factor, m[4 + c] *= factor, m[8 + c] *= factor;
      } else {  // a collapsed axis comes back along itself
        m[c] = m[4 + c] = m[8 + c] = 0.0;
        m[static_cast<std::size_t>(col * 4 + col)] = scales[col];
      }
    }
  probe(ui, scope + "scale");
  if (ImGui::IsItemHovered() && !ImGui::IsItemActive())
    ImGui::SetTooltip("absolute: the length of the map's x, y and z axes (1 keeps a length; under 1 contracts)");

  if (ImGui::TreeNode("numbers")) {
    static constexpr const char* kRows[] = {"x' = x y z 1", "y' = x y z 1", "z' = x y z 1"};
    const double minV = -100.0, maxV = 100.0;
    for (int row = 0; row < 3; ++row) {
      reportEdit(ui,
                 ImGui::DragScalarN(kRows[row], ImGuiDataType_Double, &m[static_cast<std::size_t>(row * 4)], 4, 0.002f,
                                    &minV, &maxV, "%.3f", kClamp),
                 core::Affects::Pattern);
      probe(ui, scope + "row" + std::to_string(row));
    }
    ImGui::TreePop();
  }
}

// A transform's variations: weight and parameter sliders each, remove buttons, and a filterable
// list of the whole catalogue to add from.
void variationsEditor(Ui& ui, PatternPanelState& pattern, const std::string& scope, core::FlameXform& xform) {
  std::size_t removeIndex = xform.variations.size();
  for (std::size_t v = 0; v < xform.variations.size(); ++v) {
    core::VariationTerm& term = xform.variations[v];
    const core::VariationInfo* info = core::findVariation(term.name);
    const std::string vscope = scope + "var" + std::to_string(v) + "/";
    ImGui::PushID(static_cast<int>(v));
    // The weight slider, its remove button, then the variation's name where labels go (or above,
    // when it is too long for them); its formula is the tooltip.
    const bool nameBeside = labelFitsBeside(ui, term.name, vscope + "weight");
    if (!nameBeside) labelAbove(ui, term.name, vscope + "weight");
    const double minW = -2.0, maxW = 2.0;
    ImGui::SetNextItemWidth(ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - ImGui::GetStyle().ItemSpacing.x);
    reportEdit(ui,
               ImGui::SliderScalar("##weight", ImGuiDataType_Double, &term.weight, &minW, &maxW, "weight %.3f", kClamp),
               core::Affects::Pattern);
    probe(ui, vscope + "weight");
    if (ImGui::IsItemHovered() && !ImGui::IsItemActive())
      ImGui::SetTooltip("%s\n%s", term.name.c_str(), info ? info->formula.c_str() : "");
    ImGui::SameLine();
    if (ImGui::SmallButton("x")) removeIndex = v;
    probe(ui, vscope + "remove");
    if (nameBeside) {
      ImGui::SameLine();
      ImGui::TextUnformatted(term.name.c_str());
    }
    if (info && term.params.size() == info->params.size()) {
      ImGui::Indent();
      for (std::size_t p = 0; p < info->params.size(); ++p) {
        const core::VariationParam& param = info->params[p];
        // Under its variation's row, a parameter is named by itself, its words apart ("center x"):
        // the variation's name before it left no room for the axis that tells its three apart.
        std::string label = param.name;
        std::replace(label.begin(), label.end(), '_', ' ');
        ImGui::PushID(static_cast<int>(p));
        const bool beside = labelFitsBeside(ui, label, vscope + param.name);
        if (!beside) labelAbove(ui, label, vscope + param.name);
        const std::string widgetLabel = beside ? label : "##" + label;
        if (param.integer) {
          int value = static_cast<int>(std::lround(term.params[p]));
          if (reportEdit(ui,
                         ImGui::SliderInt(widgetLabel.c_str(), &value, static_cast<int>(std::ceil(param.sliderMin)),
                                          static_cast<int>(std::floor(param.sliderMax)), "%d", kClamp),
                         core::Affects::Pattern))
            term.params[p] = value;
        } else {
          reportEdit(ui,
                     ImGui::SliderScalar(widgetLabel.c_str(), ImGuiDataType_Double, &term.params[p], &param.sliderMin,
                                         &param.sliderMax, "%.3f", kClamp),
                     core::Affects::Pattern);
        }
        probe(ui, vscope + param.name);
        parameterReset(ui, term.params[p], param.defaultValue, "right-click to reset", term.name + " " + param.name);
        ImGui::PopID();
      }
      ImGui::Unindent();
    }
    ImGui::PopID();
  }
  if (reportEdit(ui, removeIndex < xform.variations.size(), core::Affects::Pattern))
    xform.variations.erase(xform.variations.begin() + static_cast<std::ptrdiff_t>(removeIndex));

  ImGui::BeginDisabled(xform.variations.size() >= core::kMaxXformVariations);
  if (ImGui::BeginCombo("add variation", "choose…", ImGuiComboFlags_HeightLarge)) {
    if (ImGui::IsWindowAppearing()) {
      pattern.variationFilter[0] = '\0';
      takeKeyboard(ui);
    }
    ImGui::InputTextWithHint("##variationfilter", "filter", pattern.variationFilter, sizeof pattern.variationFilter);
    noteTyped(ui, "variation filter", pattern.variationFilter);
    const std::string filter = lowercase(pattern.variationFilter);
    for (const core::VariationInfo& info : core::variationCatalogue()) {
      if (!filter.empty() && lowercase(info.name).find(filter) == std::string::npos) continue;
      const bool chosen = ImGui::Selectable(info.name.c_str());
      probe(ui, scope + "add/" + info.name);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", info.formula.c_str());
      if (chosen) {
        // A new term starts small, so adding one bends the flame rather than replacing it.
        xform.variations.push_back({info.name, xform.variations.empty() ? 1.0 : 0.25, info.defaultParams()});
        ui.document.edited(core::Affects::Pattern);
      }
    }
    ImGui::EndCombo();
  }
  probe(ui, scope + "add variation");
  ImGui::EndDisabled();
}

// Xaos (flam3's chaos) as a matrix: row i is transform i's xaos, and its cell in column j scales
// transform j's weight when the transform after i is chosen (1 is no xaos, 0 forbids the step). A
// missing factor is 1. The final transform has no row or column: flam3 gives it no xaos. Each
// cell is an ordinary ImGui item, so handleHistory records a whole drag as one undo step.
//
// ImGui 1.86 tables hold at most 64 columns (IMGUI_TABLE_MAX_COLUMNS) and a flame up to 128
// transforms, so wide flames show their "to" columns a page at a time.
constexpr std::size_t kXaosColumnsPerPage = 32;
constexpr std::size_t kXaosVisibleRows = 8;  // taller matrices scroll, their header row frozen
constexpr double kXaosMin = 0.0, kXaosMax = 5.0;

double xaosFactor(const core::FlameXform& from, std::size_t to) {
  return to < from.xaos.size() ? from.xaos[to] : 1.0;
}

// A cell's tint: red where the step is forbidden, blue where it is less likely, amber where it is
// more likely; none at 1, so a flame without xaos shows a plain matrix.
ImU32 xaosCellColor(double factor) {
  if (factor == 0.0) return IM_COL32(180, 50, 40, 120);
  return factor < 1.0 ? IM_COL32(50, 100, 190, 110) : IM_COL32(200, 150, 30, 110);
}

// The "to" columns shown: all of them, or for flames wider than a page the page chosen in a combo.
std::pair<std::size_t, std::size_t> xaosColumnPage(Ui& ui, PatternPanelState& pattern, std::size_t index,
                                                   const std::string& scope, std::size_t count) {
  if (count <= kXaosColumnsPerPage) return {0, count};
  const auto pageLabel = [count](std::size_t page) {
    const std::size_t first = page * kXaosColumnsPerPage;
    return "to " + std::to_string(first + 1) + "–" + std::to_string(std::min(count, first + kXaosColumnsPerPage));
  };
  const std::size_t pages = (count + kXaosColumnsPerPage - 1) / kXaosColumnsPerPage;
  std::size_t& page = pattern.xaosColumnPage[index];
  page = std::min(page, pages - 1);  // the flame may have lost transforms since
  if (ImGui::BeginCombo("columns", pageLabel(page).c_str())) {
    for (std::size_t p = 0; p < pages; ++p) {
      const std::string label = pageLabel(p);
      if (ImGui::Selectable(label.c_str(), p == page)) page = p;
      probe(ui, scope + "xaos columns/" + label);
    }
    ImGui::EndCombo();
  }
  probe(ui, scope + "xaos columns");
  const std::size_t first = page * kXaosColumnsPerPage;
  return {first, std::min(count, first + kXaosColumnsPerPage)};
}

// The matrix under an "Xaos" tree node: a row per transform (named by number, as the transform
// buttons name them, the selected one highlighted) with its reset button, a column per transform,
// and a reset for the whole matrix. Cells are probed as "xaos <from> to <to>", both 1-based.
void xaosMatrix(Ui& ui, PatternPanelState& pattern, std::size_t index, const std::string& scope,
                core::FlameGenome& flame, int selected) {
  const bool open = ImGui::TreeNode("Xaos");
  probe(ui, scope + "Xaos");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("row: the transform just applied; column: the next one, chosen by its weight times this factor");
  if (!open) return;
  const std::size_t count = flame.xforms.size();
  const auto [firstColumn, endColumn] = xaosColumnPage(ui, pattern, index, scope, count);

  const ImGuiStyle& style = ImGui::GetStyle();
  const float cellWidth = ImGui::CalcTextSize("0.000").x + 2.0f * style.FramePadding.x;
  const float rowHeight = ImGui::GetFrameHeight() + 2.0f * style.CellPadding.y;
  // Room for the header, up to kXaosVisibleRows rows and a horizontal scroll bar.
  const float height = ImGui::GetTextLineHeight() + 2.0f * style.CellPadding.y +
                       rowHeight * static_cast<float>(std::min(count, kXaosVisibleRows)) + style.ScrollbarSize;
  constexpr ImGuiTableFlags kFlags =
      ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX | ImGuiTableFlags_ScrollY;
  // The transform's number and its reset button stay in view while the factors scroll.
  constexpr int kFrozenColumns = 2;
  const int columns = kFrozenColumns + static_cast<int>(endColumn - firstColumn);
  if (ImGui::BeginTable("xaos matrix", columns, kFlags, ImVec2(0.0f, height))) {
    ImGui::TableSetupScrollFreeze(kFrozenColumns, 1);
    ImGui::TableSetupColumn("from\\to");
    ImGui::TableSetupColumn("##reset");
    for (std::size_t to = firstColumn; to < endColumn; ++to)
      ImGui::TableSetupColumn(std::to_string(to + 1).c_str(), ImGuiTableColumnFlags_WidthFixed, cellWidth);
    ImGui::TableHeadersRow();
    for (std::size_t from = 0; from < count; ++from) {
      core::FlameXform& row = flame.xforms[from];
      const std::string fromName = std::to_string(from + 1);
      ImGui::PushID(static_cast<int>(from));
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::AlignTextToFramePadding();
      ImGui::TextUnformatted(fromName.c_str());
      if (static_cast<int>(from) == selected)
        ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, ImGui::GetColorU32(ImGuiCol_Header));
      ImGui::TableNextColumn();
      ImGui::BeginDisabled(row.xaos.empty());
      if (reportEdit(ui, ImGui::SmallButton("reset"), core::Affects::Pattern)) row.xaos.clear();
      probe(ui, scope + "xaos reset " + fromName);
      ImGui::EndDisabled();
      for (std::size_t to = firstColumn; to < endColumn; ++to) {
        ImGui::TableNextColumn();
        ImGui::PushID(static_cast<int>(to));
        double factor = xaosFactor(row, to);
        ImGui::SetNextItemWidth(-FLT_MIN);
        if (reportEdit(ui,
                       ImGui::DragScalar("##factor", ImGuiDataType_Double, &factor, 0.01f, &kXaosMin, &kXaosMax, "%.2f",
                                         kClamp),
                       core::Affects::Pattern)) {
          if (row.xaos.size() <= to) row.xaos.resize(to + 1, 1.0);
          row.xaos[to] = factor;
        }
        const std::string toName = std::to_string(to + 1);
        probe(ui, scope + "xaos " + fromName + " to " + toName);
        if (ImGui::IsItemHovered() && !ImGui::IsItemActive())
          ImGui::SetTooltip("after %s, %s's weight × %.3f (0: never) — drag, or double-click to type", fromName.c_str(),
                            toName.c_str(), factor);
        if (factor != 1.0) ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, xaosCellColor(factor));
        ImGui::PopID();
      }
      ImGui::PopID();
    }
    ImGui::EndTable();
  }
  const bool anyXaos =
      std::any_of(flame.xforms.begin(), flame.xforms.end(), [](const core::FlameXform& x) { return !x.xaos.empty(); });
  ImGui::BeginDisabled(!anyXaos);
  if (reportEdit(ui, button(ui, scope, "Reset xaos"), core::Affects::Pattern))
    for (core::FlameXform& x : flame.xforms) x.xaos.clear();
  ImGui::EndDisabled();
  ImGui::TreePop();
}

// One transform: weight (not for the final one), colour, colour speed, opacity (and direct colour), the affine map
// and an optional post map, the variations. Its xaos is a row of the flame's xaos matrix.
void xformEditor(Ui& ui, PatternPanelState& pattern, const std::string& scope, core::FlameXform& xform, bool isFinal) {
  if (!isFinal) fieldWidget(ui, scope, xform, core::xformFields(), "weight");
  fieldWidget(ui, scope, xform, core::xformFields(), "color");
  fieldWidget(ui, scope, xform, core::xformFields(), "color_speed");
  fieldWidget(ui, scope, xform, core::xformFields(), "opacity");
  // The direct colour matters only to a transform with a variation that sets the colour (dc_linear, ...).
  if (std::any_of(xform.variations.begin(), xform.variations.end(), [](const core::VariationTerm& term) {
        const core::VariationInfo* info = core::findVariation(term.name);
        return info && info->directColour;
      }))
    fieldWidget(ui, scope, xform, core::xformFields(), "direct_color");
  affineEditor(ui, pattern, scope, xform.affine);
  reportEdit(ui, ImGui::Checkbox("post-affine", &xform.hasPost), core::Affects::Pattern);
  probe(ui, scope + "post-affine");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("a second affine map applied after the variations");
  if (xform.hasPost) {
    ImGui::PushID("post");
    ImGui::Indent();
    affineEditor(ui, pattern, scope + "post/", xform.post);
    ImGui::Unindent();
    ImGui::PopID();
  }
  ImGui::Separator();
  dimText("variations");
  variationsEditor(ui, pattern, scope, xform);
}

void flameEditor(Ui& ui, PatternPanelState& pattern, ExplorePanelState& explore, std::size_t index,
                 const std::string& scope, core::FlameGenome& flame) {
  int& selected = pattern.selectedXform[index];
  if (selected >= static_cast<int>(flame.xforms.size()) || (selected < 0 && !flame.hasFinal)) selected = 0;
  // The transform selector: one button per transform, then the final one.
  dimText("transform");
  // Up to 128 transforms: 16 buttons a row.
  constexpr std::size_t kButtonsPerRow = 16;
  for (std::size_t i = 0; i < flame.xforms.size(); ++i) {
    if (i == 0 || i % kButtonsPerRow != 0) ImGui::SameLine();
    const std::string label = std::to_string(i + 1);
    if (ImGui::Selectable(label.c_str(), selected == static_cast<int>(i), 0, ImVec2(ImGui::GetFrameHeight(), 0)))
      selected = static_cast<int>(i);
    probe(ui, scope + "xform " + label);
  }
  // selected: −1 is the final transform, −2 − k the k-th chained one (JWildfire's chain).
  if (flame.hasFinal) {
    ImGui::SameLine();
    if (ImGui::Selectable("final", selected == -1, 0, ImVec2(ImGui::CalcTextSize("final").x, 0))) selected = -1;
    probe(ui, scope + "xform final");
    for (std::size_t k = 0; k < flame.chainedFinals.size(); ++k) {
      const std::string label = "final " + std::to_string(k + 2);
      ImGui::SameLine();
      if (ImGui::Selectable(label.c_str(), selected == -2 - static_cast<int>(k), 0,
                            ImVec2(ImGui::CalcTextSize(label.c_str()).x, 0)))
        selected = -2 - static_cast<int>(k);
      probe(ui, scope + "xform " + label);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("applied after the final transform before it (a chain of finals)");
    }
  }
  if (selected < -1 - static_cast<int>(flame.chainedFinals.size())) selected = -1;
  const bool full = flame.xforms.size() >= core::kMaxFlameXforms;
  ImGui::BeginDisabled(full);
  if (reportEdit(ui, button(ui, scope, "Add transform"), core::Affects::Pattern)) {
    flame.xforms.push_back(
        core::randomTransform(explore.searchSeed++, std::fmod(0.37 * static_cast<double>(flame.xforms.size()), 1.0)));
    selected = static_cast<int>(flame.xforms.size()) - 1;
  }
  ImGui::SameLine();
  if (button(ui, scope, "Duplicate") && reportEdit(ui, selected >= 0, core::Affects::Pattern)) {
    const auto at = static_cast<std::size_t>(selected);
    flame.xforms.insert(flame.xforms.begin() + selected + 1, flame.xforms[at]);
    // Xaos columns follow the transforms: the copy is followed as often as its original.
    for (core::FlameXform& x : flame.xforms)
      if (x.xaos.size() > at) x.xaos.insert(x.xaos.begin() + selected + 1, x.xaos[at]);
    ++selected;
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(selected >= 0 && flame.xforms.size() <= 1);
  if (reportEdit(ui, button(ui, scope, "Remove"), core::Affects::Pattern)) {
    if (selected < -1) {
      flame.chainedFinals.erase(flame.chainedFinals.begin() + (-2 - selected));
      selected = -1;
    } else if (selected < 0 && !flame.chainedFinals.empty()) {
      // The next final of the chain takes the removed one's place.
      flame.finalXform = flame.chainedFinals.front();
      flame.chainedFinals.erase(flame.chainedFinals.begin());
    } else if (selected < 0) {
      flame.hasFinal = false;
      selected = 0;
    } else if (flame.xforms.size() > 1) {
      flame.xforms.erase(flame.xforms.begin() + selected);
      for (core::FlameXform& x : flame.xforms)
        if (x.xaos.size() > static_cast<std::size_t>(selected)) x.xaos.erase(x.xaos.begin() + selected);
      selected = std::min(selected, static_cast<int>(flame.xforms.size()) - 1);
    }
  }
  ImGui::EndDisabled();
  if (reportEdit(ui, ImGui::Checkbox("final transform", &flame.hasFinal), core::Affects::Pattern)) {
    if (flame.hasFinal) {
      if (flame.finalXform.variations.empty()) flame.finalXform.variations = {{"linear", 1.0, {}}};
      selected = -1;
    } else if (selected < 0) {
      selected = 0;
    }
  }
  probe(ui, scope + "final transform");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("bends what is drawn without feeding back into the iteration");

  const std::string xscope = scope + (selected < 0 ? "final/" : "xform/");
  ImGui::PushID(selected);
  core::FlameXform& xform = selected >= 0    ? flame.xforms[static_cast<std::size_t>(selected)]
                            : selected == -1 ? flame.finalXform
                                             : flame.chainedFinals[static_cast<std::size_t>(-2 - selected)];
  xformEditor(ui, pattern, xscope, xform, selected < 0);
  ImGui::PopID();
  // With one transform every factor leads back to it (a 0 falls back to the plain weights).
  if (flame.xforms.size() > 1) xaosMatrix(ui, pattern, index, scope, flame, selected);

  if (ImGui::TreeNode("Symmetry")) {
    core::FlameSymmetry& symmetry = flame.symmetry;
    fieldWidget(ui, scope, symmetry, core::symmetryFields(), "rotational");
    fieldWidget(ui, scope, symmetry, core::symmetryFields(), "mirror");
    const std::string axisProbe = scope + "symmetry axis";
    fieldWidget(ui, scope, symmetry, core::symmetryFields(), "axis", axisProbe.c_str());
    ImGui::TreePop();
  }
}

}  // namespace voxflame::app::panels
