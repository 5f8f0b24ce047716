// FOSSSim --stats FILE: the per-step diagnostics CSV, checked against the physics of a scene whose
// answer is known (an elastic head-on collision of equal balls, no forces: momentum and energy
// kept, one contact) and against the documented layout (a header, a row per state).
#include "run_fosssim.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace fosssim::testing {
namespace {

struct Csv {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  double at(size_t row, const std::string& column) const {
    for (size_t c = 0; c < columns.size(); ++c)
      if (columns[c] == column) return rows[row][c];
    ADD_FAILURE() << "no column " << column;
    return 0;
  }
};

Csv readCsv(const std::string& text) {
  Csv csv;
  std::istringstream in(text);
  std::string line, cell;
  std::getline(in, line);
  std::istringstream header(line);
  while (std::getline(header, cell, ',')) csv.columns.push_back(cell);
  while (std::getline(in, line)) {
    std::istringstream row(line);
    csv.rows.emplace_back();
    while (std::getline(row, cell, ',')) csv.rows.back().push_back(std::strtod(cell.c_str(), nullptr));
  }
  return csv;
}

std::string scratch(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("fosssim-stats-" + std::to_string(getpid()) + "-" + name)).string();
}

const std::string kScene = FOSSSIM_SOURCE_DIR "/assets/t2m2/ContinuousTimeTests/head_on_swap.xml";

TEST(Stats, HeadOnCollisionKeepsMomentumAndEnergyAndCountsOneContact) {
  const std::string path = scratch("swap.csv");
  const Outcome o = runFosssim({"-s", kScene, "-d", "0", "-q", "--stats", path});
  ASSERT_TRUE(o.exited && o.code == 0) << o;
  const Csv csv = readCsv(slurp(path));
  std::remove(path.c_str());
  ASSERT_FALSE(csv.columns.empty());
  EXPECT_EQ(csv.columns.front(), "step");
  ASSERT_EQ(csv.rows.size(), 26u);  // the initial state and ceil(0.25 / 0.01) = 25 steps
  double contacts = 0;
  for (size_t r = 0; r < csv.rows.size(); ++r) {
    ASSERT_EQ(csv.rows[r].size(), csv.columns.size()) << "row " << r;
    EXPECT_EQ(csv.at(r, "step"), static_cast<double>(r));
    EXPECT_NEAR(csv.at(r, "time"), 0.01 * r, 1e-12);
    // Equal masses 1, velocities (9, 12) and (-5.4, -7.2): p = (3.6, 4.8), E = 1/2 (225 + 81) = 153.
    EXPECT_NEAR(csv.at(r, "momentum_x"), 3.6, 1e-12) << "row " << r;
    EXPECT_NEAR(csv.at(r, "momentum_y"), 4.8, 1e-12) << "row " << r;
    EXPECT_NEAR(csv.at(r, "kinetic"), 153.0, 1e-9) << "row " << r;
    EXPECT_EQ(csv.at(r, "energy"), csv.at(r, "kinetic") + csv.at(r, "potential"));
    contacts += csv.at(r, "contacts");
    if (r > 0) {
      EXPECT_GT(csv.at(r, "cost_total"), 0.0);
    }
    EXPECT_EQ(csv.at(r, "failsafe_zones"), 0.0);
    EXPECT_EQ(csv.at(r, "newton_iterations"), 0.0);  // explicit Euler solves nothing
  }
  EXPECT_EQ(contacts, 1.0);
}

// The example spring stays on the x axis with its free end right of the anchor, where the spring
// force -k (x - l0) is affine: Newton's first update solves implicit Euler's equation exactly and
// the second is round-off, so every step takes exactly 2 iterations; linearized implicit Euler is
// one Newton step by definition. Row 0 (the initial state) took none.
TEST(Stats, NewtonIterationsOfTheImplicitIntegrators) {
  for (const auto& [example, expected] : {std::pair{"spring_implicit", 2.0}, {"spring_linearized_implicit", 1.0}}) {
    const std::string path = scratch(std::string(example) + ".csv");
    const Outcome o = runFosssim({"-s", std::string(FOSSSIM_SOURCE_DIR "/assets/examples/") + example + ".xml", "-d",
                                  "0", "-q", "--stats", path});
    ASSERT_TRUE(o.exited && o.code == 0) << o;
    const Csv csv = readCsv(slurp(path));
    std::remove(path.c_str());
    ASSERT_EQ(csv.rows.size(), 301u) << example;  // 3 s at dt = 0.01, and the initial state
    EXPECT_EQ(csv.at(0, "newton_iterations"), 0.0);
    for (size_t r = 1; r < csv.rows.size(); ++r)
      EXPECT_EQ(csv.at(r, "newton_iterations"), expected) << example << " row " << r;
  }
}

