// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Library-internal: an OpenEXR image of named planar channels (float, or
// half when `half_planes` is non-empty) with string attributes, written
// through an AtomicFile.

#ifndef BRDFBAKE_SRC_IO_EXR_WRITE_H_
#define BRDFBAKE_SRC_IO_EXR_WRITE_H_

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace brdfbake {

void WriteExrPlanes(const std::string& path, int width, int height,
                    const std::vector<std::string>& names,
                    const std::vector<std::vector<float>>& planes,
                    const std::vector<std::vector<uint16_t>>& half_planes,
                    const std::vector<std::pair<std::string, std::string>>& attributes);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_IO_EXR_WRITE_H_
