// fosssim-scene-format [FILE]: writes the scene format's reference page (docs/scene-format.md),
// rendered from the loader's element table, to FILE or to standard output. A first word that
// starts with '-' is no file name: "--help" wrote a file named "--help".
#include "fosssim/io/scene_format.h"

#include <cstdio>
#include <fstream>
#include <string>

namespace {

const char* const kUsage = "usage: fosssim-scene-format [OUTPUT.md]  (without OUTPUT.md: to standard output)\n";

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2) {
    const std::string first = argv[1];
    if (first == "-h" || first == "--help") return std::fputs(kUsage, stdout) < 0 ? 1 : 0;
    if (!first.empty() && first[0] == '-') {
      std::fprintf(stderr, "fosssim-scene-format: unknown option \"%s\" (for a file of that name write ./%s)\n%s",
                   argv[1], argv[1], kUsage);
      return 2;
    }
    if (argc > 2) {
      std::fprintf(stderr, "fosssim-scene-format: one output path only, got also \"%s\"\n%s", argv[2], kUsage);
      return 2;
    }
  }
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
