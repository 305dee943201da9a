// A small SVG rasteriser for svg_wf (svg_raster.h). It follows what JWildfire's SVGWFFunc gets from
// svgSalamander and Java2D where that decides which pixels are painted: the document's width and
// height in pixels (at 96 per inch, a desktop screen's, as svgSalamander converts), its viewBox
// fitted in them, each shape's fill (SVG's default: painted) and stroke (default: none) with its
// width, the fill rule, transforms, display:none and zero opacities. Colours do not matter (any
// paint marks a pixel), so gradients and patterns count as paint. It differs in details that move
// the outline by a fraction of a pixel: strokes get round caps and joins, one thinner than a pixel
// marks the pixels within half a pixel of it, and an antialiased shape marks the pixels within
// 7/16 of a pixel of it (Java2D's 8 × 8 subpixel samples paint a pixel that any sample of it lies
// in). Text, <use> and images are not drawn (said in problems).
#include "core/flame/svg_raster.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <set>
#include <string>

#include <pugixml.hpp>

namespace voxflame::core {

namespace {

// A 2D affine map (SVG's matrix(a b c d e f)): x' = a x + c y + e, y' = b x + d y + f.
struct Matrix {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
  Matrix then(const Matrix& m) const {  // this map, then m
    return {m.a * a + m.c * b, m.b * a + m.d * b,       m.a * c + m.c * d,
            m.b * c + m.d * d, m.a * e + m.c * f + m.e, m.b * e + m.d * f + m.f};
  }
  std::array<double, 2> apply(double x, double y) const { return {a * x + c * y + e, b * x + d * y + f}; }
  double scale() const { return std::sqrt(std::abs(a * d - b * c)); }  // of lengths, for stroke widths
};

struct Point {
  double x, y;
};
using Polyline = std::vector<Point>;  // in image pixels

// Far outside any image, yet small enough that the arithmetic below stays finite.
constexpr double kCoordinateLimit = 1e9;
// The most line segments one document may flatten to, and the most pixel visits its drawing may
// make: beyond them the rest is left out (said in problems), so no document can hang a render.
constexpr std::size_t kMaxSegments = 2'000'000;
constexpr double kMaxWork = 3e8;
constexpr double kAntialiasReach = 7.0 / 16.0;

// The text's numbers as SVG writes them: sign, digits, point, exponent; nothing else (no "nan",
// "inf" or hex), so that odd input stops the path instead of becoming a NaN.
class NumberReader {
 public:
  explicit NumberReader(std::string_view text) : text_(text) {}
  void skipSeparators() {
    while (at_ < text_.size() && (std::isspace(static_cast<unsigned char>(text_[at_])) || text_[at_] == ',')) ++at_;
  }
  bool done() {
    skipSeparators();
    return at_ >= text_.size();
  }
  char peek() {
    skipSeparators();
    return at_ < text_.size() ? text_[at_] : '\0';
  }
  char take() { return text_[at_++]; }
  bool startsNumber() {
    const char ch = peek();
    return (ch >= '0' && ch <= '9') || ch == '-' || ch == '+' || ch == '.';
  }
  std::optional<double> number() {
    skipSeparators();
    const std::size_t begin = at_;
    std::size_t i = at_;
    if (i < text_.size() && (text_[i] == '-' || text_[i] == '+')) ++i;
    std::size_t digits = 0;
    while (i < text_.size() && std::isdigit(static_cast<unsigned char>(text_[i]))) ++i, ++digits;
    if (i < text_.size() && text_[i] == '.') {
      ++i;
      while (i < text_.size() && std::isdigit(static_cast<unsigned char>(text_[i]))) ++i, ++digits;
    }
    if (digits == 0) return std::nullopt;
    if (i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
      std::size_t j = i + 1;
      if (j < text_.size() && (text_[j] == '-' || text_[j] == '+')) ++j;
      if (j < text_.size() && std::isdigit(static_cast<unsigned char>(text_[j]))) {
        while (j < text_.size() && std::isdigit(static_cast<unsigned char>(text_[j]))) ++j;
        i = j;
      }
    }
    at_ = i;
    const std::string token(text_.substr(begin, i - begin));
    const double value = std::strtod(token.c_str(), nullptr);
    // A number past the double's range is as far off as any other beyond the image.
    return std::clamp(value, -kCoordinateLimit, kCoordinateLimit);
  }
  // An arc's flag: a single 0 or 1, which SVG lets run into what follows ("a1 1 0 105 5").
  std::optional<bool> flag() {
    const char ch = peek();
    if (ch != '0' && ch != '1') return std::nullopt;
    ++at_;
    return ch == '1';
  }

