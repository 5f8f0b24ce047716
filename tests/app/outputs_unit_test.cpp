// The output observers with their clock and their disk replaced: the progress line's time-based
// reports (stderr not a terminal), the size estimate's warnings and the stop before the disk is
// full, without waiting minutes or writing large files.
#include "disk_budget.h"
#include "outputs.h"

#include "fosssim/core/simulator.h"
#include "fosssim/io/trajectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fosssim::app {
namespace {

using Clock = ProgressOutput::Clock;

SceneFile parsed(const std::string& text) {
  SceneFile file;
  const Status s = parseScene(text, "test.xml", file);
  EXPECT_TRUE(s.isOk()) << s.message();
  return file;
}

/// A scene of `steps` steps of one free particle.
std::string freeParticle(long steps) {
  return "<scene><duration time=\"" + std::to_string(steps) + "\"/><integrator type=\"explicit-euler\" dt=\"1\"/>"
         "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"1\" vy=\"0\" fixed=\"0\"/></scene>";
}

/// Runs a ProgressOutput over `steps` steps whose clock advances `secondsPerStep` per step;
/// returns the step numbers of the lines printed (and checks each line's form).
std::vector<long> progressLines(long steps, double secondsPerStep) {
  const SceneFile file = parsed(freeParticle(steps));
  char* text = nullptr;
  std::size_t size = 0;
  std::FILE* out = open_memstream(&text, &size);
  Clock::time_point now{};
  const auto tick = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(secondsPerStep));
  ProgressOutput progress(out, false, [&] { return now; });
  State state = file.initial;
  EXPECT_TRUE(progress.start(file, state, RecordLayout{}).isOk());
  for (long k = 1; k <= steps; ++k) {
    now += tick;
    state.step = k;
    state.time = static_cast<double>(k);
    EXPECT_TRUE(progress.afterStep(file, state, CollisionLog{}).isOk());
  }
  EXPECT_TRUE(progress.finish().isOk());
  std::fclose(out);
  std::vector<long> printed;
  std::istringstream lines(std::string(text, size));
  std::free(text);
  for (std::string line; std::getline(lines, line);) {
    long step = 0, total = 0;
    if (std::sscanf(line.c_str(), "step %ld/%ld", &step, &total) == 2) {
      EXPECT_EQ(total, steps) << line;
      printed.push_back(step);
    } else {
      EXPECT_EQ(line.rfind("done: " + std::to_string(steps) + " steps", 0), 0u) << line;
    }
  }
  return printed;
}

TEST(ProgressOutput, FastRunsReportEveryTenthOfTheSteps) {
  // No time passes: the first step, then every 10% (the 100% line is the last step's).
  const std::vector<long> expected = {1, 100, 200, 300, 400, 500, 600, 700, 800, 900, 1000};
  EXPECT_EQ(progressLines(1000, 0.0), expected);
}

TEST(ProgressOutput, SlowRunsReportAtLeastEveryTenSeconds) {
  // 1000 steps of 3 s each: a line at the first step that ends 10 s or more after the last line
  // (a line can only follow a step): so the step before each line ended less than 10 s after
  // the line before. Not a line per step either.
  const std::vector<long> printed = progressLines(1000, 3.0);
  ASSERT_FALSE(printed.empty());
  EXPECT_EQ(printed.front(), 1);
  EXPECT_EQ(printed.back(), 1000);
  for (std::size_t k = 1; k < printed.size(); ++k) {
    EXPECT_GT(printed[k], printed[k - 1]);
    EXPECT_LT((printed[k] - 1 - printed[k - 1]) * 3.0, ProgressOutput::kInterval.count())
        << "after step " << printed[k - 1];
  }
  EXPECT_LT(printed.size(), 1000u / 3);
}

/// A disk of `capacity` bytes that fills as the budget's writes are counted into `used`.
struct FakeDisk {
  std::uint64_t capacity, used = 0;
  int queries = 0;
  FreeSpaceQuery query() {
    return [this](const std::string&, std::uint64_t& bytes) {
      ++queries;
      bytes = capacity > used ? capacity - used : 0;
      return true;
    };
  }
};

