// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Library-internal text helpers.

#ifndef BRDFBAKE_SRC_TEXT_H_
#define BRDFBAKE_SRC_TEXT_H_

#include <cctype>
#include <string>

namespace brdfbake {

// ASCII lower case (file extensions).
inline std::string Lowercase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_TEXT_H_
