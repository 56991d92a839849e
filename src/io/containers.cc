// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Image layouts and containers (containers.h). The facts behind each
// engine's layout (axes, placement, row order, channels, size, pixel type,
// clamps) are in docs/engines.md, with the engines' source files.

#include "brdfbake/containers.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <nlohmann/json.hpp>
#include <png.h>
#include <zstd.h>

#include "base/error.h"
#include "base/pixel.h"
#include "base/text.h"
#include "brdfbake/exr.h"
#include "brdfbake/model.h"
#include "brdfbake/output_file.h"
#include "brdfbake/version.h"
#include "io/exr_write.h"

namespace brdfbake {
namespace {

// The value of `s` at texel i of the table, in double (before rounding).
// Returns false when the table does not hold it.
struct SourceReader {
  explicit SourceReader(const Table& table) {
    for (const Channel& c : table.channels) {
      if (!of[int(c.meaning)]) of[int(c.meaning)] = &c;
    }
    e = Of(Meaning::kE);
    one_minus_e = Of(Meaning::kOneMinusE);
    eavg = Of(Meaning::kEavg);
    one_minus_eavg = Of(Meaning::kOneMinusEavg);
    scale = Of(Meaning::kDfgScale);
    bias = Of(Meaning::kDfgBias);
  }
  // The first channel of each meaning.
  const Channel* of[kMeaningCount] = {};
  const Channel* Of(Meaning m) const { return of[int(m)]; }
  const Channel *e, *one_minus_e, *eavg, *one_minus_eavg, *scale, *bias;

