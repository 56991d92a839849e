// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The tool's promises (docs/reliability.md) under bad input and faults, each at the input that
// once broke it: output files (devices, symbolic links at the temporary's
// name, signals during the write, long names, modes), standard output on a
// full device, one-line errors with control characters, out-of-range
// numbers, memory failures before the work, stored values in [0, 1], the
// domain bounds of alpha and gamma, and the file header's self-description.

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <Imath/half.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "brdfbake/bake.h"
#include "brdfbake/eval.h"
#include "brdfbake/exr.h"
#include "brdfbake/grid.h"
#include "brdfbake/model.h"
#include "brdfbake/models/std_ndf.h"
#include "brdfbake/output_file.h"
#include "brdfbake/report.h"
#include "util/cli_util.h"
#include "util/lookup_util.h"

namespace brdfbake {
namespace {

std::string ScratchDir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/brdfbake_reliability_" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::vector<std::string> Listing(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    names.push_back(e.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

// ---------------------------------------------------------------- output files

TEST(OutputFileTest, RefusesDevicesDirectoriesAndMissingDirectories) {
  EXPECT_THROW(CheckOutputPath("/dev/full"), std::invalid_argument);
  EXPECT_THROW(CheckOutputPath("/dev/null"), std::invalid_argument);
  EXPECT_THROW(CheckOutputPath("/tmp"), std::invalid_argument);
  EXPECT_THROW(CheckOutputPath("/nonexistent-dir/x.exr"), std::invalid_argument);
  EXPECT_THROW(CheckOutputPath(""), std::invalid_argument);
  const std::string dir = ScratchDir("check");
  EXPECT_NO_THROW(CheckOutputPath(dir + "/new.exr"));
  WriteText(dir + "/file", "x");
  EXPECT_THROW(CheckOutputPath(dir + "/file/x.exr"), std::invalid_argument);  // not a directory
  // A symbolic link to a device is refused; a dangling one too.
  std::filesystem::create_symlink("/dev/full", dir + "/full.exr");
  EXPECT_THROW(CheckOutputPath(dir + "/full.exr"), std::invalid_argument);
  std::filesystem::create_symlink(dir + "/missing", dir + "/dangling.exr");
  EXPECT_THROW(CheckOutputPath(dir + "/dangling.exr"), std::invalid_argument);
  try {
    CheckOutputPath("/dev/full");
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
  }
}

// A file of another user in a sticky directory (/tmp) is writable when its
// mode is 0666, but only its owner (or the directory's) may rename over it:
// refused before the work (it failed at the rename after the bake). As
// root, checked from a child that becomes nobody.
TEST(OutputFileTest, AnotherUsersFileInAStickyDirectoryIsRefused) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to make another user's file";
  const std::string dir = ScratchDir("sticky");
  ASSERT_EQ(::chmod(dir.c_str(), 01777), 0);
  const std::string path = dir + "/root.exr";
  WriteText(path, "x");
  ASSERT_EQ(::chmod(path.c_str(), 0666), 0);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    if (::setgid(65534) != 0 || ::setuid(65534) != 0) ::_exit(3);
    try {
      CheckOutputPath(path);
    } catch (const std::invalid_argument& e) {
      ::_exit(std::string(e.what()).find("belongs to another user") != std::string::npos ? 0 : 2);
    }
    ::_exit(1);  // accepted
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: accepted, 2: another message, 3: setuid failed";
  // Root itself, and the owner, may replace it.
  EXPECT_NO_THROW(CheckOutputPath(path));
}

TEST(OutputFileTest, ExtensionMustMatch) {
  EXPECT_NO_THROW(CheckOutputExtension("a/b.exr", ".exr", "bake"));
  EXPECT_NO_THROW(CheckOutputExtension("B.EXR", ".exr", "bake"));
  for (const char* bad : {"dfg.h", "dfg.ktx2", "dfg.dds", "dfg.gif", "dfg", "/dev/full"}) {
    EXPECT_THROW(CheckOutputExtension(bad, ".exr", "bake"), std::invalid_argument) << bad;
  }
}

TEST(OutputFileTest, KeepsModeWritesThroughLinksAndLeavesNoTemporary) {
  const std::string dir = ScratchDir("mode");
  const std::string path = dir + "/out.exr";
  WriteText(path, "old");
  ASSERT_EQ(::chmod(path.c_str(), 0600), 0);
  {
    AtomicFile f(path);
    f.Append("new contents");
    f.Commit();
  }
  struct stat st;
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0600u);
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "new contents");
  // Through a symbolic link: the link stays, its target gets the contents.
  std::filesystem::create_symlink(path, dir + "/link.exr");
  {
    AtomicFile f(dir + "/link.exr");
    f.Append("via link");
    f.Commit();
  }
  EXPECT_TRUE(std::filesystem::is_symlink(dir + "/link.exr"));
  std::ifstream in2(path);
  std::string text2((std::istreambuf_iterator<char>(in2)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text2, "via link");
  // Not committed: nothing is left, the old file is untouched.
  {
    AtomicFile f(path);
    f.Append("abandoned");
  }
  EXPECT_EQ(Listing(dir), (std::vector<std::string>{"link.exr", "out.exr"}));
}

TEST(OutputFileTest, LongNamesWork) {
  const std::string dir = ScratchDir("long");
  for (size_t len : {247u, 251u, 255u}) {
    const std::string name = std::string(len - 4, 'n') + ".exr";
    AtomicFile f(dir + "/" + name);
    f.Append("x");
    EXPECT_NO_THROW(f.Commit()) << len;
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + name)) << len;
  }
}

// A process killed by SIGINT or SIGTERM while it writes leaves no temporary.
TEST(OutputFileTest, SignalsRemoveTheTemporary) {
  for (int sig : {SIGINT, SIGTERM}) {
    const std::string dir = ScratchDir("signal" + std::to_string(sig));
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      InstallTemporaryCleanup();
      AtomicFile f(dir + "/out.exr");
      f.Append(std::string(1 << 20, 'x'));
      ::raise(sig);
      ::_exit(0);  // not reached
    }
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << status;
    EXPECT_TRUE(Listing(dir).empty()) << Listing(dir).front();
  }
}

// Forks a child that installs the temporary cleanup, starts an idle second
// thread (which does not block the signals) and runs `work` forever; kills
// it with `sig` after `delay_us` and returns its wait status.
template <class Work>
int KillWorkingChild(const Work& work, int sig, unsigned delay_us) {
  const pid_t pid = ::fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    InstallTemporaryCleanup();
    std::thread idle([] {
      for (;;) ::pause();
    });
    idle.detach();
    work();
    ::_exit(0);  // not reached
  }
  ::usleep(delay_us);
  ::kill(pid, sig);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