 private:
  std::string_view text_;
  std::size_t at_ = 0;
};

// Everything the drawing of one document shares.
struct Drawing {
  double resolution = 1.0;
  int width = 0, height = 0;
  bool antialias = true;
  std::vector<std::uint8_t> painted;  // width × height, row-major
  std::size_t segments = 0;
  double work = 0.0;
  std::set<std::string> problems;

  bool overBudget() {
    if (segments <= kMaxSegments && work <= kMaxWork) return false;
    problems.insert("the drawing is too complex; the rest was left out");
    return true;
  }
  // Marks the pixels of row `row` whose centres lie in [from, to].
  void markSpan(int row, double from, double to) {
    if (row < 0 || row >= height || !(from <= to)) return;
    const double first = std::max(std::ceil(from - 0.5), 0.0);
    const double last = std::min(std::floor(to - 0.5), static_cast<double>(width - 1));
    if (first > last) return;
    work += last - first + 1.0;
    std::uint8_t* line = painted.data() + static_cast<std::size_t>(row) * static_cast<std::size_t>(width);
    std::fill(line + static_cast<std::ptrdiff_t>(first), line + static_cast<std::ptrdiff_t>(last) + 1, 1);
  }
  // The rows whose centres lie in [low, high], clipped to the image.
  std::array<int, 2> rows(double low, double high) const {
    return {static_cast<int>(std::max(std::ceil(low - 0.5), 0.0)),
            static_cast<int>(std::min(std::floor(high - 0.5), static_cast<double>(height - 1)))};
  }

  // The pixels whose centres lie within `reach` of the segment p–q (a capsule: convex, so each row
  // meets it in one interval, the hull of its meetings with the two end discs and the band).
  void capsule(Point p, Point q, double reach) {
    if (!(reach > 0.0)) return;
    const auto [first, last] = rows(std::min(p.y, q.y) - reach, std::max(p.y, q.y) + reach);
    const double dx = q.x - p.x, dy = q.y - p.y, length = std::hypot(dx, dy);
    for (int row = first; row <= last; ++row) {
      const double y = row + 0.5;
      double low = INFINITY, high = -INFINITY;
      for (const Point& end : {p, q}) {
        const double h = reach * reach - (y - end.y) * (y - end.y);
        if (h < 0.0) continue;
        const double s = std::sqrt(h);
        low = std::min(low, end.x - s);
        high = std::max(high, end.x + s);
      }
      if (length > 0.0) {
        const double ux = dx / length, uy = dy / length;
        // |−uy (x − p.x) + ux (y − p.y)| ≤ reach and 0 ≤ ux (x − p.x) + uy (y − p.y) ≤ length.
        double bandLow = -INFINITY, bandHigh = INFINITY;
        const auto within = [&](double coefficient, double constant, double lo, double hi) {
          // lo ≤ coefficient · (x − p.x) + constant ≤ hi
          if (coefficient == 0.0) {
            if (constant < lo || constant > hi) bandLow = INFINITY;
            return;
          }
          double a = (lo - constant) / coefficient + p.x, b = (hi - constant) / coefficient + p.x;
          if (a > b) std::swap(a, b);
          bandLow = std::max(bandLow, a);
          bandHigh = std::min(bandHigh, b);
        };
        within(-uy, ux * (y - p.y), -reach, reach);
        within(ux, uy * (y - p.y), 0.0, length);
        if (bandLow <= bandHigh) {
          low = std::min(low, bandLow);
          high = std::max(high, bandHigh);
        }
      }
      markSpan(row, low, high);
    }
  }