  bool Has(Source s) const {
    switch (s) {
      case Source::kE:
      case Source::kOneMinusE: return e || one_minus_e || (scale && bias);
      case Source::kEavg:
      case Source::kOneMinusEavg: return eavg || one_minus_eavg;
      case Source::kZero:
      case Source::kOne: return true;
      default: return Of(Meaning(int(s))) != nullptr;
    }
  }
  // Derived values (a sum of two channels) carry the sum of two errors.
  bool Derived(Source s) const {
    return (s == Source::kE && !e && !one_minus_e) || (s == Source::kOneMinusE && !e && !one_minus_e);
  }
  double At(Source s, size_t i) const {
    switch (s) {
      case Source::kE:
        if (e) return e->values[i];
        if (one_minus_e) return 1.0 - one_minus_e->values[i];
        return std::min(1.0, scale->values[i] + bias->values[i]);
      case Source::kOneMinusE:
        if (one_minus_e) return one_minus_e->values[i];
        if (e) return 1.0 - e->values[i];
        return std::max(0.0, 1.0 - (scale->values[i] + bias->values[i]));
      case Source::kEavg: return eavg ? eavg->values[i] : 1.0 - one_minus_eavg->values[i];
      case Source::kOneMinusEavg: return one_minus_eavg ? one_minus_eavg->values[i] : 1.0 - eavg->values[i];
      case Source::kZero: return 0.0;
      case Source::kOne: return 1.0;
      default: return Of(Meaning(int(s)))->values[i];
    }
  }
};

}  // namespace

Source SourceOfMeaning(Meaning m) {
  if (m == Meaning::kSelIntegral || m == Meaning::kSelRatio || m == Meaning::kError) {
    Bad(std::string("the ") + MeaningName(m) +
        " channel has no image layout (sel_norm tables are written as their own EXR only: no rgba, other "
        "containers or shaders)");
  }
  return Source(int(m));
}

namespace {

void PutU32(std::string* out, uint32_t v) {
  for (int k = 0; k < 4; ++k) out->push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}
void SetU32(std::string* out, size_t at, uint32_t v) {
  for (int k = 0; k < 4; ++k) (*out)[at + k] = static_cast<char>((v >> (8 * k)) & 0xff);
}
void SetU64(std::string* out, size_t at, uint64_t v) {
  for (int k = 0; k < 8; ++k) (*out)[at + k] = static_cast<char>((v >> (8 * k)) & 0xff);
}

// Pixel data, little-endian, interleaved, row 0 first.
std::string PixelBytes(const Image& im) {
  std::string out;
  const size_t n = im.values.size();
  if (im.pixel == PixelType::kFloat) {
    out.resize(n * 4);
    for (size_t i = 0; i < n; ++i) {
      const float f = float(im.values[i]);
      uint32_t u;
      std::memcpy(&u, &f, 4);
      SetU32(&out, i * 4, u);
    }
  } else {
    out.resize(n * 2);
    for (size_t i = 0; i < n; ++i) {
      out[2 * i] = static_cast<char>(im.bits16[i] & 0xff);
      out[2 * i + 1] = static_cast<char>(im.bits16[i] >> 8);
    }
  }
  return out;
}

std::string CommentBlock(const std::vector<std::pair<std::string, std::string>>& conv,
                         const char* open, const char* line, const char* close) {
  std::string s = std::string(open) + "\n";
  for (const auto& kv : conv) s += std::string(line) + kv.first + ": " + kv.second + "\n";
  return s + close + "\n";
}

// The values as C (suffix "f") or JavaScript (no suffix) literals, or the
// 16-bit codes in hex.
std::string ArrayBody(const Image& im, bool half_bits, const char* float_suffix) {
  std::string s;
  const size_t n = im.values.size();
  const size_t per_line = half_bits ? 12 : 6;
  for (size_t i = 0; i < n; ++i) {
    if (i % per_line == 0) s += "    ";
    if (half_bits) {
      char buf[16];
      std::snprintf(buf, sizeof(buf), "0x%04x", im.bits16[i]);
      s += buf;
    } else {
      char buf[40];
      std::snprintf(buf, sizeof(buf), "%.9g", im.values[i]);
      std::string v = buf;
      if (v.find_first_of(".e") == std::string::npos) v += ".0";
      s += v + float_suffix;
    }
    s += i + 1 < n ? (i % per_line == per_line - 1 ? ",\n" : ", ") : "\n";
  }
  return s;
}

// KTX 2.0 (Khronos KTX 2.0 specification, sections 3-4; the data format
// descriptor is the Khronos Data Format basic block, one sample per
// channel).
std::string Ktx2Bytes(const Image& im, const std::vector<std::pair<std::string, std::string>>& kv,
                      int zstd_level) {
  const bool half = im.pixel == PixelType::kHalf;
  if (im.pixel == PixelType::kUnorm16) Bad("{format} ktx2: holds half or float pixels, not unorm16");
  const int nc = im.channels;
  uint32_t vk = 0;
  if (half) {
    const uint32_t formats[] = {76, 83, 90, 97};  // R16, R16G16, R16G16B16, R16G16B16A16 _SFLOAT
    vk = formats[nc - 1];
  } else {
    const uint32_t formats[] = {100, 103, 106, 109};  // R32 ... R32G32B32A32 _SFLOAT
    vk = formats[nc - 1];
  }
  const uint32_t bytes_per_channel = half ? 2 : 4;
  std::string f;
  const unsigned char id[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32, 0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
  f.append(reinterpret_cast<const char*>(id), 12);
  PutU32(&f, vk);
  PutU32(&f, bytes_per_channel);  // typeSize
  PutU32(&f, uint32_t(im.width));
  PutU32(&f, uint32_t(im.height));
  PutU32(&f, 0);  // pixelDepth
  PutU32(&f, 0);  // layerCount
  PutU32(&f, 1);  // faceCount
  PutU32(&f, 1);  // levelCount
  PutU32(&f, zstd_level > 0 ? 2 : 0);  // supercompressionScheme: none, or 2 = Zstandard
  const size_t index_at = f.size();
  f.append(32, '\0');  // dfd offset/length, kvd offset/length, sgd offset/length
  const size_t level_at = f.size();
  f.append(24, '\0');  // one level: byteOffset, byteLength, uncompressedByteLength
  // Data format descriptor.
  const size_t dfd_at = f.size();
  const uint32_t block_size = 24 + 16 * uint32_t(nc);
  PutU32(&f, 4 + block_size);             // dfdTotalSize
  PutU32(&f, 0);                          // vendorId 0 (Khronos), descriptorType 0 (basic)
  PutU32(&f, 2u | (block_size << 16));    // versionNumber 2 (1.3), descriptorBlockSize
  PutU32(&f, 1u | (1u << 8) | (1u << 16));  // colorModel RGBSDA, primaries BT709, transfer linear, flags 0
  PutU32(&f, 0);                          // texelBlockDimension0..3 = 1 x 1 x 1 x 1
  PutU32(&f, bytes_per_channel * uint32_t(nc));  // bytesPlane0
  PutU32(&f, 0);                          // bytesPlane4..7
  for (int c = 0; c < nc; ++c) {
    const uint32_t channel_id = c == 3 ? 15u : uint32_t(c);  // R, G, B, then A = 15
    const uint32_t qualifiers = 0x80 | 0x40;                 // float, signed
    PutU32(&f, uint32_t(c) * bytes_per_channel * 8 | ((bytes_per_channel * 8 - 1) << 16) |
                   ((channel_id | qualifiers) << 24));
    PutU32(&f, 0);           // sample position
    PutU32(&f, 0xBF800000);  // sampleLower: -1.0f
    PutU32(&f, 0x3F800000);  // sampleUpper: 1.0f
  }
  const size_t dfd_len = f.size() - dfd_at;
  // Key/value data, sorted by key, each entry padded to 4 bytes.
  std::vector<std::pair<std::string, std::string>> sorted = kv;
  sorted.push_back({"KTXorientation", "rd"});
  sorted.push_back({"KTXwriter", std::string("brdfbake ") + BRDFBAKE_VERSION});
  std::sort(sorted.begin(), sorted.end());
  const size_t kvd_at = f.size();
  for (const auto& e : sorted) {
    const std::string entry = e.first + std::string(1, '\0') + e.second + std::string(1, '\0');
    PutU32(&f, uint32_t(entry.size()));
    f += entry;
    while (f.size() % 4) f.push_back('\0');
  }
  const size_t kvd_len = f.size() - kvd_at;
  // Level data aligned to lcm(texel block size, 4); a supercompressed
  // level needs no alignment.
  const size_t texel = bytes_per_channel * size_t(nc);
  const size_t align = zstd_level > 0 ? 1 : texel % 4 == 0 ? texel : (texel % 2 == 0 ? texel * 2 : texel * 4);
  while (f.size() % align) f.push_back('\0');
  const size_t data_at = f.size();
  const std::string pixels = PixelBytes(im);
  std::string level = pixels;
  if (zstd_level > 0) {
    level.resize(ZSTD_compressBound(pixels.size()));
    const size_t n = ZSTD_compress(level.data(), level.size(), pixels.data(), pixels.size(), zstd_level);
    if (ZSTD_isError(n)) {
      throw std::runtime_error(std::string("KTX2 zstd supercompression failed: ") + ZSTD_getErrorName(n));
    }
    level.resize(n);
  }
  f += level;
  SetU32(&f, index_at + 0, uint32_t(dfd_at));
  SetU32(&f, index_at + 4, uint32_t(dfd_len));
  SetU32(&f, index_at + 8, uint32_t(kvd_at));
  SetU32(&f, index_at + 12, uint32_t(kvd_len));
  SetU64(&f, level_at + 0, data_at);
  SetU64(&f, level_at + 8, level.size());
  SetU64(&f, level_at + 16, pixels.size());
  return f;
}

// PNG through libpng: 8- or 16-bit codes (big-endian), the channel count
// as the colour type, the conventions as tEXt chunks (their keys).
// libpng reports errors by longjmp to the setjmp below, out of its own
// frames only; the objects with destructors live outside that scope.
struct PngOut {
  std::string bytes;
  std::string error;
};

extern "C" {
static void PngWrite(png_structp png, png_bytep data, png_size_t n) {
  static_cast<PngOut*>(png_get_io_ptr(png))->bytes.append(reinterpret_cast<const char*>(data), n);
}
static void PngFlush(png_structp) {}
static void PngError(png_structp png, png_const_charp msg) {
  static_cast<PngOut*>(png_get_error_ptr(png))->error = msg;
  png_longjmp(png, 1);
}
static void PngWarning(png_structp, png_const_charp) {}
}

// The libpng calls, in a frame of their own that holds no object with a
// destructor and no local the longjmp of an error could leave stale.
bool PngEncode(png_structp png, png_infop info, PngOut* out, int width, int height, int depth,
               int color_type, png_textp text, int n_text, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png)) != 0) return false;
  png_set_write_fn(png, out, PngWrite, PngFlush);
  png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), depth, color_type, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_text(png, info, text, n_text);
  png_set_rows(png, info, rows);
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  return true;
}

