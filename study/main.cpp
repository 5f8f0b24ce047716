// fosssim-study: runs the study's experiments and writes their CSV files (experiments.h).
// The charts and docs/study.md are made from those files by study/charts.py; scripts/study runs
// both. Usage:
//   fosssim-study [--out DIR] [--quick] [--only accuracy,stability,robustness,hybrid,profile,contacts]
#include "experiments.h"

#include <chrono>
#include <cstring>
#include <iostream>
#include <sstream>

namespace {

void usage(std::ostream& out) {
  out << "usage: fosssim-study [--out DIR] [--quick] [--only NAME[,NAME...]]\n"
         "  --out DIR   where the CSV files go (default: the current directory; it must exist)\n"
         "  --quick     a tiny matrix of every experiment (seconds instead of minutes)\n"
         "  --only      some of: accuracy, stability, robustness, hybrid, profile,\n"
         "              contacts\n";
}

}  // namespace

int main(int argc, char** argv) {
  using namespace fosssim::study;
  StudyOptions options;
  options.log = &std::cerr;
  std::string only = "accuracy,stability,robustness,hybrid,profile,contacts";
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc) {
      options.outDir = argv[++i];
    } else if (arg == "--quick") {
      options.quick = true;
    } else if (arg == "--only" && i + 1 < argc) {
      only = argv[++i];
    } else if (arg == "-h" || arg == "--help") {
      usage(std::cout);
      return 0;
    } else {
      std::cerr << "fosssim-study: unknown argument '" << arg << "'\n";
      usage(std::cerr);
      return 2;
    }
  }
  struct Experiment {
    const char* name;
    fosssim::Status (*run)(const StudyOptions&);
  };
  const Experiment experiments[] = {{"accuracy", runAccuracy},
                                    {"stability", runStability},
                                    {"robustness", runRobustness},
                                    {"hybrid", runHybridCost},
                                    {"profile", runProfile},
                                    {"contacts", runContacts}};
  std::stringstream wanted(only);
  std::string name;
  while (std::getline(wanted, name, ',')) {
    const Experiment* found = nullptr;
    for (const Experiment& e : experiments)
      if (name == e.name) found = &e;
    if (!found) {
      std::cerr << "fosssim-study: unknown experiment '" << name << "'\n";
      return 2;
    }
    const auto begin = std::chrono::steady_clock::now();
    if (fosssim::Status s = found->run(options); !s) {
      std::cerr << "fosssim-study: " << name << ": " << s.message() << "\n";
      return 1;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    std::cerr << "fosssim-study: " << name << " done in " << static_cast<int>(seconds + 0.5) << " s\n";
  }
  return 0;
}
