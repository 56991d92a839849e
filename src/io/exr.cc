// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Self-describing OpenEXR tables (docs/format.md): every convention the
// table was baked with is a string attribute (JSON where structured).

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <nlohmann/json.hpp>

#include "brdfbake/bake.h"
#include "brdfbake/exr.h"
#include "brdfbake/output_file.h"
#include "brdfbake/version.h"
#include "io/exr_write.h"

namespace brdfbake {

namespace {

// OpenEXR's output stream over an AtomicFile: errors name the target, never
// the temporary.
class AtomicOStream : public Imf::OStream {
 public:
  explicit AtomicOStream(AtomicFile* file) : Imf::OStream(file->path().c_str()), file_(file) {}
  void write(const char c[], int n) override {
    file_->WriteAt(c, size_t(n), pos_);
    pos_ += uint64_t(n);
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = pos; }

 private:
  AtomicFile* file_;
  uint64_t pos_ = 0;
};

// Writes `header` and `fb` through a temporary file and a rename.
void WriteAtomically(const std::string& path, const Imf::Header& header,
                     const Imf::FrameBuffer& fb, int height) {
  AtomicFile file(path);
  try {
    AtomicOStream os(&file);
    Imf::OutputFile out(os, header);
    out.setFrameBuffer(fb);
    out.writePixels(height);
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    if (what.rfind("cannot write", 0) == 0) throw;
    throw std::runtime_error("cannot write '" + path + "': " + what);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot write '" + path + "': " + e.what());
  }
  file.Commit();
}

}  // namespace

void WriteExr(const Table& table, const std::string& path) {
  const BakeSpec& spec = table.spec;
  Imf::Header header(table.width, table.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  auto put = [&](const char* name, const std::string& value) {
    header.insert(name, Imf::StringAttribute(value));
  };
  put("brdfbake.version", BRDFBAKE_VERSION);
  put("brdfbake.table", TableName(spec.table));
  put("brdfbake.model", table.model_json);
  put("brdfbake.masking", MaskingName(spec.masking));
  put("brdfbake.fresnel", spec.Glass() && spec.part == DielectricPart::kTransmissionSchlick
                              ? kSchlickComplementFresnel
                          : spec.Glass() ? "dielectric"
                                         : "one");
  nlohmann::json axes = nlohmann::json::array();
  for (const Axis& a : table.axes) axes.push_back(nlohmann::json::parse(a.ToJson()));
  put("brdfbake.axes", axes.dump());
  put("brdfbake.layout", kLayoutText);
  nlohmann::json channels = nlohmann::json::object();
  nlohmann::json order = nlohmann::json::array();
  nlohmann::json info = nlohmann::json::array();
  for (size_t i = 0; i < table.channels.size(); ++i) {
    const Channel& c = table.channels[i];
    channels[c.name] = MeaningName(c.meaning);
    order.push_back(c.name);
    info.push_back({{"index", i}, {"name", c.name}, {"meaning", MeaningName(c.meaning)}, {"definition", c.definition}});
  }
  put("brdfbake.channels", channels.dump());
  put("brdfbake.channel_order", order.dump());
  put("brdfbake.channel_info", info.dump());
  put("brdfbake.range", kStoredRange);
  put("brdfbake.integrator", table.integrator_json);
  // Four significant digits, rounded up: the claim is never printed below
  // the bound it states.
  char err[64];
  std::snprintf(err, sizeof(err), "%.3e", table.max_abs_error);
  if (std::strtod(err, nullptr) < table.max_abs_error) {
    std::snprintf(err, sizeof(err), "%.3e", table.max_abs_error * (1 + 1e-3));
  }
  put("brdfbake.max_abs_error", err);

  const Imf::PixelType type = spec.half ? Imf::HALF : Imf::FLOAT;
  Imf::FrameBuffer fb;
  for (const Channel& c : table.channels) {
    const size_t n = size_t(table.width) * table.height;
    if (c.stored.size() != n || (spec.half && c.half_bits.size() != n)) {
      throw std::logic_error("WriteExr: channel '" + c.name + "' has no stored pixels");
    }
    header.channels().insert(c.name, Imf::Channel(type));
    if (spec.half) {
      static_assert(sizeof(Imath::half) == sizeof(uint16_t), "half is 16 bits");
      fb.insert(c.name, Imf::Slice(Imf::HALF, const_cast<char*>(reinterpret_cast<const char*>(c.half_bits.data())),
                                   sizeof(uint16_t), sizeof(uint16_t) * table.width));
    } else {
      fb.insert(c.name, Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(c.stored.data())),
                                   sizeof(float), sizeof(float) * table.width));
    }
  }
  WriteAtomically(path, header, fb, table.height);
}

