// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "brdfbake/output_file.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <stdexcept>

#include "base/text.h"
#include "brdfbake/error.h"

namespace brdfbake {
namespace {

[[noreturn]] void Bad(const std::string& option, const std::string& what) {
  throw ParameterError(option + ": " + what);
}

std::string DirectoryOf(const std::string& path) {
  const std::string dir = std::filesystem::path(path).parent_path().string();
  return dir.empty() ? "." : dir;
}

// The signals whose handler removes the temporaries (and that are held
// while one is created or a set renamed).
constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};

// Live temporaries, for the signal handler: fixed storage, no allocation.
constexpr int kSlots = 16;
struct Slot {
  std::atomic<bool> used{false};
  char path[PATH_MAX + 1] = {};
};
Slot g_slots[kSlots];
std::mutex g_slot_mutex;

int Register(const std::string& tmp) {
  std::lock_guard<std::mutex> lock(g_slot_mutex);
  for (int i = 0; i < kSlots; ++i) {
    if (!g_slots[i].used.load()) {
      std::strncpy(g_slots[i].path, tmp.c_str(), PATH_MAX);
      g_slots[i].path[PATH_MAX] = '\0';
      g_slots[i].used.store(true);
      return i;
    }
  }
  return -1;  // more than kSlots open files: still removed on errors, not on signals
}

void Unregister(int slot) {
  if (slot < 0) return;
  std::lock_guard<std::mutex> lock(g_slot_mutex);
  g_slots[slot].used.store(false);
}

// Sections the signal handler must not cut: a temporary being created
// (between mkstemp and Register) and a set of renames (CommitAll). The
// thread in one blocks the signals, but another thread (a oneTBB worker)
// may take one meanwhile: its handler marks the process as dying, so that
// no section starts after that, and waits for those under way to finish
// before it removes what is registered. (Each side writes its flag, then
// reads the other's: one of them sees the other.)
std::atomic<int> g_critical{0};
std::atomic<bool> g_dying{false};

// Holds the cleanup signals on this thread and marks a critical section;
// if the process is already dying, waits for the end instead.
class Critical {
 public:
  Critical() {
    sigset_t block;
    sigemptyset(&block);
    for (int sig : kCleanupSignals) sigaddset(&block, sig);
    ::pthread_sigmask(SIG_BLOCK, &block, &old_);
    g_critical.fetch_add(1);
    if (g_dying.load()) {
      // A handler on another thread is removing the temporaries and ending
      // the process: start nothing more.
      g_critical.fetch_sub(1);
      for (;;) ::pause();
    }
  }
  ~Critical() {
    g_critical.fetch_sub(1);
    ::pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  Critical(const Critical&) = delete;
  Critical& operator=(const Critical&) = delete;

 private:
  sigset_t old_;
};

extern "C" void RemoveTemporariesAndDie(int sig) {
  g_dying.store(true);
  while (g_critical.load() != 0) {
  }
  for (Slot& s : g_slots) {
    if (s.used.load()) ::unlink(s.path);  // async-signal-safe
  }
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

}  // namespace

void CheckOutputPath(const std::string& path, const std::string& option) {
  if (path.empty()) Bad(option, "an output file name is required");
  struct stat st;
  if (::lstat(path.c_str(), &st) == 0) {
    if (S_ISLNK(st.st_mode) && ::stat(path.c_str(), &st) != 0) {
      Bad(option, "'" + path + "' is a symbolic link to a missing file");
    }
    if (S_ISDIR(st.st_mode)) Bad(option, "'" + path + "' is a directory");
    if (!S_ISREG(st.st_mode)) {
      Bad(option, "'" + path + "' exists and is not a regular file (a device, pipe or socket); "
                  "brdfbake writes regular files only");
    }
    if (::access(path.c_str(), W_OK) != 0) Bad(option, "'" + path + "' is not writable");
    std::error_code ec;
    const std::string target = std::filesystem::canonical(path, ec).string();
    const std::string dir = DirectoryOf(ec ? path : target);
    if (::access(dir.c_str(), W_OK | X_OK) != 0) {
      Bad(option, "directory '" + dir + "' is not writable: " + std::strerror(errno));
    }
    // The file is replaced by a rename, which a sticky directory (/tmp)
    // allows only to the owner of the file or of the directory (or root).
    struct stat dir_st;
    const uid_t me = ::geteuid();
    if (me != 0 && ::stat(dir.c_str(), &dir_st) == 0 && (dir_st.st_mode & S_ISVTX) &&
        st.st_uid != me && dir_st.st_uid != me) {
      Bad(option, "'" + path + "' belongs to another user in the sticky directory '" + dir +
                      "': it cannot be replaced");
    }
    return;
  }
  if (errno != ENOENT) Bad(option, "cannot write '" + path + "': " + std::strerror(errno));
  const std::string dir = DirectoryOf(path);
  if (::stat(dir.c_str(), &st) != 0) {
    if (errno == ENOENT) Bad(option, "directory '" + dir + "' does not exist");
    Bad(option, "cannot write '" + path + "': " + std::strerror(errno));
  }
  if (!S_ISDIR(st.st_mode)) Bad(option, "'" + dir + "' is not a directory");
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    Bad(option, "directory '" + dir + "' is not writable: " + std::strerror(errno));
  }
}

void CheckOutputExtension(const std::string& path, const std::string& extension,
                          const std::string& what, const std::string& option) {
  const std::string ext = Lowercase(std::filesystem::path(path).extension().string());
  if (ext == extension) return;
  Bad(option, "'" + path + "' " + (ext.empty() ? "has no extension" : "names a " + ext + " file") +
                  "; " + what + " writes " + extension + " files only");
}

void InstallTemporaryCleanup() {
  struct sigaction sa;
  std::memset(&sa, 0, sizeof(sa));
  sa.sa_handler = RemoveTemporariesAndDie;
  sigemptyset(&sa.sa_mask);
  for (int sig : kCleanupSignals) {
    struct sigaction old;
    // Keep an inherited "ignore" (nohup, a shell's background job).
    if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    ::sigaction(sig, &sa, nullptr);
  }
  // A write beyond the file-size limit (ulimit -f) then fails with EFBIG,
  // which removes the temporary and reports "File too large", instead of
  // killing the process with the temporary left behind.
  ::signal(SIGXFSZ, SIG_IGN);
}

AtomicFile::AtomicFile(const std::string& path) : path_(path), target_(path) {
  try {
    CheckOutputPath(path, "cannot write '" + path + "'");
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(e.what());
  }
  struct stat st;
  if (::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
    target_ = std::filesystem::canonical(path).string();
  }
  std::string tmpl = DirectoryOf(target_) + "/.brdfbake-XXXXXX";
  // Signals are held while the temporary is created and registered, so
  // none can leave it behind unregistered.
  int err = 0;
  {
    const Critical critical;
    fd_ = ::mkstemp(tmpl.data());
    err = errno;
    if (fd_ >= 0) {
      tmp_ = tmpl;
      slot_ = Register(tmp_);
    }
  }
  if (fd_ < 0) throw std::runtime_error("cannot write '" + path_ + "': " + std::strerror(err));
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  if (fd_ >= 0) ::close(fd_);
  if (!tmp_.empty()) ::unlink(tmp_.c_str());
  Unregister(slot_);
}

void AtomicFile::Fail(const std::string& what) {
  const std::string msg = "cannot write '" + path_ + "': " + what;
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlink(tmp_.c_str());
  Unregister(slot_);
  slot_ = -1;
  tmp_.clear();
  throw std::runtime_error(msg);
}

void AtomicFile::WriteAt(const void* data, size_t n, size_t offset) {
  if (fd_ < 0) Fail("the file is already closed");
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = ::pwrite(fd_, p, n, static_cast<off_t>(offset));
    if (w < 0) {
      if (errno == EINTR) continue;
      Fail(std::strerror(errno));
    }
    p += w;
    n -= static_cast<size_t>(w);
    offset += static_cast<size_t>(w);
  }
  size_ = std::max(size_, offset);
}

