#include "core/flame/text_raster.h"

#include <fontconfig/fontconfig.h>
#include <ft2build.h>  // IWYU pragma: keep (defines FT_FREETYPE_H, the header below)
#include FT_FREETYPE_H

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace voxflame::core {

namespace {

// JWildfire's text_wf names Arial when a flame gives no font.
constexpr std::string_view kDefaultFont = "Arial";
// Java caps nothing, but a line of a million glyphs is no flame's: longer text is cut here.
constexpr std::size_t kMaxCodePoints = 4096;

struct FontFile {
  std::string path, family;
  int index = 0;
};

std::string lowered(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

// fontconfig's answer for a family name: the installed font it would draw with. Calls are
// serialised, as fontconfig's configuration is shared by the whole process.
FontFile matchFont(std::string_view name) {
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  static FcConfig* const config = FcInitLoadConfigAndFonts();
  FontFile found;
  if (config == nullptr) return found;
  const std::string family(name.empty() ? kDefaultFont : name);
  FcPattern* pattern = FcPatternCreate();
  FcPatternAddString(pattern, FC_FAMILY, reinterpret_cast<const FcChar8*>(family.c_str()));
  FcConfigSubstitute(config, pattern, FcMatchPattern);
  FcDefaultSubstitute(pattern);
  FcResult result = FcResultNoMatch;
  FcPattern* match = FcFontMatch(config, pattern, &result);
  FcPatternDestroy(pattern);
  if (match == nullptr) return found;
  FcChar8* file = nullptr;
  FcChar8* matchedFamily = nullptr;
  if (FcPatternGetString(match, FC_FILE, 0, &file) == FcResultMatch && file != nullptr)
    found.path = reinterpret_cast<const char*>(file);
  if (FcPatternGetString(match, FC_FAMILY, 0, &matchedFamily) == FcResultMatch && matchedFamily != nullptr)
    found.family = reinterpret_cast<const char*>(matchedFamily);
  FcPatternGetInteger(match, FC_INDEX, 0, &found.index);
  FcPatternDestroy(match);
  return found;
}

// UTF-8 to code points; a malformed byte stands for itself (Latin-1), as elsewhere in the importer.
std::vector<char32_t> codePoints(std::string_view text) {
  std::vector<char32_t> out;
  for (std::size_t i = 0; i < text.size() && out.size() < kMaxCodePoints;) {
    const auto byte = static_cast<unsigned char>(text[i]);
    int length = byte < 0x80 ? 1 : (byte >> 5) == 0x6 ? 2 : (byte >> 4) == 0xE ? 3 : (byte >> 3) == 0x1E ? 4 : 0;
    char32_t cp = length == 1 ? byte : length == 2 ? byte & 0x1F : length == 3 ? byte & 0x0F : byte & 0x07;
    for (int k = 1; k < length; ++k) {
      if (i + k >= text.size() || (static_cast<unsigned char>(text[i + k]) >> 6) != 0x2) {
        length = 0;
        break;
      }
      cp = (cp << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
    }
    if (length == 0) {
      out.push_back(byte);
      ++i;
      continue;
    }
    out.push_back(cp);
    i += static_cast<std::size_t>(length);
  }
  return out;
}

struct FreeTypeFace {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  ~FreeTypeFace() {
    if (face) FT_Done_Face(face);
    if (library) FT_Done_FreeType(library);
  }
};

int pixels(FT_Pos value26_6) {
  return static_cast<int>((value26_6 + 32) >> 6);
}

}  // namespace

std::string substituteFontFamily(std::string_view fontName) {
  const std::string wanted(fontName.empty() ? kDefaultFont : fontName);
  const FontFile font = matchFont(wanted);
  if (font.path.empty()) return "no font";
  return lowered(font.family) == lowered(wanted) ? std::string() : font.family;
}

TextRaster rasteriseText(std::string_view text, std::string_view fontName, int fontSize, int baseline) {
  TextRaster raster;
  if (fontSize <= 0) return raster;  // Java draws nothing at size 0
  const FontFile font = matchFont(fontName);
  raster.fontFamily = font.family;
  if (font.path.empty()) {
    raster.problem = "no font is installed";
    return raster;
  }
  FreeTypeFace ft;
  if (FT_Init_FreeType(&ft.library) != 0 || FT_New_Face(ft.library, font.path.c_str(), font.index, &ft.face) != 0) {
    raster.problem = "the font file " + font.path + " could not be read";
    return raster;
  }
  const std::vector<char32_t> glyphs = codePoints(text);
  // Java draws a line of text at its own size: the advance of each glyph (whole pixels, as Java2D's
  // default metrics are), a height of ascent + descent + leading, the baseline at the maximal ascent.
  const auto measure = [&](int size, int& width, int& height, int& ascent) {
    FT_Set_Pixel_Sizes(ft.face, 0, static_cast<FT_UInt>(size));
    width = 0;
    for (const char32_t c : glyphs) {
      if (c < 0x20) continue;  // control characters draw nothing in Java2D
      if (FT_Load_Char(ft.face, c, FT_LOAD_DEFAULT | FT_LOAD_TARGET_MONO) == 0)
        width += pixels(ft.face->glyph->advance.x);
    }
    ascent = pixels(ft.face->size->metrics.ascender);
    height = pixels(ft.face->size->metrics.height) + baseline;
  };
  int size = std::clamp(fontSize, 1, kTextRasterMaxSide);
  int textWidth = 0, textHeight = 0, ascent = 0;
  measure(size, textWidth, textHeight, ascent);
  if (textWidth <= 0) return raster;  // nothing to draw: the variation falls back as JWildfire's does
  // Too large a picture is drawn smaller: only its shape matters, the variation scales it to unit size.
  const int side = std::max(textWidth, textHeight) + 2 * size;
  if (side > kTextRasterMaxSide) {
    size = std::max(1, static_cast<int>(static_cast<double>(size) * kTextRasterMaxSide / side));
    measure(size, textWidth, textHeight, ascent);
  }
  raster.width = textWidth + 2 * size;
  raster.height = std::max(textHeight, 0) + 2 * size;
  if (raster.width <= 0 || raster.height <= 0 || raster.width > 2 * kTextRasterMaxSide ||
      raster.height > 2 * kTextRasterMaxSide) {
    raster.width = raster.height = 0;
    return raster;
  }
  std::vector<std::uint8_t> painted(static_cast<std::size_t>(raster.width) * raster.height, 0);
  // TextTransformer's CENTRE alignment: left = (width − text width) / 2, top = (height − text
  // height) / 2 + baseline, the pen on the line (top + ascent).
  int penX = (raster.width - textWidth) / 2;
  const int penY = (raster.height - textHeight) / 2 + baseline + ascent;
  for (const char32_t c : glyphs) {
    if (c < 0x20) continue;
    if (FT_Load_Char(ft.face, c, FT_LOAD_RENDER | FT_LOAD_TARGET_MONO | FT_LOAD_MONOCHROME) != 0) continue;
    const FT_GlyphSlot glyph = ft.face->glyph;
    const FT_Bitmap& bitmap = glyph->bitmap;
    for (unsigned int r = 0; r < bitmap.rows; ++r) {
      for (unsigned int col = 0; col < bitmap.width; ++col) {
        const unsigned char* line = bitmap.buffer + static_cast<std::ptrdiff_t>(r) * bitmap.pitch;
        const bool on =
            bitmap.pixel_mode == FT_PIXEL_MODE_MONO ? (line[col >> 3] & (0x80 >> (col & 7))) != 0 : line[col] >= 128;
        if (!on) continue;
        const int x = penX + glyph->bitmap_left + static_cast<int>(col);
        const int y = penY - glyph->bitmap_top + static_cast<int>(r);
        if (x >= 0 && x < raster.width && y >= 0 && y < raster.height)
          painted[static_cast<std::size_t>(y) * raster.width + x] = 1;
      }
    }
    penX += pixels(glyph->advance.x);
  }
  for (int i = 0; i < raster.height; ++i)
    for (int j = 0; j < raster.width; ++j)
      if (painted[static_cast<std::size_t>(i) * raster.width + j]) {
        raster.column.push_back(j);
        raster.row.push_back(i);
      }
  return raster;
}

}  // namespace voxflame::core
