// libFuzzer target: trajectory files (-i) on arbitrary bytes.
// The first byte chooses what to do with the rest, which is written to a file:
//   bit 7 set:   grade the file against a fixed small scene (simple collisions: impulse records)
//   bit 7 clear: read every record with the layout in bits 0-1 (impulses, polynomials) for
//                1 + bits 2-3 particles, checking that the reader stays inside the file
// The reader must end cleanly or report a record that does not fit; it must never read past the
// end, allocate what the file cannot hold, or loop.
#include "fosssim/core/simulator.h"
#include "fosssim/io/grader.h"
#include "fosssim/io/scene_file.h"
#include "fosssim/io/trajectory.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <unistd.h>

namespace {

constexpr const char* kScene = R"(<scene>
  <duration time="0.05"/>
  <integrator type="symplectic-euler" dt="0.01"/>
  <particle m="1" px="0" py="0" vx="1" vy="0" fixed="0"/>
  <particle m="2" px="0.15" py="0" vx="-1" vy="0" fixed="0"/>
  <particle m="1" px="1" py="1" vx="0" vy="-5" fixed="0" radius="0.2"/>
  <edge i="0" j="1"/>
  <halfplane px="0" py="-1" nx="0" ny="1"/>
  <simplegravity fx="0" fy="-9.81"/>
  <collision type="simple" COR="0.5"/>
</scene>)";

[[noreturn]] void broken(const std::string& what) {
  std::fprintf(stderr, "fuzz_trajectory: invariant violated: %s\n", what.c_str());
  std::abort();
}

const std::string& scratchPath() {
  static const std::string path = [] {
    const char* dir = std::getenv("TMPDIR");
    return std::string(dir && *dir ? dir : "/tmp") + "/fosssim-fuzz-trajectory-" + std::to_string(getpid()) + ".bin";
  }();
  // The file is rewritten for every input; it goes when the process ends (fuzzer or test).
  static const bool cleanup = [] { return std::atexit([] { std::remove(path.c_str()); }) == 0; }();
  (void)cleanup;
  return path;
}

void writeFile(const std::uint8_t* data, std::size_t size) {
  std::FILE* f = std::fopen(scratchPath().c_str(), "wb");
  if (!f || (size > 0 && std::fwrite(data, 1, size, f) != size) || std::fclose(f) != 0)
    broken("cannot write " + scratchPath());
}

void readAll(int particles, fosssim::RecordLayout layout, std::size_t size) {
  std::unique_ptr<fosssim::TrajectoryReader> reader;
  if (fosssim::Status s = fosssim::TrajectoryReader::open(scratchPath(), particles, layout, reader); !s)
    broken("open: " + s.message());
  if (reader->fileSize() != size) broken("the reader's file size differs from the file's");
  // Every record holds at least the 2N positions and velocities, so this bounds the loop.
  const long maxRecords = static_cast<long>(size / (32u * static_cast<unsigned>(particles)));
  fosssim::TrajectoryRecord record;
  for (long k = 0;; ++k) {
    bool atEnd = false;
    const fosssim::Status s = reader->next(record, atEnd);
    if (!s) {
      if (s.message().rfind(scratchPath(), 0) != 0) broken("a reader error does not name the file");
      return;
    }
    if (atEnd) return;
    if (k >= maxRecords) broken("more records than the file can hold");
    if (record.x.size() != 2 * particles || record.v.size() != 2 * particles) broken("record size");
    if (!layout.impulses && !record.log.impulses.empty()) broken("impulses in a layout without them");
    if (!layout.polynomials && record.log.polynomials.size() != 0) broken("polynomials in a layout without them");
  }
}

struct Fixture {
  fosssim::SceneFile file;
  std::unique_ptr<fosssim::Simulator> simulator;
  Fixture() {
    if (fosssim::Status s = fosssim::parseScene(kScene, "fixed.xml", file); !s) broken(s.message());
    if (fosssim::Status s = fosssim::Simulator::create(file.scene, {}, simulator); !s) broken(s.message());
  }
};

void grade() {
  static Fixture fixture;
  std::ostringstream out;
  const fosssim::GradeReport report = fosssim::gradeTrajectory(fixture.file.scene, fixture.file.initial,
                                                               *fixture.simulator, scratchPath(), out);
  const std::string text = out.str();
  const bool passed = report.passed(fosssim::GradeTolerances{});
  const char* verdict = passed ? "Overall success: Passed.\n" : "Overall success: Failed.\n";
  if (text.size() < 25 || text.compare(text.size() - 25, 25, verdict) != 0) broken("the grade's last line");
  if (report.stepsGraded > fixture.file.scene.numSteps()) broken("more steps graded than the scene has");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t mode = data[0];
  writeFile(data + 1, size - 1);
  if (mode & 0x80) {
    grade();
  } else {
    fosssim::RecordLayout layout;
    layout.impulses = (mode & 1) != 0;
    layout.polynomials = (mode & 2) != 0;
    layout.midStep = layout.polynomials;
    readAll(1 + ((mode >> 2) & 3), layout, size - 1);
  }
  return 0;
}
