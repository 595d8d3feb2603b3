// Files that appear together or not at all: when one of them cannot be written whole, none of the
// set is put in place and the old files stay as they were.

#include "io/output_set.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/test_files.hpp"

namespace fragsim {
namespace {

namespace fs = std::filesystem;
using fragsim::test::entries;
using fragsim::test::fresh_dir;
using fragsim::test::read_all;

TEST(OutputSet, CommitPutsEveryFileInPlace) {
  const fs::path dir = fresh_dir("fragsim_set_commit");
  OutputSet files;
  files.add((dir / "a.csv").string(), "a\n");
  files.add((dir / "b.csv").string()) << "b\n";
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files.path(1), (dir / "b.csv").string());
  files.commit();
  EXPECT_EQ(read_all(dir / "a.csv"), "a\n");
  EXPECT_EQ(read_all(dir / "b.csv"), "b\n");
  EXPECT_EQ(entries(dir), 2);
}

TEST(OutputSet, AbandonedSetLeavesTheOldFilesAndNoTemporary) {
  const fs::path dir = fresh_dir("fragsim_set_abandoned");
  std::ofstream(dir / "a.csv") << "old\n";
  {
    OutputSet files;
    files.add((dir / "a.csv").string(), "new\n");
    files.add((dir / "b.csv").string(), "new\n");
  }
  EXPECT_EQ(read_all(dir / "a.csv"), "old\n");
  EXPECT_EQ(entries(dir), 1);
}

// A full disk, made in a child process with a file-size limit of 4 KiB (the limit holds for root
// too, where a read-only folder would not): the first file fits, the second does not. Committed
// one by one, the first would be left in place alone.
// Run in the child: 0 when the commit failed on `large` as a full disk would.
int commit_under_a_4_kib_limit(const std::string& small, const std::string& large) {
  std::signal(SIGXFSZ, SIG_IGN);  // a write past the limit fails with EFBIG instead
  const rlimit four_kib{4096, 4096};
  if (::setrlimit(RLIMIT_FSIZE, &four_kib) != 0) return 3;
  OutputSet files;
  files.add(small, std::string(100, 's'));
  files.add(large, std::string(64 * 1024, 'l'));
  try {
    files.commit();
  } catch (const std::runtime_error& e) {
    return std::string(e.what()) == large + ": write failed (disk full?)" ? 0 : 4;
  }
  return 5;
}  // the set's temporary files go here, as they would when the exception leaves main

TEST(OutputSet, FileThatCannotBeWrittenWholeKeepsTheWholeSetOut) {
  const fs::path dir = fresh_dir("fragsim_set_full");
  std::ofstream(dir / "small.csv") << "old\n";
  const std::string small = (dir / "small.csv").string();
  const std::string large = (dir / "large.csv").string();
  EXPECT_EXIT(std::_Exit(commit_under_a_4_kib_limit(small, large)), ::testing::ExitedWithCode(0),
              "");
  EXPECT_EQ(read_all(dir / "small.csv"), "old\n");
  EXPECT_EQ(entries(dir), 1);  // no large.csv, no temporary file
}

}  // namespace
}  // namespace fragsim