std::string PngBytes(const Image& im, const std::vector<std::pair<std::string, std::string>>& kv) {
  if (im.pixel != PixelType::kUnorm8 && im.pixel != PixelType::kUnorm16) {
    Bad(std::string("{format} png: holds unorm8 or unorm16 pixels, not ") + PixelTypeName(im.pixel));
  }
  const int nc = im.channels;
  const int types[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                       PNG_COLOR_TYPE_RGBA};
  const bool wide = im.pixel == PixelType::kUnorm16;
  const size_t row_bytes = size_t(im.width) * nc * (wide ? 2 : 1);
  std::vector<unsigned char> pixels(row_bytes * im.height);
  for (size_t i = 0; i < im.bits16.size(); ++i) {
    if (wide) {
      pixels[2 * i] = static_cast<unsigned char>(im.bits16[i] >> 8);
      pixels[2 * i + 1] = static_cast<unsigned char>(im.bits16[i] & 0xff);
    } else {
      pixels[i] = static_cast<unsigned char>(im.bits16[i]);
    }
  }
  std::vector<png_bytep> rows(im.height);
  for (int y = 0; y < im.height; ++y) rows[y] = pixels.data() + size_t(y) * row_bytes;
  std::vector<std::string> keys, values;
  for (const auto& [k, v] : kv) {
    keys.push_back(k.substr(0, 79));
    values.push_back(v);
  }
  std::vector<png_text> text(kv.size());
  for (size_t i = 0; i < kv.size(); ++i) {
    text[i].compression = PNG_TEXT_COMPRESSION_NONE;
    text[i].key = const_cast<char*>(keys[i].c_str());
    text[i].text = const_cast<char*>(values[i].c_str());
    text[i].text_length = values[i].size();
  }
  PngOut out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &out, PngError, PngWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  const bool ok = png != nullptr && info != nullptr &&
                  PngEncode(png, info, &out, im.width, im.height, wide ? 16 : 8, types[nc - 1],
                            text.data(), int(text.size()), rows.data());
  png_destroy_write_struct(&png, &info);
  if (!ok) throw std::runtime_error("png: libpng failed: " + out.error);
  return out.bytes;
}

