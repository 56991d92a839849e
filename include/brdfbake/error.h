// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The library's error for a bad input: a one-line std::invalid_argument
// that names the parameter and the value, e.g. "table: unknown table 'x'
// (expected E, ...)". The message marks each parameter it names, {table}:
// what() shows the parameter's own name (table, mu_o, output), Render
// another spelling of it (the command line shows --table, --mu-o, -o), so
// that one message serves the library's callers and the tool.

#ifndef BRDFBAKE_ERROR_H_
#define BRDFBAKE_ERROR_H_

#include <functional>
#include <stdexcept>
#include <string>

namespace brdfbake {

class ParameterError : public std::invalid_argument {
 public:
  explicit ParameterError(const std::string& text);
  // The message with each marked parameter as spell(name).
  std::string Render(const std::function<std::string(const std::string&)>& spell) const;
  // The message with its marks, to be passed on inside another message.
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

// The parameters a message may mark: the names of BakeSpec's, EvalRequest's,
// GridRequest's and the report's fields and the output's settings.
bool IsParameterName(const std::string& name);

// A marked text (an error's, or help text naming parameters) with each
// marked parameter as spell(name).
std::string SpellParameters(const std::string& marked, const std::function<std::string(const std::string&)>& spell);

// e's message with its marks (ParameterError) or as it is.
std::string ErrorText(const std::exception& e);

}  // namespace brdfbake

#endif  // BRDFBAKE_ERROR_H_
