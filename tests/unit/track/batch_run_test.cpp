// The pieces of core/track/batch_run that need no model: shard parsing and selection (every item
// in exactly one shard), the summary table written and read back (cells with commas, quotes and
// line breaks), the output names, and the merge's checks of the shard summaries.
#include "core/track/batch_run.hpp"

#include <gtest/gtest.h>

#include <set>

#include "core/common/atomic_file.hpp"
#include "core/common/csv_cell.hpp"
#include "core/common/error.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

TEST(BatchRun, ShardsParseAndCoverEveryItemOnce) {
  ASSERT_TRUE(parseBatchShard("2/3"));
  EXPECT_EQ(parseBatchShard("2/3")->index, 2);
  EXPECT_EQ(parseBatchShard("2/3")->count, 3);
  for (const char* bad : {"0/3", "4/3", "1/0", "x/2", "1/2/3", "", "1", "-1/2", "1 /2"}) {
    EXPECT_FALSE(parseBatchShard(bad)) << bad;
  }
  for (const std::size_t total : {0U, 1U, 7U, 100U}) {
    for (int count = 1; count <= 9; ++count) {
      std::multiset<std::size_t> seen;
      for (int index = 1; index <= count; ++index) {
        for (const std::size_t k : shardItems(total, BatchShard{index, count})) {
          EXPECT_EQ(static_cast<int>(k % static_cast<std::size_t>(count)), index - 1);
          seen.insert(k);
        }
      }
      ASSERT_EQ(seen.size(), total);
      for (std::size_t k = 0; k < total; ++k) EXPECT_EQ(seen.count(k), 1U);
    }
  }
}

TEST(BatchRun, SummaryRoundTripsAwkwardCells) {
  std::vector<BatchRow> rows(4);
  rows[0] = {"a, b.png", ImageFitStatus::Ok, 1, 0, 0.25, ""};
  rows[1] = {"say \"hi\".mp4", ImageFitStatus::Error, 0, 0, 1.5, "x: broken,\nreally"};
  rows[2] = {"c.jpg", ImageFitStatus::NoFace, 1, 1, std::nan(""), "c.jpg: no face found"};
  rows[3] = {"d.jpg", ImageFitStatus::Rejected, 1, 1, 0.5, "d.jpg: the check rejects the fit"};
  const std::string text = formatBatchSummary(rows);
  EXPECT_EQ(text.substr(0, text.find('\n')), "item,status,frames,failures,time,error");
  const auto back = parseBatchSummary(text, "t.csv");
  ASSERT_EQ(back.size(), 4U);
  EXPECT_EQ(back[0].item, "a, b.png");
  EXPECT_EQ(back[1].item, "say \"hi\".mp4");
  EXPECT_EQ(back[1].error, "x: broken, really");  // one line per row
  EXPECT_EQ(back[1].status, ImageFitStatus::Error);
  EXPECT_DOUBLE_EQ(back[1].seconds, 1.5);
  EXPECT_TRUE(std::isnan(back[2].seconds));
  EXPECT_EQ(back[2].failures, 1);
  EXPECT_EQ(back[3].status, ImageFitStatus::Rejected);
  EXPECT_THROW(parseBatchSummary("a,b\n", "t.csv"), InputError);
  EXPECT_THROW(parseBatchSummary(text + "d.png,maybe,1,0,1.0,\n", "t.csv"), InputError);
  EXPECT_THROW(parseBatchSummary(text + "\"open,ok,1,0,1.0,\n", "t.csv"), InputError);
  EXPECT_FALSE(parseCsvLine("\"a\"b,c"));
  EXPECT_EQ(*parseCsvLine(",,"), (std::vector<std::string>{"", "", ""}));
}

TEST(BatchRun, OutputNamesAndSummaryNames) {
  EXPECT_EQ(batchOutputPath("out", "in/a.JPG"), fs::path("out/a.pts"));
  EXPECT_EQ(batchOutputPath("out", "in/v.MP4"), fs::path("out/v.csv"));
  EXPECT_EQ(batchSummaryPath("out", BatchShard{}), fs::path("out/summary.csv"));
  EXPECT_EQ(batchSummaryPath("out", BatchShard{2, 5}), fs::path("out/summary-2-of-5.csv"));
}

TEST(BatchRun, MergeRestoresJobOrderAndNamesWhatIsWrong) {
  test::TempDir dir;
  EXPECT_THROW(mergeBatchShards(dir.path()), InputError);  // nothing to merge
  std::vector<BatchRow> items(5);
  for (int k = 0; k < 5; ++k) {
    items[static_cast<std::size_t>(k)] = {
        "item" + std::to_string(k), ImageFitStatus::Ok, 1, 0, 0.1, ""};
  }
  items[3].status = ImageFitStatus::Error;
  for (int index = 1; index <= 2; ++index) {
    std::vector<BatchRow> shard;
    for (const std::size_t k : shardItems(5, BatchShard{index, 2})) shard.push_back(items[k]);
    writeTextAtomically(batchSummaryPath(dir.path(), BatchShard{index, 2}),
                        formatBatchSummary(shard));
  }
  const BatchMergeSummary merged = mergeBatchShards(dir.path());
  ASSERT_EQ(merged.rows.size(), 5U);
  for (int k = 0; k < 5; ++k)
    EXPECT_EQ(merged.rows[static_cast<std::size_t>(k)].item,
              items[static_cast<std::size_t>(k)].item);
  EXPECT_EQ(merged.ok, 4);
  EXPECT_EQ(merged.errors, 1);
  EXPECT_TRUE(fs::exists(dir / "summary.csv"));

  // A shard holding fewer rows than its share.
  writeTextAtomically(batchSummaryPath(dir.path(), BatchShard{2, 2}), formatBatchSummary({}));
  EXPECT_THROW(mergeBatchShards(dir.path()), InputError);
  // Summaries of two different splits.
  writeTextAtomically(batchSummaryPath(dir.path(), BatchShard{1, 3}), formatBatchSummary({}));
  try {
    mergeBatchShards(dir.path());
    ADD_FAILURE() << "merged summaries of 2 and 3 shards";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("shard summaries of"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace clm3d
