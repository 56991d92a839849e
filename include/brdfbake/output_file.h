// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Output files that are never left partial. A file is written to a unique
// temporary in the target's own directory (mkstemp: created with O_EXCL, so
// a pre-placed name or symbolic link is never followed) and renamed over
// the target only when complete. Rename semantics: the target's directory
// entry is replaced, so other hard links to the old file keep the old
// contents; the old file's mode (and, as root, its owner) is kept. An
// existing target must be a regular file (or a symbolic link to one, which
// is then written through: the link stays); devices, pipes and directories
// are refused before any work is done.

#ifndef BRDFBAKE_OUTPUT_FILE_H_
#define BRDFBAKE_OUTPUT_FILE_H_

#include <cstddef>
#include <string>
#include <vector>

namespace brdfbake {

// Checks that `path` can be written before any work is done: its directory
// exists and is writable, and `path` is not a directory, a device or
// another non-regular file, and is writable if it exists. Throws
// a ParameterError "<option>: ..." (one line; the default option is the
// output parameter, -o on the command line).
void CheckOutputPath(const std::string& path, const std::string& option = "{output}");

// Checks that `path` ends in `extension` (e.g. ".exr", case-insensitive).
void CheckOutputExtension(const std::string& path, const std::string& extension,
                          const std::string& what, const std::string& option = "{output}");

// Removes every live temporary on SIGINT, SIGTERM, SIGHUP and SIGPIPE, then
// ends the process with the signal's default action. Call once from main.
void InstallTemporaryCleanup();

// One output file. The temporary is created by the constructor and removed
// by the destructor unless Commit() renamed it over the target. Errors
// throw std::runtime_error naming the target (never the temporary).
// The whole of `text` as the file `path`, through an AtomicFile.
void WriteFileAtomically(const std::string& path, const std::string& text);

class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& path() const { return path_; }  // the target
  // Writes `n` bytes at byte offset `offset` of the temporary.
  void WriteAt(const void* data, size_t n, size_t offset);
  void Append(const std::string& bytes);
  // Gives the temporary the old file's mode (or the umask's), flushes it
  // to disk and closes it: everything of Commit() that can fail but the
  // rename. Throws on failure (the temporary is removed).
  void Prepare();
  // Prepare(), then renames the temporary over the target.
  void Commit();

 private:
  friend void CommitAll(const std::vector<AtomicFile*>& files);
  void Rename();
  [[noreturn]] void Fail(const std::string& what);
  std::string path_;    // target as given, for messages
  std::string target_;  // where the rename goes (a symbolic link resolved)
  std::string tmp_;
  int fd_ = -1;
  int slot_ = -1;  // signal-cleanup registry slot
  size_t size_ = 0;
  bool prepared_ = false;
  bool committed_ = false;
};

// Commits a set of files together, all or nothing as far as a process can
// make it: every file is prepared (flushed, closed) before any is renamed,
// so a write or fsync error leaves every target as it was; then the renames
// run back to back with the cleanup signals held, on this thread and (by
// the handler waiting for them) on every other, so a signal leaves either
// the whole old set or the whole new one. Only a rename failing part-way
// (or SIGKILL in those microseconds) leaves a mixed set: the error then
// names the targets already renamed.
void CommitAll(const std::vector<AtomicFile*>& files);

}  // namespace brdfbake

#endif  // BRDFBAKE_OUTPUT_FILE_H_
