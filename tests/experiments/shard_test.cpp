// Slices of a plan and their merge (experiments/shard.hpp): --shard parsing, the slices' ranges,
// each refusal of merge_slices on hand-made slices. End to end (`fragsim sweep --shard` and
// `fragsim suite --shard` slices merged by `fragsim merge`): tests/cli/merge_command_test.cpp.

#include "experiments/shard.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace fragsim {
namespace {

TEST(Shard, KCountsFromZeroAndMustBeBelowN) {
  const Shard s = parse_shard("3/4");
  EXPECT_EQ(s.index, 3u);
  EXPECT_EQ(s.count, 4u);
  EXPECT_EQ(parse_shard("0/1").count, 1u);
  for (const char* bad : {"4/4", "1/0", "0/0", "-1/4", "1", "", "a/4", "1/b", "1/4/2", " 1/4",
                          "1/4 ", "+1/4", "0/1000001", "99999999999999999999/4"}) {
    EXPECT_THROW(parse_shard(bad), ShardError) << bad;
  }
  try {
    parse_shard("4/4");
    FAIL();
  } catch (const ShardError& e) {
    EXPECT_NE(std::string(e.what()).find("0/4 .. 3/4"), std::string::npos) << e.what();
  }
}

TEST(Shard, SlicesAreContiguousCoverEveryJobOnceAndDifferByAtMostOne) {
  // 10 jobs in 4: floor(10 k / 4) = 0, 2, 5, 7, 10.
  const std::size_t expected[] = {0, 2, 5, 7, 10};
  for (std::size_t k = 0; k < 4; ++k) {
    const JobRange r = shard_range(10, {k, 4});
    EXPECT_EQ(r.begin, expected[k]);
    EXPECT_EQ(r.end, expected[k + 1]);
  }
  for (std::size_t m = 0; m <= 20; ++m) {
    for (std::size_t n = 1; n <= 25; ++n) {
      std::size_t next = 0;
      for (std::size_t k = 0; k < n; ++k) {
        const JobRange r = shard_range(m, {k, n});
        ASSERT_EQ(r.begin, next) << m << " jobs, slice " << k << "/" << n;
        ASSERT_LE(r.end - r.begin, m / n + 1);
        ASSERT_GE(r.end - r.begin, m / n);
        next = r.end;
      }
      ASSERT_EQ(next, m) << m << " jobs in " << n;
    }
  }
  // More slices than jobs: 3 jobs in 5 slices, two of them empty.
  EXPECT_EQ(shard_range(3, {0, 5}).end, 0u);
  EXPECT_EQ(shard_range(3, {4, 5}).begin, 2u);
}

TEST(Shard, IsFnv1a64AndPartsAreLengthPrefixed) {
  // FNV-1a 64 of "" is its offset basis; of "a", the published 0xaf63dc4c8601ec8c.
  EXPECT_EQ(plan_fingerprint(""), "cbf29ce484222325");
  EXPECT_EQ(plan_fingerprint("a"), "af63dc4c8601ec8c");
  EXPECT_NE(PlanText().add("ab").add("c").text(), PlanText().add("a").add("bc").text());
}

// A slice of a made-up plan of `total` jobs with one row per job: rows "j,<job>".
SliceFile slice(const std::string& name, std::size_t k, std::size_t n, std::size_t total,
                const std::string& plan = "0123456789abcdef") {
  std::string csv = "job,value\n";
  const JobRange r = shard_range(total, {k, n});
  for (std::size_t j = r.begin; j < r.end; ++j) csv += std::to_string(j) + ",x\n";
  return {name, slice_line("sweep", {k, n}, plan, total, csv) + csv};
}

std::string merge_error(const std::vector<SliceFile>& files) {
  try {
    merge_slices(files);
  } catch (const ShardError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "merged";
  return "";
}

TEST(Shard, JoinsInSliceOrderWhateverTheFileOrder) {
  const std::string merged =
      merge_slices({slice("c", 2, 3, 5), slice("a", 0, 3, 5), slice("b", 1, 3, 5)});
  EXPECT_EQ(merged, "job,value\n0,x\n1,x\n2,x\n3,x\n4,x\n");
  // Six slices of five jobs: slice 0 is empty and still counts.
  std::vector<SliceFile> six;
  for (std::size_t k = 0; k < 6; ++k) six.push_back(slice(std::to_string(k), k, 6, 5));
  EXPECT_EQ(merge_slices(six), merged);
  EXPECT_NE(six[0].bytes.find("jobs=0-0/5 rows=0\n"), std::string::npos) << six[0].bytes;
}

TEST(Shard, EachRefusalIsOneLineNamingTheFile) {
  EXPECT_NE(merge_error({slice("a", 0, 2, 4), slice("b", 1, 2, 4, "fedcba9876543210")})
                .find("b: a slice of another plan"),
            std::string::npos);
  EXPECT_NE(merge_error({slice("a", 0, 2, 4), slice("b", 1, 3, 4)}).find("b: slice 1/3"),
            std::string::npos);
  EXPECT_NE(merge_error({slice("a", 0, 2, 4), slice("b", 0, 2, 4)})
                .find("b: slice 0/2 is given twice (also a)"),
            std::string::npos);
  EXPECT_NE(merge_error({slice("a", 1, 4, 8), slice("b", 3, 4, 8)})
                .find("missing slices 0/4, 2/4 (2 of 4 given)"),
            std::string::npos);
  EXPECT_NE(merge_error({slice("a", 0, 2, 4)}).find("missing slice 1/2"), std::string::npos);

  SliceFile plain{"p.csv", "job,value\n0,x\n"};
  EXPECT_NE(merge_error({plain}).find("p.csv:1: not a slice"), std::string::npos);
  SliceFile cut = slice("cut", 0, 1, 3);
  cut.bytes.resize(cut.bytes.size() - 4);  // "2,x\n" gone: 2 rows where the line says 3
  EXPECT_NE(merge_error({cut}).find("cut: 2 rows, its slice line says 3"), std::string::npos);
  SliceFile unterminated = slice("u", 0, 1, 3);
  unterminated.bytes.pop_back();
  EXPECT_NE(merge_error({unterminated}).find("u: the last row has no line end"), std::string::npos);
  SliceFile other_columns = slice("h", 1, 2, 4);
  other_columns.bytes.replace(other_columns.bytes.find("job,value"), 9, "job,other");
  EXPECT_NE(merge_error({slice("a", 0, 2, 4), other_columns}).find("h:2: the CSV header differs"),
            std::string::npos);
  SliceFile wrong_range = slice("r", 0, 2, 4);
  wrong_range.bytes.replace(wrong_range.bytes.find("jobs=0-2"), 8, "jobs=0-3");
  EXPECT_NE(merge_error({wrong_range}).find("r:1: jobs=0-3/4 is not slice 0/2"), std::string::npos);
  SliceFile suite = slice("s", 1, 2, 4);
  suite.bytes.replace(suite.bytes.find("command=sweep"), 13, "command=suite");
  EXPECT_NE(merge_error({slice("a", 0, 2, 4), suite}).find("s: a suite slice; a is a sweep"),
            std::string::npos);
  EXPECT_NE(merge_error({}).find("no slice files"), std::string::npos);
}

// A slice saved with Windows line ends said "rows='4\r' is not a whole number": it is the same
// slice. A NUL in its slice line is shown, not an end to the message.
TEST(Shard, WindowsLineEndsAreTheSameSliceAndControlCharactersAreShown) {
  const auto crlf = [](SliceFile f) {
    std::string out;
    for (char c : f.bytes) out += c == '\n' ? std::string("\r\n") : std::string(1, c);
    f.bytes = out;
    return f;
  };
  const std::string merged = merge_slices({slice("a", 0, 2, 4), slice("b", 1, 2, 4)});
  EXPECT_EQ(merge_slices({crlf(slice("a", 0, 2, 4)), crlf(slice("b", 1, 2, 4))}), merged);
  SliceFile bad = slice("a", 0, 1, 2);
  bad.bytes.replace(bad.bytes.find("rows=2"), 6, std::string("rows=2\0", 7));
  EXPECT_EQ(merge_error({bad}), "a:1: rows='2\\x00' is not a whole number");
}

}  // namespace
}  // namespace fragsim
