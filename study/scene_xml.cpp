#include "scene_xml.h"

#include <cstdio>

namespace fosssim::study {

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

void SceneXml::append(const std::ostringstream& element) { body_ += "  " + element.str() + "\n"; }

SceneXml& SceneXml::duration(double seconds) {
  std::ostringstream o;
  o << "<duration time=\"" << number(seconds) << "\"/>";
  append(o);
  return *this;
}

SceneXml& SceneXml::integrator(const std::string& type, double dt) {
  std::ostringstream o;
  o << "<integrator type=\"" << type << "\" dt=\"" << number(dt) << "\"/>";
  append(o);
  return *this;
}

SceneXml& SceneXml::collision(const CollisionChoice& c) {
  if (c.type == "none") return *this;  // no element: the loader's "no collision handling"
  std::ostringstream o;
  o << "<collision type=\"" << c.type << "\" COR=\"" << number(c.cor) << "\"";
  if (c.maxIterations >= 0) o << " maxiters=\"" << c.maxIterations << "\"";
  if (c.k >= 0) o << " k=\"" << number(c.k) << "\"";
  if (c.thickness >= 0) o << " thickness=\"" << number(c.thickness) << "\"";
  o << "/>";
  append(o);
  return *this;
}

SceneXml& SceneXml::method(const Method& m, double dt) {
  integrator(m.integrator, dt);
  return collision(m.collision);
}

int SceneXml::particle(const Vec2& x, const Vec2& v, double mass, bool fixed, double radius) {
  std::ostringstream o;
  o << "<particle m=\"" << number(mass) << "\" px=\"" << number(x.x()) << "\" py=\"" << number(x.y())
         << "\" vx=\"" << number(v.x()) << "\" vy=\"" << number(v.y()) << "\" fixed=\"" << (fixed ? 1 : 0)
         << "\" radius=\"" << number(radius) << "\"/>";
  append(o);
  return particles_++;
}

int SceneXml::edge(int i, int j, double radius) {
  std::ostringstream o;
  o << "<edge i=\"" << i << "\" j=\"" << j << "\" radius=\"" << number(radius) << "\"/>";
  append(o);
  return edges_++;
}

SceneXml& SceneXml::halfplane(const Vec2& p, const Vec2& n) {
  std::ostringstream o;
  o << "<halfplane px=\"" << number(p.x()) << "\" py=\"" << number(p.y()) << "\" nx=\"" << number(n.x())
         << "\" ny=\"" << number(n.y()) << "\"/>";
  append(o);
  return *this;
}

SceneXml& SceneXml::spring(int edge, double k, double l0, double b) {
  std::ostringstream o;
  o << "<springforce edge=\"" << edge << "\" k=\"" << number(k) << "\" l0=\"" << number(l0) << "\" b=\""
         << number(b) << "\"/>";
  append(o);
  return *this;
}

SceneXml& SceneXml::gravity(const Vec2& g) {
  std::ostringstream o;
  o << "<simplegravity fx=\"" << number(g.x()) << "\" fy=\"" << number(g.y()) << "\"/>";
  append(o);
  return *this;
}

SceneXml& SceneXml::gravitational(int i, int j, double G) {
  std::ostringstream o;
  o << "<gravitationalforce i=\"" << i << "\" j=\"" << j << "\" G=\"" << number(G) << "\"/>";
  append(o);
  return *this;
}

std::string SceneXml::text() const { return "<scene>\n" + body_ + "</scene>\n"; }

Status SceneXml::load(const std::string& name, SceneFile& out) const { return parseScene(text(), name, out); }

}  // namespace fosssim::study
