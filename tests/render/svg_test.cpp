// -m: the SVG document of a picture, parsed back and checked element by element; and the
// FOSSSim executable writing one per frame (this works in builds without the renderer too).
#include "render_test_support.h"

#include "fosssim/render/frame_outputs.h"
#include "fosssim/render/svg_writer.h"

#include <tinyxml2.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace fosssim::render {
namespace {

using testing::kShapesScene;
using testing::parsed;
using testing::TempDir;

Picture shapesPicture() {
  const SceneFile file = parsed(kShapesScene);
  PathTrails trails(file.look.paths, file.scene.dt);
  State moved = file.initial;
  trails.record(moved);
  at(moved.x, 0).x() += 0.1;
  trails.record(moved);
  View view;
  view.width = 100;
  view.height = 80;
  view.camera = initialCamera(file.look, file.initial, 100, 80);
  return makePicture(file, file.initial, trails, view);
}

const tinyxml2::XMLElement* group(const tinyxml2::XMLElement* svg, const char* id) {
  for (auto* g = svg->FirstChildElement(); g; g = g->NextSiblingElement())
    if (g->Attribute("id", id)) return g;
  return nullptr;
}

std::vector<const tinyxml2::XMLElement*> children(const tinyxml2::XMLElement* g, const char* name) {
  std::vector<const tinyxml2::XMLElement*> out;
  for (auto* e = g->FirstChildElement(name); e; e = e->NextSiblingElement(name)) out.push_back(e);
  return out;
}

TEST(Svg, IsAWellFormedDocumentOfThePicturesSize) {
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(svgDocument(shapesPicture()).c_str()), tinyxml2::XML_SUCCESS);
  const auto* svg = doc.RootElement();
  ASSERT_NE(svg, nullptr);
  EXPECT_STREQ(svg->Name(), "svg");
  EXPECT_STREQ(svg->Attribute("xmlns"), "http://www.w3.org/2000/svg");
  EXPECT_EQ(svg->IntAttribute("width"), 100);
  EXPECT_EQ(svg->IntAttribute("height"), 80);
  EXPECT_STREQ(svg->Attribute("viewBox"), "0 0 100 80");
}

TEST(Svg, ElementsComeInDrawOrder) {
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(svgDocument(shapesPicture()).c_str()), tinyxml2::XML_SUCCESS);
  std::vector<std::string> ids;
  for (auto* e = doc.RootElement()->FirstChildElement(); e; e = e->NextSiblingElement())
    ids.push_back(e->Attribute("id") ? e->Attribute("id") : "?");
  EXPECT_EQ(ids, (std::vector<std::string>{"background", "paths", "edges", "halfplanes", "particles", "labels"}));
}

