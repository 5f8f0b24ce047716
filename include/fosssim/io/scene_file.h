// A scene file, loaded: the physics (Scene), the initial State, and what only matters for showing
// it (Appearance). The loader checks everything and reports bad input with file, line, element
// and attribute.
#pragma once

#include "fosssim/core/scene.h"
#include "fosssim/core/state.h"
#include "fosssim/core/status.h"

#include <optional>
#include <string>
#include <vector>

namespace fosssim {

struct Rgb {
  double r = 0, g = 0, b = 0;
};

/// <viewport cx cy size>: the camera. size is the half-height of the visible world.
struct Viewport {
  double cx = 0, cy = 0, size = 1;
};

/// <particlepath i duration r g b>: a trail of the particle's last ceil(duration/dt) positions.
struct ParticlePath {
  int particle = 0;
  double duration = 0;
  Rgb color;
};

/// Display properties; the physics never reads them.
struct Appearance {
  Rgb background{1, 1, 1};
  std::vector<Rgb> particleColors;   ///< N
  std::vector<Rgb> edgeColors;       ///< one per edge
  std::vector<Rgb> halfplaneColors;  ///< one per half-plane
  std::vector<ParticlePath> paths;
  std::optional<Viewport> viewport;  ///< absent: the camera fits the particles
  double maxSimFreq = 100;           ///< the window's steps per wall second
};

/// One message about a scene file, located: "file:line: <element> attribute 'a': what is wrong".
struct SceneMessage {
  enum class Severity { Warning, Error };
  Severity severity = Severity::Error;
  int line = 0;      ///< 0: about the whole file (listed after the located ones)
  std::string text;  ///< the whole message, starting with the file name

  bool isError() const { return severity == Severity::Error; }
};

struct SceneFile {
  std::string path;         ///< as given, for messages
  std::string description;  ///< <description text>, may be empty
  std::string tag;          ///< <scenetag tag>, may be empty
  Scene scene;
  State initial;
  Appearance look;
  std::vector<std::string> warnings;  ///< located messages about ignored input (the warnings of `messages`)
  /// Every error and warning in line order, a typo's warning before the error it causes; repeats
  /// of one kind are shown a few times and then summarised in one line ("... and 12,345 more").
  std::vector<SceneMessage> messages;
  long warningCount = 0;  ///< every warning, the summarised ones included
  long errorCount = 0;    ///< every error, the summarised ones included
};

/// Loads and checks a scene file. On failure the message starts with "path:line:" (the first
/// error; out.messages holds them all). On success out.messages holds the warnings.
Status loadScene(const std::string& path, SceneFile& out);
/// The same from text in memory; `name` stands for the file in messages.
Status parseScene(const std::string& text, const std::string& name, SceneFile& out);

/// The reference's default colours.
inline constexpr Rgb kDefaultParticleColor{0.650980392156863, 0.294117647058824, 0.0};
inline constexpr Rgb kDefaultEdgeColor{0.0, 0.388235294117647, 0.388235294117647};
inline constexpr Rgb kDefaultHalfplaneColor{0.0, 0.0, 0.0};

}  // namespace fosssim