void AtomicFile::Append(const std::string& bytes) { WriteAt(bytes.data(), bytes.size(), size_); }

void WriteFileAtomically(const std::string& path, const std::string& text) {
  AtomicFile f(path);
  f.Append(text);
  f.Commit();
}

void AtomicFile::Prepare() {
  if (prepared_) return;
  if (fd_ < 0) Fail("the file is already closed");
  struct stat st;
  mode_t mode;
  if (::stat(target_.c_str(), &st) == 0) {
    mode = st.st_mode & 07777;
    if (::geteuid() == 0 && ::fchown(fd_, st.st_uid, st.st_gid) != 0) {
      Fail(std::string("cannot keep the owner: ") + std::strerror(errno));
    }
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  if (::fchmod(fd_, mode) != 0) Fail(std::strerror(errno));
  if (::fsync(fd_) != 0) Fail(std::strerror(errno));
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) Fail(std::strerror(errno));
  prepared_ = true;
}

void AtomicFile::Rename() {
  if (::rename(tmp_.c_str(), target_.c_str()) != 0) Fail(std::strerror(errno));
  committed_ = true;
  Unregister(slot_);
  slot_ = -1;
}

void AtomicFile::Commit() {
  Prepare();
  Rename();
}

void CommitAll(const std::vector<AtomicFile*>& files) {
  for (AtomicFile* f : files) f->Prepare();
  std::string renamed;
  const Critical critical;
  for (AtomicFile* f : files) {
    try {
      f->Rename();
    } catch (const std::exception& e) {
      throw std::runtime_error(std::string(e.what()) +
                               (renamed.empty() ? "; no file of the set was written"
                                                : "; written before the failure:" + renamed));
    }
    renamed += " " + f->path();
  }
}

}  // namespace brdfbake
