// Output files appear whole or not at all: a committed file holds exactly its text, an abandoned
// or failed one leaves the old target as it was and no temporary file beside it.

#include "io/atomic_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "support/test_files.hpp"

namespace fragsim {
namespace {

namespace fs = std::filesystem;
using fragsim::test::entries;
using fragsim::test::fresh_dir;
using fragsim::test::read_all;

// The temporary file of this process's AtomicFile for `target` (the name a SIGKILL leaves).
fs::path temporary_of(const fs::path& target) {
  return target.string() + ".tmp." + std::to_string(::getpid());
}

TEST(AtomicFile, CommitPutsTheWholeTextInPlace) {
  const fs::path dir = fresh_dir("fragsim_atomic_commit");
  const fs::path target = dir / "out.csv";
  {
    AtomicFile f(target.string());
    f.out() << "a,b\n1,2\n";
    // Until the commit, the text is in the temporary file and the target does not exist.
    EXPECT_TRUE(fs::exists(temporary_of(target)));
    EXPECT_FALSE(fs::exists(target));
    f.commit();
  }
  EXPECT_EQ(read_all(target), "a,b\n1,2\n");
  EXPECT_EQ(entries(dir), 1);
  write_file_atomically(target.string(), "replaced");
  EXPECT_EQ(read_all(target), "replaced");
  EXPECT_EQ(entries(dir), 1);
}

TEST(AtomicFile, AbandonedWriteKeepsTheOldFileAndLeavesNoTemporary) {
  const fs::path dir = fresh_dir("fragsim_atomic_abandon");
  const fs::path target = dir / "summary.csv";
  write_file_atomically(target.string(), "old\n");
  try {
    AtomicFile f(target.string());
    f.out() << "new, half written";
    throw std::runtime_error("the run failed");  // before commit()
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(read_all(target), "old\n");
  EXPECT_FALSE(fs::exists(temporary_of(target)));
  EXPECT_EQ(entries(dir), 1);
}

TEST(AtomicFile, MissingFolderIsRefusedNamingThePath) {
  const fs::path dir = fresh_dir("fragsim_atomic_missing");
  const std::string target = (dir / "no" / "out.csv").string();
  try {
    AtomicFile f(target);
    FAIL() << "opened " << target;
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(target + ": cannot write (", 0), 0u) << e.what();
  }
  EXPECT_EQ(entries(dir), 0);
}

TEST(AtomicFile, FolderInTheTargetsPlaceIsRefusedBeforeWriting) {
  const fs::path dir = fresh_dir("fragsim_atomic_folder");
  const fs::path target = dir / "taken";
  fs::create_directories(target);
  try {
    AtomicFile f(target.string());
    FAIL() << "opened the folder " << target << " as a file";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), target.string() + ": is a folder");
  }
  EXPECT_EQ(entries(dir), 1);  // no temporary file
}

TEST(AtomicFile, FailedRenameKeepsTheTargetAndLeavesNoTemporary) {
  // A folder put in the target's place after the file was opened: the text is written, but
  // rename() cannot replace a folder with a file, so the commit fails after the writing.
  const fs::path dir = fresh_dir("fragsim_atomic_rename");
  const fs::path target = dir / "taken";
  AtomicFile f(target.string());
  f.out() << "new";
  fs::create_directories(target);
  write_file_atomically((target / "inside.txt").string(), "kept");
  try {
    f.commit();
    FAIL() << "replaced the folder " << target;
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(target.string() + ": cannot rename into place (", 0), 0u)
        << e.what();
  }
  EXPECT_TRUE(fs::is_directory(target));
  EXPECT_EQ(read_all(target / "inside.txt"), "kept");
  EXPECT_FALSE(fs::exists(temporary_of(target)));
  EXPECT_EQ(entries(dir), 1);
}

}  // namespace
}  // namespace fragsim
