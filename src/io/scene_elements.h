// Internal header: the element table. Every element of the scene format, every attribute with its
// kind, unit, default, bound and meaning, and the function that reads the element. The loader
// reads through it (an attribute not declared here cannot be read), docs/scene-format.md is
// rendered from it (sceneFormatMarkdown()), and a test checks that the two agree.
#pragma once

#include "fosssim/io/scene_file.h"

#include "fosssim/core/force.h"
#include "fosssim/core/scene_values.h"
#include "scene_messages.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace fosssim::io {

class ElementReader;

/// How an attribute's text is read and checked.
enum class Kind {
  Number,       ///< any finite number
  Positive,     ///< a finite number > 0 with a finite reciprocal (it is divided by)
  NonNegative,  ///< a finite number >= 0
  Fraction,     ///< a number in [0, 1]
  Index,        ///< an integer >= 0 naming an element by its position (from 0, in file order)
  Flag,         ///< 0 or 1
  Text,         ///< a word
};

struct AttributeSpec {
  const char* name;
  Kind kind;
  const char* unit;     ///< SI unit ("m", "kg", "m/s"), "" for none
  const char* fallback; ///< nullptr: required; a value: the default; "(...)": a default the reader computes, in words
  const char* meaning;
  const char* example;  ///< a valid value (the docs' example; the table test loads it)
  double max = 0;       ///< > 0: the largest value accepted
  const char* maxReason = nullptr;  ///< why, for the message and the docs

  bool required() const { return fallback == nullptr; }
  bool computedDefault() const { return fallback && fallback[0] == '('; }
};

/// What a second element of the same name does.
enum class Repeat {
  Adds,         ///< every one adds a thing (particles, forces, ...)
  FirstCounts,  ///< later ones are ignored, with a warning (the reference's rule)
  LastCounts,   ///< a setting: the last one counts
};

struct Builder;

struct ElementSpec {
  const char* name;
  const char* section;  ///< the docs' heading
  bool required;        ///< the scene must have one
  Repeat repeat;
  const char* meaning;
  std::vector<AttributeSpec> attributes;
  void (*read)(ElementReader&, Builder&);

  const AttributeSpec* attribute(const std::string& attributeName) const;
};

/// Every element of the scene format, in the docs' order.
const std::vector<ElementSpec>& elementTable();
const ElementSpec* findElement(const std::string& name);
/// The most attributes an element of the table declares (messages and docs about kMaxAttributes).
size_t mostAttributes();

/// An index read from the file, checked once the counts are known (-1: already reported).
struct IndexRef {
  int value = -1;
  int line = 0;
  std::string where;  ///< "file:line: <element> attribute 'i'"
};

struct SpringSpec {
  IndexRef edge;
  double k, l0, b;
};

/// A force between two particles: gravitational (a = G) or vortex (a = kbs, b = kvc).
struct PairForceSpec {
  IndexRef i, j;
  double a = 0, b = 0;
};

template <class T>
struct Indexed {  // something that refers to a particle, edge or half-plane by index
  IndexRef ref;
  T value;
};

/// Everything read so far, before cross references are resolved.
struct Builder {
  Builder(SceneFile& file, SceneMessages& log) : out(file), messages(log) {}
  SceneFile& out;
  SceneMessages& messages;
  std::vector<ParticleSpec> particles;
  std::vector<double> positions, velocities;  // 2 per particle
  std::vector<std::pair<IndexRef, IndexRef>> edgeEnds;
  std::vector<SpringSpec> springs;
  std::vector<std::unique_ptr<Force>> gravity, constant, drag;
  std::vector<PairForceSpec> gravitational, vortex;
  std::vector<Indexed<Rgb>> particleColors, edgeColors, halfplaneColors;
  std::vector<Indexed<ParticlePath>> paths;
  bool sawIntegrator = false, sawDuration = false;  ///< the element is there (read well or not)
  bool integratorOk = false, durationOk = false, collisionOk = true;
  int integratorLine = 0;
  std::string integratorWhere;
  /// Unknown element names seen, with their first line: a missing required element may be one of
  /// them, misspelt.
  std::vector<std::pair<std::string, int>> unknownElements;
  std::map<std::string, std::string> suggestions;  ///< unknown element name -> "did you mean" (or "")
};

/// Resolves indices, checks what needs the whole file, builds the Scene, State and Appearance.
void assemble(Builder& b, const std::string& file);

/// The trail positions all <particlepath> elements may keep together (memory: 16 bytes each).
inline constexpr double kMaxTrailPoints = 1e7;
/// The most steps a run may take: the core's limit (scene_values.h), which a scene built in code keeps too.
using fosssim::kMaxSteps;

}  // namespace fosssim::io
