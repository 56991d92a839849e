// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The library's one way to reject a bad input: a ParameterError
// (brdfbake/error.h), one line naming the parameter, marked {name}, and
// the value.

#ifndef BRDFBAKE_SRC_BASE_ERROR_H_
#define BRDFBAKE_SRC_BASE_ERROR_H_

#include <string>

#include "brdfbake/error.h"

namespace brdfbake {

[[noreturn]] inline void Bad(const std::string& what) { throw ParameterError(what); }

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_BASE_ERROR_H_
