// The scene writer: load, write, load gives the same scene, field for field and bit for bit
// (every asset scene and a scene with every element and awkward numbers); numbers read back
// exactly; scenes the format cannot express are refused with a message naming the force.
#include "fosssim/io/scene_writer.h"

#include "fosssim/core/forces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>

namespace fosssim {
namespace {

/// Equal to the last bit (so 0.0 and -0.0 differ, and nothing is compared with a tolerance).
bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

#define EXPECT_SAME(a, b) EXPECT_TRUE(same((a), (b))) << #a << " = " << (a) << ", " << #b << " = " << (b)

void expectSameVector(const VecX& a, const VecX& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (Eigen::Index k = 0; k < a.size(); ++k)
    EXPECT_TRUE(same(a[k], b[k])) << what << "[" << k << "]: " << a[k] << " vs " << b[k];
}

void expectSameRgb(const Rgb& a, const Rgb& b) {
  EXPECT_SAME(a.r, b.r);
  EXPECT_SAME(a.g, b.g);
  EXPECT_SAME(a.b, b.b);
}

/// Every parameter of two forces, through their accessors.
void expectSameForce(const Force& a, const Force& b) {
  ASSERT_STREQ(a.keyword(), b.keyword());
  if (auto* s = dynamic_cast<const SpringForce*>(&a)) {
    auto* t = dynamic_cast<const SpringForce*>(&b);
    ASSERT_TRUE(t);
    EXPECT_EQ(s->i(), t->i());
    EXPECT_EQ(s->j(), t->j());
    EXPECT_SAME(s->stiffness(), t->stiffness());
    EXPECT_SAME(s->restLength(), t->restLength());
    EXPECT_SAME(s->damping(), t->damping());
  } else if (auto* g = dynamic_cast<const SimpleGravityForce*>(&a)) {
    auto* h = dynamic_cast<const SimpleGravityForce*>(&b);
    ASSERT_TRUE(h);
    EXPECT_SAME(g->acceleration().x(), h->acceleration().x());
    EXPECT_SAME(g->acceleration().y(), h->acceleration().y());
  } else if (auto* c = dynamic_cast<const ConstantForce*>(&a)) {
    auto* d = dynamic_cast<const ConstantForce*>(&b);
    ASSERT_TRUE(d);
    EXPECT_SAME(c->force().x(), d->force().x());
    EXPECT_SAME(c->force().y(), d->force().y());
  } else if (auto* gr = dynamic_cast<const GravitationalForce*>(&a)) {
    auto* hr = dynamic_cast<const GravitationalForce*>(&b);
    ASSERT_TRUE(hr);
    EXPECT_EQ(gr->i(), hr->i());
    EXPECT_EQ(gr->j(), hr->j());
    EXPECT_SAME(gr->G(), hr->G());
  } else if (auto* dr = dynamic_cast<const DragDampingForce*>(&a)) {
    auto* er = dynamic_cast<const DragDampingForce*>(&b);
    ASSERT_TRUE(er);
    EXPECT_SAME(dr->damping(), er->damping());
  } else if (auto* v = dynamic_cast<const VortexForce*>(&a)) {
    auto* w = dynamic_cast<const VortexForce*>(&b);
    ASSERT_TRUE(w);
    EXPECT_EQ(v->i(), w->i());
    EXPECT_EQ(v->j(), w->j());
    EXPECT_SAME(v->kbs(), w->kbs());
    EXPECT_SAME(v->kvc(), w->kvc());
  } else if (auto* p = dynamic_cast<const PenaltyForce*>(&a)) {
    auto* q = dynamic_cast<const PenaltyForce*>(&b);
    ASSERT_TRUE(q);
    EXPECT_SAME(p->stiffness(), q->stiffness());
    EXPECT_SAME(p->thickness(), q->thickness());
  } else {
    ADD_FAILURE() << "a force of unknown kind: " << a.keyword();
  }
}

/// Every field the loader fills, compared.
void expectSameSceneFile(const SceneFile& a, const SceneFile& b) {
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.tag, b.tag);
  const Scene &s = a.scene, &t = b.scene;
  expectSameVector(s.mass, t.mass, "mass");
  EXPECT_EQ(s.fixed, t.fixed);
  ASSERT_EQ(s.radius.size(), t.radius.size());
  for (size_t i = 0; i < s.radius.size(); ++i) EXPECT_SAME(s.radius[i], t.radius[i]);
  ASSERT_EQ(s.edges.size(), t.edges.size());
  for (size_t e = 0; e < s.edges.size(); ++e) {
    EXPECT_EQ(s.edges[e].i, t.edges[e].i);
    EXPECT_EQ(s.edges[e].j, t.edges[e].j);
    EXPECT_SAME(s.edges[e].radius, t.edges[e].radius);
  }
  ASSERT_EQ(s.halfplanes.size(), t.halfplanes.size());
  for (size_t h = 0; h < s.halfplanes.size(); ++h) {
    EXPECT_SAME(s.halfplanes[h].point.x(), t.halfplanes[h].point.x());
    EXPECT_SAME(s.halfplanes[h].point.y(), t.halfplanes[h].point.y());
    EXPECT_SAME(s.halfplanes[h].normal.x(), t.halfplanes[h].normal.x());
    EXPECT_SAME(s.halfplanes[h].normal.y(), t.halfplanes[h].normal.y());
  }
  ASSERT_EQ(s.forces.size(), t.forces.size());
  for (size_t k = 0; k < s.forces.size(); ++k) expectSameForce(*s.forces[k], *t.forces[k]);
  EXPECT_EQ(s.integrator, t.integrator);
  EXPECT_SAME(s.dt, t.dt);
  EXPECT_SAME(s.duration, t.duration);
  EXPECT_EQ(s.collision.type, t.collision.type);
  EXPECT_SAME(s.collision.cor, t.collision.cor);
  EXPECT_EQ(s.collision.maxIterations, t.collision.maxIterations);
  EXPECT_EQ(s.collision.failsafe, t.collision.failsafe);
  EXPECT_SAME(s.collision.penaltyK, t.collision.penaltyK);
  EXPECT_SAME(s.collision.penaltyThickness, t.collision.penaltyThickness);

