// presets/SCHEMA.md, generated: the prose is fixed text here, every row of the tables of keys
// comes from the schema tables (scene_schema_tables.cpp). The keyframes' own table and the
// version table are fixed text too: the keyframe reader (keyframes.cpp) and the migrations
// (scene_io.cpp) are hand code. To regenerate the committed file after a change: VOXFLAME_UPDATE_SCHEMA=1 ctest -R
// SchemaDocument (or run the schema_document test binary with that variable set).
#include <charconv>
#include <cmath>

#include "color.h"
#include "scene_schema.h"

namespace voxflame::core {

namespace {

struct DocRow {
  std::string key, type, range, defaultValue, meaning;
};

std::string superscript(long n) {
  static constexpr const char* kDigits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string text = n < 0 ? "⁻" : "";
  for (char c : std::to_string(std::labs(n))) text += kDigits[c - '0'];
  return text;
}

// How SCHEMA.md writes a number: 10⁶ and 2⁵³ for the huge and tiny limits, a typographic minus in
// prose (`code` keeps JSON's "-").
std::string formatNumber(double v, bool prose = true) {
  if (v < 0.0) return (prose ? "−" : "-") + formatNumber(-v, prose);
  if (v == 0.0) return "0";
  const long ten = std::lround(std::log10(v));
  if ((ten >= 5 || ten <= -4) && std::abs(v / std::pow(10.0, static_cast<double>(ten)) - 1.0) < 1e-12)
    return "10" + superscript(ten);
  const long two = std::lround(std::log2(v));
  if (two >= 30 && v == std::ldexp(1.0, static_cast<int>(two))) return "2" + superscript(two);
  char buffer[64];
  const bool whole = v == std::floor(v) && v < 1e15;
  const auto end = whole ? std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed, 0).ptr
                         : std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
  return std::string(buffer, end);
}

template <class Owner>
std::string defaultOf(const Owner& owner, const Field<Owner>& f) {
  return std::visit(
      [&]<class M>(const M& member) -> std::string {
        if constexpr (std::is_same_v<M, std::monostate>) {
          return "";
        } else if constexpr (std::is_same_v<M, bool Owner::*>) {
          return owner.*member ? "true" : "false";
        } else if constexpr (std::is_same_v<M, std::string Owner::*>) {
          return "`\"" + owner.*member + "\"`";
        } else if constexpr (std::is_same_v<M, glm::vec3 Owner::*>) {
          return "`\"" + toHexColor(owner.*member) + "\"`";
        } else if constexpr (std::is_same_v<M, glm::dvec3 Owner::*>) {
          const glm::dvec3& v = owner.*member;
          return "`[" + formatNumber(v.x, false) + ", " + formatNumber(v.y, false) + ", " + formatNumber(v.z, false) +
                 "]`";
        } else if constexpr (std::is_same_v<M, Choice<Owner>>) {
          return "`" + std::string(member.names[static_cast<std::size_t>(member.get(owner))]) + "`";
        } else {
          return formatNumber(static_cast<double>(owner.*member));
        }
      },
      f.member);
}

std::string typeOf(FieldType type) {
  switch (type) {
    case FieldType::Number:
      return "number";
    case FieldType::Integer:
    case FieldType::Unsigned:
      return "whole number";
    case FieldType::Boolean:
      return "true/false";
    case FieldType::String:
    case FieldType::Choice:
      return "string";
    case FieldType::Color:
      return "colour";
    case FieldType::Vector3:
      return "3 numbers";
    case FieldType::Hand:
      break;
  }
  return "";
}

template <class Owner>
std::string rangeOf(const Field<Owner>& f) {
  const std::string span = formatNumber(f.min) + "–" + formatNumber(f.max);
  switch (f.type()) {
    case FieldType::Number:
    case FieldType::Integer:
    case FieldType::Unsigned:
      return span;
    case FieldType::Vector3:
      return "each " + span;
    case FieldType::Choice: {
      std::string names;
      for (std::string_view name : std::get<Choice<Owner>>(f.member).names)
        names += (names.empty() ? "`" : ", `") + std::string(name) + "`";
      return names;
    }
    default:
      return "";
  }
}

template <class Owner>
std::vector<DocRow> rows(Table<Owner> table, const std::string& prefix = "") {
  static const Owner defaults{};
  std::vector<DocRow> out;
  for (const Field<Owner>& f : table)
    out.push_back({prefix + std::string(f.key), f.typeText.empty() ? typeOf(f.type()) : std::string(f.typeText),
                   f.rangeText.empty() ? rangeOf(f) : std::string(f.rangeText),
                   f.defaultText.empty() ? defaultOf(defaults, f) : std::string(f.defaultText), std::string(f.help)});
  return out;
}

std::vector<DocRow> concat(std::initializer_list<std::vector<DocRow>> parts) {
  std::vector<DocRow> out;
  for (const auto& part : parts) out.insert(out.end(), part.begin(), part.end());
  return out;
}

std::vector<DocRow> topRows() {
  return rows(sceneFields());
}

std::vector<DocRow> layerRows() {
  return concat({rows(layerFields()), rows(colorFields(), "color."), rows(transformFields(), "transform."),
                 rows(lockedFitFields(), "transform.locked_fit.")});
}

std::vector<DocRow> flameRows() {
  // xforms, then its transforms' keys, then the flame's other keys (final, final_chain, the background's).
  const std::vector<DocRow> flame = rows(flameFields(), "flame.");
  return concat({{flame.front()},
                 rows(xformFields(), "flame.xforms[j]."),
                 rows(variationFields(), "flame.xforms[j].variations[k]."),
                 std::vector<DocRow>(flame.begin() + 1, flame.end()),
                 rows(symmetryFields(), "flame.symmetry."),
                 rows(postSymmetryFields(), "flame.post_symmetry.")});
}

std::vector<DocRow> juliaRows() {
  return rows(juliaFields(), "julia.");
}

std::string table(const std::vector<DocRow>& rows) {
  std::string out = "| key | type | range | default | meaning |\n| --- | --- | --- | --- | --- |\n";
  for (const DocRow& r : rows) {
    const auto cell = [](const std::string& text) { return text.empty() ? std::string(" ") : " " + text + " "; };
    out += "| `" + r.key + "` |" + cell(r.type) + "|" + cell(r.range) + "|" + cell(r.defaultValue) + "|" +
           cell(r.meaning) + "|\n";
  }
  return out;
}

}  // namespace

