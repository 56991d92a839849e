// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Tables in the shape engines load: an image layout (which axis is x, row
// order, which quantity in which channel, pixel type) and the containers
// engines read (OpenEXR, C/C++ headers, ES modules, KTX 2.0, DDS). The
// numbers are always brdfbake's exact integration; only their arrangement
// follows the engine. Shader lookups are in shaders.h, the engine presets
// in presets.h.

#ifndef BRDFBAKE_CONTAINERS_H_
#define BRDFBAKE_CONTAINERS_H_

#include <cstdint>
#include <string>
#include <vector>

#include "brdfbake/bake.h"

namespace brdfbake {

// What an output channel holds: a channel of the table by its meaning, or
// the constant 0 or 1. A channel source has the value of its Meaning, so
// every meaning is a source (SourceOfMeaning) without an enumerator of its
// own; the enumerators name the ones layouts pick. E and 1-E (E_avg and
// 1-E_avg) each come from the other too, and E from dfg.scale + dfg.bias.
enum class Source : int {
  kE = int(Meaning::kE),
  kOneMinusE = int(Meaning::kOneMinusE),
  kEavg = int(Meaning::kEavg),
  kOneMinusEavg = int(Meaning::kOneMinusEavg),
  kScale = int(Meaning::kDfgScale),
  kBias = int(Meaning::kDfgBias),
  kS = int(Meaning::kS),  // the factor s of a gen_schlick table
  kZero = kMeaningCount,
  kOne,
};
// The source of a table's channel of meaning m; throws a ParameterError for
// the meanings no image holds (sel_norm's, the error).
Source SourceOfMeaning(Meaning m);
// A channel source's MeaningName ("E", "dfg.scale", "s", "f82_bias"), "0"
// or "1".
const char* SourceName(Source s);

const char* PixelTypeName(PixelType p);  // float, half, unorm16, unorm8

// kInc is the array body alone (comma-separated values after a comment), to
// be #included inside an initializer: `const uint16_t lut[] = {\n#include
// "dfg.inc"\n};` (Filament's form).
// kPng is 8- or 16-bit unorm PNG (libpng): gray, gray + alpha, RGB or RGBA
// by the channel count, with the conventions in tEXt chunks.
enum class Container { kExr, kHeader, kJs, kKtx2, kDds, kInc, kPng };
const char* ContainerName(Container c);  // exr, header, js, ktx2, dds, inc, png
// Throws std::invalid_argument naming the bad value.
Container ParseContainer(const std::string& s);
// The container a file name's extension names (.exr, .h/.hpp, .inc,
// .js/.mjs, .ktx2, .dds, .png); throws std::invalid_argument for any other.
Container ContainerFromPath(const std::string& path);

struct ImageLayout {
  bool roughness_on_x = false;  // x = roughness, y = mu (three.js, Cycles)
  bool flip_rows = false;       // row 0 holds the last entry of the y axis
  // A channel: scale * (its source in table `table`) + offset, clamped to
  // at most `max`. Table 0 is the image's own table, k > 0 the k-th of the
  // others ArrangeTables takes (another model over the same axes: the
  // Charlie sheen in Filament's third channel, say). HDRP stores the
  // Disney diffuse E / 1.03571 - 0.5, MaterialX its sheen clamped to 1.
  struct Out {
    std::string name;  // channel name (EXR) / role in the comments
    Source source;
    int table = 0;
    double scale = 1, offset = 0, max = kInfinity;
  };
  std::vector<Out> channels;
  PixelType pixel = PixelType::kFloat;
  bool header_half_bits = false;  // header container: uint16 half bits instead of floats
};

// The default layout of a table: x = mu, y = roughness, the table's own
// channels (without `error`), its pixel type.
ImageLayout DefaultLayout(const Table& table);
// The same from the spec, before its bake (ShapeOf's channels).
ImageLayout DefaultLayout(const BakeSpec& spec);
// The same layout for loaders that know only R, G, B and A: the channels
// renamed R, G, B, A in order and padded to four (B = 0, A = 1); their
// meanings stay in the file's conventions. Throws std::invalid_argument
// for more than four channels.
ImageLayout RgbaLayout(const ImageLayout& layout);

// A table arranged by a layout: interleaved, row-major, values as stored
// (rounded to the pixel type) and their encoding.
struct Image {
  int width = 0, height = 0, channels = 0;
  PixelType pixel = PixelType::kFloat;
  std::vector<double> values;     // width * height * channels, as stored
  std::vector<uint16_t> bits16;   // half bits or unorm16 codes (16-bit types)
  std::vector<std::string> channel_names;
  std::vector<std::string> channel_sources;
  // The axes along x then y (a copy of the table's, in image order) and
  // whether rows are flipped, for the metadata and the shader functions.
  std::vector<Axis> axes;
  bool transposed = false;  // x = roughness
  bool flip_rows = false;
  double max_abs_error = 0;  // the table's integration error plus this image's rounding
  // An image formed from a table rather than holding it (a preset's
  // Enterprise PBR Base_E over F0): its brdfbake.table and brdfbake.fresnel
  // (empty: the table's own, "one").
  std::string table_name, fresnel;
};

// Throws std::invalid_argument if a channel's source is not in the table.
Image ArrangeTable(const Table& table, const ImageLayout& layout);
// The same with the channels of `others` (the layout's tables 1, 2, ...),
// each over the same axes as `table`; the claim covers every table read.
Image ArrangeTables(const Table& table, const std::vector<const Table*>& others,
                    const ImageLayout& layout);

// A channel's meaning as the file's conventions state it: "E", or with
// another table, its affine map and clamp, "E of disney-diffuse * 0.9655 -
// 0.5".
std::string ChannelMeaning(const ImageLayout::Out& out, const std::vector<const Table*>& others);

// Everything a loader needs, as "key: value" lines (table, model, masking,
// axes with their maps, row order, channels, pixel type, error, preset).
std::vector<std::pair<std::string, std::string>> ImageConventions(const Table& table,
                                                                  const Image& image,
                                                                  const std::string& preset);

// Writes `image` (with `table`'s conventions) as `container`, through an
// AtomicFile. `symbol` names the arrays of the header and js containers.
// Throws std::runtime_error (or std::invalid_argument for a pixel type the
// container cannot hold).
// The memory arranging and writing `values` stored values in `container`
// takes at its peak (the Image, the text or bytes of the file and their
// copies while they are put together), and a check, before a bake, that
// this much can be allocated beside the `held` bytes the bakes will hold
// (BakeOutputBytes): throws std::runtime_error naming the size and the
// file if not, so that a file that cannot be written fails before the work
// rather than after it.
size_t ContainerWriteBytes(Container container, int64_t values);
void CheckContainerMemory(Container container, int64_t values, size_t held,
                          const std::string& path);

// `ktx2_zstd_level` > 0 supercompresses a KTX2 file's level with
// Zstandard at that level (scheme 2, as Bevy ships its dfg.ktx2).
void WriteImage(const Table& table, const Image& image, Container container,
                const std::string& path, const std::string& symbol, const std::string& preset,
                int ktx2_zstd_level = 0);

// Several arrays in one C/C++ header (Cycles' E and E_avg, say).
void WriteHeader(const std::vector<std::pair<const Table*, const Image*>>& arrays,
                 const std::vector<std::string>& symbols, const std::string& path,
                 const std::string& preset);

}  // namespace brdfbake

#endif  // BRDFBAKE_CONTAINERS_H_
