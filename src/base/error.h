// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The library's one way to reject a bad input: std::invalid_argument with a
// one-line message naming the parameter and the value.

#ifndef BRDFBAKE_SRC_BASE_ERROR_H_
#define BRDFBAKE_SRC_BASE_ERROR_H_

#include <stdexcept>
#include <string>

namespace brdfbake {

[[noreturn]] inline void Bad(const std::string& what) { throw std::invalid_argument(what); }

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_BASE_ERROR_H_
