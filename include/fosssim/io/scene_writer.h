// Writing a scene as an XML scene file that loads back into the same scene: every element the
// loader reads (forces, collision settings, colours and paths included), numbers in their
// shortest form that reads back to the same double.
#pragma once

#include "fosssim/core/status.h"
#include "fosssim/io/scene_file.h"

#include <string>

namespace fosssim {

/// The shortest decimal text that reads back (strtod) to exactly `value`, e.g. 0.1 -> "0.1",
/// 1.0 -> "1", 1e-300 -> "1e-300". Non-finite values give "inf", "-inf" or "nan" (which the
/// loader rejects: the writer refuses them first).
std::string formatNumber(double value);

/// Why `text` cannot be an attribute's text in a scene file ("holds the control character U+0001
/// (a scene file is XML text, which has none but tab and line ends)", or invalid UTF-8), or "":
/// the writer's rule for every text it writes, for setters that take text to check at once.
std::string xmlTextProblem(const std::string& text);

/// The scene file's XML text. Loading it gives back `file` field for field: the scene (forces
/// in the same order, collision settings, integrator, dt, duration), the initial state and the
/// appearance. Fails, naming the element, when the scene cannot be expressed in the format:
/// a non-finite number, a spring whose two particles no edge joins, a force the format has no
/// element for, a penalty force that differs from the collision settings, or forces out of the
/// format's order (the loader sums them springs, simple gravity, gravitational, constant, drag,
/// vortex, penalty: another order would be a different scene to the last bit).
Status sceneToXml(const SceneFile& file, std::string& out);

/// sceneToXml written to `path` (created or truncated). Messages name the path.
Status writeScene(const std::string& path, const SceneFile& file);

}  // namespace fosssim