  // Fills the closed outlines by the nonzero or even-odd rule, testing pixel centres.
  void fill(const std::vector<Polyline>& outlines, bool evenOdd) {
    double top = INFINITY, bottom = -INFINITY;
    for (const Polyline& line : outlines)
      for (const Point& p : line) {
        top = std::min(top, p.y);
        bottom = std::max(bottom, p.y);
      }
    if (!(top <= bottom)) return;
    const auto [first, last] = rows(top, bottom);
    std::vector<std::pair<double, int>> crossings;
    for (int row = first; row <= last; ++row) {
      const double y = row + 0.5;
      crossings.clear();
      for (const Polyline& line : outlines)
        for (std::size_t k = 0; k < line.size(); ++k) {
          const Point& p = line[k];
          const Point& q = line[(k + 1) % line.size()];  // closed for filling, as SVG closes it
          if ((p.y <= y) == (q.y <= y)) continue;
          const double x = p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y);
          crossings.emplace_back(x, q.y > p.y ? 1 : -1);
        }
      work += static_cast<double>(crossings.size());
      std::sort(crossings.begin(), crossings.end());
      int winding = 0;
      for (std::size_t k = 0; k + 1 < crossings.size(); ++k) {
        winding += evenOdd ? 1 : crossings[k].second;
        const bool inside = evenOdd ? (winding & 1) != 0 : winding != 0;
        if (inside) markSpan(row, crossings[k].first, crossings[k + 1].first);
      }
    }
  }
};

// svgSalamander converts a length's units to pixels at the screen's resolution (72 per inch where
// Java has no screen); JWildfire runs on a desktop, where Java reports 96 per inch on most systems.
constexpr double kPixelsPerInch = 96.0;

// The document's length attribute in pixels (svgSalamander's conversion); nullopt when absent, a
// percentage or not a number.
std::optional<double> lengthInPixels(const char* text) {
  if (!text || !*text) return std::nullopt;
  NumberReader reader{text};
  const std::optional<double> value = reader.number();
  if (!value) return std::nullopt;
  std::string unit;
  while (!reader.done()) unit += static_cast<char>(std::tolower(static_cast<unsigned char>(reader.take())));
  if (unit.empty() || unit == "px" || unit == "em" || unit == "ex") return *value;
  if (unit == "in") return *value * kPixelsPerInch;
  if (unit == "pt") return *value * kPixelsPerInch / 72.0;
  if (unit == "pc") return *value * kPixelsPerInch / 6.0;
  if (unit == "cm") return *value * 0.3936 * kPixelsPerInch;  // svgSalamander's inches per cm
  if (unit == "mm") return *value * 0.03936 * kPixelsPerInch;
  return std::nullopt;  // %, and anything else
}

// The style property `name` of an element: its style="..." declaration wins over its attribute.
std::optional<std::string> ownProperty(const pugi::xml_node& node, std::string_view name) {
  const std::string_view style = node.attribute("style").value();
  std::optional<std::string> found;
  std::size_t at = 0;
  while (at < style.size()) {
    std::size_t end = style.find(';', at);
    if (end == std::string_view::npos) end = style.size();
    const std::string_view declaration = style.substr(at, end - at);
    const std::size_t colon = declaration.find(':');
    if (colon != std::string_view::npos) {
      auto trim = [](std::string_view s) {
        while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
        while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
        return s;
      };
      if (trim(declaration.substr(0, colon)) == name) found = std::string(trim(declaration.substr(colon + 1)));
    }
    at = end + 1;
  }
  if (found) return found;
  const pugi::xml_attribute attribute = node.attribute(std::string(name).c_str());
  if (attribute) return std::string(attribute.value());
  return std::nullopt;
}

// The painting properties that matter here, inherited down the tree as SVG's are.
struct Style {
  bool fill = true;  // SVG's initial fill is black
  bool stroke = false;
  double strokeWidth = 1.0;
  bool evenOdd = false;
  bool visible = true;
};

bool paints(const std::string& value) {
  return value != "none" && value != "transparent" && !value.empty();
}
bool zero(const std::optional<std::string>& value) {
  if (!value) return false;
  NumberReader reader{*value};
  const std::optional<double> number = reader.number();
  return number && *number <= 0.0;
}

Style styleOf(const pugi::xml_node& node, Style style) {
  if (const auto v = ownProperty(node, "fill")) style.fill = paints(*v);
  if (const auto v = ownProperty(node, "stroke")) style.stroke = paints(*v);
  if (const auto v = ownProperty(node, "stroke-width")) {
    NumberReader reader{*v};
    if (const auto width = reader.number()) style.strokeWidth = std::max(*width, 0.0);
  }
  if (const auto v = ownProperty(node, "fill-rule")) style.evenOdd = *v == "evenodd";
  if (const auto v = ownProperty(node, "visibility")) style.visible = *v != "hidden" && *v != "collapse";
  if (zero(ownProperty(node, "fill-opacity"))) style.fill = false;
  if (zero(ownProperty(node, "stroke-opacity"))) style.stroke = false;
  return style;
}

// A transform="..." list: matrix, translate, scale, rotate, skewX, skewY, applied right to left.
Matrix parseTransform(std::string_view text, std::set<std::string>& problems) {
  Matrix total;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t open = text.find('(', at);
    if (open == std::string_view::npos) break;
    const std::size_t close = text.find(')', open);
    if (close == std::string_view::npos) break;
    std::string name(text.substr(at, open - at));
    std::erase_if(name, [](char ch) { return std::isspace(static_cast<unsigned char>(ch)) || ch == ','; });
    NumberReader reader{text.substr(open + 1, close - open - 1)};
    std::vector<double> v;
    while (!reader.done()) {
      const auto number = reader.number();
      if (!number) break;
      v.push_back(*number);
    }
    Matrix m;
    const auto arg = [&](std::size_t k, double otherwise) { return k < v.size() ? v[k] : otherwise; };
    constexpr double kDegree = std::numbers::pi / 180.0;
    if (name == "matrix" && v.size() == 6) {
      m = {v[0], v[1], v[2], v[3], v[4], v[5]};
    } else if (name == "translate" && !v.empty()) {
      m.e = v[0];
      m.f = arg(1, 0.0);
    } else if (name == "scale" && !v.empty()) {
      m.a = v[0];
      m.d = arg(1, v[0]);
    } else if (name == "rotate" && !v.empty()) {
      const double angle = v[0] * kDegree, cx = arg(1, 0.0), cy = arg(2, 0.0);
      const Matrix turn{std::cos(angle), std::sin(angle), -std::sin(angle), std::cos(angle), 0.0, 0.0};
      m = Matrix{1, 0, 0, 1, -cx, -cy}.then(turn).then(Matrix{1, 0, 0, 1, cx, cy});
    } else if (name == "skewX" && !v.empty()) {
      m.c = std::tan(v[0] * kDegree);
    } else if (name == "skewY" && !v.empty()) {
      m.b = std::tan(v[0] * kDegree);
    } else {
      problems.insert("transform '" + name + "'");
    }
    total = m.then(total);  // the list's later maps act first
    at = close + 1;
  }
  return total;
}

