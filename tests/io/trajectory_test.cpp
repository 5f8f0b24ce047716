// Trajectory files: the writer's bytes and the reader's values against the format (spec
// section 6), round trips for every layout, and files that do not fit (truncated at every byte,
// trailing bytes, negative or absurd counts, unknown impulse kinds, unreadable paths), which the
// reader must report without reading past the end of the file.
#include "trajectory_file.h"

#include "fosssim/io/trajectory.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

namespace fosssim::testing {
namespace {

constexpr RecordLayout kPlain{false, false, false};
constexpr RecordLayout kImpulses{true, false, false};
constexpr RecordLayout kEverything{true, true, true};

State twoParticles(double t) {
  State s;
  s.x = (VecX(4) << 1 + t, -2, 0.5, 1e-300).finished();
  s.v = (VecX(4) << -0.0, 3, -t, std::numeric_limits<double>::denorm_min()).finished();
  return s;
}

CollisionLog someLog(bool polynomials) {
  CollisionLog log;
  log.impulses.push_back(Impulse{PairKind::ParticleEdge, 1, 0, Vec2(0.25, -0.5), 0.75});
  log.impulses.push_back(Impulse{PairKind::ParticleHalfPlane, 0, 3, Vec2(0, 1), 0});
  if (polynomials) {
    log.polynomials.setEnabled(true);
    const double p[] = {1, -2, 1}, q[] = {4};
    log.polynomials.add(p, 3);
    log.polynomials.add(q, 1);
    log.polynomials.add(p, 0);
  }
  return log;
}

void writeAll(const std::string& path, RecordLayout layout, const std::vector<State>& states,
              const std::vector<CollisionLog>& logs) {
  std::unique_ptr<TrajectoryWriter> writer;
  ASSERT_TRUE(TrajectoryWriter::open(path, layout, writer).isOk());
  for (size_t k = 0; k < states.size(); ++k) ASSERT_TRUE(writer->write(states[k], logs[k]).isOk());
  ASSERT_TRUE(writer->close().isOk());
}

/// Reads every record; the error message if one does not fit, else "".
std::string readAll(const std::string& path, int n, RecordLayout layout, std::vector<TrajectoryRecord>& out) {
  out.clear();
  std::unique_ptr<TrajectoryReader> reader;
  if (Status s = TrajectoryReader::open(path, n, layout, reader); !s) return s.message();
  for (;;) {
    TrajectoryRecord r;
    bool atEnd = false;
    if (Status s = reader->next(r, atEnd); !s) return s.message();
    if (atEnd) return "";
    out.push_back(std::move(r));
    if (out.size() > 100000) return "runaway";
  }
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(Trajectory, WriterBytesFollowTheFormat) {
  TempDir dir("trajectory");
  const State s = twoParticles(0);
  const CollisionLog log = someLog(true);
  writeAll(dir.file("a.bin"), kEverything, {s}, {log});
  Bytes expected;
  expected.f64s({1, -2, 0.5, 1e-300}).f64s({-0.0, 3, -0.0, std::numeric_limits<double>::denorm_min()});
  expected.i32(2).i32(1).i32(1).i32(0).f64(0.25).f64(-0.5).f64(0.75);
  expected.i32(2).i32(0).i32(3).f64(0).f64(1).f64(0);
  expected.i32(3).i32(3).f64s({1, -2, 1}).i32(1).f64(4).i32(0);
  EXPECT_EQ(readFile(dir.file("a.bin")), expected.data);
  // Without impulses and polynomials a record is positions and velocities only.
  writeAll(dir.file("b.bin"), kPlain, {s, s}, {log, log});
  EXPECT_EQ(readFile(dir.file("b.bin")).size(), 2u * 8 * 8);
}

TEST(Trajectory, ReaderReadsHandPackedRecords) {
  TempDir dir("trajectory");
  Bytes b;
  b.f64s({1, 2, 3, 4}).i32(1).i32(2).i32(0).i32(5).f64(-1).f64(0).f64(0.5);  // 1 particle, 1 impulse
  b.i32(1).i32(2).f64(7).f64(8);                                              // 1 polynomial of 2
  b.f64s({5, 6, 7, 8}).i32(0).i32(0);                                         // an empty record
  std::vector<TrajectoryRecord> records;
  ASSERT_EQ(readAll(dir.write("t.bin", b.data), 1, kEverything, records), "");
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].x, Vec2(1, 2));
  EXPECT_EQ(records[0].v, Vec2(3, 4));
  ASSERT_EQ(records[0].log.impulses.size(), 1u);
  const Impulse& im = records[0].log.impulses[0];
  EXPECT_EQ(im.kind, PairKind::ParticleHalfPlane);
  EXPECT_EQ(im.i, 0);
  EXPECT_EQ(im.j, 5);
  EXPECT_EQ(im.n, Vec2(-1, 0));
  EXPECT_EQ(im.tau, 0.5);
  ASSERT_EQ(records[0].log.polynomials.size(), 1);
  EXPECT_EQ(records[0].log.polynomials.length(0), 2);
  EXPECT_EQ(records[0].log.polynomials.coefficients(0)[1], 8.0);
  EXPECT_TRUE(records[1].log.impulses.empty());
  EXPECT_EQ(records[1].log.polynomials.size(), 0);
}

TEST(Trajectory, RoundTripForEveryLayout) {
  TempDir dir("trajectory");
  for (const RecordLayout layout : {kPlain, kImpulses, kEverything}) {
    std::vector<State> states;
    std::vector<CollisionLog> logs;
    for (int k = 0; k < 5; ++k) {
      states.push_back(twoParticles(0.1 * k));
      logs.push_back(k % 2 ? someLog(layout.polynomials) : CollisionLog{});
    }
    writeAll(dir.file("r.bin"), layout, states, logs);
    std::vector<TrajectoryRecord> records;
    ASSERT_EQ(readAll(dir.file("r.bin"), 2, layout, records), "");
    ASSERT_EQ(records.size(), states.size());
    for (size_t k = 0; k < states.size(); ++k) {
      for (int d = 0; d < 4; ++d) {
        EXPECT_TRUE(sameBits(records[k].x[d], states[k].x[d])) << k << " " << d;
        EXPECT_TRUE(sameBits(records[k].v[d], states[k].v[d])) << k << " " << d;
      }
      const CollisionLog& want = logs[k];
      ASSERT_EQ(records[k].log.impulses.size(), layout.impulses ? want.impulses.size() : 0u);
      for (size_t i = 0; i < records[k].log.impulses.size(); ++i) {
        EXPECT_EQ(records[k].log.impulses[i].kind, want.impulses[i].kind);
        EXPECT_EQ(records[k].log.impulses[i].j, want.impulses[i].j);
        EXPECT_EQ(records[k].log.impulses[i].n, want.impulses[i].n);
      }
      ASSERT_EQ(records[k].log.polynomials.size(), layout.polynomials ? want.polynomials.size() : 0);
      for (int p = 0; p < records[k].log.polynomials.size(); ++p)
        ASSERT_EQ(records[k].log.polynomials.length(p), want.polynomials.length(p));
    }
  }
}

TEST(Trajectory, TruncatedAtEveryByteIsReported) {
  TempDir dir("trajectory");
  writeAll(dir.file("full.bin"), kEverything, {twoParticles(0), twoParticles(1), twoParticles(2)},
           {CollisionLog{}, someLog(true), someLog(true)});
  const std::string full = readFile(dir.file("full.bin"));
  const size_t first = 64 + 4 + 4, second = first + (full.size() - first) / 2;  // record boundaries
  for (size_t n = 0; n < full.size(); ++n) {
    std::vector<TrajectoryRecord> records;
    const std::string message = readAll(dir.write("cut.bin", full.substr(0, n)), 2, kEverything, records);
    if (n == 0 || n == first || n == second) {
      EXPECT_EQ(message, "") << n;  // a clean end between records
      EXPECT_EQ(records.size(), n == 0 ? 0u : n == first ? 1u : 2u);
    } else {
      // Cut short, not "impossible": every count in the file is the writer's own.
      EXPECT_NE(message.find("cut.bin: the file ends early at record " + std::to_string(records.size()) + " (byte "),
                std::string::npos)
          << n << ": " << message;
      EXPECT_EQ(message.find("impossible"), std::string::npos) << n << ": " << message;
      EXPECT_NE(message.find("of " + std::to_string(n) + ")"), std::string::npos) << message;
    }
  }
}

TEST(Trajectory, TrailingBytesAreReported) {
  TempDir dir("trajectory");
  writeAll(dir.file("t.bin"), kPlain, {twoParticles(0), twoParticles(1)}, {CollisionLog{}, CollisionLog{}});
  for (int extra : {1, 7, 31, 63}) {
    std::vector<TrajectoryRecord> records;
    const std::string message =
        readAll(dir.write("x.bin", readFile(dir.file("t.bin")) + std::string(extra, 'z')), 2, kPlain, records);
    EXPECT_NE(message.find("record 2"), std::string::npos) << message;
    EXPECT_EQ(records.size(), 2u);
  }
}

TEST(Trajectory, AbsurdCountsAndKindsAreReported) {
  TempDir dir("trajectory");
  const Bytes state = Bytes().f64s({0, 0, 0, 0});  // one particle
  struct Case {
    Bytes bytes;
    const char* fragment;
  };
  const std::vector<Case> cases = {
      {Bytes(state).i32(std::numeric_limits<std::int32_t>::max()), "impulse count 2147483647"},
      {Bytes(state).i32(-1), "impulse count -1"},
      {Bytes(state).i32(2).i32(0).i32(0).i32(0).f64(0).f64(1).f64(0), "impulse count 2"},  // one is missing
      {Bytes(state).i32(1).i32(3).i32(0).i32(0).f64(0).f64(1).f64(0).i32(0), "unknown kind 3"},
      {Bytes(state).i32(1).i32(-1).i32(0).i32(0).f64(0).f64(1).f64(0).i32(0), "unknown kind -1"},
      {Bytes(state).i32(0).i32(std::numeric_limits<std::int32_t>::min()), "polynomial count"},
      {Bytes(state).i32(0).i32(1 << 30), "polynomial count"},
      {Bytes(state).i32(0).i32(1).i32(std::numeric_limits<std::int32_t>::max()), "length 2147483647"},
      {Bytes(state).i32(0).i32(1).i32(-3).f64(0), "length -3"},
      {Bytes(state).i32(0).i32(2).i32(1).f64(5), "polynomial 1"},
  };
  for (const Case& c : cases) {
    std::vector<TrajectoryRecord> records;
    const std::string message = readAll(dir.write("a.bin", c.bytes.data), 1, kEverything, records);
    EXPECT_NE(message.find(c.fragment), std::string::npos) << c.fragment << ": " << message;
    EXPECT_NE(message.find("record 0"), std::string::npos) << message;
  }
}

TEST(Trajectory, UnreadablePathsAreReported) {
  TempDir dir("trajectory");
  std::unique_ptr<TrajectoryReader> reader;
  Status s = TrajectoryReader::open(dir.file("missing.bin"), 1, kPlain, reader);
  EXPECT_NE(s.message().find("missing.bin: cannot open"), std::string::npos) << s.message();
  s = TrajectoryReader::open(dir.file(""), 1, kPlain, reader);
  EXPECT_NE(s.message().find("directory"), std::string::npos) << s.message();
  s = TrajectoryReader::open(dir.write("e.bin", ""), 0, kPlain, reader);
  EXPECT_FALSE(s.isOk());  // records of zero particles would have no bytes
  EXPECT_EQ(reader, nullptr);
}

TEST(Trajectory, UnwritablePathsAreReported) {
  TempDir dir("trajectory");
  std::unique_ptr<TrajectoryWriter> writer;
  Status s = TrajectoryWriter::open(dir.file("no/such/dir/t.bin"), kPlain, writer);
  EXPECT_NE(s.message().find("no/such/dir/t.bin: cannot create"), std::string::npos) << s.message();
  s = TrajectoryWriter::open(dir.file(""), kPlain, writer);
  EXPECT_FALSE(s.isOk());
  // A full disk: the error comes at a write or at the latest when the file is closed.
  ASSERT_TRUE(TrajectoryWriter::open("/dev/full", kPlain, writer).isOk());
  bool failed = false;
  for (int k = 0; k < 1000 && !failed; ++k) failed = !writer->write(twoParticles(k), CollisionLog{}).isOk();
  if (!failed) failed = !writer->close().isOk();
  EXPECT_TRUE(failed);
}

TEST(Trajectory, ANonFiniteRecordIsRefusedNamingItsFirstNonFiniteNumberAndNothingIsWritten) {
  TempDir dir("trajectory");
  // Each case spoils one number; the message names what the spec's record would carry there.
  struct Case {
    const char* what;
    RecordLayout layout;
    void (*spoil)(State&, CollisionLog&);
    const char* named;
  };
  const Case cases[] = {
      {"position", kPlain, [](State& s, CollisionLog&) { s.x(3) = -std::numeric_limits<double>::infinity(); },
       "particle 1's position"},
      {"velocity", kPlain, [](State& s, CollisionLog&) { s.v(0) = std::numeric_limits<double>::quiet_NaN(); },
       "particle 0's velocity"},
      {"impulse normal", kImpulses, [](State&, CollisionLog& l) { l.impulses[1].n.y() = std::nan(""); },
       "impulse 1 (particle-half-plane, 0 and 3"},
      {"impulse time", kImpulses,
       [](State&, CollisionLog& l) { l.impulses[0].tau = std::numeric_limits<double>::infinity(); }, "impulse 0"},
      {"polynomial", kEverything,
       [](State&, CollisionLog& l) {
         const std::array<double, 2> p{1, std::nan("")};
         l.polynomials.add(p.data(), 2);
       },
       "polynomial 3 of the collision log"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    State state = twoParticles(0.5);
    CollisionLog log = someLog(c.layout.polynomials);
    c.spoil(state, log);
    const std::string path = dir.file(std::string(c.what) + ".bin");
    std::unique_ptr<TrajectoryWriter> writer;
    ASSERT_TRUE(TrajectoryWriter::open(path, c.layout, writer).isOk());
    const Status s = writer->write(state, log);
    ASSERT_FALSE(s.isOk());
    EXPECT_NE(s.message().find("cannot hold a non-finite number: "), std::string::npos) << s.message();
    EXPECT_NE(s.message().find(c.named), std::string::npos) << s.message();
    ASSERT_TRUE(writer->close().isOk());
    std::vector<TrajectoryRecord> records;
    EXPECT_EQ(readAll(path, 2, c.layout, records), "");
    EXPECT_TRUE(records.empty());  // the refused record left no bytes
  }
}

}  // namespace
}  // namespace fosssim::testing
