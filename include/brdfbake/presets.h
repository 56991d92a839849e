// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Engine presets: the tables an engine ships, in its layouts and containers.

#ifndef BRDFBAKE_PRESETS_H_
#define BRDFBAKE_PRESETS_H_

#include <string>
#include <vector>

#include "brdfbake/bake.h"
#include "brdfbake/containers.h"
#include "brdfbake/shaders.h"
#include "brdfbake/table_files.h"

namespace brdfbake {

// The form of a file that is an engine's own: the same name, symbols,
// include or import form and API as the file the engine ships.
enum class EngineForm {
  kGeneric,              // brdfbake's container as it is
  kThreeDfgModule,       // three.js src/renderers/shaders/DFGLUTData.js: export getDFGLUT()
  kEnterprisePbrHeader,  // Enterprise PBR res/pbrlut.hpp: extern arrays, PBRLUT_IMPLEMENTATION
  kOpenPbrEnergyArrays,  // OpenPBR impl/data/openpbr_energy_arrays.h: unorm16 OpenPBR_*_Array
  kEeveeLut,             // Blender EEVEE eevee_lut.cc: btdf_ggx[16][64][64][1], the rest Blender's own
};

struct PresetTable {
  BakeSpec spec;
  ImageLayout layout;
  Container container = Container::kExr;
  std::string file;    // default file name
  std::string symbol;  // array name (header, js), and the shader lookup's brdfbake_<symbol>
  EngineForm form = EngineForm::kGeneric;
  int ktx2_zstd_level = 0;  // > 0: the KTX2 level supercompressed with Zstandard
  // Other containers the engine loads this table from (bake --preset
  // --format): the file keeps its stem and takes the container's extension.
  std::vector<Container> also;
  // The other tables the layout's channels read (its table k is with[k -
  // 1]): another model's E over the same axes, such as the Charlie sheen
  // in Filament's third channel. Their axes are the table's own.
  std::vector<BakeSpec> with;
  // Whether the engine's code fixes the table's size, so that a scene may
  // not choose another: a header array (Cycles, Enterprise PBR), an .inc
  // body (Filament's DFG_LUT_SIZE) or edges placement (HDRP's remap by the
  // texture's resolution). Otherwise the engine samples at normalized
  // coordinates over texel centres and reads the size from the file.
  bool size_fixed = false;
  // A table formed from GGX's over a third axis, F0 (`f0`, slices; rows
  // for E_avg): Enterprise PBR's Base_E and Base_E_avg ([EnterprisePbr]
  // "Energy Conservation"), the albedo of GGX with Schlick's Fresnel (F90 =
  // 1) and [KullaConty17]'s multiple-scattering lobe weighted by F_ms:
  //   Base_E(mu) = F0 scale + bias + F_ms (1 - E(mu)),
  //   Base_E_avg = F0 E_avg + (1 - F0) bias_avg + F_ms (1 - E_avg),
  //   F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), F_avg = (20 F0 + 1) / 21,
  // each at most `layout.channels[0].max`. spec is the dfg (Base_E) or E_avg
  // (Base_E_avg) table they are formed from.
  enum class Over { kNone, kSchlickMsE, kSchlickMsEavg };
  Over over = Over::kNone;
  Axis f0{"f0", 16, 0.0, 1.0, Warp::kLinear, Placement::kCenters};
};

struct Preset {
  std::string name;
  std::string description;  // one line: what the engine ships and what differs
  std::vector<PresetTable> tables;
  std::string header_file;  // when non-empty, every table also goes into this one header
  EngineForm header_form = EngineForm::kGeneric;
};

const std::vector<Preset>& Presets();
const Preset& FindPreset(const std::string& name);  // throws std::invalid_argument
// Whether this build holds every model family the preset's tables need
// (BRDFBAKE_MODELS): Filament's cloth channel needs charlie, say.
bool PresetBuilt(const Preset& preset);

// What a preset bake writes besides the tables themselves: a container the
// engine also loads (empty: the preset's own), and shader lookups.
struct PresetRun {
  std::string dir = ".";
  std::string format;
  std::vector<ShaderLanguage> shaders;
};

// A file a preset bake writes (table_files.h): a table's container, a
// table's lookup (named by its symbol, the engine's own files often hold
// several tables), or (table -1) the engine's header of every table.
using PresetFile = OutputFile;

// The files `run` writes, in order, so that each can be checked before any
// work. Throws std::invalid_argument for a --format no table of the engine
// is loaded from.
std::vector<PresetFile> PresetFiles(const Preset& preset, const PresetRun& run);

// The image of `table` (pt.spec's bake, or a scene's over its own axes) in
// pt's layout: pt.with baked over table's mu and roughness axes (with
// `threads`, and `tolerance` when > 0; progress per table) and arranged
// with it.
Image ArrangePresetTable(const PresetTable& pt, const Table& table, int threads = 0,
                         double tolerance = 0, const ProgressFn& progress = nullptr);

// Writes file `f` of the preset's tables (through an AtomicFile) from the
// baked tables and their arrangements, one per preset table: a file of all
// of them (table -1) in the preset's header form, a table's in its form or
// its container.
void WritePresetFile(const Preset& preset, const PresetFile& f, const std::vector<Table>& tables,
                     const std::vector<Image>& images);

// Writes every file of PresetFiles(preset, run).
void WritePresetFiles(const Preset& preset, const PresetRun& run, const std::vector<Table>& tables,
                      const std::vector<Image>& images);

}  // namespace brdfbake

#endif  // BRDFBAKE_PRESETS_H_