// A disk resting on the floor (COR 0: nothing bounces) is still from the first step, so it falls
// asleep at the end of step kStepsToSleep = 30 (src/core/collision/sleepers.h) and stays asleep;
// with --no-sleep, or --compat, nothing ever sleeps.
TEST(Stats, AsleepCountsTheRestingDiskFromItsThirtiethStep) {
  const std::string scene = scratch("rest.xml"), path = scratch("rest.csv");
  {
    std::ofstream out(scene);
    out << "<scene><duration time=\"1.0\"/><integrator type=\"symplectic-euler\" dt=\"0.01\"/>"
           "<collision type=\"hybrid\" COR=\"0\"/><simplegravity fx=\"0\" fy=\"-9.81\"/>"
           "<particle m=\"1\" px=\"0\" py=\"0.1\" vx=\"0\" vy=\"0\" fixed=\"0\" radius=\"0.1\"/>"
           "<halfplane px=\"0\" py=\"0\" nx=\"0\" ny=\"1\"/></scene>";
  }
  for (const char* mode : {"", "--no-sleep", "--compat"}) {
    std::vector<std::string> args = {"-s", scene, "-d", "0", "-q", "--stats", path};
    if (*mode) args.emplace_back(mode);
    const Outcome o = runFosssim(args);
    ASSERT_TRUE(o.exited && o.code == 0) << o;
    const Csv csv = readCsv(slurp(path));
    std::remove(path.c_str());
    ASSERT_EQ(csv.rows.size(), 101u) << mode;
    for (size_t r = 0; r < csv.rows.size(); ++r)
      EXPECT_EQ(csv.at(r, "asleep"), (*mode == 0 && r >= 30) ? 1.0 : 0.0) << mode << " row " << r;
  }
  std::remove(scene.c_str());
}

TEST(Stats, PotentialEnergyPerForceHasAColumnEach) {
  const std::string path = scratch("spring.csv");
  const Outcome o = runFosssim(
      {"-s", FOSSSIM_SOURCE_DIR "/assets/examples/spring_symplectic.xml", "-d", "0", "-q", "--stats", path});
  ASSERT_TRUE(o.exited && o.code == 0) << o;
  const Csv csv = readCsv(slurp(path));
  std::remove(path.c_str());
  std::vector<std::string> perForce;
  for (const auto& c : csv.columns)
    if (c.rfind("potential_", 0) == 0) perForce.push_back(c);
  ASSERT_FALSE(perForce.empty());
  EXPECT_EQ(perForce.front(), "potential_0_springforce");
  for (size_t r = 0; r < csv.rows.size(); ++r) {
    double sum = 0;
    for (const auto& c : perForce) sum += csv.at(r, c);
    EXPECT_NEAR(sum, csv.at(r, "potential"), 1e-12 * (1 + std::abs(sum)));
  }
}

TEST(Stats, GradingWritesNoStatsAndBadPathsAreNamed) {
  const Outcome graded = runFosssim({"-s", kScene, "-i", scratch("x.bin"), "--stats", scratch("x.csv")});
  EXPECT_TRUE(graded.exited && graded.code == 2) << graded;
  EXPECT_NE(graded.err.find("--stats"), std::string::npos) << graded;
  const std::string bad = scratch("no-such-folder") + "/s.csv";
  const Outcome o = runFosssim({"-s", kScene, "-d", "0", "-q", "--stats", bad});
  EXPECT_TRUE(o.exited && o.code == 1) << o;
  EXPECT_NE(o.err.find(bad + ": cannot create the --stats file"), std::string::npos) << o;
}

}  // namespace
}  // namespace fosssim::testing