TEST(Svg, ShapesHaveTheScenesGeometryAndColours) {
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(svgDocument(shapesPicture()).c_str()), tinyxml2::XML_SUCCESS);
  const auto* svg = doc.RootElement();
  // 40 pixels per unit, origin at (50, 40) counted from the bottom; SVG counts from the top.
  EXPECT_STREQ(group(svg, "background")->Attribute("fill"), "#336699");

  const auto paths = children(group(svg, "paths"), "polyline");
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_STREQ(paths[0]->Attribute("stroke"), "#ffff00");
  EXPECT_STREQ(paths[0]->Attribute("points"), "70,30 74,30");

  const auto edges = children(group(svg, "edges"), "line");
  ASSERT_EQ(edges.size(), 1u);
  EXPECT_DOUBLE_EQ(edges[0]->DoubleAttribute("x1"), 30);
  EXPECT_DOUBLE_EQ(edges[0]->DoubleAttribute("y1"), 20);
  EXPECT_DOUBLE_EQ(edges[0]->DoubleAttribute("x2"), 30);
  EXPECT_DOUBLE_EQ(edges[0]->DoubleAttribute("y2"), 52);
  EXPECT_DOUBLE_EQ(edges[0]->DoubleAttribute("stroke-width"), 4);  // 2 * 0.05 * 40: the capsule
  EXPECT_STREQ(edges[0]->Attribute("stroke"), "#006363");
  EXPECT_STREQ(group(svg, "edges")->Attribute("stroke-linecap"), "round");

  const auto planes = children(group(svg, "halfplanes"), "polygon");
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_STREQ(planes[0]->Attribute("fill"), "#008000");
  // The solid side is below the boundary row (y = 60 from the top), down past the picture.
  std::stringstream points(planes[0]->Attribute("points"));
  std::string xy;
  int count = 0;
  while (points >> xy) {
    const double y = std::stod(xy.substr(xy.find(',') + 1));
    EXPECT_GE(y, 60 - 1e-9) << xy;
    ++count;
  }
  EXPECT_EQ(count, 4);

  const auto disks = children(group(svg, "particles"), "circle");
  ASSERT_EQ(disks.size(), 4u);
  EXPECT_DOUBLE_EQ(disks[0]->DoubleAttribute("cx"), 70);
  EXPECT_DOUBLE_EQ(disks[0]->DoubleAttribute("cy"), 30);
  EXPECT_DOUBLE_EQ(disks[0]->DoubleAttribute("r"), 8);
  EXPECT_STREQ(disks[0]->Attribute("fill"), "#ff0000");
  EXPECT_STREQ(disks[1]->Attribute("fill"), "#a64b00");  // the reference's default colour

  const auto labels = children(group(svg, "labels"), "path");
  ASSERT_EQ(labels.size(), 1u);
  EXPECT_STREQ(labels[0]->Attribute("stroke"), "#cc9966");  // 1 - background
  ASSERT_NE(labels[0]->FirstChildElement("title"), nullptr);
  EXPECT_STREQ(labels[0]->FirstChildElement("title")->GetText(), "t = 0.00");
  EXPECT_EQ(labels[0]->Attribute("d")[0], 'M');
}

