// fosssim-scene-format [FILE]: writes the scene format's reference page (docs/scene-format.md),
// rendered from the loader's element table, to FILE or to standard output.
#include "fosssim/io/scene_format.h"

#include <cstdio>
#include <fstream>

int main(int argc, char** argv) {
  const std::string text = fosssim::sceneFormatMarkdown();
  if (argc < 2) return std::fputs(text.c_str(), stdout) < 0 ? 1 : 0;
  std::ofstream out(argv[1], std::ios::binary);
  out << text;
  if (!out.flush()) {
    std::fprintf(stderr, "fosssim-scene-format: cannot write %s\n", argv[1]);
    return 1;
  }
  return 0;
}