// DDS with the DX10 extension header (Microsoft's DDS_HEADER and
// DDS_HEADER_DXT10 layouts).
std::string DdsBytes(const Image& im) {
  uint32_t dxgi = 0;
  const int nc = im.channels;
  if (im.pixel == PixelType::kHalf) {
    const uint32_t formats[] = {54, 34, 0, 10};  // R16_FLOAT, R16G16_FLOAT, -, R16G16B16A16_FLOAT
    dxgi = formats[nc - 1];
  } else if (im.pixel == PixelType::kUnorm16) {
    const uint32_t formats[] = {56, 35, 0, 11};  // R16_UNORM, R16G16_UNORM, -, R16G16B16A16_UNORM
    dxgi = formats[nc - 1];
  } else {
    const uint32_t formats[] = {41, 16, 6, 2};  // R32, R32G32, R32G32B32, R32G32B32A32 _FLOAT
    dxgi = formats[nc - 1];
  }
  if (dxgi == 0) Bad("{format} dds: three 16-bit channels have no DXGI format; use two or four");
  const uint32_t bpp = (im.pixel == PixelType::kFloat ? 4 : 2) * uint32_t(nc);
  std::string f = "DDS ";
  PutU32(&f, 124);                                 // dwSize
  PutU32(&f, 0x1 | 0x2 | 0x4 | 0x8 | 0x1000);      // CAPS | HEIGHT | WIDTH | PITCH | PIXELFORMAT
  PutU32(&f, uint32_t(im.height));
  PutU32(&f, uint32_t(im.width));
  PutU32(&f, uint32_t(im.width) * bpp);            // pitch
  PutU32(&f, 0);                                   // depth
  PutU32(&f, 0);                                   // mip count
  for (int i = 0; i < 11; ++i) PutU32(&f, 0);      // reserved
  PutU32(&f, 32);                                  // pixel format: size
  PutU32(&f, 0x4);                                 // DDPF_FOURCC
  f += "DX10";
  for (int i = 0; i < 5; ++i) PutU32(&f, 0);       // bit count and masks
  PutU32(&f, 0x1000);                              // DDSCAPS_TEXTURE
  for (int i = 0; i < 4; ++i) PutU32(&f, 0);       // caps2..4, reserved2
  PutU32(&f, dxgi);
  PutU32(&f, 3);                                   // D3D10_RESOURCE_DIMENSION_TEXTURE2D
  PutU32(&f, 0);                                   // misc flags
  PutU32(&f, 1);                                   // array size
  PutU32(&f, 0);                                   // misc flags 2
  f += PixelBytes(im);
  return f;
}

}  // namespace

const char* SourceName(Source s) {
  switch (s) {
    case Source::kZero: return "0";
    case Source::kOne: return "1";
    default: return MeaningName(Meaning(int(s)));
  }
}

const char* PixelTypeName(PixelType p) {
  switch (p) {
    case PixelType::kFloat: return "float";
    case PixelType::kHalf: return "half";
    case PixelType::kUnorm16: return "unorm16";
    case PixelType::kUnorm8: return "unorm8";
  }
  return "float";
}

const char* ContainerName(Container c) {
  switch (c) {
    case Container::kExr: return "exr";
    case Container::kHeader: return "header";
    case Container::kJs: return "js";
    case Container::kKtx2: return "ktx2";
    case Container::kDds: return "dds";
    case Container::kInc: return "inc";
    case Container::kPng: return "png";
  }
  return "exr";
}

