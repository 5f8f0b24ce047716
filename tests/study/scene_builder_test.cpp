// The study's scenes built in code are the scenes their XML gives: every one of them, written by
// the io layer's scene writer and loaded back by the ordinary loader, writes the same text again
// (the writer prints every field the loader reads, numbers in round-trip form, so equal text is
// an equal scene). And a bad builder is an error naming the scene, not a crash.
#include "contact_problems.h"
#include "pile.h"
#include "problems.h"
#include "robustness.h"
#include "shots.h"
#include "stability.h"

#include "fosssim/io/scene_writer.h"

#include <gtest/gtest.h>

namespace fosssim::study {
namespace {

void expectRoundTrip(const SceneBuilder& builder, const std::string& what) {
  SCOPED_TRACE(what);
  SceneFile built;
  ASSERT_TRUE(builder.build(what + ".xml", built).isOk());
  std::string text, again;
  const Status written = builder.xml(text);
  ASSERT_TRUE(written.isOk()) << written.message();
  SceneFile loaded;
  const Status parsed = parseScene(text, what + ".xml", loaded);
  ASSERT_TRUE(parsed.isOk()) << parsed.message();
  ASSERT_TRUE(sceneToXml(loaded, again).isOk());
  EXPECT_EQ(text, again);
  // The built scene itself, not only its text: the same forces in the same order.
  ASSERT_EQ(built.scene.forces.size(), loaded.scene.forces.size());
  for (size_t k = 0; k < built.scene.forces.size(); ++k)
    EXPECT_STREQ(built.scene.forces[k]->keyword(), loaded.scene.forces[k]->keyword());
  EXPECT_TRUE(built.initial.x == loaded.initial.x);
  EXPECT_TRUE(built.initial.v == loaded.initial.v);
}

TEST(StudySceneBuilder, EveryStudySceneLoadsBackFromItsText) {
  for (bool integrators : {true, false})
    for (const Problem& p : integrators ? integratorProblems(true) : collisionProblems(true))
      for (const Method& m : p.methods) expectRoundTrip(p.scene(m, p.dts.front()), p.name + " " + m.label);
  for (const ContactProblem& p : contactProblems(true))
    for (const char* collision : {"continuous-time", "hybrid"}) expectRoundTrip(p.scene(collision, 0), p.name);
  for (const Method& m : collisionMethods()) {
    expectRoundTrip(edgeThrowScene(m, 4.0, 1e-3), "thin edge " + m.label);
    expectRoundTrip(pileScene(m, 1e-3, 3, 2), "pile " + m.label);
  }
  for (const Method& m : shotMethods())
    for (int target = 0; target < 4; ++target)
      expectRoundTrip(shotScene(randomShot(static_cast<ShotTarget>(target), 1), m), "shot " + m.label);
  expectRoundTrip(springRow(3, 1e3, "symplectic-euler", 1e-3), "spring row");
}

// The forces go into the loader's summation order (springs, simple gravity, gravitational), not
// the order they were added in: the sums, and so the results, are the loader's to the last bit.
TEST(StudySceneBuilder, ForcesInTheLoadersOrder) {
  SceneBuilder b;
  b.duration(1).integrator("symplectic-euler", 0.01);
  const int i = b.particle(Vec2(0, 0), Vec2(0, 0), 1), j = b.particle(Vec2(1, 0), Vec2(0, 0), 1);
  b.gravitational(i, j, 1.0).gravity(Vec2(0, -1)).spring(b.edge(i, j), 10, 1);
  b.collision(CollisionChoice{"penalty"});
  SceneFile f;
  ASSERT_TRUE(b.build("order.xml", f).isOk());
  ASSERT_EQ(f.scene.forces.size(), 4u);
  EXPECT_STREQ(f.scene.forces[0]->keyword(), "springforce");
  EXPECT_STREQ(f.scene.forces[1]->keyword(), "simplegravity");
  EXPECT_STREQ(f.scene.forces[2]->keyword(), "gravitationalforce");
  EXPECT_STREQ(f.scene.forces[3]->keyword(), "collision penalty");  // finalizeScene's, with the table's defaults
  expectRoundTrip(b, "order");
}

TEST(StudySceneBuilder, BadNamesAndIndicesAreErrorsNamingTheScene) {
  SceneBuilder b;
  b.integrator("runge-kutta", 0.01);
  SceneFile f;
  Status s = b.build("bad.xml", f);
  ASSERT_FALSE(s.isOk());
  EXPECT_NE(s.message().find("bad.xml"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("runge-kutta"), std::string::npos) << s.message();
  SceneBuilder c;
  c.particle(Vec2(0, 0), Vec2(0, 0), 1);
  c.spring(c.edge(0, 5), 1, 1);
  s = c.build("edge.xml", f);
  ASSERT_FALSE(s.isOk());
  EXPECT_NE(s.message().find("edge"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace fosssim::study