// A signal sent to the process lands on any thread that does not block it:
// on a second thread while the main thread creates a temporary (with the
// signals blocked there), the handler waits for the creation to finish and
// removes it. 400 children create temporaries in a loop beside an idle
// thread and are killed at random times; none may leave one.
TEST(OutputFileTest, SignalsOnAnotherThreadRemoveTheTemporary) {
  std::mt19937 rng(7);
  int left = 0;
  for (int run = 0; run < 400; ++run) {
    const std::string dir = ScratchDir("thread_signal" + std::to_string(run));
    const int status = KillWorkingChild(
        [&] {
          for (;;) AtomicFile f(dir + "/out.exr");
        },
        SIGTERM, 1000 + rng() % 3000);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
    left += Listing(dir).empty() ? 0 : 1;
  }
  EXPECT_EQ(left, 0) << "runs that left a temporary";
}

// Past the file-size limit (ulimit -f) the write fails with "File too
// large", as one line, and leaves neither the target nor a temporary (the
// default SIGXFSZ killed the process with the temporary left behind).
TEST(CliReliabilityTest, FileSizeLimitIsAnErrorWithoutLeftovers) {
  const std::string dir = ScratchDir("fsize");
  for (const char* out : {"big.exr", "big.h", "big.ktx2"}) {
    const ToolRun r = ExecuteShell("cd " + Quote(dir) + " && ulimit -f 20 && \"$BRDFBAKE\" bake -t E "
                                   "--size 256x256 -o " + std::string(out), dir);
    EXPECT_EQ(r.status, 1) << out << ": " << r.err;
    EXPECT_FALSE(r.signaled) << out;
    EXPECT_NE(r.err.find("File too large"), std::string::npos) << r.err;
    for (const std::string& f : Listing(dir)) {
      EXPECT_TRUE(f == "stdout" || f == "stderr") << out << ": " << f << " left behind";
    }
  }
}

// A set of four files committed together (CommitAll, as report writes
// its files), killed at random times while a second thread idles: every
// run leaves one whole set, the old one or the new one, and no temporary.
// Each generation writes its number into all four files.
TEST(OutputFileTest, SetsAreWholeUnderRandomSignals) {
  std::mt19937 rng(11);
  const char* names[4] = {"report.csv", "report.svg", "interpolation.csv", "interpolation.svg"};
  int mixed = 0, runs_with_sets = 0;
  for (int run = 0; run < 300; ++run) {
    const std::string dir = ScratchDir("set_signal" + std::to_string(run));
    const int sig = rng() % 2 ? SIGTERM : SIGINT;
    const int status = KillWorkingChild(
        [&] {
          for (int generation = 0;; ++generation) {
            std::vector<std::unique_ptr<AtomicFile>> files;
            std::vector<AtomicFile*> set;
            for (const char* name : names) {
              files.push_back(std::make_unique<AtomicFile>(dir + "/" + name));
              files.back()->Append(std::to_string(generation));
              set.push_back(files.back().get());
            }
            CommitAll(set);
          }
        },
        sig, 3000 + rng() % 40000);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << status;
    std::vector<std::string> seen;
    for (const std::string& f : Listing(dir)) {
      ASSERT_NE(f.rfind(".brdfbake-", 0), 0u) << "temporary left: " << f;
    }
    for (const char* name : names) {
      if (std::filesystem::exists(dir + "/" + name)) seen.push_back(test::Slurp(dir + "/" + name));
    }
    if (seen.empty()) continue;  // killed before the first set
    ++runs_with_sets;
    bool whole = seen.size() == 4;
    for (const std::string& v : seen) whole &= v == seen[0];
    mixed += whole ? 0 : 1;
  }
  std::printf("300 runs killed at random times: %d left a set, %d of them mixed\n", runs_with_sets,
              mixed);
  EXPECT_EQ(mixed, 0);
  // How many runs get past their first set depends on the machine's load
  // (about half on an idle one): enough of them to mean something.
  EXPECT_GT(runs_with_sets, 50);
}

TEST(OutputFileTest, ReportFilesAreAllOrNothing) {
  ReportSpec rs;
  rs.table.mu.size = rs.table.roughness.size = 4;
  rs.repeats = 1;
  rs.interpolation_sizes = {4};
  const Report r = RunReport(rs);
  const std::string dir = ScratchDir("report");
  // One of the four names is taken by a directory: no file is written.
  std::filesystem::create_directories(dir + "/interpolation.svg");
  EXPECT_THROW(WriteReport(r, dir), std::runtime_error);
  EXPECT_EQ(Listing(dir), std::vector<std::string>{"interpolation.svg"});
  std::filesystem::remove(dir + "/interpolation.svg");
  WriteReport(r, dir);
  EXPECT_EQ(Listing(dir), (std::vector<std::string>{"interpolation.csv", "interpolation.svg",
                                                    "report.csv", "report.svg"}));
}

// ------------------------------------------------------------- the command line

#ifdef BRDFBAKE_CLI_PATH

void ExpectOneLineError(const ToolRun& r, const std::string& what, const std::string& needle = "") {
  EXPECT_FALSE(r.signaled) << what;
  EXPECT_TRUE(r.status == 1 || r.status == 2) << what << ": exit " << r.status;
  std::string err = r.err;
  while (!err.empty() && err.back() == '\n') err.pop_back();
  EXPECT_FALSE(err.empty()) << what;
  EXPECT_EQ(err.find('\n'), std::string::npos) << what << ": " << err;
  EXPECT_EQ(err.rfind("brdfbake: error: ", 0), 0u) << what << ": " << err;
  if (!needle.empty()) {
    EXPECT_NE(err.find(needle), std::string::npos) << what << ": " << err;
  }
}

TEST(CliReliabilityTest, PreplacedLinkAtTheOldTemporaryNameIsNotFollowed) {
  const std::string dir = ScratchDir("symlink");
  WriteText(dir + "/victim", "precious");
  // The old temporary was "<output>.tmp.<pid>"; exec keeps the shell's pid.
  const ToolRun r = ExecuteShell("cd " + Quote(dir) +
                                     " && ln -s victim out.exr.tmp.$$ && exec \"$BRDFBAKE\" bake "
                                     "--table E --size 4x4 -o out.exr",
                                 dir);
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(dir + "/victim");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "precious");
  EXPECT_NO_THROW(ReadExr(dir + "/out.exr"));
}