// Flattens SVG path data into polylines (user units, then mapped by `ctm` into pixels). Stops at
// the first error, drawing what came before, as SVG says.
class PathFlattener {
 public:
  PathFlattener(const Matrix& ctm, Drawing& drawing) : ctm_(ctm), drawing_(drawing) {}
  std::vector<Polyline> lines;
  std::vector<bool> closed;

  void moveTo(double x, double y) {
    lines.emplace_back();
    closed.push_back(false);
    start_ = {x, y};
    add(x, y);
  }
  void lineTo(double x, double y) {
    // A segment after a closepath starts a new subpath where the closed one began.
    if (lines.empty() || closed.back()) moveTo(current_.x, current_.y);
    add(x, y);
  }
  void close() {
    if (!lines.empty()) closed.back() = true;
    current_ = start_;
  }
  void cubic(Point p1, Point p2, Point p3) {
    const int steps = stepsFor({current_, p1, p2, p3});
    const Point p0 = current_;
    for (int k = 1; k <= steps; ++k) {
      const double t = static_cast<double>(k) / steps, u = 1.0 - t;
      lineTo(u * u * u * p0.x + 3 * u * u * t * p1.x + 3 * u * t * t * p2.x + t * t * t * p3.x,
             u * u * u * p0.y + 3 * u * u * t * p1.y + 3 * u * t * t * p2.y + t * t * t * p3.y);
    }
  }
  void quadratic(Point p1, Point p2) {
    const int steps = stepsFor({current_, p1, p2, p2});
    const Point p0 = current_;
    for (int k = 1; k <= steps; ++k) {
      const double t = static_cast<double>(k) / steps, u = 1.0 - t;
      lineTo(u * u * p0.x + 2 * u * t * p1.x + t * t * p2.x, u * u * p0.y + 2 * u * t * p1.y + t * t * p2.y);
    }
  }
  // SVG's elliptical arc (endpoint form, implementation notes F.6.5–F.6.6).
  void arc(double rx, double ry, double rotation, bool large, bool sweep, Point to) {
    const Point from = current_;
    rx = std::abs(rx);
    ry = std::abs(ry);
    if ((from.x == to.x && from.y == to.y)) return;
    if (rx == 0.0 || ry == 0.0) return lineTo(to.x, to.y);
    const double phi = rotation * std::numbers::pi / 180.0, cp = std::cos(phi), sp = std::sin(phi);
    const double hx = (from.x - to.x) / 2, hy = (from.y - to.y) / 2;
    const double x1 = cp * hx + sp * hy, y1 = -sp * hx + cp * hy;
    const double lambda = x1 * x1 / (rx * rx) + y1 * y1 / (ry * ry);
    if (lambda > 1.0) {
      rx *= std::sqrt(lambda);
      ry *= std::sqrt(lambda);
    }
    const double num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
    const double den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
    double root = den > 0.0 ? std::sqrt(std::max(num / den, 0.0)) : 0.0;
    if (large == sweep) root = -root;
    const double cx1 = root * rx * y1 / ry, cy1 = -root * ry * x1 / rx;
    const double cx = cp * cx1 - sp * cy1 + (from.x + to.x) / 2, cy = sp * cx1 + cp * cy1 + (from.y + to.y) / 2;
    const double start = std::atan2((y1 - cy1) / ry, (x1 - cx1) / rx);
    double delta = std::atan2((-y1 - cy1) / ry, (-x1 - cx1) / rx) - start;
    if (sweep && delta < 0) delta += 2 * std::numbers::pi;
    if (!sweep && delta > 0) delta -= 2 * std::numbers::pi;
    const double radius = std::max(rx, ry) * ctm_.scale() * drawing_.resolution;
    const int steps = std::clamp(static_cast<int>(std::ceil(std::abs(delta) * std::sqrt(radius + 1.0))), 4, 1024);
    for (int k = 1; k < steps; ++k) {
      const double angle = start + delta * k / steps;
      const double ex = rx * std::cos(angle), ey = ry * std::sin(angle);
      lineTo(cp * ex - sp * ey + cx, sp * ex + cp * ey + cy);
    }
    lineTo(to.x, to.y);
  }
  Point current() const { return current_; }