/// The SVG of `sceneText`'s first frame (100 x 80 pixels), written to a file and read back.
std::string svgFileOf(const char* sceneText) {
  const SceneFile file = parsed(sceneText);
  PathTrails trails(file.look.paths, file.scene.dt);
  trails.record(file.initial);
  View view;
  view.width = 100;
  view.height = 80;
  view.camera = initialCamera(file.look, file.initial, 100, 80);
  TempDir tmp;
  EXPECT_TRUE(writeSvg(tmp / "far.svg", makePicture(file, file.initial, trails, view)).isOk());
  std::ifstream in(tmp / "far.svg", std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Every number of every geometric attribute, read as SVG numbers are written ("x,y" pairs, path
/// commands M and L). Fails the test for text that is no number.
std::vector<double> geometry(const tinyxml2::XMLElement* root) {
  std::vector<double> numbers;
  std::vector<const tinyxml2::XMLElement*> todo = {root};
  while (!todo.empty()) {
    const tinyxml2::XMLElement* e = todo.back();
    todo.pop_back();
    for (auto* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) todo.push_back(c);
    for (const char* name : {"x", "y", "width", "height", "x1", "y1", "x2", "y2", "cx", "cy", "r", "stroke-width",
                             "points", "d"}) {
      const char* value = e->Attribute(name);
      if (!value || (std::string(e->Name()) == "svg")) continue;
      std::string words(value);
      for (char& ch : words)
        if (ch == ',' || ch == 'M' || ch == 'L') ch = ' ';
      std::istringstream in(words);
      for (std::string word; in >> word;) {
        char* end = nullptr;
        numbers.push_back(std::strtod(word.c_str(), &end));
        EXPECT_EQ(*end, '\0') << e->Name() << " " << name << ": \"" << word << "\" is no number";
      }
    }
  }
  return numbers;
}

// A particle 1e50 m out, or a viewport of size 1e-300, puts pixels near 1e308 away: every number
// is still short text (it was formatted into a 48-byte buffer, whose unwritten rest was read),
// finite, and far off the picture; an edge towards the far particle keeps its direction.
TEST(Svg, PointsFarOutsideThePictureAreShortFiniteNumbers) {
  const char* farParticle = R"(<scene>
  <duration time="0.1"/>
  <integrator type="explicit-euler" dt="0.01"/>
  <viewport cx="0" cy="0" size="1"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1" radius="0.1"/>
  <particle m="1" px="1e50" py="1e49" vx="0" vy="0" fixed="1" radius="1e45"/>
  <edge i="0" j="1" radius="0.05"/>
  <particlepath i="1" duration="0.05" r="1" g="1" b="0"/>
</scene>)";
  const char* tinyViewport = R"(<scene>
  <duration time="0.1"/>
  <integrator type="explicit-euler" dt="0.01"/>
  <viewport cx="0" cy="0" size="1e-300"/>
  <particle m="1" px="1" py="0.5" vx="0" vy="0" fixed="1" radius="0.1"/>
  <particle m="1" px="-1" py="-3" vx="0" vy="0" fixed="1" radius="1e-301"/>
  <edge i="0" j="1" radius="0.05"/>
  <halfplane px="0" py="-1" nx="1" ny="1"/>
  <particlepath i="0" duration="0.05" r="1" g="1" b="0"/>
</scene>)";
  for (const char* scene : {farParticle, tinyViewport}) {
    SCOPED_TRACE(scene);
    const std::string text = svgFileOf(scene);
    EXPECT_EQ(text.find('\0'), std::string::npos) << "a NUL byte in the SVG";
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.Parse(text.c_str(), text.size()), tinyxml2::XML_SUCCESS) << text;
    const std::vector<double> numbers = geometry(doc.RootElement());
    EXPECT_GT(numbers.size(), 10u);
    for (double v : numbers) {
      EXPECT_TRUE(std::isfinite(v)) << v;
      EXPECT_LE(std::fabs(v), 1e10) << v;  // single precision draws it, and it is off the picture
    }
  }
  // The edge from the picture's centre (50, 40) towards (1e50, 1e49): slope 0.1 up, so -0.1 in
  // SVG's y-down pixels, and it ends beyond the picture's right side.
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(svgFileOf(farParticle).c_str()), tinyxml2::XML_SUCCESS);
  const auto edges = children(group(doc.RootElement(), "edges"), "line");
  ASSERT_EQ(edges.size(), 1u);
  const double x1 = edges[0]->DoubleAttribute("x1"), y1 = edges[0]->DoubleAttribute("y1");
  const double x2 = edges[0]->DoubleAttribute("x2"), y2 = edges[0]->DoubleAttribute("y2");
  EXPECT_DOUBLE_EQ(x1, 50);
  EXPECT_DOUBLE_EQ(y1, 40);
  EXPECT_GT(x2, 1e6);
  EXPECT_NEAR((y2 - y1) / (x2 - x1), -0.1, 1e-6);
}

TEST(Svg, FrameNamesFollowTheReference) {
  EXPECT_EQ(svgFrameName("out", 1), "out/frame00000000000000000001.svg");
  EXPECT_EQ(svgFrameName("out", 123), "out/frame00000000000000000123.svg");
}

TEST(Svg, FrameOutputsCreateTheFolderAndWriteEveryKthFrame) {
  TempDir tmp;
  const SceneFile file = parsed(kShapesScene);
  std::unique_ptr<SvgFrames> svg;
  ASSERT_TRUE(SvgFrames::open(tmp / "a/b", svg).isOk());
  FrameOutputs outputs(64, 48, 4);
  outputs.add(std::move(svg));
  ASSERT_TRUE(outputs.start(file, file.initial).isOk());
  for (int step = 0; step < 10; ++step) ASSERT_TRUE(outputs.afterStep(file, file.initial).isOk());
  ASSERT_TRUE(outputs.finish().isOk());
  EXPECT_TRUE(std::filesystem::exists(svgFrameName(tmp / "a/b", 1)));
  EXPECT_TRUE(std::filesystem::exists(svgFrameName(tmp / "a/b", 2)));
  EXPECT_FALSE(std::filesystem::exists(svgFrameName(tmp / "a/b", 3)));
}