Container ParseContainer(const std::string& given) {
  const std::string s = Lowercase(given);
  for (Container c : {Container::kExr, Container::kHeader, Container::kJs, Container::kKtx2,
                      Container::kDds, Container::kInc, Container::kPng}) {
    if (s == ContainerName(c)) return c;
  }
  Bad("{format}: unknown format '" + given + "' (expected exr, header, js, ktx2, dds, inc or png)" +
      DidYouMean(given, {"exr", "header", "js", "ktx2", "dds", "inc", "png"}, {{"h", "header"}, {"hpp", "header"},
                                                                         {"mjs", "js"}, {"ktx", "ktx2"}}));
}

Container ContainerFromPath(const std::string& path) {
  const std::string ext = Lowercase(std::filesystem::path(path).extension().string());
  if (ext == ".exr") return Container::kExr;
  if (ext == ".h" || ext == ".hpp") return Container::kHeader;
  if (ext == ".inc") return Container::kInc;
  if (ext == ".js" || ext == ".mjs") return Container::kJs;
  if (ext == ".ktx2") return Container::kKtx2;
  if (ext == ".dds") return Container::kDds;
  if (ext == ".png") return Container::kPng;
  Bad("{output}: '" + path + "' " + (ext.empty() ? "has no extension" : "names a " + ext + " file") +
      "; bake writes .exr, .h/.hpp (header), .inc (array body), .js/.mjs, .ktx2, .dds or .png");
}

namespace {

// The layout of `channels` (a table's or ShapeOf's) without the error.
template <class Channels>
ImageLayout ChannelsLayout(const Channels& channels, bool half) {
  ImageLayout l;
  for (const auto& c : channels) {
    if (c.meaning == Meaning::kError) continue;
    l.channels.push_back({c.name, SourceOfMeaning(c.meaning)});
  }
  l.pixel = half ? PixelType::kHalf : PixelType::kFloat;
  return l;
}

}  // namespace

ImageLayout DefaultLayout(const Table& table) { return ChannelsLayout(table.channels, table.spec.half); }

ImageLayout DefaultLayout(const BakeSpec& spec) { return ChannelsLayout(ShapeOf(spec).channels, spec.half); }

ImageLayout RgbaLayout(const ImageLayout& layout) {
  if (layout.channels.size() > 4) {
    Bad("{channels} rgba: the table has " + std::to_string(layout.channels.size()) +
        " channels, more than R, G, B and A");
  }
  ImageLayout l = layout;
  const char* names[] = {"R", "G", "B", "A"};
  while (l.channels.size() < 4) l.channels.push_back({"", l.channels.size() == 3 ? Source::kOne : Source::kZero});
  for (size_t c = 0; c < 4; ++c) l.channels[c].name = names[c];
  return l;
}

std::string ChannelMeaning(const ImageLayout::Out& o, const std::vector<const Table*>& others) {
  std::string m = SourceName(o.source);
  if (o.table > 0 && o.table <= int(others.size())) {
    m += std::string(" of ") + others[o.table - 1]->spec.model.name();
    if (ModelTakes(others[o.table - 1]->spec.model.kind, ModelOption::kVisibility)) {
      m += std::string(" (") + SheenVisibilityName(others[o.table - 1]->spec.model.visibility) + ")";
    }
  }
  if (o.scale != 1) m += " * " + NumG9(o.scale);
  if (o.offset != 0) m += (o.offset < 0 ? " - " : " + ") + NumG9(std::abs(o.offset));
  if (std::isfinite(o.max)) m += ", at most " + NumG9(o.max);
  return m;
}

Image ArrangeTable(const Table& t, const ImageLayout& layout) { return ArrangeTables(t, {}, layout); }