TEST(CliReliabilityTest, DeviceTargetsAreRefusedBeforeTheBake) {
  const std::string dir = ScratchDir("device");
  std::filesystem::create_symlink("/dev/full", dir + "/full.exr");
  ExpectOneLineError(Execute({"bake", "--table", "E", "-o", dir + "/full.exr"}, dir), "device",
                     "not a regular file");
  EXPECT_TRUE(std::filesystem::is_symlink(dir + "/full.exr"));
  ExpectOneLineError(Execute({"bake", "--table", "E", "-o", "/dev/full"}, dir), "/dev/full");
  ExpectOneLineError(Execute({"bake", "--table", "E", "-o", "/proc/self/fd/1"}, dir), "fd/1");
  ExpectOneLineError(Execute({"eval", "--grid", "slice", "-o", dir + "/full.exr"}, dir), "grid");
  // A directory that cannot be made (a file is in its way) is found
  // before the work; the temporary's name is never shown.
  WriteText(dir + "/file", "");
  const ToolRun r = Execute({"bake", "--table", "E", "--size", "2048x2048", "-o", dir + "/file/dir/x.exr"}, dir);
  ExpectOneLineError(r, "missing dir", "cannot create directory");
  EXPECT_EQ(r.err.find(".tmp."), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(".brdfbake-"), std::string::npos) << r.err;
}

