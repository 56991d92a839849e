// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Library-internal text helpers.

#ifndef BRDFBAKE_SRC_BASE_TEXT_H_
#define BRDFBAKE_SRC_BASE_TEXT_H_

#include <cctype>
#include <cstdio>
#include <string>

namespace brdfbake {

// ASCII lower case (file extensions).
inline std::string Lowercase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A number in C's "%.9g": every float exactly, short where it can be.
inline std::string NumG9(double v) {
  char buf[40];
  std::snprintf(buf, sizeof(buf), "%.9g", v);
  return buf;
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_BASE_TEXT_H_
