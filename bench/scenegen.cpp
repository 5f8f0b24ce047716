// fosssim-scenegen: writes a benchmark scene (bench_scenes.h) as a FOSSSim scene file.
//   fosssim-scenegen rain|gas|chains|bullets|pile-... N [collision type, default hybrid] > scene.xml
#include "bench_scenes.h"

#include "cli_values.h"
#include "fosssim/io/scene_writer.h"

#include <iostream>
#include <string>

int main(int argc, char** argv) {
  using namespace fosssim;
  std::string kind, collision = "hybrid";
  long n = 0;
  CLI::App app("Writes a benchmark scene as a FOSSSim scene file to stdout, e.g.\n"
               "  fosssim-scenegen rain 2000 > rain.xml && FOSSSim -s rain.xml\n"
               "Scenes: rain (disks falling into a V), gas (elastic disks in a box), chains (chains of capsules\n"
               "falling onto a floor), bullets (fast small disks shot at a chain of thin edges).",
               "fosssim-scenegen");
  app.add_option("scene", kind, "one of " + cli::listed(bench::allKinds()))
      ->required()
      ->option_text("(required)")
      ->check(cli::oneOf("scene", bench::allKinds()));
  app.add_option("N", n, "particles, 1 to 10^7 (about N for chains and bullets)")
      ->required()
      ->option_text("(required)")
      ->check(cli::integerIn(1, 10000000));
  app.add_option("collision", collision,
                 "collision type, one of " + cli::listed(bench::collisionTypes()) + " (default hybrid)")
      ->option_text("(optional)")
      ->check(cli::oneOf("collision type", bench::collisionTypes()));
  if (const int status = cli::parseCommandLine(app, argc, argv); status >= 0) return status;

  bench::BenchScene scene;
  if (!bench::makeScene(kind, static_cast<int>(n), collision, 1, scene)) return 1;  // kinds were checked above
  std::string xml;
  if (Status s = sceneToXml(bench::toSceneFile(std::move(scene)), xml); !s) {
    std::cerr << "fosssim-scenegen: " << s.message() << "\n";
    return 1;
  }
  std::cout << xml;
  std::cout.flush();
  if (!std::cout) {
    std::cerr << "fosssim-scenegen: could not write the scene to stdout\n";
    return 1;
  }
  return 0;
}
