// fosssim-scenegen: writes a benchmark scene as a FOSSSim scene file.
//   fosssim-scenegen rain|gas|chains|bullets N [collision type] > scene.xml
#include "bench_scenes.h"

#include <cstdio>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  using namespace fosssim::bench;
  if (argc < 3) {
    std::fprintf(stderr, "usage: fosssim-scenegen rain|gas|chains|bullets N [collision type, default hybrid] > scene.xml\n");
    return 2;
  }
  BenchScene scene;
  const std::string collision = argc > 3 ? argv[3] : "hybrid";
  if (!makeScene(argv[1], std::stoi(argv[2]), collision, 1, scene)) {
    std::fprintf(stderr, "fosssim-scenegen: unknown scene '%s'\n", argv[1]);
    return 2;
  }
  writeSceneFile(scene, std::cout);
  return 0;
}