 private:
  // Enough steps that the chords stay within a fraction of a pixel: by the control polygon's
  // length in pixels.
  int stepsFor(const std::array<Point, 4>& control) const {
    double length = 0.0;
    for (std::size_t k = 1; k < control.size(); ++k)
      length += std::hypot(control[k].x - control[k - 1].x, control[k].y - control[k - 1].y);
    const double pixels = length * ctm_.scale() * drawing_.resolution;
    return std::isfinite(pixels) ? std::clamp(static_cast<int>(std::ceil(std::sqrt(pixels) * 2.0)), 2, 256) : 2;
  }
  void add(double x, double y) {
    current_ = {x, y};
    if (drawing_.overBudget()) return;
    ++drawing_.segments;
    const auto [px, py] = ctm_.apply(x, y);
    const double s = drawing_.resolution;
    lines.back().push_back({std::clamp(px * s, -kCoordinateLimit, kCoordinateLimit),
                            std::clamp(py * s, -kCoordinateLimit, kCoordinateLimit)});
  }

  Matrix ctm_;
  Drawing& drawing_;
  Point current_{0, 0}, start_{0, 0};
};

void flattenPathData(std::string_view data, PathFlattener& path, std::set<std::string>& problems) {
  NumberReader reader{data};
  char command = '\0';
  Point lastControl{0, 0};
  char lastCommand = '\0';
  while (!reader.done()) {
    if (std::isalpha(static_cast<unsigned char>(reader.peek()))) {
      command = reader.take();
    } else if (command == '\0' || !reader.startsNumber()) {
      problems.insert("path data that is not SVG's");
      return;
    }
    // After a moveto, further coordinate pairs are linetos.
    const bool relative = std::islower(static_cast<unsigned char>(command)) != 0;
    const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(command)));
    const Point here = path.current();
    const double bx = relative ? here.x : 0.0, by = relative ? here.y : 0.0;
    std::array<double, 7> v{};
    const auto read = [&](int count) {
      for (int k = 0; k < count; ++k) {
        const auto number = reader.number();
        if (!number) return false;
        v[static_cast<std::size_t>(k)] = *number;
      }
      return true;
    };
    bool ok = true;
    switch (upper) {
      case 'Z':
        path.close();
        break;
      case 'M':
        if ((ok = read(2))) path.moveTo(bx + v[0], by + v[1]);
        command = relative ? 'l' : 'L';
        break;
      case 'L':
        if ((ok = read(2))) path.lineTo(bx + v[0], by + v[1]);
        break;
      case 'H':
        if ((ok = read(1))) path.lineTo(bx + v[0], here.y);
        break;
      case 'V':
        if ((ok = read(1))) path.lineTo(here.x, by + v[0]);
        break;
      case 'C':
        if ((ok = read(6))) {
          lastControl = {bx + v[2], by + v[3]};
          path.cubic({bx + v[0], by + v[1]}, lastControl, {bx + v[4], by + v[5]});
        }
        break;
      case 'S':
        if ((ok = read(4))) {
          const bool follows = lastCommand == 'C' || lastCommand == 'S';
          const Point first = follows ? Point{2 * here.x - lastControl.x, 2 * here.y - lastControl.y} : here;
          lastControl = {bx + v[0], by + v[1]};
          path.cubic(first, lastControl, {bx + v[2], by + v[3]});
        }
        break;
      case 'Q':
        if ((ok = read(4))) {
          lastControl = {bx + v[0], by + v[1]};
          path.quadratic(lastControl, {bx + v[2], by + v[3]});
        }
        break;
      case 'T':
        if ((ok = read(2))) {
          const bool follows = lastCommand == 'Q' || lastCommand == 'T';
          lastControl = follows ? Point{2 * here.x - lastControl.x, 2 * here.y - lastControl.y} : here;
          path.quadratic(lastControl, {bx + v[0], by + v[1]});
        }
        break;
      case 'A': {
        ok = read(3);
        const auto large = ok ? reader.flag() : std::nullopt;
        const auto sweep = large ? reader.flag() : std::nullopt;
        ok = ok && large && sweep;
        if (ok) {
          const double rx = v[0], ry = v[1], rotation = v[2];
          if ((ok = read(2))) path.arc(rx, ry, rotation, *large, *sweep, {bx + v[0], by + v[1]});
        }
        break;
      }
      default:
        problems.insert(std::string("path command '") + command + "'");
        return;
    }
    if (!ok) {
      problems.insert("path data that ends early or is malformed");
      return;
    }
    lastCommand = upper;
  }
}

}  // namespace