Image ArrangeTables(const Table& t, const std::vector<const Table*>& others, const ImageLayout& layout) {
  std::vector<SourceReader> readers = {SourceReader{t}};
  for (const Table* o : others) {
    if (o->width != t.width || o->height != t.height) {
      Bad(std::string("the ") + o->spec.model.name() + " table's size differs from the " +
          TableName(t.spec.table) + " table's");
    }
    readers.push_back(SourceReader{*o});
  }
  for (const ImageLayout::Out& o : layout.channels) {
    if (o.table < 0 || o.table >= int(readers.size())) {
      Bad("channel " + o.name + " reads table " + std::to_string(o.table) + " of " +
          std::to_string(readers.size()));
    }
    const Table& src = o.table == 0 ? t : *others[o.table - 1];
    if (!readers[o.table].Has(o.source)) {
      Bad(std::string("the ") + TableName(src.spec.table) + " table has no " + SourceName(o.source));
    }
  }
  const SourceReader& reader = readers[0];
  const bool one_d = t.spec.table == TableKind::kEavg;
  const bool transpose = layout.roughness_on_x && !one_d;
  // Tables over a third axis stack its slices vertically (t.height = rows
  // x slices); a transposed image keeps them stacked and transposes each.
  const int rows = transpose && t.axes.size() > 2 ? t.axes[1].size : t.height;
  const int slices = t.height / rows;
  Image im;
  im.width = transpose ? rows : t.width;
  im.height = transpose ? t.width * slices : t.height;
  im.channels = int(layout.channels.size());
  im.pixel = layout.pixel;
  im.flip_rows = layout.flip_rows && !one_d;
  im.transposed = transpose;
  im.axes = t.axes;
  if (transpose) std::swap(im.axes[0], im.axes[1]);
  for (const ImageLayout::Out& o : layout.channels) {
    im.channel_names.push_back(o.name);
    im.channel_sources.push_back(ChannelMeaning(o, others));
  }
  // The claim: the largest integration estimate of a table read (twice for
  // E or 1-E formed from scale + bias; times a channel's scale) plus this
  // image's largest rounding.
  double integration = 0;
  for (const ImageLayout::Out& o : layout.channels) {
    const Table& src = o.table == 0 ? t : *others[o.table - 1];
    const bool derived = readers[o.table].Derived(o.source);
    integration = std::max(integration, src.integration_error * (derived ? 2 : 1) * std::abs(o.scale));
  }
  double rounding = 0;
  const size_t n = size_t(im.width) * im.height * im.channels;
  im.values.resize(n);
  if (im.pixel != PixelType::kFloat) im.bits16.resize(n);
  // Which channels hold dfg's scale and bias: rounded as a pair, as the
  // table's own EXR rounds them (base/pixel.h).
  int scale_c = -1, bias_c = -1;
  for (int c = 0; c < im.channels; ++c) {
    if (layout.channels[c].source == Source::kScale) scale_c = c;
    if (layout.channels[c].source == Source::kBias) bias_c = c;
  }
  std::vector<double> raw(im.channels);
  for (int y = 0; y < im.height; ++y) {
    const int ty = im.flip_rows ? im.height - 1 - y : y;
    for (int x = 0; x < im.width; ++x) {
      const size_t src = transpose ? (size_t(ty / t.width) * rows + x) * t.width + ty % t.width
                                   : size_t(ty) * t.width + x;
      const size_t dst = (size_t(y) * im.width + x) * im.channels;
      for (int c = 0; c < im.channels; ++c) {
        const ImageLayout::Out& o = layout.channels[c];
        raw[c] = o.table == 0 && o.scale == 1 && o.offset == 0 && !(o.max < kInfinity)
                     ? reader.At(o.source, src)
                     : std::min(o.scale * readers[o.table].At(o.source, src) + o.offset, o.max);
        im.values[dst + c] = RoundToPixel(raw[c], im.pixel);
      }
      if (scale_c >= 0 && bias_c >= 0) {
        RoundScaleBias(raw[scale_c], raw[bias_c], im.pixel, &im.values[dst + scale_c],
                       &im.values[dst + bias_c]);
      }
      for (int c = 0; c < im.channels; ++c) {
        if (im.pixel != PixelType::kFloat) im.bits16[dst + c] = PixelCode(im.values[dst + c], im.pixel);
        rounding = std::max(rounding, std::abs(im.values[dst + c] - raw[c]));
      }
    }
  }
  im.max_abs_error = integration + rounding;
  return im;
}