std::string schemaMarkdown() {
  std::string out;
  out += R"md(# The voxflame preset schema (version 2)

A preset is one JSON object. Every key is checked when it is loaded: an unknown key, a value of
the wrong type or a number outside its range is an error that names the file, the key path
(`layers[0].color.scale`) and the allowed range. Only `mesh` and `layers` are required; every
other key has the default given below. `voxflame render`, `voxflame animate` and the explorer
all read this format, and PNG renders carry it in their `voxflame:preset` text chunk.

Exported volumes (`voxflame render -o OUT.vdb|OUT.nrrd`) carry the preset too, as metadata
`voxflame_preset`; see the README for their density normalisation.

Numbers are JSON numbers; JSON has no NaN or infinity, and a number too large for a double
(`1e999`) is refused as invalid JSON. Colours are sRGB hex strings `"#rrggbb"`; voxflame works
with them in linear RGB.

## Versions and migration

| key | type | range | default |
| --- | --- | --- | --- |
| `schema_version` | whole number | 1–2 | 2 (the current version) |

* A preset with an older `schema_version` is migrated when it is read: one function per version
  step turns a version-*n* document into a version-*n*+1 document, and the steps chain, so every
  older preset keeps loading. Saving writes the current version.
* A newer version than the running voxflame knows is refused, naming the version it understands.
* A preset without `schema_version` is read as the current version.
* Keys added by a later version are errors in a document that declares an earlier one (a
  version-1 preset with `keyframes` is refused, not half-read).
* Version 1 → 2: version 2 adds `animation` and `keyframes`; everything else means the same, so
  the migration only changes the version number.

## Top level

)md";
  out += table(topRows());
  out += R"md(
## `layers[i]`

)md";
  out += table(layerRows());
  out += R"md(
The automatic fit compares the attractor's robust box (5–95% of a probe sample on each axis) with
the box of the mesh's inside voxels:

* `contain`: one scale, so the attractor covers the shape along its middle axis and spills at most
  2.5× over along its widest (the thinnest axis is ignored: for flat attractors it is unsteady).
* `cover`: one scale, the largest of the per-axis ratios, so the attractor covers the shape along
  every axis and the mask carves the shape out of it; for a flat attractor it stops at 3× the
  middle axis's ratio, so a sheet is not blown up until only its middle shows.
* `stretch`: a scale per attractor axis, so the robust box matches the shape's box on each axis
  (before `rotation_deg`); the pattern's proportions change. No axis is stretched more than 8×
  the geometric mean of the three.
* `previous`: the fit of the layer before it (its original, not a copy; `contain` for the first
  layer), so layers drawn in one coordinate system stay in register: the layers of a JWildfire
  flame are imported this way, the first one fitted and the others placed with it.

A ribbon or a sheet covers more of its mesh with `copies`: the same pattern again, turned, with
one set of parameters for all (the shipped presets do this). Each copy is fitted like the original
(the fit is taken before the rotation, so they all have the same size).