namespace {

double attributeNumber(const pugi::xml_node& node, const char* name, double otherwise) {
  const char* text = node.attribute(name).value();
  if (!*text) return otherwise;
  NumberReader reader{text};
  return reader.number().value_or(otherwise);
}

// Draws one shape's outlines with its style.
void drawShape(Drawing& drawing, const std::vector<Polyline>& lines, const std::vector<bool>& closed,
               const Style& style, const Matrix& ctm) {
  if (!style.visible || lines.empty()) return;
  const double margin = drawing.antialias ? kAntialiasReach : 0.0;
  if (style.fill) {
    drawing.fill(lines, style.evenOdd);
    if (margin > 0.0)
      for (const Polyline& line : lines)
        for (std::size_t k = 0; k < line.size() && !drawing.overBudget(); ++k)
          drawing.capsule(line[k], line[(k + 1) % line.size()], margin);
  }
  if (style.stroke && style.strokeWidth > 0.0) {
    // Java2D draws a stroke thinner than a pixel without antialiasing as a line one pixel wide.
    double reach = style.strokeWidth * ctm.scale() * drawing.resolution / 2.0;
    reach = margin > 0.0 ? reach + margin : std::max(reach, 0.5);
    for (std::size_t l = 0; l < lines.size(); ++l) {
      const Polyline& line = lines[l];
      if (line.size() == 1) drawing.capsule(line[0], line[0], reach);
      for (std::size_t k = 0; k + 1 < line.size() && !drawing.overBudget(); ++k)
        drawing.capsule(line[k], line[k + 1], reach);
      if (closed[l] && line.size() > 2) drawing.capsule(line.back(), line.front(), reach);
    }
  }
}

void drawNode(Drawing& drawing, const pugi::xml_node& node, const Style& inherited, const Matrix& parent, int depth) {
  if (depth > 64) {
    drawing.problems.insert("groups nested too deeply");
    return;
  }
  std::string name = node.name();
  if (const std::size_t colon = name.find(':'); colon != std::string::npos) {
    // svg:path and the like (a prefix bound to SVG's namespace); other namespaces' elements
    // (Inkscape's, RDF's) are not drawn.
    if (name.substr(0, colon) != "svg") return;
    name = name.substr(colon + 1);
  }
  if (const auto display = ownProperty(node, "display"); display && *display == "none") return;
  if (zero(ownProperty(node, "opacity"))) return;
  const Style style = styleOf(node, inherited);
  const Matrix ctm = parseTransform(node.attribute("transform").value(), drawing.problems).then(parent);
  if (name == "g" || name == "a" || name == "switch" || (name == "svg" && depth > 0)) {
    for (const pugi::xml_node& child : node.children()) drawNode(drawing, child, style, ctm, depth + 1);
    return;
  }
  PathFlattener path(ctm, drawing);
  if (name == "path") {
    flattenPathData(node.attribute("d").value(), path, drawing.problems);
  } else if (name == "rect") {
    const double x = attributeNumber(node, "x", 0), y = attributeNumber(node, "y", 0);
    const double w = attributeNumber(node, "width", 0), h = attributeNumber(node, "height", 0);
    if (!(w > 0 && h > 0)) return;
    double rx = attributeNumber(node, "rx", -1), ry = attributeNumber(node, "ry", -1);
    if (rx < 0) rx = ry;
    if (ry < 0) ry = rx;
    rx = std::clamp(rx, 0.0, w / 2);
    ry = std::clamp(ry, 0.0, h / 2);
    if (rx > 0 && ry > 0) {
      path.moveTo(x + rx, y);
      path.lineTo(x + w - rx, y);
      path.arc(rx, ry, 0, false, true, {x + w, y + ry});
      path.lineTo(x + w, y + h - ry);
      path.arc(rx, ry, 0, false, true, {x + w - rx, y + h});
      path.lineTo(x + rx, y + h);
      path.arc(rx, ry, 0, false, true, {x, y + h - ry});
      path.lineTo(x, y + ry);
      path.arc(rx, ry, 0, false, true, {x + rx, y});
    } else {
      path.moveTo(x, y);
      path.lineTo(x + w, y);
      path.lineTo(x + w, y + h);
      path.lineTo(x, y + h);
    }
    path.close();
  } else if (name == "circle" || name == "ellipse") {
    const double cx = attributeNumber(node, "cx", 0), cy = attributeNumber(node, "cy", 0);
    const double rx = name == "circle" ? attributeNumber(node, "r", 0) : attributeNumber(node, "rx", 0);
    const double ry = name == "circle" ? rx : attributeNumber(node, "ry", 0);
    if (!(rx > 0 && ry > 0)) return;
    path.moveTo(cx + rx, cy);
    path.arc(rx, ry, 0, false, true, {cx - rx, cy});
    path.arc(rx, ry, 0, false, true, {cx + rx, cy});
    path.close();
  } else if (name == "line") {
    path.moveTo(attributeNumber(node, "x1", 0), attributeNumber(node, "y1", 0));
    path.lineTo(attributeNumber(node, "x2", 0), attributeNumber(node, "y2", 0));
  } else if (name == "polyline" || name == "polygon") {
    NumberReader reader{node.attribute("points").value()};
    bool first = true;
    while (!reader.done()) {
      const auto x = reader.number();
      const auto y = x ? reader.number() : std::nullopt;
      if (!y) break;
      if (first)
        path.moveTo(*x, *y);
      else
        path.lineTo(*x, *y);
      first = false;
    }
    if (name == "polygon") path.close();
  } else if (name == "text" || name == "use" || name == "image") {
    drawing.problems.insert("<" + name + "> elements");
    return;
  } else {
    return;  // defs, metadata, gradients, clip paths, ...: not drawn themselves
  }
  drawShape(drawing, path.lines, path.closed, style, ctm);
}

}  // namespace