constexpr std::uint64_t kMiB = 1ull << 20;

TEST(DiskBudget, WarnsOnceWhenTheEstimateIsLarge) {
  FakeDisk disk{1ull << 50};  // room enough: only the size warning
  DiskBudget budget("t.bin", "t.bin", 1000, "use --compact", disk.query());
  std::uint64_t written = 1000;  // record 0
  ASSERT_TRUE(budget.reserve(written, 0).isOk());
  std::vector<std::string> warnings;
  for (long step = 1; step <= 5; ++step) {
    ASSERT_TRUE(budget.reserve(2 * kMiB, step).isOk());
    written += 2 * kMiB;
    const std::string w = budget.estimate(step, written, 1000);
    if (!w.empty()) warnings.push_back(w);
  }
  // 2 MiB a step for 1000 steps: about 2000 MiB = 2.0 GiB, said after the first step.
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(
      warnings[0].find("t.bin: at this rate the trajectory will take about 2.0 GiB (2.0 MiB per step, 1000 steps)"),
      std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[0].find("use --compact"), std::string::npos) << warnings[0];

  // Below the limit: nothing.
  DiskBudget small("s.bin", "s.bin", 100, "", disk.query());
  ASSERT_TRUE(small.reserve(2 * kMiB, 1).isOk());
  EXPECT_EQ(small.estimate(1, 2 * kMiB, 0), "");
}

TEST(DiskBudget, StopsBeforeTheRecordThatWouldLeaveLessThanTheMargin) {
  // 100 MiB free, 10 MiB a step, 1000 steps: the estimate exceeds the free space at once, and
  // the writes stop while at least the margin (16 MiB) is left: after 8 steps (84 MiB).
  FakeDisk disk{100 * kMiB};
  DiskBudget budget("t.bin", "t.bin", 1000, "", disk.query());
  long stoppedAt = -1;
  std::string fullWarning, error;
  for (long step = 1; step <= 1000; ++step) {
    const Status s = budget.reserve(10 * kMiB, step);
    if (!s) {
      stoppedAt = step;
      error = s.message();
      break;
    }
    disk.used += 10 * kMiB;  // the write happens
    const std::string w = budget.estimate(step, disk.used, 0);
    if (step == 1) fullWarning = w;
    else EXPECT_EQ(w, "") << "warned twice, at step " << step;
  }
  EXPECT_EQ(stoppedAt, 9);
  EXPECT_GE(disk.capacity - disk.used, DiskBudget::kFreeMargin);
  EXPECT_LT(disk.capacity - disk.used, DiskBudget::kFreeMargin + 10 * kMiB);
  EXPECT_NE(fullWarning.find("but only 90 MiB are free on its disk: the run will stop before the disk is full"),
            std::string::npos)
      << fullWarning;
  EXPECT_NE(error.find("t.bin: stopped before writing the records of step 9 (10 MiB): they would leave less than "
                       "16 MiB free on its disk (20 MiB free)"),
            std::string::npos)
      << error;
  // Not a query per write while there is plenty of room: about one per halving of the headroom.
  EXPECT_LT(disk.queries, 9);
}

TEST(DiskBudget, AnUnknownFreeSpaceStopsNothing) {
  DiskBudget budget("t.bin", "t.bin", 10, "", [](const std::string&, std::uint64_t&) { return false; });
  for (long step = 0; step < 10; ++step) EXPECT_TRUE(budget.reserve(1ull << 40, step).isOk());
}

/// A temporary folder of this test, removed at the end.
struct TempDir {
  std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("fosssim-outputs-unit-" + std::to_string(getpid()));
  TempDir() { std::filesystem::create_directories(path); }
  ~TempDir() { std::filesystem::remove_all(path); }
};

