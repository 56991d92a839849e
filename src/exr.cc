// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Self-describing OpenEXR tables (SPEC.md section 4): every convention the
// table was baked with is a string attribute (JSON where structured).

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <nlohmann/json.hpp>

#include "brdfbake/bake.h"
#include "brdfbake/grid.h"
#include "brdfbake/version.h"

namespace brdfbake {

std::string BakeModelJson(const BakeSpec& spec);  // bake.cc

namespace {

// Writes `header` and `fb` to a temporary file beside `path`, then renames
// it: never a partial file.
void WriteAtomically(const std::string& path, const Imf::Header& header,
                     const Imf::FrameBuffer& fb, int height) {
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  try {
    Imf::OutputFile file(tmp.c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(height);
  } catch (const std::exception& e) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write '" + path + "': " + e.what());
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
  }
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
  put("brdfbake.model", BakeModelJson(spec));
  put("brdfbake.masking", MaskingName(spec.masking));
  put("brdfbake.fresnel", "one");
  nlohmann::json axes = nlohmann::json::array();
  for (const Axis& a : table.axes) axes.push_back(nlohmann::json::parse(a.ToJson()));
  put("brdfbake.axes", axes.dump());
  nlohmann::json channels = nlohmann::json::object();
  for (const Channel& c : table.channels) channels[c.name] = c.meaning;
  put("brdfbake.channels", channels.dump());
  put("brdfbake.integrator", table.integrator_json);
  char err[64];
  std::snprintf(err, sizeof(err), "%.3e", table.max_abs_error);
  put("brdfbake.max_abs_error", err);

  const Imf::PixelType type = spec.half ? Imf::HALF : Imf::FLOAT;
  for (const Channel& c : table.channels) header.channels().insert(c.name, Imf::Channel(type));

  const size_t n = size_t(table.width) * table.height;
  std::vector<std::vector<float>> fdata;
  std::vector<std::vector<Imath::half>> hdata;
  Imf::FrameBuffer fb;
  for (const Channel& c : table.channels) {
    if (spec.half) {
      hdata.emplace_back(n);
      for (size_t i = 0; i < n; ++i) hdata.back()[i] = Imath::half(static_cast<float>(c.values[i]));
      fb.insert(c.name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(hdata.back().data()),
                                   sizeof(Imath::half), sizeof(Imath::half) * table.width));
    } else {
      fdata.emplace_back(n);
      for (size_t i = 0; i < n; ++i) fdata.back()[i] = static_cast<float>(c.values[i]);
      fb.insert(c.name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(fdata.back().data()),
                                   sizeof(float), sizeof(float) * table.width));
    }
  }

  WriteAtomically(path, header, fb, table.height);
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