std::vector<std::pair<std::string, std::string>> ImageConventions(const Table& t, const Image& im,
                                                                  const std::string& preset) {
  nlohmann::json axes = nlohmann::json::array();
  for (const Axis& a : im.axes) axes.push_back(nlohmann::json::parse(a.ToJson()));
  // As in the tables' EXR files: name -> meaning, the order, and per channel
  // its index, name and meaning ("0" and "1" are constant channels).
  nlohmann::json channels = nlohmann::json::object();
  nlohmann::json order = nlohmann::json::array();
  nlohmann::json info = nlohmann::json::array();
  for (size_t c = 0; c < im.channel_names.size(); ++c) {
    channels[im.channel_names[c]] = im.channel_sources[c];
    order.push_back(im.channel_names[c]);
    info.push_back({{"index", c}, {"name", im.channel_names[c]}, {"meaning", im.channel_sources[c]}});
  }
  const bool one_d = im.height == 1;
  std::string layout = "x (columns) = " + im.axes[0].name;
  if (!one_d) {
    layout += ", y (rows) = " + im.axes[1].name + (im.flip_rows ? ", row 0 = the LAST " : ", row 0 = the first ") +
              im.axes[1].name + " entry";
  } else {
    layout += ", one row";
  }
  if (im.axes.size() > 2) {
    layout += ", then slices of " + std::to_string(im.axes[1].size) + " rows stacked vertically over";
    for (size_t k = 2; k < im.axes.size(); ++k) layout += (k > 2 ? ", " : " ") + im.axes[k].name;
    layout += " (the third axis fastest)";
  }
  layout += "; channels interleaved per texel in the order of brdfbake.channel_order; axis i of size N: "
            "t = (i + 0.5) / N (centers) or i / (N - 1) (edges), value = min + (max - min) w(t), "
            "w = t, t^2, sqrt(t) for linear, square, sqrt (the tail and fresnel-z warps: the axis' map); "
            "the integrand at max(value, clamp_min)";
  for (const Axis& a : im.axes) {
    if (a.clamp_max < kInfinity) {
      layout += " and at most clamp_max";
      break;
    }
  }
  char err[40];
  std::snprintf(err, sizeof(err), "%.3e", im.max_abs_error * (1 + 1e-3));
  std::vector<std::pair<std::string, std::string>> kv = {
      {"brdfbake.version", BRDFBAKE_VERSION},
      {"brdfbake.table", im.table_name.empty() ? std::string(TableName(t.spec.table)) : im.table_name},
      {"brdfbake.model", t.model_json},
      {"brdfbake.masking", MaskingName(t.spec.masking)},
      {"brdfbake.fresnel", !im.fresnel.empty() ? im.fresnel
                           : t.spec.Glass() && t.spec.part == DielectricPart::kTransmissionSchlick
                               ? kSchlickComplementFresnel
                           : t.spec.Glass()      ? "dielectric"
                           : t.spec.GenSchlick() ? "generalized Schlick: mix(F0, F90, s)"
                                                 : "one"},
      {"brdfbake.axes", axes.dump()},
      {"brdfbake.layout", layout},
      {"brdfbake.channels", channels.dump()},
      {"brdfbake.channel_order", order.dump()},
      {"brdfbake.channel_info", info.dump()},
      {"brdfbake.pixel", PixelTypeName(im.pixel)},
      {"brdfbake.range", kStoredRange},
      {"brdfbake.integrator", t.integrator_json},
      {"brdfbake.max_abs_error", err},
  };
  if (!preset.empty()) kv.insert(kv.begin() + 1, {"brdfbake.preset", preset});
  return kv;
}

void WriteHeader(const std::vector<std::pair<const Table*, const Image*>>& arrays,
                 const std::vector<std::string>& symbols, const std::string& path,
                 const std::string& preset) {
  std::string s = "// Generated by brdfbake " + std::string(BRDFBAKE_VERSION) +
                  ". Do not edit: bake again instead.\n#pragma once\n\n#include <cstdint>\n\n";
  for (size_t k = 0; k < arrays.size(); ++k) {
    const Table& t = *arrays[k].first;
    const Image& im = *arrays[k].second;
    const bool half_bits = im.pixel != PixelType::kFloat;
    s += CommentBlock(ImageConventions(t, im, preset), "/*", " * ", " */");
    const std::string sym = symbols[k];
    s += "inline constexpr int " + sym + "_width = " + std::to_string(im.width) + ";\n";
    s += "inline constexpr int " + sym + "_height = " + std::to_string(im.height) + ";\n";
    s += "inline constexpr int " + sym + "_channels = " + std::to_string(im.channels) + ";\n";
    s += std::string("inline constexpr ") + (half_bits ? "uint16_t " : "float ") + sym + "[" +
         std::to_string(im.values.size()) + "] = {\n" + ArrayBody(im, half_bits, "f") + "};\n\n";
  }
  WriteFileAtomically(path, s);
}

size_t ContainerWriteBytes(Container container, int64_t values) {
  // Per value: the arranged Image (a double and 16 bits), then the file.
  size_t per_value = sizeof(double) + sizeof(uint16_t);
  switch (container) {
    case Container::kExr:
      per_value += 2 * (sizeof(float) + sizeof(uint16_t));  // planes, and OpenEXR's copy
      break;
    case Container::kHeader:
    case Container::kJs:
    case Container::kInc:
      per_value += 3 * 24;  // up to 24 characters a value; the array, the file, their sum
      break;
    case Container::kKtx2:
    case Container::kDds:
    case Container::kPng:
      per_value += 3 * sizeof(float);  // the pixels, the file, their sum
      break;
  }
  return size_t(values) * per_value;
}

