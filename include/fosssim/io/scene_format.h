// The scene format's reference page (docs/scene-format.md), rendered from the loader's own
// element table, so that the page cannot drift from what the loader reads.
#pragma once

#include <string>

namespace fosssim {

/// The whole of docs/scene-format.md: every element and attribute with meaning, unit, default,
/// whether it is required, its bounds, and the keyword tables of integrators and collision types.
std::string sceneFormatMarkdown();

}  // namespace fosssim