// A scene bake whose output directory holds a directory in the place of a
// planned table is refused before the plan is worked out (it failed after
// 20 s of planning): nothing printed, the error names the file.
TEST(CliReliabilityTest, SceneOutputsAreCheckedBeforeThePlan) {
  const std::string dir = ScratchDir("scene_out");
  std::filesystem::create_directories(dir + "/out/E_ggx.exr");
  const ToolRun r = Execute({"bake", std::string(BRDFBAKE_TEST_DATA) + "/../../examples/scene.toml",
                             "-o", dir + "/out"},
                            dir);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("E_ggx.exr' is a directory"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// A glTF scene naming a FIFO as a buffer and as an image: the tool never
// opens it (opening a FIFO blocks until a writer comes), plans the
// material, and says nothing of the file (a timeout ends a run that
// blocks).
TEST(CliReliabilityTest, GltfUrisNamingAFifoDoNotBlock) {
  const std::string dir = ScratchDir("fifo");
  const ToolRun r = ExecuteShell(
      "cd " + Quote(dir) + " && rm -f pipe && mkfifo pipe && printf '%s' "
      "'{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"uri\":\"pipe\",\"byteLength\":4}],"
      "\"images\":[{\"uri\":\"pipe\"}],\"materials\":[{\"name\":\"m\"}]}' > scene.gltf && "
      "timeout 60 \"$BRDFBAKE\" plan scene.gltf",
      dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("m"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("pipe"), std::string::npos) << r.out;
  EXPECT_EQ(r.err.find("pipe"), std::string::npos) << r.err;
}

// Under a memory limit a text or binary container that cannot be written
// is refused before the bake, naming the size (it ran the whole bake, then
// died with a bare std::bad_alloc), and leaves no file.
TEST(CliReliabilityTest, ContainersThatCannotFitFailBeforeTheBake) {
  const std::string dir = ScratchDir("memory");
  for (const char* ext : {".h", ".js"}) {
    const std::string out = std::string("mem") + ext;
    const ToolRun r = ExecuteShell("cd " + Quote(dir) + " && ulimit -v 60000 && \"$BRDFBAKE\" bake -t E "
                                   "--size 1024x1024 -o " + out, dir);
    EXPECT_NE(r.status, 0) << ext;
    EXPECT_FALSE(r.signaled) << ext;
    EXPECT_NE(r.err.find("MiB to bake and write the"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("baked"), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir + "/" + out)) << ext;
  }
  // Every outcome is whole: the file written, or a one-line error and none.
  for (const char* ext : {".ktx2", ".dds"}) {
    const std::string out = std::string("mem") + ext;
    const ToolRun r = ExecuteShell("cd " + Quote(dir) + " && ulimit -v 60000 && \"$BRDFBAKE\" bake -t E "
                                   "--size 1024x1024 -o " + out, dir);
    EXPECT_FALSE(r.signaled) << ext;
    if (r.status != 0) {
      EXPECT_NE(r.err.find("brdfbake: error: "), std::string::npos) << r.err;
      EXPECT_EQ(r.err.find("std::bad_alloc"), std::string::npos) << r.err;
      EXPECT_FALSE(std::filesystem::exists(dir + "/" + out)) << ext;
    }
  }
}

// eval's CSV under a memory limit: the whole CSV, or a one-line error, a
// non-zero exit and nothing on standard output (it printed 134 MB of 321 MB,
// cut mid-row, and exited 0).
TEST(CliReliabilityTest, EvalCsvIsWholeOrAnError) {
  const std::string dir = ScratchDir("csv");
  const ToolRun r = ExecuteShell("cd " + Quote(dir) + " && ulimit -v 250000 && \"$BRDFBAKE\" eval "
                                 "--quantity D,G1,Lambda,brdf --sweep theta --count 3000000 > out.csv",
                                 dir);
  EXPECT_FALSE(r.signaled);
  const std::string csv = test::Slurp(dir + "/out.csv");
  if (r.status == 0) {
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3000001) << r.err;
  } else {
    EXPECT_TRUE(csv.empty()) << csv.size() << " bytes";
    EXPECT_NE(r.err.find("brdfbake: error: "), std::string::npos) << r.err;
  }
}

// Error lines show C1 controls and bidirectional overrides from the
// command line as escapes, like the C0 controls.
TEST(CliReliabilityTest, ErrorsEscapeC1AndBidiControls) {
  const std::string dir = ScratchDir("bidi");
  const ToolRun r = ExecuteShell(
      "\"$BRDFBAKE\" eval --model \"$(printf 'x\\342\\200\\256y\\302\\205z\\033')\"", dir);
  EXPECT_NE(r.status, 0);
  EXPECT_EQ(r.err.find("\xe2\x80\xae"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("\xc2\x85"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("x\\u{202e}y\\u{0085}z\\x1b"), std::string::npos) << r.err;
}

TEST(CliReliabilityTest, FailedWritesToStdoutAreErrors) {
  const std::string dir = ScratchDir("stdout");
  const std::vector<std::string> commands = {
      "stability --samples 10",
      "eval --quantity D --count 5",
      "bake --table E --size 4x4 -o " + Quote(dir + "/e.exr"),
      "report --table E --size 4x4 --repeats 1 -o " + Quote(dir + "/report"),
      "--help",
      "--version",
      "bake --help",
  };
  for (const std::string& c : commands) {
    const ToolRun r = ExecuteShell("\"$BRDFBAKE\" " + c + " >/dev/full", dir);
    EXPECT_EQ(r.status, 1) << c;
    // The error is the last line of stderr (after a report's log, say).
    std::string err = r.err;
    while (!err.empty() && err.back() == '\n') err.pop_back();
    const std::string last =
        err.substr(err.rfind('\n') == std::string::npos ? 0 : err.rfind('\n') + 1);
    EXPECT_EQ(last.rfind("brdfbake: error: cannot write to standard output", 0), 0u) << c << ": " << r.err;
  }
}

TEST(CliReliabilityTest, ControlCharactersInArgumentsAreEscaped) {
  const std::string dir = ScratchDir("escape");
  const std::string o = dir + "/x.exr";
  const std::vector<std::vector<std::string>> runs = {
      {"bake", "--table", "E\nX", "-o", o},
      {"bake", "--table", "E", "--model", "g\ngx", "-o", o},
      {"bake", "--table", "E", "--warp", "lin\near", "-o", o},
      {"bake", "--table", "E", "--size", "8\nx8", "-o", o},
      {"bake", "--table", "E", "-o", dir + "/a\nb.exr.gif"},
      {"bake", "--table", "E", "-o", dir + "/no\ndir/x.gif"},
      {"eval", "--quantity", "D\nG1"},
      {"eval", "--fresnel", "one\r\x1b[2J"},
      {"eval", "--no-such\nflag"},
  };
  for (const auto& args : runs) {
    const ToolRun r = Execute(args, dir);
    ExpectOneLineError(r, args[1] + " " + args[2]);
    EXPECT_NE(r.err.find('\\'), std::string::npos) << "no escape in: " << r.err;
    EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
  }
  EXPECT_TRUE(Listing(dir).size() == 2) << "stdout, stderr only";
}

TEST(CliReliabilityTest, BadNumbersAreRejected) {
  const std::string dir = ScratchDir("numbers");
  const std::string o = dir + "/x.exr";
  for (const char* seed : {"18446744073709551616", "99999999999999999999999", "-1",
                           "-18446744073709551615", "", "1.5", "0x10", " 1"}) {
    ExpectOneLineError(Execute({"bake", "--table", "E", "--seed", seed, "-o", o}, dir),
                       std::string("bake --seed ") + seed, "--seed");
    ExpectOneLineError(Execute({"stability", "--samples", "10", "--seed", seed}, dir),
                       std::string("stability --seed ") + seed, "--seed");
  }
  const ToolRun max_seed = Execute({"bake", "--table", "E", "--size", "2x2", "--integrator", "mc",
                                    "--seed", "18446744073709551615", "-o", o}, dir);
  EXPECT_EQ(max_seed.status, 0) << max_seed.err;
  EXPECT_EQ(nlohmann::json::parse(ReadExr(o).Attribute("brdfbake.integrator"))["seed"].get<uint64_t>(),
            18446744073709551615ull);
  std::filesystem::remove(o);
  ExpectOneLineError(Execute({"bake", "--table", "E", "--threads", "2147483647", "-o", o}, dir),
                     "threads", "--threads");
  ExpectOneLineError(Execute({"bake", "--table", "E", "--threads", "1025", "-o", o}, dir),
                     "threads", "--threads");
  ExpectOneLineError(Execute({"eval", "--grid", "slice", "--threads", "5000", "-o", o}, dir),
                     "grid threads", "--threads");
  ExpectOneLineError(Execute({"bake", "--table", "E", "--model", "ggx", "--gamma", "3", "-o", o}, dir),
                     "gamma on ggx", "--gamma");
  ExpectOneLineError(Execute({"bake", "--table", "E_avg", "--size", "999x64", "-o", o}, dir),
                     "E_avg WxH", "--size");
  EXPECT_FALSE(std::filesystem::exists(o));
}

// A bake too large for the memory fails at once, naming the size, instead
// of after the work (an 8192x8192 bake would run for minutes).
TEST(CliReliabilityTest, MemoryFailureComesBeforeTheBake) {
  const std::string dir = ScratchDir("memory");
  const ToolRun r = ExecuteShell("ulimit -v 400000 && exec \"$BRDFBAKE\" bake --table E --size "
                                 "8192x8192 -o " + Quote(dir + "/big.exr"),
                                 dir);
  ExpectOneLineError(r, "8192x8192 under ulimit", "cannot allocate");
  EXPECT_NE(r.err.find("MiB"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/big.exr"));
}

TEST(CliReliabilityTest, AcceptedButIgnoredOptionsAreRejected) {
  const std::string dir = ScratchDir("ignored");
  const std::string o = dir + "/x.exr";
  const std::vector<std::pair<std::vector<std::string>, std::string>> runs = {
      {{"bake", "--table", "E", "--model", "ggx", "--gamma", "3", "-o", o}, "--gamma"},
      {{"bake", "--table", "E_avg", "--size", "16x64", "-o", o}, "--size"},
      {{"bake", "--table", "E_avg", "--warp", "mu=square", "-o", o}, "no mu axis"},
      {{"bake", "--table", "E", "--warp", "mu=square,mu=sqrt", "-o", o}, "twice"},
      {{"bake", "--table", "E", "--warp", "square,roughness=sqrt", "-o", o}, "twice"},
      {{"bake", "--table", "E", "--range", "mu=0:1,mu=0.5:1", "-o", o}, "twice"},
      {{"bake", "--table", "E", "--integrator", "qmc", "--tolerance", "1e-3", "-o", o}, "--tolerance"},
      {{"bake", "--table", "dfg", "-o", dir + "/dfg.gif"}, ".gif"},
      {{"bake", "--table", "dfg", "-o", dir + "/dfg"}, "no extension"},
      {{"bake", "--table", "dfg", "--format", "ktx2", "-o", dir + "/dfg.dds"}, "does not name"},
      {{"bake", "--table", "dfg", "--pixel", "unorm16", "-o", dir + "/dfg.exr"}, "unorm16"},
      {{"eval", "--model", "ggx", "--gamma", "3"}, "--gamma"},
      {{"eval", "--model", "beckmann", "--theta-x", "10"}, "--theta-x"},
      {{"eval", "--fresnel", "one", "--f0", "0.5"}, "--f0"},
      {{"eval", "--fresnel", "schlick", "--eta", "1.3"}, "--eta"},
      {{"bake", "--table", "E", "--alpha-x", "0.2", "--alpha-y", "0.5", "-o", o},
       "--alpha-x: only ellipsoid tables take a material's widths and angles"},
      {{"bake", "--table", "E", "--size", "8x8x8", "-o", o}, "--size: expected WxH"},
      {{"bake", "--table", "E", "--range", "mu=0.5:0.2", "-o", o}, "--range"},
      {{"bake", "--table", "E", "--range", "roughness=0:2", "-o", o}, "--range"},
  };
  for (const auto& run : runs) {
    std::string line;
    for (const std::string& a : run.first) line += " " + a;
    ExpectOneLineError(Execute(run.first, dir), line, run.second);
  }
  EXPECT_EQ(Listing(dir), (std::vector<std::string>{"stderr", "stdout"}));
}

TEST(CliReliabilityTest, EdgesTablesCarryANote) {
  const std::string dir = ScratchDir("note");
  ToolRun r = Execute({"bake", "--table", "E", "--size", "4x4", "-o", dir + "/e.exr"}, dir);
  ASSERT_EQ(r.status, 0);
  EXPECT_NE(r.err.find("note: edges placement"), std::string::npos) << r.err;
  r = Execute({"bake", "--table", "E", "--size", "4x4", "--placement", "centers", "-o",
               dir + "/c.exr"}, dir);
  ASSERT_EQ(r.status, 0);
  EXPECT_EQ(r.err, "");
}

// Progress on a terminal: percent, elapsed and remaining time.
TEST(CliReliabilityTest, ProgressShowsTheRemainingTime) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1)";
  const std::string dir = ScratchDir("progress");
  // A bake of a few seconds (progress shows after one) under a pseudo-terminal
  // (script(1)): 4 million QMC samples for each of 16 texels by the scalar
  // reference, whose cost does not move with the quadrature's or the lanes'.
  const ToolRun r = ExecuteShell(
      "script -qec " +
          Quote("\"$BRDFBAKE\" bake --table E --model ggx --integrator qmc --samples 4000000 "
                "--size 4x4 --threads 1 --target scalar -o " +
                Quote(dir + "/p.exr")) +
          " /dev/null",
      dir);
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("% "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("s elapsed, "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("s left"), std::string::npos) << r.out;
}

// `eval --quantity E|dfg|E_avg` gives what `bake` stores.
TEST(CliReliabilityTest, EvalTableQuantitiesMatchTheBake) {
  const std::string dir = ScratchDir("evalE");
  ToolRun r = Execute({"eval", "--quantity", "E,dfg,E_avg", "--roughness", "0.5", "--mu-o", "0.3"}, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream in(r.out);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(header, "mu,roughness,E,E_error,dfg_scale,dfg_bias,dfg_error,E_avg,E_avg_error");
  std::vector<double> v;
  std::stringstream cells(row);
  std::string cell;
  while (std::getline(cells, cell, ',')) v.push_back(std::stod(cell));
  ASSERT_EQ(v.size(), 9u);
  BakeSpec spec;
  const TexelEstimate t = IntegrateTexel(spec, 0.5, 0.3);
  EXPECT_EQ(v[2], t.e);
  spec.table = TableKind::kDfg;
  const TexelEstimate d = IntegrateTexel(spec, 0.5, 0.3);
  EXPECT_EQ(v[4], d.scale);
  EXPECT_EQ(v[5], d.bias);
  EXPECT_NEAR(v[2], v[4] + v[5], v[3] + v[6]);
  EXPECT_EQ(v[7], IntegrateEavg(BakeSpec(), 0.5).value);
  // A sweep over roughness; E along mu with D in the same call.
  r = Execute({"eval", "--quantity", "E", "--sweep", "roughness", "--from", "0", "--to", "1",
               "--count", "5", "--mu-o", "0.5"}, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 6);
  r = Execute({"eval", "--quantity", "D,E", "--count", "3"}, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  ExpectOneLineError(Execute({"eval", "--quantity", "E", "--model", "sel"}, dir), "sel E");
  ExpectOneLineError(Execute({"eval", "--quantity", "E", "--alpha-x", "0.1", "--alpha-y", "0.3"}, dir),
                     "aniso E", "isotropic");
  ExpectOneLineError(Execute({"eval", "--quantity", "D", "--sweep", "roughness"}, dir), "D roughness");
}

#endif  // BRDFBAKE_CLI_PATH

// ------------------------------------------------------------- the file header

TEST(HeaderTest, ChannelsSortIntoTheirOrderAndDescribeThemselves) {
  BakeSpec spec;
  spec.table = TableKind::kDfg;
  spec.mu.size = spec.roughness.size = 4;
  spec.error_channel = true;
  spec.complement = true;
  const Table t = Bake(spec);
  const std::string path = ::testing::TempDir() + "/brdfbake_header_dfg.exr";
  WriteExr(t, path);
  const ExrContents c = ReadExr(path);  // channels in file order
  ASSERT_EQ(c.channels.size(), 4u);
  EXPECT_EQ(c.channels[0].first, "dfg.0_scale");
  EXPECT_EQ(c.channels[1].first, "dfg.1_bias");
  EXPECT_EQ(c.channels[2].first, "dfg.2_1-E");
  EXPECT_EQ(c.channels[3].first, "dfg.3_error");
  const auto order = nlohmann::json::parse(c.Attribute("brdfbake.channel_order"));
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(order[i], c.channels[i].first);
  const auto channels = nlohmann::json::parse(c.Attribute("brdfbake.channels"));
  EXPECT_EQ(channels["dfg.3_error"], "error");
  EXPECT_EQ(channels["dfg.0_scale"], "dfg.scale");
  EXPECT_EQ(channels["dfg.1_bias"], "dfg.bias");
  EXPECT_EQ(channels["dfg.2_1-E"], "1-E");
  const auto info = nlohmann::json::parse(c.Attribute("brdfbake.channel_info"));
  ASSERT_EQ(info.size(), 4u);
  const std::string bias_def = info[1]["definition"];
  EXPECT_NE(bias_def.find("(1 - wo.h)^5"), std::string::npos);
  EXPECT_NE(bias_def.find("F0 scale + F90 bias"), std::string::npos);
  EXPECT_NE(c.Attribute("brdfbake.layout").find("x = columns, then y = rows, then slices"),
            std::string::npos);
  EXPECT_NE(c.Attribute("brdfbake.layout").find("t = (i + 0.5) / N"), std::string::npos);
  EXPECT_FALSE(c.Attribute("brdfbake.range").empty());
  // With or without the error channel the order is the same.
  for (const bool err : {false, true}) {
    for (const TableKind k : {TableKind::kE, TableKind::kEavg}) {
      for (const bool comp : {false, true}) {
        BakeSpec s;
        s.table = k;
        s.mu.size = s.roughness.size = 3;
        s.error_channel = err;
        s.complement = comp;
        WriteExr(Bake(s), path);
        const ExrContents e = ReadExr(path);
        ASSERT_EQ(e.channels.size(), err ? 2u : 1u);
        EXPECT_EQ(e.channels[0].first,
                  std::string(comp ? "1-" : "") + (k == TableKind::kE ? "E" : "E_avg"));
        if (err) {
          EXPECT_EQ(e.channels[1].first, "error");
        }
      }
    }
  }
}

// OpenImageIO lists the channels of a table with an error channel in the
// order of brdfbake.channel_order (it lists unlayered channels first: an
// unlayered `error` came before the dfg layer).
TEST(HeaderTest, OpenImageIoListsChannelsInTheirOrder) {
  if (std::system("command -v iinfo >/dev/null 2>&1") != 0) GTEST_SKIP() << "no iinfo";
  const std::string dir = ScratchDir("oiio_order");
  for (const bool complement : {false, true}) {
    for (const TableKind k : {TableKind::kDfg, TableKind::kE}) {
      BakeSpec spec;
      spec.table = k;
      spec.mu.size = spec.roughness.size = 4;
      spec.error_channel = true;
      spec.complement = complement;
      const std::string path = dir + "/t.exr";
      WriteExr(Bake(spec), path);
      const auto order = nlohmann::json::parse(ReadExr(path).Attribute("brdfbake.channel_order"));
      ASSERT_EQ(std::system(("iinfo -v " + path + " > " + dir + "/info.txt 2>&1").c_str()), 0);
      const std::string info = test::Slurp(dir + "/info.txt");
      // "    channel list: dfg.0_scale, dfg.1_bias, dfg.2_error"
      const size_t at = info.find("channel list: ");
      ASSERT_NE(at, std::string::npos) << info;
      const std::string list = info.substr(at + 14, info.find('\n', at) - at - 14);
      std::string want;
      for (const auto& name : order) want += (want.empty() ? "" : ", ") + name.get<std::string>();
      EXPECT_EQ(list, want) << TableName(k) << (complement ? " complement" : "");
    }
  }
}

// --range: the axes cover the given sub-ranges, and each texel is the
// integral at its mapped (mu, roughness).
TEST(HeaderTest, RangesAreRecordedAndBaked) {
  BakeSpec spec;
  spec.mu.size = spec.roughness.size = 5;
  spec.mu.min = 1e-4;
  spec.roughness.min = 0.1;
  spec.roughness.max = 0.9;
  spec.mu.placement = spec.roughness.placement = Placement::kCenters;
  const Table t = Bake(spec);
  const std::string path = ::testing::TempDir() + "/brdfbake_header_range.exr";
  WriteExr(t, path);
  const auto axes = nlohmann::json::parse(ReadExr(path).Attribute("brdfbake.axes"));
  EXPECT_EQ(axes[0]["min"], 1e-4);
  EXPECT_EQ(axes[1]["min"], 0.1);
  EXPECT_EQ(axes[1]["max"], 0.9);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 5; ++x) {
      const double mu = 1e-4 + (1 - 1e-4) * (x + 0.5) / 5, r = 0.1 + 0.8 * (y + 0.5) / 5;
      EXPECT_NEAR(t.channels[0].values[y * 5 + x], IntegrateTexel(BakeSpec(), r, mu).e, 1e-12);
    }
  }
}

TEST(HeaderTest, GridsRecordTheirAxes) {
  GridRequest req;
  req.kind = GridKind::kG1;
  req.width = req.height = 8;
  const Grid g = EvalGrid(req);
  const auto attrs = GridAttributes(req, g);
  auto get = [&](const std::string& name) {
    for (const auto& kv : attrs) {
      if (kv.first == name) return kv.second;
    }
    return std::string();
  };
  const auto axes = nlohmann::json::parse(get("brdfbake.axes"));
  ASSERT_EQ(axes.size(), 2u);
  EXPECT_EQ(axes[0]["name"], "mu");
  EXPECT_EQ(axes[1]["name"], "roughness");
  EXPECT_EQ(axes[1]["placement"], "centers");
  const auto model = nlohmann::json::parse(get("brdfbake.model"));
  EXPECT_FALSE(model.contains("alpha_x"));  // g1 sweeps roughness
  EXPECT_NE(get("brdfbake.layout").find("x = columns"), std::string::npos);
  req.kind = GridKind::kHemisphere;
  const auto hemi = nlohmann::json::parse(GridAttributes(req, g)[5].second);
  EXPECT_EQ(hemi[1]["min"], 1.0);
  EXPECT_EQ(hemi[1]["max"], -1.0);
}

// ---------------------------------------------------- stored values in [0, 1]

TEST(RangeTest, StoredValuesStayInTheUnitInterval) {
  struct Case {
    TableKind table;
    IntegratorKind integrator;
    const char* model;
    int samples;
    bool half;
  };
  const Case cases[] = {
      {TableKind::kE, IntegratorKind::kEngine, "ggx", 2, false},  // stored 1.17 once
      {TableKind::kE, IntegratorKind::kMc, "std", 0, false},      // 1.034 once
      {TableKind::kE, IntegratorKind::kQmc, "std", 0, false},
      {TableKind::kDfg, IntegratorKind::kQuadrature, "ggx", 0, false},  // sum 1 + 3e-8 once
      {TableKind::kDfg, IntegratorKind::kQuadrature, "ggx", 0, true},   // 1 + 2.4e-4 once
      {TableKind::kDfg, IntegratorKind::kEngine, "ggx", 2, true},
      {TableKind::kEavg, IntegratorKind::kEngine, "ggx", 2, false},
  };
  for (const Case& c : cases) {
    BakeSpec spec;
    spec.table = c.table;
    spec.integrator = c.integrator;
    spec.model.kind = ParseModelKind(c.model);
    spec.model.gamma = 3;
    spec.samples = c.samples;
    spec.half = c.half;
    spec.mu.size = spec.roughness.size = c.integrator == IntegratorKind::kQuadrature ? 32 : 8;
    const Table t = Bake(spec);
    const size_t n = t.channels[0].stored.size();
    for (size_t i = 0; i < n; ++i) {
      double sum = 0;
      for (const Channel& ch : t.channels) {
        if (ch.meaning == brdfbake::Meaning::kError) continue;
        ASSERT_GE(ch.stored[i], 0.0f) << ch.name;
        ASSERT_LE(ch.stored[i], 1.0f) << ch.name;
        if (ch.meaning == brdfbake::Meaning::kDfgScale || ch.meaning == brdfbake::Meaning::kDfgBias) sum += ch.stored[i];
        if (c.half) {
          EXPECT_EQ(float(Imath::half(ch.stored[i])), ch.stored[i]);
        }
      }
      ASSERT_LE(sum, 1.0) << TableName(c.table) << " texel " << i;
    }
    // The claim covers the clamp and the rounding against the true values.
    if (c.integrator == IntegratorKind::kQuadrature) {
      for (size_t i = 0; i < n; i += 7) {
        const int x = int(i % size_t(t.width)), y = int(i / size_t(t.width));
        BakeSpec ref = spec;
        ref.tolerance = 1e-11;
        const TexelEstimate v =
            IntegrateTexel(ref, spec.roughness.Value(y), spec.mu.Value(x));
        EXPECT_LE(std::abs(t.channels[0].stored[i] - v.scale), t.max_abs_error);
        EXPECT_LE(std::abs(t.channels[1].stored[i] - v.bias), t.max_abs_error);
      }
    }
  }
}

// 1 - E_avg in half: not rounded to 0 at small roughness, and accurate to
// half precision where E_avg is near 1 (the complement is taken in double).
TEST(RangeTest, ComplementOfEavgInHalf) {
  BakeSpec spec;
  spec.table = TableKind::kEavg;
  spec.roughness.size = 32;
  spec.complement = true;
  spec.half = true;
  const Table t = Bake(spec);
  EXPECT_EQ(t.channels[0].name, "1-E_avg");
  BakeSpec plain = spec;
  plain.complement = false;
  plain.half = false;
  const Table ref = Bake(plain);
  int positive_small = 0;
  for (int i = 1; i < 32; ++i) {
    const double exact = 1.0 - ref.channels[0].values[i];
    const double stored = t.channels[0].stored[i];
    // Half: relative 2^-11 for normal numbers, absolute 2^-25 below 2^-14.
    EXPECT_LE(std::abs(stored - exact), std::max(exact * 0x1p-11, 0x1p-25)) << "i=" << i;
    if (spec.roughness.Value(i) < 0.2 && exact > 0) positive_small += stored > 0;
  }
  EXPECT_GT(positive_small, 0);
  // The roughness 0.14 texel of the issue: E in half would give 1 - E 13% off.
  BakeSpec one = spec;
  one.roughness.size = 1;
  one.roughness.placement = Placement::kCenters;
  one.roughness.min = one.roughness.max = 0.14;
  const double c = Bake(one).channels[0].stored[0];
  one.complement = false;
  one.half = false;
  const double exact = 1.0 - Bake(one).channels[0].values[0];
  EXPECT_LE(std::abs(c - exact), exact * 0x1p-11);
  // What the complement avoids: 1 minus a stored half E_avg.
  one.half = true;
  const double naive = 1.0 - double(Bake(one).channels[0].stored[0]);
  std::printf("r = 0.14: 1 - E_avg = %.6g; 1 - half(E_avg) = %.6g (%.1f%% off); half(1 - E_avg) = "
              "%.6g\n", exact, naive, 100 * std::abs(naive - exact) / exact, c);
  EXPECT_GT(std::abs(naive - exact), 0.05 * exact);
}

// A GPU's bilinear texture(lut, vec2(NoV, r)) with clamp-to-edge addressing.
double GpuBilinear(const Table& t, double u, double v) {
  auto at = [&](int x, int y) { return double(t.channels[0].stored[size_t(y) * t.width + x]); };
  return test::TextureBilinear(at, t.width, t.height, u, v);
}

// The note the tool prints for edges tables: looked up without the remap,
// an edges table is off by several times the error of a remapped lookup.
TEST(PlacementTest, GpuLookupOfAnEdgesTableNeedsTheRemap) {
  BakeSpec spec;
  const Table edges = Bake(spec);
  spec.mu.placement = spec.roughness.placement = Placement::kCenters;
  const Table centers = Bake(spec);
  const int n = 32;
  auto remap = [&](double t) { return (t * (n - 1) + 0.5) / n; };
  double plain = 0, remapped = 0, centred = 0;
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (int i = 0; i < 1500; ++i) {
    // Random points, a third of them near the ends of an axis.
    double mu = uni(rng), r = uni(rng);
    if (i % 3 == 1) mu = uni(rng) < 0.5 ? mu * 0.05 : 1 - mu * 0.05;
    if (i % 3 == 2) r = uni(rng) < 0.5 ? r * 0.05 : 1 - r * 0.05;
    // Away from the grazing boundary layer of E (the first mu cells),
    // whose interpolation error (~0.1) no placement removes.
    if (mu < 0.1) mu = 0.1 + 0.9 * mu;
    const double exact = IntegrateTexel(BakeSpec(), r, mu).e;
    plain = std::max(plain, std::abs(GpuBilinear(edges, mu, r) - exact));
    remapped = std::max(remapped, std::abs(GpuBilinear(edges, remap(mu), remap(r)) - exact));
    // A centres table covers the same [0, 1] with its texels half a cell in.
    centred = std::max(centred, std::abs(GpuBilinear(centers, mu, r) - exact));
  }
  std::printf("GPU bilinear lookup of the 32x32 GGX E table at mu >= 0.1, max error: edges %.3g, "
              "edges with the remap %.3g, centres %.3g\n", plain, remapped, centred);
  EXPECT_GT(plain, 2 * remapped);
  // A centres table is right without a remap except within half a texel of
  // the ends, where clamp-to-edge holds the last texel's value.
  EXPECT_LT(centred, plain);
}

// ------------------------------------------------------------ domain bounds

TEST(DomainTest, AlphaIsBoundedAndFiniteUpToTheBound) {
  ModelParams p;
  p.alpha_x = p.alpha_y = 1.4e154;
  EXPECT_THROW(ValidateModelParams(p), std::invalid_argument);
  p.kind = ModelKind::kSel;
  p.alpha_x = 1;
  p.alpha_y = 1e154;
  EXPECT_THROW(ValidateModelParams(p), std::invalid_argument);
  // At the bound, in every grid of every model (float SIMD kernels): finite.
  for (const char* model : {"ggx", "beckmann", "std", "ellipsoid"}) {
    for (const GridKind kind : {GridKind::kSlice, GridKind::kHemisphere}) {
      for (const double ay : {kMaxAlpha, 1e-4, 1.0}) {
        GridRequest req;
        req.model.kind = ParseModelKind(model);
        req.model.alpha_x = kMaxAlpha;
        req.model.alpha_y = ay;
        req.model.gamma = 1.6;
        req.model.theta_x = 0.5;
        req.kind = kind;
        req.width = req.height = 32;
        req.mu_o = 0.3;
        for (const Fresnel& f : {Fresnel::One(), Fresnel::Schlick({0.04, 0.5, 0.9})}) {
          req.fresnel = f;
          const Grid g = EvalGrid(req);
          for (float v : g.values) {
            ASSERT_TRUE(std::isfinite(v) && v >= 0) << model << " " << GridKindName(kind) << " ay=" << ay;
          }
        }
      }
    }
  }
}

TEST(DomainTest, SelLobeIsFiniteUpToTheBound) {
  for (const double ay : {kMaxAlpha, 1e-4}) {
    ModelParams p;
    p.kind = ModelKind::kSel;
    p.alpha_x = kMaxAlpha;
    p.alpha_y = ay;
    p.theta_x = 0.3;
    const auto model = MakeModel(p);
    for (int i = 0; i <= 400; ++i) {
      const double mu = -1.0 + i / 200.0;
      const double k = model->K(FromMuPhi(mu, 0.1 * i));
      ASSERT_TRUE(std::isfinite(k) && k >= 0) << "mu=" << mu << " ay=" << ay;
    }
  }
}

// A gamma in (1.5, 1.5 + 1e-6), evaluated at the models' floor 1.5 + 1e-6
// under a header naming the gamma asked for, would store 0.7047 where E is
// 0.2798 (mu = 1, r = 1/31, gamma 1.5000001): it is refused wherever a
// user gives a gamma, with the floor in the message.
TEST(DomainTest, GammaBelowTheFloorIsRefused) {
  const std::string dir = ScratchDir("gamma_floor");
  const std::string o = dir + "/E.exr";
  const std::string why = "must be >= 1.500001 or inf (the STD's mean slope diverges at 1.5; got ";
  const std::string error = "brdfbake: error: gamma " + why + "1.5000001)\n";
  const ToolRun bake = Execute({"bake", "--table", "E", "--model", "std", "--gamma", "1.5000001", "-o", o}, dir);
  ExpectOneLineError(bake, "bake --gamma 1.5000001");
  EXPECT_EQ(bake.err, error);
  const ToolRun eval = Execute({"eval", "--model", "std", "--gamma", "1.5000001", "--quantity", "E",
                                "--roughness", "1", "--mu-o", "1"}, dir);
  ExpectOneLineError(eval, "eval --gamma 1.5000001");
  EXPECT_EQ(eval.err, error);
  EXPECT_EQ(eval.out, "");
  ExpectOneLineError(Execute({"bake", "--table", "E", "--model", "std", "--size", "4x4x3", "--range",
                              "gamma=1.5000001:inf", "-o", o}, dir),
                     "gamma axis from 1.5000001",
                     "--range: the gamma axis must satisfy 1.500001 <= min < max <= inf (the STD's "
                     "mean slope diverges at 1.5; got 1.5000001:inf)");
  WriteText(dir + "/scene.toml",
            "[[material]]\nname = \"m\"\nmodel = \"std\"\ngamma = 1.5000001\nroughness = 0.5\n");
  ExpectOneLineError(Execute({"plan", dir + "/scene.toml"}, dir), "scene gamma 1.5000001",
                     "field 'gamma': " + why + "1.5000001)");
  EXPECT_FALSE(std::filesystem::exists(o));
  // The library's check: the floor itself and inf are in, the double below is out.
  ModelParams p;
  p.kind = ModelKind::kStudentT;
  for (const double g : {kMinStudentTGamma<double>, 2.0, std::numeric_limits<double>::infinity()}) {
    p.gamma = g;
    EXPECT_NO_THROW(ValidateModelParams(p)) << g;
  }
  for (const double g : {std::nextafter(kMinStudentTGamma<double>, 0.0), 1.5000001, 1.5,
                         std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()}) {
    p.gamma = g;
    EXPECT_THROW(ValidateModelParams(p), std::invalid_argument) << g;
  }
  // At the floor the bake runs and records the gamma it evaluated.
  const ToolRun floor = Execute({"bake", "--table", "E", "--model", "std", "--gamma", "1.500001", "--size",
                                 "2x2", "-o", o}, dir);
  ASSERT_EQ(floor.status, 0) << floor.err;
  EXPECT_EQ(nlohmann::json::parse(ReadExr(o).Attribute("brdfbake.model"))["gamma"].get<double>(),
            kMinStudentTGamma<double>);
}

TEST(DomainTest, HugeGammaIsBeckmann) {
  const BeckmannNdf<double> beckmann(0.3, 0.3);
  for (const double gamma : {1e16, 1e19, 1e20, std::ldexp(1.0, 1023), 1.7e308,
                             std::numeric_limits<double>::max()}) {
    const StudentTNdf<double> ndf(0.3, 0.3, gamma);
    for (const double mu : {1e-6, 0.1, 0.5, 0.9, 1.0}) {
      const Vec3<double> w = FromMuPhi(mu, 0.4);
      const double lb = beckmann.Lambda(w), ls = ndf.Lambda(w);
      EXPECT_NEAR(ls, lb, 1e-13 * std::max(1.0, lb)) << "gamma=" << gamma << " mu=" << mu;
      const double db = beckmann.D(w), ds = ndf.D(w);
      EXPECT_NEAR(ds, db, 1e-13 * std::max(1.0, db)) << "gamma=" << gamma << " mu=" << mu;
    }
  }
  // The table at the largest gammas is the Beckmann table, with an honest claim.
  BakeSpec spec;
  spec.mu.size = spec.roughness.size = 6;
  spec.model.kind = ModelKind::kBeckmann;
  const Table b = Bake(spec);
  for (const double gamma : {1.7e308, std::numeric_limits<double>::max()}) {
    spec.model.kind = ModelKind::kStudentT;
    spec.model.gamma = gamma;
    const Table s = Bake(spec);
    for (size_t i = 0; i < s.channels[0].values.size(); ++i) {
      EXPECT_LE(s.channels[0].values[i], 1.0);
      EXPECT_NEAR(s.channels[0].values[i], b.channels[0].values[i],
                  s.integration_error + b.integration_error);
    }
    EXPECT_LT(s.max_abs_error, 1e-6);
  }
}

}  // namespace
}  // namespace brdfbake