void CheckContainerMemory(Container container, int64_t values, size_t held,
                          const std::string& path) {
  const size_t bytes = ContainerWriteBytes(container, values) + held;
  // Allocated and released at once: where the address space or memory is
  // limited (ulimit -v), a write that cannot fit fails here. The volatile
  // store keeps the compiler from eliding the pair.
  static char* volatile probe = nullptr;
  probe = static_cast<char*>(std::malloc(bytes));
  const bool ok = probe != nullptr || bytes == 0;
  std::free(probe);
  probe = nullptr;
  if (!ok) {
    char msg[200];
    std::snprintf(msg, sizeof(msg),
                  "cannot allocate %.1f MiB to bake and write the %s file %s (out of memory)",
                  double(bytes) / (1 << 20), ContainerName(container), path.c_str());
    throw std::runtime_error(msg);
  }
}

void WriteImage(const Table& table, const Image& im, Container container, const std::string& path,
                const std::string& symbol, const std::string& preset, int ktx2_zstd_level) {
  const auto conv = ImageConventions(table, im, preset);
  if (im.pixel == PixelType::kUnorm8 && container != Container::kPng) {
    Bad(std::string("{format} ") + ContainerName(container) + ": holds no unorm8 pixels (png does)");
  }
  switch (container) {
    case Container::kExr: {
      if (im.pixel == PixelType::kUnorm16) Bad("{format} exr: holds half or float pixels, not unorm16");
      // One planar buffer per channel: OpenEXR's slices.
      std::vector<std::vector<float>> planes(im.channels, std::vector<float>(size_t(im.width) * im.height));
      std::vector<std::vector<uint16_t>> half_planes(im.pixel == PixelType::kHalf ? im.channels : 0,
                                                     std::vector<uint16_t>(size_t(im.width) * im.height));
      for (size_t i = 0; i < size_t(im.width) * im.height; ++i) {
        for (int c = 0; c < im.channels; ++c) {
          planes[c][i] = float(im.values[i * im.channels + c]);
          if (!half_planes.empty()) half_planes[c][i] = im.bits16[i * im.channels + c];
        }
      }
      WriteExrPlanes(path, im.width, im.height, im.channel_names, planes, half_planes, conv);
      return;
    }
    case Container::kHeader:
      WriteHeader({{&table, &im}}, {symbol}, path, preset);
      return;
    case Container::kJs: {
      const bool half = im.pixel == PixelType::kHalf;
      if (im.pixel == PixelType::kUnorm16) Bad("{format} js: holds half or float pixels, not unorm16");
      std::string s = CommentBlock(conv, "/*", " * ", " */");
      s += "// Generated by brdfbake " + std::string(BRDFBAKE_VERSION) + ".\n";
      s += "export const width = " + std::to_string(im.width) + ";\n";
      s += "export const height = " + std::to_string(im.height) + ";\n";
      s += "export const channels = " + std::to_string(im.channels) + ";\n";
      const char* formats_half[] = {"R16F", "RG16F", "RGB16F", "RGBA16F"};
      const char* formats_float[] = {"R32F", "RG32F", "RGB32F", "RGBA32F"};
      s += std::string("export const format = '") +
           (half ? formats_half[im.channels - 1] : formats_float[im.channels - 1]) + "';\n";
      nlohmann::json conv_json = nlohmann::json::object();
      for (const auto& kv : conv) conv_json[kv.first] = kv.second;
      s += "export const conventions = " + conv_json.dump() + ";\n";
      s += std::string("export const ") + symbol + " = new " + (half ? "Uint16Array" : "Float32Array") +
           "([\n" + ArrayBody(im, half, "") + "]);\n";
      WriteFileAtomically(path, s);
      return;
    }
    case Container::kKtx2:
      WriteFileAtomically(path, Ktx2Bytes(im, conv, ktx2_zstd_level));
      return;
    case Container::kDds:
      WriteFileAtomically(path, DdsBytes(im));
      return;
    case Container::kPng:
      WriteFileAtomically(path, PngBytes(im, conv));
      return;
    case Container::kInc: {
      // The conventions as a comment, then the values alone: the file is
      // #included inside an array's initializer.
      const bool half_bits = im.pixel != PixelType::kFloat;
      std::string s = "// Generated by brdfbake " + std::string(BRDFBAKE_VERSION) +
                      ". Do not edit: bake again instead.\n";
      s += CommentBlock(conv, "/*", " * ", " */");
      s += "// " + std::to_string(im.width) + " x " + std::to_string(im.height) + " texels x " +
           std::to_string(im.channels) + " channels, row 0 first, " +
           (half_bits ? std::string(PixelTypeName(im.pixel)) + " codes (uint16_t)" : "float") + "\n";
      s += ArrayBody(im, half_bits, "f");
      WriteFileAtomically(path, s);
      return;
    }
  }
}

}  // namespace brdfbake