SvgRaster rasteriseSvg(std::string_view document, double resolution, bool antialias) {
  SvgRaster result;
  pugi::xml_document xml;
  const pugi::xml_parse_result parsed = xml.load_buffer(document.data(), document.size());
  if (!parsed) {
    result.problems.push_back(std::string("the SVG is not XML (") + parsed.description() + ")");
    return result;
  }
  pugi::xml_node root = xml.document_element();
  if (std::string_view(root.name()) != "svg" && std::string_view(root.name()) != "svg:svg") {
    result.problems.push_back("the document is not SVG (no <svg> element)");
    return result;
  }
  // The viewBox, fitted into width × height (SVG's default xMidYMid meet).
  std::optional<double> width = lengthInPixels(root.attribute("width").value());
  std::optional<double> height = lengthInPixels(root.attribute("height").value());
  Matrix view;
  NumberReader box{root.attribute("viewBox").value()};
  std::array<double, 4> vb{};
  bool hasBox = true;
  for (double& value : vb) {
    const auto number = box.number();
    hasBox = hasBox && number.has_value();
    if (number) value = *number;
  }
  hasBox = hasBox && vb[2] > 0 && vb[3] > 0;
  if (hasBox) {
    if (!width) width = vb[2];
    if (!height) height = vb[3];
    const double scale = std::min(*width / vb[2], *height / vb[3]);
    view = {scale,
            0,
            0,
            scale,
            -vb[0] * scale + (*width - vb[2] * scale) / 2,
            -vb[1] * scale + (*height - vb[3] * scale) / 2};
  }
  if (!width || !height || !(*width > 0) || !(*height > 0)) {
    result.problems.push_back("the SVG has no size (width and height, or a viewBox)");
    return result;
  }
  Drawing drawing;
  drawing.antialias = antialias;
  drawing.resolution = std::isfinite(resolution) ? std::clamp(resolution, 0.1, 100.0) : 1.0;
  // Tools.FTOI of the size times the multiplier, at most kSvgRasterMaxSide a side.
  double w = std::round(*width * drawing.resolution), h = std::round(*height * drawing.resolution);
  if (w > kSvgRasterMaxSide || h > kSvgRasterMaxSide) {
    const double shrink = kSvgRasterMaxSide / std::max(w, h);
    drawing.resolution *= shrink;
    w = std::min(std::round(*width * drawing.resolution), double{kSvgRasterMaxSide});
    h = std::min(std::round(*height * drawing.resolution), double{kSvgRasterMaxSide});
    drawing.problems.insert("the image would be over " + std::to_string(kSvgRasterMaxSide) +
                            " pixels a side; it was drawn smaller");
  }
  drawing.width = static_cast<int>(w);
  drawing.height = static_cast<int>(h);
  if (drawing.width <= 0 || drawing.height <= 0) {
    result.problems.push_back("the SVG's image is empty at this resolution");
    return result;
  }
  drawing.painted.assign(static_cast<std::size_t>(drawing.width) * static_cast<std::size_t>(drawing.height), 0);
  const Style style = styleOf(root, Style{});
  const Matrix rootMatrix = parseTransform(root.attribute("transform").value(), drawing.problems).then(view);
  for (const pugi::xml_node& child : root.children()) drawNode(drawing, child, style, rootMatrix, 1);
  result.width = drawing.width;
  result.height = drawing.height;
  for (int i = 0; i < drawing.height; ++i)
    for (int j = 0; j < drawing.width; ++j)
      if (drawing.painted[static_cast<std::size_t>(i) * static_cast<std::size_t>(drawing.width) +
                          static_cast<std::size_t>(j)]) {
        result.column.push_back(static_cast<std::uint16_t>(j));
        result.row.push_back(static_cast<std::uint16_t>(i));
      }
  result.problems.assign(drawing.problems.begin(), drawing.problems.end());
  return result;
}

}  // namespace voxflame::core
