// The checkpoint format (io/checkpoint_codec.hpp, io/checkpoint_file.hpp): values come back bit for bit, and a
// damaged, cut-off or foreign file is refused with its reason instead of being read.
#include "io/checkpoint_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include "io/output_folder.hpp"
#include "io/temp_folder.hpp"
#include "read_text.hpp"

namespace heliostand::checkpoint {
namespace {
namespace fs = std::filesystem;

std::uint64_t bits(double value) {
  std::uint64_t out;
  std::memcpy(&out, &value, sizeof out);
  return out;
}

struct Plain {
  double x;
  int n;
  bool flag;
};

TEST(CheckpointCodec, DoublesStringsAndVectorsComeBackBitForBit) {
  const std::vector<double> doubles = {0.1, -0.0, std::numeric_limits<double>::denorm_min(),
                                       std::numeric_limits<double>::quiet_NaN(), 1e308, 1.0 / 3.0};
  Writer out;
  out.raw_vector(doubles);
  out.text("todomatsu, ümlaut\n");
  out.raw(Plain{2.5, -7, true});
  out.bools({true, false, true});
  out.raw(std::uint64_t{0xfedcba9876543210ULL});

  Reader in(out.bytes());
  const auto back = in.raw_vector<double>("doubles");
  ASSERT_EQ(back.size(), doubles.size());
  for (std::size_t k = 0; k < doubles.size(); ++k) EXPECT_EQ(bits(back[k]), bits(doubles[k])) << k;
  EXPECT_EQ(in.text("text"), "todomatsu, ümlaut\n");
  const auto plain = in.raw<Plain>("plain");
  EXPECT_EQ(plain.x, 2.5);
  EXPECT_EQ(plain.n, -7);
  EXPECT_TRUE(plain.flag);
  EXPECT_EQ(in.bools("bools"), (std::vector<bool>{true, false, true}));
  EXPECT_EQ(in.raw<std::uint64_t>("u64"), 0xfedcba9876543210ULL);
  EXPECT_TRUE(in.at_end());
}

TEST(CheckpointCodec, ALengthBeyondTheBytesLeftIsAnErrorNotAnAllocation) {
  Writer out;
  out.size(std::numeric_limits<std::uint64_t>::max() / 8);  // a damaged length: billions of doubles
  Reader in(out.bytes());
  try {
    in.raw_vector<double>("shoots");
    FAIL() << "a length beyond the payload was accepted";
  } catch (const CheckpointError& e) {
    EXPECT_NE(std::string(e.what()).find("shoots"), std::string::npos) << e.what();
  }
  Reader short_read(std::string_view("abc"));
  EXPECT_THROW(short_read.raw<double>("height"), CheckpointError);
}

RunIdentity identity(const std::string& seed = "7") {
  RunIdentity id;
  id.add("heliostand version", "1.0");
  id.add("seed", seed);
  return id;
}

CheckpointFile sample() {
  Writer payload;
  for (int k = 0; k < 100; ++k) payload.raw(std::sin(k * 0.1));
  return {4, identity(), payload.bytes()};
}

std::string refusal(const fs::path& path, const RunIdentity& expected) {
  try {
    read_checkpoint(path, expected);
  } catch (const CheckpointError& e) {
    return e.what();
  }
  return "";
}

std::string bytes_of(const fs::path& path) { return testing::read_text(path); }

void overwrite(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

TEST(CheckpointFile, WritesAtomicallyAndReadsBackWhatWasWritten) {
  testing::TempFolder tmp("checkpoint_file");
  const fs::path path = write_checkpoint(tmp.path(), sample());
  EXPECT_EQ(path.filename(), "checkpoint_year_0004.hsck");
  EXPECT_FALSE(fs::exists(temporary_sibling(path)));
  const CheckpointFile back = read_checkpoint(path, identity());
  EXPECT_EQ(back.years_done, 4);
  EXPECT_EQ(back.payload, sample().payload);
  EXPECT_EQ(back.identity.entries, identity().entries);
}

TEST(CheckpointFile, EveryFlippedByteIsRefused) {
  testing::TempFolder tmp("checkpoint_flip");
  const fs::path path = write_checkpoint(tmp.path(), sample());
  const std::string good = bytes_of(path);
  for (std::size_t at = 0; at < good.size(); ++at) {
    std::string bad = good;
    bad[at] = static_cast<char>(bad[at] ^ 0x10);
    overwrite(path, bad);
    EXPECT_NE(refusal(path, identity()), "") << "flipped byte " << at << " was not noticed";
  }
  std::string bad = good;
  bad[good.size() / 2] ^= 1;  // inside the payload: only the checksum can tell
  overwrite(path, bad);
  EXPECT_NE(refusal(path, identity()).find("damaged"), std::string::npos) << refusal(path, identity());
}

TEST(CheckpointFile, EveryTruncationIsRefused) {
  testing::TempFolder tmp("checkpoint_truncate");
  const fs::path path = write_checkpoint(tmp.path(), sample());
  const std::string good = bytes_of(path);
  for (std::size_t length = 0; length < good.size(); ++length) {
    overwrite(path, good.substr(0, length));
    EXPECT_NE(refusal(path, identity()), "") << "cut to " << length << " bytes was accepted";
  }
  overwrite(path, good.substr(0, good.size() / 2));
  EXPECT_NE(refusal(path, identity()).find("truncated"), std::string::npos) << refusal(path, identity());
}

TEST(CheckpointFile, AnotherRunsCheckpointIsRefusedAsForeignNamingWhatDiffers) {
  testing::TempFolder tmp("checkpoint_foreign");
  const fs::path path = write_checkpoint(tmp.path(), sample());
  const std::string why = refusal(path, identity("8"));
  EXPECT_NE(why.find("foreign"), std::string::npos) << why;
  EXPECT_NE(why.find("seed is 7, this run's is 8"), std::string::npos) << why;
  overwrite(path, "not a checkpoint at all");
  EXPECT_NE(refusal(path, identity()).find("not a heliostand checkpoint"), std::string::npos);
}

TEST(CheckpointFile, ListsNewestFirstAndKeepsTheNewestTwo) {
  testing::TempFolder tmp("checkpoint_prune");
  for (int year : {2, 10, 4, 6}) {
    CheckpointFile file = sample();
    file.years_done = year;
    write_checkpoint(tmp.path(), file);
  }
  std::ofstream(tmp.path() / "checkpoint_notes.txt") << "not one";
  const auto all = checkpoints_in(tmp.path());
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all[0].filename(), "checkpoint_year_0010.hsck");
  EXPECT_EQ(all[3].filename(), "checkpoint_year_0002.hsck");
  prune_checkpoints(tmp.path(), 2);
  const auto kept = checkpoints_in(tmp.path());
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].filename(), "checkpoint_year_0010.hsck");
  EXPECT_EQ(kept[1].filename(), "checkpoint_year_0006.hsck");
}

}  // namespace
}  // namespace heliostand::checkpoint