// The whole -o path with a disk that holds little: the run's records stop at the step that would
// not fit, and the file (under its partial name) holds whole records up to the step before.
TEST(TrajectoryOutput, StopsWithWholeRecordsBeforeTheDiskIsFull) {
  TempDir dir;
  const std::string path = (dir.path / "t.bin").string();
  // Two particles approaching: continuous-time records with impulses and polynomials.
  const SceneFile file = parsed(
      "<scene><duration time=\"100\"/><integrator type=\"explicit-euler\" dt=\"0.01\"/><collision "
      "type=\"continuous-time\"/>"
      "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"1\" vy=\"0\" fixed=\"0\"/>"
      "<particle m=\"1\" px=\"3\" py=\"0\" vx=\"-1\" vy=\"0\" fixed=\"0\"/></scene>");
  SimulatorOptions options;
  options.logPolynomials = true;

  // Free space: the margin plus `room`, less what the file holds.
  std::uint64_t room = 0;
  const auto query = [&](const std::string& name) -> FreeSpaceQuery {
    const std::string expected = (dir.path / (name + ".partial.bin")).string();
    return [&, expected](const std::string& p, std::uint64_t& bytes) {
      EXPECT_EQ(p, expected);
      const std::uint64_t used = std::filesystem::exists(p) ? std::filesystem::file_size(p) : 0;
      bytes = DiskBudget::kFreeMargin + room - std::min(room, used);
      return true;
    };
  };
  // A first run measures record 0 and a step's two records (x, v, impulses, one polynomial each,
  // the same for every step until the particles meet at t = 1.5).
  room = 1 << 20;
  std::unique_ptr<Simulator> simulator;
  ASSERT_TRUE(Simulator::create(file.scene, options, simulator).isOk());
  std::uint64_t record0 = 0, stepBytes = 0;
  {
    TrajectoryOutput measure((dir.path / "m.bin").string(), false, query("m"));
    State state = file.initial;
    ASSERT_TRUE(measure.start(file, state, simulator->layout()).isOk());
    record0 = std::filesystem::file_size(dir.path / "m.partial.bin");
    ASSERT_TRUE(simulator->step(file.scene, state, &measure).isOk());
    ASSERT_TRUE(measure.afterStep(file, state, simulator->log()).isOk());
    stepBytes = std::filesystem::file_size(dir.path / "m.partial.bin") - record0;
    measure.ending(RunEnd::Completed);
    ASSERT_TRUE(measure.finish().isOk());
  }
  ASSERT_GT(stepBytes, 2 * 4 * sizeof(double));

  // The run: room for record 0 and 5 steps.
  room = record0 + 5 * stepBytes;
  ASSERT_TRUE(Simulator::create(file.scene, options, simulator).isOk());
  TrajectoryOutput output(path, false, query("t"));
  State state = file.initial;
  ASSERT_TRUE(output.start(file, state, simulator->layout()).isOk());
  Status status = Status::ok();
  while (status && state.step < 100) {
    status = simulator->step(file.scene, state, &output);
    ASSERT_TRUE(status.isOk()) << status.message();
    status = output.afterStep(file, state, simulator->log());
  }
  ASSERT_FALSE(status.isOk()) << "the run did not stop";
  EXPECT_EQ(state.step, 6) << status.message();  // the 6th step's records did not fit
  EXPECT_NE(status.message().find("stopped before writing the records of step 6"), std::string::npos)
      << status.message();
  output.ending(RunEnd::Failed);
  ASSERT_TRUE(output.finish().isOk());
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_EQ(std::filesystem::file_size(dir.path / "t.partial.bin"), record0 + 5 * stepBytes);
  EXPECT_NE(output.written().find("up to step 5 (11 whole records"), std::string::npos) << output.written();

  // The file reads as whole records.
  std::unique_ptr<TrajectoryReader> reader;
  ASSERT_TRUE(TrajectoryReader::open((dir.path / "t.partial.bin").string(), 2, simulator->layout(), reader).isOk());
  TrajectoryRecord record;
  bool atEnd = false;
  long records = 0;
  for (; records < 100; ++records) {
    const Status s = reader->next(record, atEnd);
    ASSERT_TRUE(s.isOk()) << s.message();
    if (atEnd) break;
  }
  EXPECT_EQ(records, 11);
}

}  // namespace
}  // namespace fosssim::app