With `locked_fit` the automatic fit is replaced by the stored one, so parameter changes never
move or resize the pattern (`voxflame animate` locks every layer this way, `axis_scale` included).

### Flame layers (`"kind": "flame"`)

A 3D fractal flame (Draves & Reckase's algorithm lifted into 3D), iterated by the chaos game: at
every step each point picks one transform with probability proportional to its `weight` (times
the `xaos` factor the transform it took last gives it, as flam3's and Apophysis' xaos), goes
through its `affine` map, then its `pre_` variations one after the other, the weighted sum of its
other variations (`presets/VARIATIONS.md` lists them with their formulas and the rules of the
`pre_`/`post_` forms; `voxflame list --variations`), its `post_` variations, then its optional
`post` map. Its colour index moves towards the transform's `color` by `color_speed` (flam3's
blend `c ← (1 − color_speed) · c + color_speed · color`); a transform with direct-colour
variations (`dc_linear`, …, Fractorium's) then sets it from the point, c ← c + `direct_color` ·
(dc − c). It indexes the layer's gradient
(`color.mode` `index`) as flam3 indexes its 256-colour palette: the gradient read at 256
positions, index c takes entry ⌊256 c⌋ (`flat.palette_mode` `step`, the default) or blends it
with the next one (`linear`), and the colours are summed as written (sRGB), as flam3 sums them, not
as linear light as the other colour modes are. The `final` transform bends what is drawn without feeding back. The
layer's `color`, `weight` and `transform` (fit, copies) work as for attractors.

)md";
  out += table(flameRows());
  out += R"md(
Symmetry works as in flam3 — extra transforms that turn (and mirror) the pattern take part in the
iteration, so the attractor itself becomes symmetric — and each drawn point also goes through a
random element of the symmetry group, so the drawn density is exactly symmetric too.

Classic IFS fractals are flames whose transforms are affine maps only (linear variation): the
shipped Menger sponge uses five of its twenty maps and 4-fold symmetry (the other fifteen are
their turns), the Sierpiński tetrahedron four maps, the fern four.

Every number of a flame can be keyframed (e.g. `/layers/0/flame/xforms/1/affine` as an array
track, `/layers/0/flame/xforms/0/variations/1/weight`), so a flame morphs between two sets of
transforms.

### Quaternion Julia layers (`"kind": "quaternion_julia"`)

The Julia set of q ↦ q² + c over the quaternions, drawn by inverse iteration: q ← ±√(q − c) with a
random root at every step, which samples the set's boundary. The colour index (`index` mode)
follows the sequence of roots taken.

)md";
  out += table(juliaRows());
  out += R"md(
## `tone`

The picture is made the way fractal flames are made (flam3): each pixel first sums the density its
ray sees (volume method) or the points that land in it (points method), then density estimation,
the log, the spatial filter and gamma run on that pixel's sum. The density is measured relative to
the mesh's mean, so brightness does not change with the point count, the grid, the image size,
the oversample or the samples.

)md";
  out += table(rows(toneFields()));
  out += R"md(
## `camera`

)md";
  out += table(rows(cameraFields()));
  out += R"md(
## `render`

)md";
  out += table(rows(renderFields()));
  out += R"md(
## `flat`

How flam3 frames the flame in 2D, kept by `voxflame import` from the flame file's `size`, `center`,
`scale`, `zoom`, `rotate`, `oversample` (`supersample`), `filter` and `quality`, so `voxflame
render --flat` shows the flame as flam3 renders it. The flat view's tone is `tone` (flam3's
brightness, gamma, vibrancy, highlight power, density estimation, background). A preset without
the block has flam3's defaults.

)md";
  out += table(concat({rows(flatFields()), rows(solidFields(), "solid."), rows(solidLightFields(), "solid.lights[i]."),
                       rows(solidMaterialFields(), "solid.materials[i].")}));
  out += R"md(
`solid` is JWildfire's solid rendering (`sld_render_*` in its files): each pixel keeps the nearest
point, normals come from the flame coordinates of neighbouring pixels' points, and the distant
lights shade them with each material's diffuse, ambient and phong terms, with ambient occlusion
and shadow maps when enabled. A transform's `material` (with `material_speed`) picks the material
as `color` picks the palette entry.

)md";
  out += R"md(
## `animation` (version 2)

)md";
  out += table(rows(animationFields()));
  out += R"md(
Frame *i* shows time *i* / fps. An open animation has ⌊duration · fps⌋ + 1 frames (its last key
is shown); a loop has round(duration · fps) frames (its end is its first frame again).

## `keyframes` (version 2)

Each track animates one value of the preset:

| key | type | range | default | meaning |
| --- | --- | --- | --- | --- |
| `path` | string | a JSON Pointer (RFC 6901) | required | the value animated; one track per path |
| `interpolation` | string | `linear`, `smooth` | `smooth` | `smooth` is Catmull-Rom |
| `keys` | array | 1–100000 keys | required | |
| `keys[k].time` | number | 0–10⁶ s, increasing, ≤ `duration` when set | required | |
| `keys[k].value` | number, array of 1–64 numbers, or colour | −10¹²–10¹² | required | all keys of a track of one kind |

* **Paths** address the preset as a complete document, every key present with its default:
  `/camera/azimuth_deg`, `/tone/background`, `/layers/0/params/a` (parameters by name),
  `/layers/0/color/gradient/2` (a gradient stop's colour), `/camera/target` (the whole
  vector) or `/camera/target/1` (one component), `/layers/1/transform/rotation_deg`. A track
  must name a number, an array of numbers (with keys of the same length) or a colour (with
  colour keys). Whole-number values (`/grid/resolution`, `/seed`, `/points`) are rounded. A
  layer with a `palette` has no gradient stops to address; write its `gradient` instead.
* **Between keys**, `linear` moves in a straight line; `smooth` follows a Catmull-Rom curve
  through every key: the tangent at a key is (next − previous) / (time of next − time of previous),
  at the first and last key the slope to its neighbour. Colours interpolate in OKLab.
* **Outside the keys** a track holds its first or last value. With `animation.loop` time wraps
  at the duration and each track repeats with that period: the curve's neighbours wrap around,
  so the loop has no kink. When a track has keys at 0 and at exactly the duration, the key at the
  duration closes the loop; if its value differs from the first key's (0° and 360°), each period
  continues from there, so a turntable turns on at constant speed without a jump.
* **Checks**: when the preset loads, every track's path must exist and fit its keys, and the
  preset evaluated at every key, and at points between keys of smooth tracks (where a curve
  can overshoot), must be valid; the error names the track and the time
  (`p.json: keyframes[0] ('/tone/vibrancy') at 1.125 s: 'tone.vibrancy' is 1.05, outside the
  allowed range [0, 1]`).

Example: the Lorenz-84 parameter `a` breathes and the camera turns once in a four-second loop.

```json
{
  "schema_version": 2,
  "mesh": { "path": "builtin:meshes/bunny.obj" },
  "layers": [ { "attractor": "lorenz84", "params": { "a": 1.111 } } ],
  "animation": { "duration": 4, "fps": 30, "loop": true },
  "keyframes": [
    { "path": "/layers/0/params/a", "interpolation": "smooth",
      "keys": [ { "time": 0, "value": 1.111 }, { "time": 2, "value": 1.16 } ] },
    { "path": "/camera/azimuth_deg", "interpolation": "linear",
      "keys": [ { "time": 0, "value": 0 }, { "time": 4, "value": 360 } ] },
    { "path": "/tone/background", "keys": [ { "time": 0, "value": "#05060a" }, { "time": 2, "value": "#1a0a20" } ] }
  ]
}
```

The camera track's key at 4 s closes the loop: the camera keeps turning at 90° a second, and
frame 120 would look exactly like frame 0.

## Imported flames

`voxflame import FILE.flame -o PRESET.json` writes an ordinary preset: one layer of `"kind":
"flame"` whose `flame.xforms[i].affine` holds flam3's coefficients (`coefs="a d b e c f"` becomes
`[a, b, 0, c,  d, e, 0, f,  0, 0, k, t]`), whose `color` is `{"mode": "index", "gradient": [256
colours]}` (the flame's palette, colour i at i/255), and whose `tone` carries the flame's
`brightness`, `gamma`, `gamma_threshold`, `vibrancy`, `highlight_power`, `background` and
`estimator_*` keys. The z row `[0, 0, k, t]` is the depth given to a flat flame: after the
transform's variations (2D ones multiply z by the sum W of their weights) z' = ½ z + depth · s,
so k = ½ / W and t = depth · s / W, with s from −1 (the transform of lowest colour) to +1 (the
highest) and depth 0.5 unless `--depth` says otherwise. Edit `k` and `t` to change the layering
after import; `t` = 0 for every transform flattens the flame.

The layer's `transform` places the flame as its author framed it (the `flat` block): its
`locked_fit` puts the frame's centre (`center`, with the median depth of the points drawn inside
the frame) at the mesh's centre, at `scale` = `grid.resolution` / the frame's longer side in flame
units, so that side spans the mesh's longest axis, and its `axis_scale` z makes the depth of those
points (5–95%) 0.6 of that side. `rotation_deg` turns the frame by −`rotate` about z, by 180°
about x (the flat view's top up on screen) and then to face the camera the scene had. The preset's
`render.method` is `points`.
)md";
  return out;
}

}  // namespace voxflame::core
