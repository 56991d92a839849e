// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Running the command-line tool from a test: through the shell, with
// standard output and error captured in files of a scratch directory.

#ifndef BRDFBAKE_TESTS_UTIL_CLI_UTIL_H_
#define BRDFBAKE_TESTS_UTIL_CLI_UTIL_H_

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "util/file_util.h"

namespace brdfbake {

#ifdef BRDFBAKE_CLI_PATH

// Shell-quotes one argument.
inline std::string Quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

struct ToolRun {
  int status = -1;
  bool signaled = false;
  std::string out, err;
};

// Runs `shell` (a command line for sh, "$BRDFBAKE" is the tool) with
// stdout and stderr captured unless `shell` redirects them itself.
inline ToolRun ExecuteShell(const std::string& shell, const std::string& dir) {
  const std::string cmd = "BRDFBAKE=" + Quote(BRDFBAKE_CLI_PATH) + "; export BRDFBAKE; (" + shell +
                          ") >" + Quote(dir + "/stdout") + " 2>" + Quote(dir + "/stderr");
  const int raw = std::system(cmd.c_str());
  ToolRun r;
  r.signaled = WIFSIGNALED(raw) || (WIFEXITED(raw) && WEXITSTATUS(raw) > 128);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = test::Slurp(dir + "/stdout");
  r.err = test::Slurp(dir + "/stderr");
  return r;
}

// Runs the tool with `args`.
inline ToolRun Execute(const std::vector<std::string>& args, const std::string& dir) {
  std::string cmd = "\"$BRDFBAKE\"";
  for (const std::string& a : args) cmd += " " + Quote(a);
  return ExecuteShell(cmd, dir);
}

#endif  // BRDFBAKE_CLI_PATH

}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_UTIL_CLI_UTIL_H_