TEST(Svg, CommandLineWritesOneSvgPerStep) {
  TempDir tmp;
  testing::writeText(tmp / "scene.xml", kShapesScene);
  const auto r = testing::run(std::string(FOSSSIM_EXECUTABLE) + " -s " + (tmp / "scene.xml") + " -d 0 -q -m " +
                              (tmp / "svg"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(tmp / "svg")) {
    ++files;
    tinyxml2::XMLDocument doc;
    EXPECT_EQ(doc.LoadFile(entry.path().c_str()), tinyxml2::XML_SUCCESS) << entry.path();
  }
  EXPECT_EQ(files, 10);  // 0.1 s at dt 0.01
  EXPECT_TRUE(std::filesystem::exists(svgFrameName(tmp / "svg", 10)));
  EXPECT_FALSE(std::filesystem::exists(svgFrameName(tmp / "svg", 0)));
  const std::string last = testing::readText(svgFrameName(tmp / "svg", 10));
  EXPECT_NE(last.find("<title>t = 0.10</title>"), std::string::npos);
}

TEST(Svg, TheCameraKeepsAFallingRainInEveryFrame) {
  // 20 disks on a 5 x 4 grid 1.2 m wide fall freely for 1.5 s (11 m): the camera fixed at the
  // start would lose them all. Every frame must show every disk whole, and -m keeps the
  // reference's numbering (1, 2, ... after steps 10, 20, ...).
  std::string scene = "<scene>\n<duration time=\"1.5\"/>\n<integrator type=\"symplectic-euler\" dt=\"0.01\"/>\n";
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j)
      scene += "<particle m=\"1\" px=\"" + std::to_string(0.3 * i) + "\" py=\"" + std::to_string(0.3 * j) +
               "\" vx=\"" + std::to_string(0.2 * (i - 2)) + "\" vy=\"0\" fixed=\"0\" radius=\"0.05\"/>\n";
  scene += "<simplegravity fx=\"0\" fy=\"-9.81\"/>\n</scene>\n";
  TempDir tmp;
  testing::writeText(tmp / "rain.xml", scene);
  const auto r = testing::run(std::string(FOSSSIM_EXECUTABLE) + " -s " + (tmp / "rain.xml") +
                              " -d 0 -q --frame-size 320x240 --frame-every 10 -m " + (tmp / "svg"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_FALSE(std::filesystem::exists(svgFrameName(tmp / "svg", 0)));
  EXPECT_FALSE(std::filesystem::exists(svgFrameName(tmp / "svg", 16)));
  for (int frame = 1; frame <= 15; ++frame) {
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.LoadFile(svgFrameName(tmp / "svg", frame).c_str()), tinyxml2::XML_SUCCESS) << frame;
    int disks = 0;
    for (auto* g = doc.RootElement()->FirstChildElement("g"); g; g = g->NextSiblingElement("g")) {
      if (std::string(g->Attribute("id")) != "particles") continue;
      for (auto* c = g->FirstChildElement("circle"); c; c = c->NextSiblingElement("circle")) {
        ++disks;
        const double x = c->DoubleAttribute("cx"), y = c->DoubleAttribute("cy"), rad = c->DoubleAttribute("r");
        EXPECT_GE(x - rad, -0.01) << "frame " << frame;  // the SVG's two decimals
        EXPECT_LE(x + rad, 320.01) << "frame " << frame;
        EXPECT_GE(y - rad, -0.01) << "frame " << frame;
        EXPECT_LE(y + rad, 240.01) << "frame " << frame;
      }
    }
    EXPECT_EQ(disks, 20) << "frame " << frame;
  }
}

}  // namespace
}  // namespace fosssim::render
