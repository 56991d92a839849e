// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// How a stored value is held.

#ifndef BRDFBAKE_PIXEL_TYPE_H_
#define BRDFBAKE_PIXEL_TYPE_H_

namespace brdfbake {

// 32-bit float, IEEE half, or a 16- or 8-bit unsigned normalized code
// (v = code / 65535, code / 255).
enum class PixelType { kFloat, kHalf, kUnorm16, kUnorm8 };

}  // namespace brdfbake

#endif  // BRDFBAKE_PIXEL_TYPE_H_
