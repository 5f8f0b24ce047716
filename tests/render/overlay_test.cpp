// Text on pictures beyond the time label: the movie's title card, the window's overlays (status
// line, note, error, key help) and the panels that keep them readable, in both outputs.
#include "render_test_support.h"

#include "fosssim/render/stroke_font.h"
#include "fosssim/render/svg_writer.h"
#include "fosssim/render/tessellator.h"
#include "fosssim/render/window_overlay.h"

#include <sstream>

namespace fosssim::render {
namespace {

using testing::kShapesScene;
using testing::parsed;

View square(int w = 512, int h = 512) {
  View v;
  v.width = w;
  v.height = h;
  return v;
}

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

/// The label lies inside the picture: from its origin to its width, and from its descenders
/// (a third of the cap height below the baseline) to its capitals.
bool inside(const LabelShape& label, const View& view) {
  const double w = textWidth(label.text, label.capHeight);
  return label.origin.x() >= 0 && label.origin.x() + w <= view.width && label.origin.y() - label.capHeight / 3 >= 0 &&
         label.origin.y() + label.capHeight <= view.height;
}

/// The panel lies under the whole label.
bool covers(const PanelShape& panel, const LabelShape& label) {
  const double w = textWidth(label.text, label.capHeight);
  return panel.lo.x() <= label.origin.x() && panel.hi.x() >= label.origin.x() + w &&
         panel.lo.y() <= label.origin.y() - label.capHeight / 3 && panel.hi.y() >= label.origin.y() + label.capHeight;
}

TEST(WrapText, BreaksAtSpacesWithinTheWidthAndKeepsEveryWord) {
  const std::string text = "A chain of edges with springs   falling on a floor, hybrid handler";
  const auto lines = wrapText(text, 16);
  std::string joined;
  for (const auto& line : lines) {
    EXPECT_LE(line.size(), 16u) << line;
    EXPECT_FALSE(line.empty());
    joined += (joined.empty() ? "" : " ") + line;
  }
  EXPECT_EQ(words(joined), words(text));
  EXPECT_EQ(wrapText("abcdefghij", 4), (std::vector<std::string>{"abcd", "efgh", "ij"}));
  EXPECT_TRUE(wrapText("   ", 10).empty());
}

TEST(TitleCard, ShowsTheWholeDescriptionInsideThePictureWithTheFileNameBelow) {
  SceneFile file = parsed(kShapesScene);
  file.path = "some/dir/bouncing.xml";
  file.description = "Three disks and a capsule on a green floor: the picture test's scene, described at some "
                     "length so that it needs several lines on the card.";
  for (const View view : {square(), square(320, 240), square(1280, 720)}) {
    const Picture card = titleCard(file, view);
    EXPECT_TRUE(card.particles.empty() && card.edges.empty() && card.halfplanes.empty() && card.paths.empty());
    EXPECT_EQ(card.background.r, file.look.background.r);
    ASSERT_GE(card.labels.size(), 3u);
    std::string shown;
    for (std::size_t k = 0; k + 1 < card.labels.size(); ++k) shown += card.labels[k].text + " ";
    EXPECT_EQ(words(shown), words(file.description)) << view.width << "x" << view.height;
    EXPECT_EQ(card.labels.back().text, "bouncing.xml");
    for (const LabelShape& label : card.labels) {
      EXPECT_TRUE(inside(label, view)) << label.text << " in " << view.width << "x" << view.height;
      EXPECT_EQ(label.color.r, 1 - file.look.background.r);
    }
    // Lines go down the card, the file name last, below them.
    for (std::size_t k = 1; k < card.labels.size(); ++k)
      EXPECT_LT(card.labels[k].origin.y(), card.labels[k - 1].origin.y());
  }
}

TEST(TitleCard, WithoutADescriptionShowsTheFileName) {
  SceneFile file = parsed(kShapesScene);
  file.path = "rain.xml";
  file.description.clear();
  const Picture card = titleCard(file, square());
  ASSERT_EQ(card.labels.size(), 1u);
  EXPECT_EQ(card.labels[0].text, "rain.xml");
}

TEST(TitleCard, AnEndlessDescriptionIsCutWithAnEllipsisNotOffThePicture) {
  SceneFile file = parsed(kShapesScene);
  for (int k = 0; k < 300; ++k) file.description += "word" + std::to_string(k) + " ";
  const Picture card = titleCard(file, square(256, 256));
  for (const LabelShape& label : card.labels) EXPECT_TRUE(inside(label, card.view)) << label.text;
  EXPECT_NE(card.labels[card.labels.size() - 2].text.find("..."), std::string::npos);
}

TEST(WindowOverlay, TheStatusLineSitsOnAPanelOfTheBackgroundColour) {
  // The issue: black text (1 - white background) over the default black half-plane. The panel
  // under it is the background colour, nearly opaque, so the text contrasts whatever lies below.
  const SceneFile file = parsed(kShapesScene);
  Picture pic = makePicture(file, file.initial, PathTrails(), square(300, 200));
  const std::size_t labels = pic.labels.size();
  WindowOverlay overlay;
  overlay.status = "scene.xml  step 3/10  t = 0.03  100 steps/s  paused  (h: keys)";
  overlay.note = "saved scene_step000003.svg";
  addWindowOverlay(pic, overlay);
  ASSERT_EQ(pic.labels.size(), labels + 2);
  ASSERT_EQ(pic.panels.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    const LabelShape& label = pic.labels[labels + k];
    const PanelShape& panel = pic.panels[k];
    EXPECT_TRUE(covers(panel, label)) << label.text;
    EXPECT_TRUE(inside(label, pic.view)) << label.text << ": a long line gets smaller letters";
    EXPECT_GE(panel.alpha, 0.8);
    EXPECT_EQ(panel.color.g, file.look.background.g);
    EXPECT_EQ(label.color.g, 1 - file.look.background.g);
  }
  EXPECT_EQ(pic.labels[labels].text, overlay.status);
  EXPECT_NEAR(pic.panels[0].lo.y(), 0, 1e-9) << "the status line is along the bottom";
  EXPECT_EQ(pic.panels[0].hi.x() - pic.panels[0].lo.x(), 300) << "across the whole width";
  EXPECT_GT(pic.labels[labels + 1].origin.y(), pic.labels[labels].origin.y()) << "the note above it";
}

TEST(WindowOverlay, TheHelpListsEveryKeyOnAPanel) {
  const SceneFile file = parsed(kShapesScene);
  Picture pic = makePicture(file, file.initial, PathTrails(), square());
  WindowOverlay overlay;
  overlay.help = true;
  addWindowOverlay(pic, overlay);
  ASSERT_EQ(pic.panels.size(), 1u);
  std::string shown;
  for (const LabelShape& label : pic.labels) {
    shown += label.text + "\n";
    EXPECT_TRUE(inside(label, pic.view)) << label.text;
  }
  for (const std::string& key : windowKeys()) {
    EXPECT_NE(shown.find(key), std::string::npos) << key;
  }
  for (const char* key : {"space", "restart", "re-centre", "zoom", "SVG", "PNG", "help", "quit"})
    EXPECT_NE(shown.find(key), std::string::npos) << key;
}

TEST(WindowOverlay, AnErrorIsShownWhiteOnRedInFull) {
  const SceneFile file = parsed(kShapesScene);
  Picture pic = makePicture(file, file.initial, PathTrails(), square(400, 300));
  WindowOverlay overlay;
  overlay.error = "step 7: particle 3 has a non-finite position (x = inf); try a smaller dt";
  addWindowOverlay(pic, overlay);
  ASSERT_EQ(pic.panels.size(), 1u);
  EXPECT_GT(pic.panels[0].color.r, 2 * pic.panels[0].color.g);
  std::string shown;
  for (std::size_t k = 1; k < pic.labels.size(); ++k) {  // label 0 is the time
    shown += pic.labels[k].text + " ";
    EXPECT_EQ(pic.labels[k].color.r, 1.0);
    EXPECT_TRUE(inside(pic.labels[k], pic.view)) << pic.labels[k].text;
    if (!pic.labels[k].text.empty()) {
      EXPECT_TRUE(covers(pic.panels[0], pic.labels[k])) << pic.labels[k].text;
    }
  }
  for (const std::string& w : words(overlay.error)) EXPECT_NE(shown.find(w), std::string::npos) << w;
}

TEST(Panels, AreDrawnBetweenTheParticlesAndTheLabelsInBothOutputs) {
  Picture pic;
  pic.view = square(100, 80);
  pic.panels.push_back({Vec2(10, 5), Vec2(60, 25), Rgb{0.2, 0.4, 0.6}, 0.5});
  Mesh mesh;
  tessellate(pic, mesh);
  ASSERT_EQ(mesh.vertexCount(), 6u);  // two triangles
  for (std::size_t v = 0; v < 6; ++v) {
    EXPECT_TRUE(mesh.xy[2 * v] == 10 || mesh.xy[2 * v] == 60);
    EXPECT_TRUE(mesh.xy[2 * v + 1] == 5 || mesh.xy[2 * v + 1] == 25);
    EXPECT_FLOAT_EQ(mesh.rgba[4 * v + 2], 0.6f);
    EXPECT_FLOAT_EQ(mesh.rgba[4 * v + 3], 0.5f);
  }
  const std::string svg = svgDocument(pic);
  // SVG's y grows downwards: the panel's top edge (y = 25 up) is at 80 - 25 = 55.
  EXPECT_NE(svg.find("<g id=\"panels\">\n<rect x=\"10\" y=\"55\" width=\"50\" height=\"20\" fill=\"#336699\" "
                     "fill-opacity=\"0.5\"/>"),
            std::string::npos)
      << svg;
  EXPECT_LT(svg.find("id=\"particles\""), svg.find("id=\"panels\""));
  EXPECT_LT(svg.find("id=\"panels\""), svg.find("id=\"labels\""));
  pic.panels.clear();
  EXPECT_EQ(svgDocument(pic).find("panels"), std::string::npos) << "no empty group in ordinary frames";
}

}  // namespace
}  // namespace fosssim::render