  expectSameVector(a.initial.x, b.initial.x, "x");
  expectSameVector(a.initial.v, b.initial.v, "v");
  EXPECT_SAME(a.initial.time, b.initial.time);
  EXPECT_EQ(a.initial.step, b.initial.step);

  const Appearance &l = a.look, &m = b.look;
  expectSameRgb(l.background, m.background);
  ASSERT_EQ(l.particleColors.size(), m.particleColors.size());
  for (size_t i = 0; i < l.particleColors.size(); ++i) expectSameRgb(l.particleColors[i], m.particleColors[i]);
  ASSERT_EQ(l.edgeColors.size(), m.edgeColors.size());
  for (size_t i = 0; i < l.edgeColors.size(); ++i) expectSameRgb(l.edgeColors[i], m.edgeColors[i]);
  ASSERT_EQ(l.halfplaneColors.size(), m.halfplaneColors.size());
  for (size_t i = 0; i < l.halfplaneColors.size(); ++i) expectSameRgb(l.halfplaneColors[i], m.halfplaneColors[i]);
  ASSERT_EQ(l.paths.size(), m.paths.size());
  for (size_t p = 0; p < l.paths.size(); ++p) {
    EXPECT_EQ(l.paths[p].particle, m.paths[p].particle);
    EXPECT_SAME(l.paths[p].duration, m.paths[p].duration);
    expectSameRgb(l.paths[p].color, m.paths[p].color);
  }
  ASSERT_EQ(l.viewport.has_value(), m.viewport.has_value());
  if (l.viewport) {
    EXPECT_SAME(l.viewport->cx, m.viewport->cx);
    EXPECT_SAME(l.viewport->cy, m.viewport->cy);
    EXPECT_SAME(l.viewport->size, m.viewport->size);
  }
  EXPECT_SAME(l.maxSimFreq, m.maxSimFreq);
}

/// Writes `a`, loads the text, compares; then writes the copy and expects the same text.
void expectRoundTrip(const SceneFile& a) {
  std::string text;
  ASSERT_TRUE(sceneToXml(a, text).isOk());
  SceneFile b;
  Status loaded = parseScene(text, "written.xml", b);
  ASSERT_TRUE(loaded.isOk()) << loaded.message() << "\n" << text;
  // The writer writes nothing the loader ignores (warnings about the scene's physics may remain).
  for (const auto& w : b.warnings) EXPECT_EQ(w.find("ignored"), std::string::npos) << w << "\n" << text;
  expectSameSceneFile(a, b);
  std::string again;
  ASSERT_TRUE(sceneToXml(b, again).isOk());
  EXPECT_EQ(text, again);
}

TEST(SceneWriter, EveryAssetSceneRoundTrips) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(FOSSSIM_SOURCE_DIR "/assets")) {
    if (entry.path().extension() != ".xml") continue;
    SCOPED_TRACE(entry.path().string());
    SceneFile a;
    Status loaded = loadScene(entry.path().string(), a);
    ASSERT_TRUE(loaded.isOk()) << loaded.message();
    expectRoundTrip(a);
    ++scenes;
  }
  EXPECT_GT(scenes, 20);  // examples, the t2m2 families and the showcase
}