void WriteExrPlanes(const std::string& path, int width, int height,
                    const std::vector<std::string>& names,
                    const std::vector<std::vector<float>>& planes,
                    const std::vector<std::vector<uint16_t>>& half_planes,
                    const std::vector<std::pair<std::string, std::string>>& attributes) {
  Imf::Header header(width, height);
  header.compression() = Imf::ZIP_COMPRESSION;
  for (const auto& kv : attributes) header.insert(kv.first, Imf::StringAttribute(kv.second));
  Imf::FrameBuffer fb;
  const bool half = !half_planes.empty();
  for (size_t c = 0; c < names.size(); ++c) {
    header.channels().insert(names[c], Imf::Channel(half ? Imf::HALF : Imf::FLOAT));
    if (half) {
      fb.insert(names[c], Imf::Slice(Imf::HALF, const_cast<char*>(reinterpret_cast<const char*>(half_planes[c].data())),
                                     sizeof(uint16_t), sizeof(uint16_t) * width));
    } else {
      fb.insert(names[c], Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(planes[c].data())),
                                     sizeof(float), sizeof(float) * width));
    }
  }
  WriteAtomically(path, header, fb, height);
}

void WriteImageExr(const std::string& path, int width, int height,
                   const std::vector<std::pair<std::string, const std::vector<float>*>>& channels,
                   const std::vector<std::pair<std::string, std::string>>& attributes) {
  Imf::Header header(width, height);
  header.compression() = Imf::ZIP_COMPRESSION;
  for (const auto& kv : attributes) header.insert(kv.first, Imf::StringAttribute(kv.second));
  Imf::FrameBuffer fb;
  for (const auto& c : channels) {
    header.channels().insert(c.first, Imf::Channel(Imf::FLOAT));
    fb.insert(c.first, Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(c.second->data())),
                                  sizeof(float), sizeof(float) * width));
  }
  WriteAtomically(path, header, fb, height);
}

std::string ExrContents::Attribute(const std::string& name) const {
  for (const auto& kv : attributes) {
    if (kv.first == name) return kv.second;
  }
  return "";
}

const std::vector<float>* ExrContents::ChannelData(const std::string& name) const {
  for (const auto& kv : channels) {
    if (kv.first == name) return &kv.second;
  }
  return nullptr;
}

ExrContents ReadExr(const std::string& path) {
  ExrContents out;
  try {
    Imf::InputFile file(path.c_str());
    const Imf::Header& h = file.header();
    const Imath::Box2i dw = h.dataWindow();
    out.width = dw.max.x - dw.min.x + 1;
    out.height = dw.max.y - dw.min.y + 1;
    for (auto it = h.begin(); it != h.end(); ++it) {
      if (std::strcmp(it.attribute().typeName(), "string") == 0) {
        out.attributes.emplace_back(
            it.name(), static_cast<const Imf::StringAttribute&>(it.attribute()).value());
      }
    }
    Imf::FrameBuffer fb;
    const size_t n = size_t(out.width) * out.height;
    for (auto it = h.channels().begin(); it != h.channels().end(); ++it) {
      out.half = it.channel().type == Imf::HALF;
      out.channels.emplace_back(it.name(), std::vector<float>(n));
    }
    for (auto& kv : out.channels) {
      char* base = reinterpret_cast<char*>(kv.second.data()) -
                   (size_t(dw.min.x) + size_t(dw.min.y) * out.width) * sizeof(float);
      fb.insert(kv.first, Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * out.width));
    }
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot read '" + path + "': " + e.what());
  }
  return out;
}

}  // namespace brdfbake
