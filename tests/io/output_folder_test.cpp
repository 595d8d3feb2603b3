// The folder of an output: made with its parents, refused when it holds files (unless forced),
// and gone again, parents included, when the output fails before keep(); a folder that was
// already there is left as it was.

#include "io/output_folder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "support/test_files.hpp"

namespace fragsim {
namespace {

namespace fs = std::filesystem;
using fragsim::test::fresh_dir;
using fragsim::test::write_text;

TEST(OutputFolder, IsMadeWithItsParentsOrMustBeAnEmptyFolder) {
  const fs::path base = fresh_dir("fragsim_out_made");
  const std::string nested = (base / "a" / "b").string();
  {
    OutputFolder folder(nested, false);
    EXPECT_TRUE(fs::is_directory(nested));
    folder.keep();
  }
  EXPECT_TRUE(fs::is_directory(nested));
  EXPECT_NO_THROW(OutputFolder(nested, false));  // empty: nothing to overwrite
  write_text(fs::path(nested) / "old.csv", "x");
  try {
    OutputFolder refused(nested, false);
    FAIL() << "took the non-empty folder " << nested;
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              nested + ": folder exists and is not empty (use --force to overwrite)");
  }
  EXPECT_NO_THROW(OutputFolder(nested, true));
  const std::string file = (base / "file").string();
  write_text(file, "x");
  try {
    OutputFolder not_a_folder(file, true);
    FAIL() << "took the file " << file << " for a folder";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), file + ": exists and is not a folder");
  }
}

TEST(OutputFolder, FailedOutputRemovesTheFoldersItMadeAndNoOther) {
  const fs::path base = fresh_dir("fragsim_out_failed");
  {
    OutputFolder folder((base / "a" / "b" / "c").string(), false);
    EXPECT_TRUE(fs::is_directory(base / "a" / "b" / "c"));
  }                                      // no keep(): the output failed
  EXPECT_FALSE(fs::exists(base / "a"));  // all three levels were made here, all three go
  EXPECT_TRUE(fs::is_directory(base));   // it was there before

  fs::create_directories(base / "kept");
  { OutputFolder folder((base / "kept" / "new").string(), false); }
  EXPECT_FALSE(fs::exists(base / "kept" / "new"));
  EXPECT_TRUE(fs::is_directory(base / "kept"));

  { OutputFolder existing((base / "kept").string(), false); }
  EXPECT_TRUE(fs::is_directory(base / "kept"));  // found, not made: left alone
}

TEST(OutputFolder, FolderHoldingSomethingNotOursStays) {
  const fs::path base = fresh_dir("fragsim_out_foreign");
  {
    OutputFolder folder((base / "out").string(), false);
    write_text(base / "out" / "notes.txt", "someone else's");
  }
  EXPECT_TRUE(fs::exists(base / "out" / "notes.txt"));
}

TEST(OutputFolder, TrailingSeparatorNamesTheSameFolder) {
  const fs::path base = fresh_dir("fragsim_out_slash");
  {
    OutputFolder folder((base / "out").string() + "/", false);
    EXPECT_TRUE(fs::is_directory(base / "out"));
  }
  EXPECT_FALSE(fs::exists(base / "out"));
}

}  // namespace
}  // namespace fragsim