// Every element and attribute of the format, with values that are not their defaults, numbers
// that need all 17 digits, tiny, huge, negative zero and subnormal values, and free text with
// XML's special characters and line breaks.
TEST(SceneWriter, EveryElementRoundTrips) {
  const std::string text = R"(<scene>
  <description text="a &lt;test&gt; &amp; &quot;quotes&quot;&#10;second line&#9;tab"/>
  <scenetag tag="every-element"/>
  <duration time="0.30000000000000004"/>
  <integrator type="linearized-implicit-euler" dt="0.001"/>
  <collision type="hybrid" COR="0.3333333333333333" maxiters="7" failsafe="rigid" k="123.456" thickness="1e-7"/>
  <maxsimfreq max="250"/>
  <viewport cx="-0.0" cy="1e300" size="2.5e-300"/>
  <backgroundcolor r="0.1" g="0.2" b="0.30000000000000004"/>
  <particle m="1" px="0.1" py="-0" vx="4.9406564584124654e-324" vy="1.7976931348623157e308" fixed="0" radius="0.05"/>
  <particle m="2.5" px="1" py="2" vx="-3" vy="0" fixed="1" radius="0.2"/>
  <particle m="0.7" px="3" py="2" vx="0" vy="0" fixed="0"/>
  <edge i="0" j="1" radius="0.02"/>
  <edge i="1" j="2"/>
  <halfplane px="0" py="-1" nx="0.6" ny="0.8"/>
  <halfplane px="5" py="0" nx="-1" ny="1e-5"/>
  <springforce edge="1" k="1000" l0="0.5" b="0.25"/>
  <springforce edge="0" k="10" l0="1.4142135623730951"/>
  <simplegravity fx="0" fy="-9.81"/>
  <gravitationalforce i="0" j="2" G="6.674e-11"/>
  <constantforce fx="0.5" fy="-0.25"/>
  <dragdamping b="0.01"/>
  <vortexforce i="2" j="0" kbs="1.5" kvc="-2"/>
  <particlecolor i="1" r="1" g="0" b="0.5"/>
  <edgecolor i="0" r="0.25" g="0.5" b="0.75"/>
  <halfplanecolor i="1" r="0.9" g="0.1" b="0"/>
  <particlepath i="2" duration="0.7" r="0" g="1" b="0"/>
</scene>
)";
  SceneFile a;
  Status loaded = parseScene(text, "every.xml", a);
  ASSERT_TRUE(loaded.isOk()) << loaded.message();
  for (const auto& w : a.warnings) ASSERT_EQ(w.find("ignored"), std::string::npos) << w;
  // The scene really has what the test claims to cover.
  ASSERT_EQ(a.scene.forces.size(), 8u);  // two springs, four field/pair forces, vortex, penalty
  ASSERT_TRUE(a.look.viewport.has_value());
  ASSERT_EQ(a.description, "a <test> & \"quotes\"\nsecond line\ttab");
  expectRoundTrip(a);
}

TEST(SceneWriter, NumbersReadBackExactly) {
  std::mt19937_64 random(14);
  std::uniform_int_distribution<std::uint64_t> bits;
  for (int k = 0; k < 100000; ++k) {
    const std::uint64_t b = bits(random);
    double x;
    std::memcpy(&x, &b, sizeof x);
    if (!std::isfinite(x)) continue;
    const std::string s = formatNumber(x);
    EXPECT_TRUE(same(std::strtod(s.c_str(), nullptr), x)) << s;
  }
  // Shortest: the text a person would write, not 17 digits.
  EXPECT_EQ(formatNumber(0.1), "0.1");
  EXPECT_EQ(formatNumber(1.0), "1");
  EXPECT_EQ(formatNumber(-9.81), "-9.81");
  EXPECT_EQ(formatNumber(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(formatNumber(-0.0), "-0");
}

/// A minimal scene built in code (no file).
SceneFile twoParticles() {
  SceneFile f;
  addParticle(f.scene, 1.0, false, 0.1);
  addParticle(f.scene, 1.0, false, 0.1);
  f.initial.x = VecX::Zero(4);
  f.initial.x[2] = 1;
  f.initial.v = VecX::Zero(4);
  f.look.particleColors.assign(2, kDefaultParticleColor);
  f.scene.duration = 1;
  return f;
}

TEST(SceneWriter, SceneBuiltInCodeRoundTrips) {
  SceneFile f = twoParticles();
  f.scene.edges.push_back(Edge{0, 1, 0.01});
  f.look.edgeColors.assign(1, kDefaultEdgeColor);
  f.scene.forces.push_back(std::make_unique<SpringForce>(0, 1, 5.0, 1.0, 0.0));
  f.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -1)));
  f.scene.collision.type = CollisionType::Penalty;
  f.scene.collision.penaltyK = 100;
  f.scene.collision.penaltyThickness = 0.01;
  f.scene.forces.push_back(std::make_unique<PenaltyForce>(100, 0.01));
  expectRoundTrip(f);
}

TEST(SceneWriter, RefusesWhatTheFormatCannotSay) {
  auto message = [](const SceneFile& f) {
    std::string text;
    Status s = sceneToXml(f, text);
    EXPECT_FALSE(s.isOk());
    EXPECT_TRUE(text.empty());
    return s.message();
  };
  {
    SceneFile f = twoParticles();  // a spring without an edge to act along
    f.scene.forces.push_back(std::make_unique<SpringForce>(0, 1, 5.0, 1.0, 0.0));
    EXPECT_EQ(message(f), "cannot write the scene: force 0 (springforce between particles 0 and 1): no edge from 0 "
                          "to 1 (a scene file's spring acts along an edge)");
  }
  {
    SceneFile f = twoParticles();  // gravity before a drag is fine, the other way round is not
    f.scene.forces.push_back(std::make_unique<DragDampingForce>(0.1));
    f.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -1)));
    EXPECT_NE(message(f).find("force 1 (simplegravity): out of the format's order"), std::string::npos);
  }
  {
    SceneFile f = twoParticles();  // a penalty force that the collision type does not make
    f.scene.forces.push_back(std::make_unique<PenaltyForce>(100, 0.01));
    EXPECT_NE(message(f).find("force 0 (collision penalty): collision type \"none\" has no penalty force"),
              std::string::npos);
  }
  {
    SceneFile f = twoParticles();  // hybrid without its penalty force
    f.scene.collision.type = CollisionType::Hybrid;
    EXPECT_NE(message(f).find("needs exactly one penalty force, the scene has 0"), std::string::npos);
  }
  {
    SceneFile f = twoParticles();  // numbers the loader would refuse
    f.initial.v[3] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(message(f),
              "cannot write the scene: <particle> attribute 'vy' is inf (a scene file holds finite numbers only)");
  }
  {
    SceneFile f = twoParticles();  // text the loader refuses: XML has no control characters
    f.description = "red \x1b[31m";
    EXPECT_NE(message(f).find("<description> attribute 'text' holds the control character U+001B"), std::string::npos);
    f.description = "fine\ttab";
    f.tag = std::string("nul\0", 4);
    EXPECT_NE(message(f).find("<scenetag> attribute 'tag' holds the control character U+0000"), std::string::npos);
  }
  {
    SceneFile f = twoParticles();  // nor bytes that are not UTF-8 (a Latin-1 "é")
    f.description = "caf\xE9";
    EXPECT_NE(message(f).find("<description> attribute 'text' holds bytes that are not UTF-8, 0xE9 at the end"),
              std::string::npos)
        << message(f);
    f.description = "caf\xC3\xA9";  // the same "é" in UTF-8
    std::string text;
    EXPECT_TRUE(sceneToXml(f, text).isOk());
  }
}

TEST(SceneWriter, WritesFilesAndNamesThePathOnFailure) {
  const char* tmp = std::getenv("TMPDIR");
  const std::filesystem::path dir = std::filesystem::path(tmp && *tmp ? tmp : "/tmp");
  const std::string path = (dir / ("fosssim-writer-" + std::to_string(::getpid()) + ".xml")).string();
  SceneFile f = twoParticles();
  ASSERT_TRUE(writeScene(path, f).isOk());
  SceneFile back;
  ASSERT_TRUE(loadScene(path, back).isOk());
  std::remove(path.c_str());
  expectSameSceneFile(f, back);
  Status bad = writeScene((dir / "no-such-folder-fosssim" / "x.xml").string(), f);
  ASSERT_FALSE(bad.isOk());
  EXPECT_EQ(bad.message().rfind((dir / "no-such-folder-fosssim" / "x.xml").string() + ": cannot create", 0), 0u)
      << bad.message();
}

}  // namespace
}  // namespace fosssim
